// Benchmark (not a test): the bone surface of a scan, vtkLKBoneSurfaceFilter
// end to end (the reader's volume to a repaired, CGAL-checked surface in
// patient coordinates), against the plain VTK pipeline that makes the same
// triangles, measured in the same run:
// - a label map (the two TCIA mandibles, 512 x 512 x 127-156 voxels): the
//   anchor is vtkImageCast (float), vtkImageGaussianSmooth (sigma 1 voxel,
//   radius factor 3) and vtkFlyingEdges3D at 0.5 over the whole volume, then
//   vtkPolyDataConnectivityFilter (largest region);
// - the CT head and the GE CT series (a DICOM folder) at 300 HU (no
//   smoothing): vtkFlyingEdges3D and the connectivity filter.
// Each time is the median of three runs; the ratio is the filter's over the
// anchor's.
//
// usage: bench_surface SAMPLE_DATA_DIR
#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"

#include <vtkFlyingEdges3D.h>
#include <vtkImageCast.h>
#include <vtkImageData.h>
#include <vtkImageGaussianSmooth.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace
{
/// The median of three runs of `run`, in seconds.
double median3(const std::function<void()>& run)
{
  std::vector<double> t;
  for (int i = 0; i < 3; ++i)
  {
    const auto t0 = std::chrono::steady_clock::now();
    run();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  return t[1];
}
} // namespace

int main(int argc, char* argv[])
{
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_ERROR);
  const std::string data = argc > 1 ? argv[1] : "sample_data";
  struct Scan
  {
    std::string name, file;
    bool labelMap;
  };
  const Scan scans[] = {
    { "mandible 1 (label map)", data + "/mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd", true },
    { "mandible 2 (label map)", data + "/mandible-tcia/test_oncologist_TCGA-CV-7236_Mandible.nrrd", true },
    { "CT head, 300 HU", data + "/cthead/cthead_hu_approx.nii.gz", false },
    { "GE CT series, 300 HU", data + "/dicom-ct-ge-tilt", false },
  };
  std::printf("%-24s %18s %12s %12s %12s %7s\n", "scan", "voxels", "triangles", "filter (s)", "anchor (s)", "ratio");
  for (const Scan& scan : scans)
  {
    vtkNew<vtkLKMedicalImageReader> reader;
    reader->SetFileName(scan.file.c_str());
    reader->Update();
    vtkImageData* volume = reader->GetOutput();
    int dims[3];
    volume->GetDimensions(dims);
    vtkNew<vtkLKBoneSurfaceFilter> bone;
    bone->SetInputData(volume);
    const double filter = median3([&] {
      bone->Modified();
      bone->Update();
    });
    vtkNew<vtkImageCast> cast;
    cast->SetInputData(volume);
    cast->SetOutputScalarTypeToFloat();
    vtkNew<vtkImageGaussianSmooth> gauss;
    gauss->SetInputConnection(cast->GetOutputPort());
    gauss->SetStandardDeviations(1.0, 1.0, 1.0);
    gauss->SetRadiusFactors(3.0, 3.0, 3.0);
    vtkNew<vtkFlyingEdges3D> contour;
    if (scan.labelMap)
      contour->SetInputConnection(gauss->GetOutputPort());
    else
      contour->SetInputData(volume);
    contour->SetValue(0, scan.labelMap ? 0.5 : 300.0);
    contour->ComputeNormalsOff();
    contour->ComputeGradientsOff();
    contour->ComputeScalarsOff();
    vtkNew<vtkPolyDataConnectivityFilter> largest;
    largest->SetInputConnection(contour->GetOutputPort());
    largest->SetExtractionModeToLargestRegion();
    const double anchor = median3([&] {
      cast->Modified();
      contour->Modified();
      largest->Update();
    });
    char voxels[64];
    std::snprintf(voxels, sizeof voxels, "%d x %d x %d", dims[0], dims[1], dims[2]);
    std::printf("%-24s %18s %12lld %12.3f %12.3f %7.2f\n", scan.name.c_str(), voxels,
      static_cast<long long>(bone->GetOutput()->GetNumberOfPolys()), filter, anchor, filter / anchor);
    if (bone->GetOutput()->GetNumberOfPolys() == 0)
      return 1;
  }
  return 0;
}
