// Benchmark (not a test): the planner's latencies on the 560,000-triangle
// skull of the bundled CT head (300 HU).
// - One stroke segment to the feature line in split mode (StrokeSplitter,
//   built once per mesh as the planner does when it loads the bone): the
//   time of each addPoint for a pen stroke sampled every millimetre.
// - The cut along the closed line (lk::cutAlongLoops, with and without the
//   flat cap, and vtkLKClosedLineCutFilter end to end).
// The stroke is a craniotomy outline: the section of the skull's outer
// surface by a sphere of radius 20 mm around the top of the dome, traced
// 0.3 mm off the surface. Anchors measured in the same run: one ray pick
// (vtkCellLocator::IntersectWithLine, what the planner does per mouse event)
// and vtkPolyDataConnectivityFilter on the same mesh (VTK's region split).
//
// usage: bench_osteotomy SAMPLE_DATA_DIR
#include "common/PlaneSection.h"
#include "latticekit/MeshCut.h"
#include "latticekit/StrokeSplitter.h"

#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKClosedLineCutFilter.h"
#include "vtkLKExtractCutPieceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKPolyDataConversion.h"

#include <vtkCellArray.h>
#include <vtkCellLocator.h>
#include <vtkDataObject.h>
#include <vtkFieldData.h>
#include <vtkGeometryFilter.h>
#include <vtkIdTypeArray.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkSphere.h>
#include <vtkThreshold.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <numeric>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;
double ms(Clock::time_point t)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

double percentile(std::vector<double> v, double q)
{
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}
} // namespace

