// Benchmark (not a test): lattice surface construction and tessellation on a
// 2,000-vertex lattice of the TCIA mandible: patches built and evaluated per
// second, display triangles per second, against vtkLoopSubdivisionFilter
// producing a comparable number of triangles from the same lattice (the
// anchor, measured in the same run).
//
// usage: bench_lattice SAMPLE_DATA_DIR
#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKLatticeSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKMeshRepairFilter.h"

#include <vtkLogger.h>
#include <vtkLoopSubdivisionFilter.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>

#include <chrono>
#include <cstdio>
#include <string>

int main(int argc, char* argv[])
{
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_ERROR);
  const std::string data = argc > 1 ? argv[1] : "sample_data";
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName((data + "/mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd").c_str());
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  bone->SetInputConnection(reader->GetOutputPort());
  bone->Update();
  vtkNew<vtkQuadricDecimation> decimate;
  decimate->SetInputConnection(bone->GetOutputPort());
  decimate->SetTargetReduction(1.0 - 2000.0 / static_cast<double>(bone->GetOutput()->GetNumberOfPoints()));
  vtkNew<vtkLKMeshRepairFilter> lattice;
  lattice->SetInputConnection(decimate->GetOutputPort());
  lattice->Update();
  std::printf("lattice: %lld vertices, %lld triangles\n",
    static_cast<long long>(lattice->GetOutput()->GetNumberOfPoints()),
    static_cast<long long>(lattice->GetOutput()->GetNumberOfPolys()));
  for (int resolution : { 2, 4, 8 })
  {
    vtkNew<vtkLKLatticeSurfaceFilter> surface;
    surface->SetInputConnection(lattice->GetOutputPort());
    surface->SetResolution(resolution);
    const auto t0 = std::chrono::steady_clock::now();
    surface->Update();
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto triangles = static_cast<double>(surface->GetOutput()->GetNumberOfPolys());
    // Anchor: Loop subdivision to at least as many triangles.
    int levels = 0;
    double loopTriangles = static_cast<double>(lattice->GetOutput()->GetNumberOfPolys());
    while (loopTriangles < triangles)
    {
      loopTriangles *= 4;
      ++levels;
    }
    vtkNew<vtkLoopSubdivisionFilter> loop;
    loop->SetInputConnection(lattice->GetOutputPort());
    loop->SetNumberOfSubdivisions(levels);
    const auto t1 = std::chrono::steady_clock::now();
    loop->Update();
    const double tl = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    std::printf("resolution %d: %lld patches, %.0f display triangles in %.3f s: %.0f patches/s, %.0f "
                "triangles/s; vtkLoopSubdivisionFilter (%d levels, %lld triangles) %.0f triangles/s, "
                "ratio %.2f\n",
      resolution, static_cast<long long>(surface->GetNumberOfPatches()), triangles, t,
      static_cast<double>(surface->GetNumberOfPatches()) / t, triangles / t, levels,
      static_cast<long long>(loop->GetOutput()->GetNumberOfPolys()),
      static_cast<double>(loop->GetOutput()->GetNumberOfPolys()) / tl,
      (triangles / t) / (static_cast<double>(loop->GetOutput()->GetNumberOfPolys()) / tl));
  }
  return 0;
}
