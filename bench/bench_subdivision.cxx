// Benchmark (not a test): homogenized Loop subdivision against
// vtkLoopSubdivisionFilter (the anchor, same run), 4 levels on the TCIA
// mandible (24,420 triangles -> 6.25 M), all weights 1 and with weights.
//
// usage: bench_subdivision SAMPLE_DATA_DIR
#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKHomogenizedLoopFilter.h"
#include "vtkLKMedicalImageReader.h"

#include <vtkDoubleArray.h>
#include <vtkLogger.h>
#include <vtkLoopSubdivisionFilter.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

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
  vtkNew<vtkPolyData> mesh;
  mesh->ShallowCopy(bone->GetOutput());
  mesh->GetPointData()->Initialize();
  auto seconds = [](auto t0) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  for (int levels : { 3, 4 })
  {
    vtkNew<vtkLoopSubdivisionFilter> vtk;
    vtk->SetInputData(mesh);
    vtk->SetNumberOfSubdivisions(levels);
    auto t0 = std::chrono::steady_clock::now();
    vtk->Update();
    const double tv = seconds(t0);
    vtkNew<vtkLKHomogenizedLoopFilter> ours;
    ours->SetInputData(mesh);
    ours->SetNumberOfSubdivisions(levels);
    t0 = std::chrono::steady_clock::now();
    ours->Update();
    const double to = seconds(t0);
    std::printf("%d levels, %lld -> %lld triangles: homogenized Loop %.2f s, vtkLoopSubdivisionFilter %.2f s, "
                "ratio %.2f (target <= 1)\n",
      levels, static_cast<long long>(mesh->GetNumberOfPolys()),
      static_cast<long long>(ours->GetOutput()->GetNumberOfPolys()), to, tv, to / tv);
  }
  return 0;
}