int main(int argc, char* argv[])
{
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_ERROR);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  const std::string data = argc > 1 ? argv[1] : "sample_data";
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName((data + "/cthead/cthead_hu_approx.nii.gz").c_str());
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  bone->SetInputConnection(reader->GetOutputPort());
  bone->SetIsoValue(300.0);
  bone->SetLabelMapMode(vtkLKBoneSurfaceFilter::LABEL_MAP_OFF);
  bone->Update();
  vtkPolyData* skull = bone->GetOutput();
  lk::TriangleMesh mesh;
  const std::string problem = lkvtk::toTriangleMesh(skull, mesh);
  if (!problem.empty())
  {
    std::fprintf(stderr, "error: %s\n", problem.c_str());
    return 1;
  }
  std::printf("skull: %zu triangles\n", mesh.triangles.size());

  // The craniotomy outline: top of the dome (smallest z: this volume's
  // superior direction is -z), sphere of radius 20 mm, the section loop
  // nearest the centre.
  std::size_t top = 0;
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    if (mesh.points[i].z() < mesh.points[top].z())
      top = i;
  const lk::Vec3 centre = mesh.points[top];
  vtkNew<vtkSphere> sphere;
  sphere->SetCenter(centre.data());
  sphere->SetRadius(20.0);
  // The outer surface's loop: its points lie above (smaller z than) the inner table's.
  std::vector<lk::Vec3> loop;
  double best = 1e300;
  for (const auto& section : lkapp::sectionLoops(skull, sphere))
  {
    if (section.size() < 20)
      continue;
    double z = 0;
    for (const auto& p : section)
      z += p[2] / static_cast<double>(section.size());
    if (z < best)
    {
      best = z;
      loop.clear();
      for (const auto& p : section)
        loop.emplace_back(p[0], p[1], p[2]);
    }
  }
  if (loop.empty())
  {
    std::fprintf(stderr, "error: no closed section of the dome\n");
    return 1;
  }
  // Every millimetre (a mouse event every few pixels), 0.3 mm off the surface outwards.
  std::vector<lk::Vec3> stroke;
  double run = 1e9;
  for (std::size_t i = 0; i + 1 < loop.size(); ++i)
  {
    run += (loop[i + 1] - loop[i]).norm();
    if (run >= 1.0)
    {
      const lk::Vec3 out = (loop[i] - centre).normalized();
      stroke.push_back(loop[i] + 0.3 * lk::Vec3(out.x() * 0.2, out.y() * 0.2, -1.0).normalized());
      run = 0.0;
    }
  }
  std::printf("stroke: %zu points around the dome (craniotomy outline, radius 20 mm)\n", stroke.size());

  auto t = Clock::now();
  lk::StrokeSplitter splitter(mesh);
  std::printf("StrokeSplitter set-up (half-edge mesh, AABB tree; once per mesh): %.0f ms\n", ms(t));
  std::vector<double> segment;
  std::size_t added = 0;
  for (const lk::Vec3& p : stroke)
  {
    t = Clock::now();
    try
    {
      added += splitter.addPoint(p);
    }
    catch (const std::exception& e)
    {
      std::fprintf(stderr, "error at stroke point %zu of %zu: %s\n", segment.size(), stroke.size(), e.what());
      return 1;
    }
    segment.push_back(ms(t));
  }
  t = Clock::now();
  splitter.close();
  const double tClose = ms(t);
  std::printf("split mode, per stroke segment: median %.3f ms, 95%% %.3f ms, max %.3f ms (target < 16 ms); "
              "close %.3f ms; %zu line vertices\n",
    percentile(segment, 0.5), percentile(segment, 0.95), percentile(segment, 1.0), tClose, splitter.line().size());

  // Anchor: one ray pick per stroke point on a prebuilt vtkCellLocator.
  vtkNew<vtkCellLocator> locator;
  locator->SetDataSet(skull);
  locator->BuildLocator();
  std::vector<double> pick;
  for (const lk::Vec3& p : stroke)
  {
    double a[3] = { p.x(), p.y(), p.z() - 200.0 }, b[3] = { p.x(), p.y(), p.z() + 200.0 }, x[3], pc[3], tt;
    int sub;
    t = Clock::now();
    locator->IntersectWithLine(a, b, 1e-6, tt, x, pc, sub);
    pick.push_back(ms(t));
  }
  std::printf("anchor, one vtkCellLocator ray pick: median %.3f ms; split segment / pick: %.2f\n",
    percentile(pick, 0.5), percentile(segment, 0.5) / percentile(pick, 0.5));

  // The cut.
  const lk::TriangleMesh split = splitter.mesh();
  lk::PolygonMesh poly;
  poly.points = split.points;
  for (const auto& tri : split.triangles)
    poly.faces.push_back({ tri[0], tri[1], tri[2] });
  // Each timing below is the median of kRuns runs, with the range: single
  // runs vary by about 30 % on a 2-core machine.
  constexpr int kRuns = 5;
  auto range = [](std::vector<double> v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.1f ms (%.1f-%.1f)", percentile(v, 0.5), percentile(v, 0.0), percentile(v, 1.0));
    return std::string(text);
  };
  // The third: capped and through the inner walls, the filter's default. The
  // craniotomy's flat cap grazes the skull's inner table, so the cut through
  // the walls is tried as well, and the plain cut kept.
  for (int mode : { 0, 1, 2 })
  {
    const bool cap = mode > 0, walls = mode == 2;
    std::vector<double> tCut;
    std::size_t pieces = 0, faces0 = 0, faces1 = 0, crossings = 0, innerLoops = 0;
    for (int run = 0; run < kRuns; ++run)
    {
      t = Clock::now();
      const auto cut = lk::cutAlongLoops(poly, { splitter.line() }, cap, walls);
      tCut.push_back(ms(t));
      pieces = cut.pieces.size();
      faces0 = cut.pieces[0].faces.size();
      faces1 = cut.pieces.size() > 1 ? cut.pieces[1].faces.size() : 0;
      crossings = std::accumulate(cut.capCrossings.begin(), cut.capCrossings.end(), std::size_t(0));
      innerLoops = cut.innerWallLoops;
    }
    std::printf("cutAlongLoops (%s): median %s of %d runs (target < 200 ms), %zu pieces: %zu and %zu faces",
      mode == 0 ? "open" : mode == 1 ? "capped" : "capped, inner walls", range(tCut).c_str(), kRuns, pieces, faces0,
      faces1);
    if (cap)
      std::printf("; %zu cap crossings, %zu inner-wall lines", crossings, innerLoops);
    std::printf("\n");
  }
  auto splitPd = lkvtk::fromTriangleMesh(split);
  vtkNew<vtkPolyData> lines;
  vtkNew<vtkPoints> lp;
  vtkNew<vtkCellArray> lc;
  vtkNew<vtkIdTypeArray> mid;
  mid->SetName("MeshPointId");
  lc->InsertNextCell(static_cast<vtkIdType>(splitter.line().size()));
  for (auto v : splitter.line())
  {
    lc->InsertCellPoint(lp->InsertNextPoint(split.points[static_cast<std::size_t>(v)].data()));
    mid->InsertNextValue(static_cast<vtkIdType>(v));
  }
  lines->SetPoints(lp);
  lines->SetLines(lc);
  lines->GetPointData()->AddArray(mid);
  std::vector<double> tFilter, tRegions;
  int filterPieces = 0;
  for (int run = 0; run < kRuns; ++run)
  {
    vtkNew<vtkLKClosedLineCutFilter> cutFilter;
    cutFilter->SetInputData(splitPd);
    cutFilter->SetLinesData(lines);
    cutFilter->SetCapping(true);
    t = Clock::now();
    cutFilter->Update();
    tFilter.push_back(ms(t));
    filterPieces = cutFilter->GetNumberOfPieces();
    vtkNew<vtkPolyDataConnectivityFilter> regions;
    regions->SetInputData(splitPd);
    regions->SetExtractionModeToAllRegions();
    regions->ColorRegionsOn();
    t = Clock::now();
    regions->Update();
    tRegions.push_back(ms(t));
  }
  std::printf("vtkLKClosedLineCutFilter (capped, with VTK conversions): median %s, %d pieces; anchor "
              "vtkPolyDataConnectivityFilter (all regions): median %s; ratio of medians %.2f\n",
    range(tFilter).c_str(), filterPieces, range(tRegions).c_str(),
    percentile(tFilter, 0.5) / percentile(tRegions, 0.5));

  // Every piece taken out of the cut: vtkLKExtractCutPieceFilter (cells in
  // the cut's order, and the cut lines) against VTK's way, vtkThreshold on
  // RegionId and vtkGeometryFilter (threaded; the order changes run to run).
  vtkNew<vtkLKClosedLineCutFilter> cutOnce;
  cutOnce->SetInputData(splitPd);
  cutOnce->SetLinesData(lines);
  cutOnce->SetCapping(true);
  cutOnce->Update();
  std::vector<double> tExtract, tThreshold;
  vtkIdType extractedCells = 0, thresholdCells = 0, cutLineEdges = 0;
  for (int run = 0; run < kRuns; ++run)
  {
    extractedCells = thresholdCells = cutLineEdges = 0;
    t = Clock::now();
    for (int r = 0; r < cutOnce->GetNumberOfPieces(); ++r)
    {
      vtkNew<vtkLKExtractCutPieceFilter> extract;
      extract->SetInputConnection(cutOnce->GetOutputPort());
      extract->SetPiece(r);
      extract->Update();
      extractedCells += extract->GetOutput()->GetNumberOfCells();
      cutLineEdges += static_cast<vtkIdType>(
        extract->GetCutLinesOutput()->GetFieldData()->GetArray("CutLineEdges")->GetTuple1(0));
    }
    tExtract.push_back(ms(t));
    t = Clock::now();
    for (int r = 0; r < cutOnce->GetNumberOfPieces(); ++r)
    {
      vtkNew<vtkThreshold> threshold;
      threshold->SetInputConnection(cutOnce->GetOutputPort());
      threshold->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "RegionId");
      threshold->SetLowerThreshold(r - 0.5);
      threshold->SetUpperThreshold(r + 0.5);
      vtkNew<vtkGeometryFilter> geometry;
      geometry->SetInputConnection(threshold->GetOutputPort());
      geometry->Update();
      thresholdCells += geometry->GetOutput()->GetNumberOfCells();
    }
    tThreshold.push_back(ms(t));
  }
  std::printf("vtkLKExtractCutPieceFilter, every piece with its cut lines (%lld cells, %lld cut-line edges): median "
              "%s; anchor vtkThreshold + vtkGeometryFilter (%lld cells): median %s; ratio of medians %.2f\n",
    static_cast<long long>(extractedCells), static_cast<long long>(cutLineEdges), range(tExtract).c_str(),
    static_cast<long long>(thresholdCells), range(tThreshold).c_str(),
    percentile(tExtract, 0.5) / percentile(tThreshold, 0.5));
  return 0;
}
