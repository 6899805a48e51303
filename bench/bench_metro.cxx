// Benchmark (not a test): Metro throughput against VTK's
// vtkHausdorffDistancePointSetFilter at equal sample counts, and the time of
// CT -> bone surface. Prints ratios measured in one run.
//
// usage: bench_metro SAMPLE_DATA_DIR
#include "latticekit/ClosestPointTree.h"
#include "latticekit/SurfaceSampling.h"

#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKMetroFilter.h"
#include "vtkLKPolyDataConversion.h"

#include <vtkCellArray.h>
#include <vtkHausdorffDistancePointSetFilter.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>
#include <vtkSMPTools.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace
{
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

lk::TriangleMesh toMesh(vtkPolyData* pd)
{
  lk::TriangleMesh m;
  lkvtk::toTriangleMesh(pd, m);
  return m;
}
} // namespace

int main(int argc, char* argv[])
{
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_ERROR);
  const std::string data = argc > 1 ? argv[1] : "sample_data";
  std::printf("threads: %d (vtkSMPTools backend %s)\n", vtkSMPTools::GetEstimatedNumberOfThreads(),
    vtkSMPTools::GetBackend());

  // CT -> bone surface.
  auto t = Clock::now();
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName((data + "/cthead/cthead_hu_approx.nii.gz").c_str());
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  bone->SetInputConnection(reader->GetOutputPort());
  bone->Update();
  const double tBone = since(t);
  vtkPolyData* skull = bone->GetOutput();
  std::printf("CT head -> bone surface (300 HU, largest, repaired): %.3f s, %lld triangles\n", tBone,
    static_cast<long long>(skull->GetNumberOfPolys()));

  // A simplified copy to compare against.
  vtkNew<vtkQuadricDecimation> decimate;
  decimate->SetInputData(skull);
  decimate->SetTargetReduction(0.95);
  t = Clock::now();
  decimate->Update();
  const double tDecimate = since(t);
  vtkPolyData* copy = decimate->GetOutput();
  std::printf("vtkQuadricDecimation to 5%%: %.3f s, %lld triangles\n", tDecimate,
    static_cast<long long>(copy->GetNumberOfPolys()));

  // Breakdown of one direction (skull samples -> copy) in the core.
  const lk::TriangleMesh a = toMesh(skull), b = toMesh(copy);
  t = Clock::now();
  lk::ClosestPointTree tree(b);
  const double tTree = since(t);
  lk::SamplingOptions options;
  options.targetSamples = 4000000;
  t = Clock::now();
  const lk::SampleSet samples = lk::sampleSurface(a, options);
  const double tSample = since(t);
  std::vector<double> d(samples.size());
  t = Clock::now();
  vtkSMPTools::For(0, static_cast<vtkIdType>(samples.size()), 2048, [&](vtkIdType s, vtkIdType e) {
    tree.distances(samples, static_cast<std::size_t>(s), static_cast<std::size_t>(e), d.data());
  });
  const double tQuery = since(t);
  std::printf("core breakdown, skull -> copy, %zu samples: tree %.3f s, sampling %.3f s, "
              "queries %.3f s (%.2f M queries/s)\n",
    samples.size(), tTree, tSample, tQuery, samples.size() / tQuery / 1e6);
  {
    t = Clock::now();
    lk::ClosestPointTree treeA(a);
    const double tTreeA = since(t);
    t = Clock::now();
    const lk::SampleSet samplesB = lk::sampleSurface(b, options);
    const double tSampleB = since(t);
    std::vector<double> dB(samplesB.size());
    t = Clock::now();
    vtkSMPTools::For(0, static_cast<vtkIdType>(samplesB.size()), 2048, [&](vtkIdType s, vtkIdType e) {
      treeA.distances(samplesB, static_cast<std::size_t>(s), static_cast<std::size_t>(e), dB.data());
    });
    const double tQueryB = since(t);
    std::printf("core breakdown, copy -> skull, %zu samples: tree %.3f s, sampling %.3f s, "
                "queries %.3f s (%.2f M queries/s)\n",
      samplesB.size(), tTreeA, tSampleB, tQueryB, samplesB.size() / tQueryB / 1e6);
  }

  // The whole filter, both directions.
  vtkNew<vtkLKMetroFilter> metro;
  metro->SetInputData(skull);
  metro->SetTargetData(copy);
  metro->SetNumberOfSamples(2000000);
  t = Clock::now();
  metro->Update();
  const double tMetro = since(t);
  const double nMetro =
    static_cast<double>(metro->GetNumberOfForwardSamples() + metro->GetNumberOfBackwardSamples());
  const double rateMetro = nMetro / tMetro;

  // VTK's anchor on the same forward sample points (points of A against the cells of B).
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  const vtkIdType nAnchor = std::min<vtkIdType>(static_cast<vtkIdType>(samples.size()), 1000000);
  pts->SetNumberOfPoints(nAnchor);
  for (vtkIdType i = 0; i < nAnchor; ++i)
  {
    pts->SetPoint(i, samples.points[static_cast<std::size_t>(i)].data());
  }
  vtkNew<vtkCellArray> verts; // vertex cells, so that its reverse direction has cells to find
  for (vtkIdType i = 0; i < nAnchor; ++i)
  {
    verts->InsertNextCell(1, &i);
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(pts);
  cloud->SetVerts(verts);
  vtkNew<vtkHausdorffDistancePointSetFilter> vtkHausdorff;
  vtkHausdorff->SetInputData(0, cloud);
  vtkHausdorff->SetInputData(1, copy);
  vtkHausdorff->SetTargetDistanceMethodToPointToCell();
  t = Clock::now();
  vtkHausdorff->Update();
  const double tVtk = since(t);
  // It measures both directions: the cloud's points and the copy's points.
  const double nVtk = static_cast<double>(nAnchor + copy->GetNumberOfPoints());
  const double rateVtk = nVtk / tVtk;

  std::printf("\n%-44s %12s %10s %14s\n", "method", "samples", "seconds", "samples/s");
  std::printf("%-44s %12.0f %10.3f %14.0f\n", "vtkLKMetroFilter (both directions)", nMetro, tMetro,
    rateMetro);
  std::printf("%-44s %12.0f %10.3f %14.0f\n", "vtkHausdorffDistancePointSetFilter (cells)", nVtk,
    tVtk, rateVtk);
  // The paper's model size: the TCIA mandible (about 12,000 vertices) against
  // a 10 % copy, both directions, Metro's default sample count.
  vtkNew<vtkLKMedicalImageReader> mandibleReader;
  mandibleReader->SetFileName((data + "/mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd").c_str());
  vtkNew<vtkLKBoneSurfaceFilter> mandible;
  mandible->SetInputConnection(mandibleReader->GetOutputPort());
  vtkNew<vtkQuadricDecimation> mandibleCopy;
  mandibleCopy->SetInputConnection(mandible->GetOutputPort());
  mandibleCopy->SetTargetReduction(0.9);
  mandibleCopy->Update();
  vtkNew<vtkLKMetroFilter> metroMandible;
  metroMandible->SetInputConnection(mandible->GetOutputPort());
  metroMandible->SetTargetConnection(mandibleCopy->GetOutputPort());
  metroMandible->SetNumberOfSamples(1000000);
  t = Clock::now();
  metroMandible->Update();
  const double tMandible = since(t);
  const double nMandible = static_cast<double>(
    metroMandible->GetNumberOfForwardSamples() + metroMandible->GetNumberOfBackwardSamples());
  std::printf("%-44s %12.0f %10.3f %14.0f\n", "vtkLKMetroFilter, TCIA mandible vs 10 % copy", nMandible,
    tMandible, nMandible / tMandible);

  std::printf("\nratio Metro / VTK samples per second: %.1f\n", rateMetro / rateVtk);
  std::printf("target: 3 M samples/s on 2 cores; measured %.2f M samples/s on the skull (%.0f%% of "
              "target), %.2f M samples/s on the mandible (%.0f%%)\n",
    rateMetro / 1e6, 100.0 * rateMetro / 3e6, nMandible / tMandible / 1e6,
    100.0 * nMandible / tMandible / 3e6);
  std::printf("ratio CT->surface time / vtkQuadricDecimation time on its output: %.2f\n",
    tBone / tDecimate);
  return 0;
}
