// Benchmark (not a test): the plane of symmetry (vtkLKSymmetryPlaneFilter:
// trimmed point-to-plane ICP on CGAL's AABB tree) against VTK's own
// registration, vtkIterativeClosestPointTransform (plain point-to-point ICP,
// rigid, 2,000 landmarks, at most 100 iterations, on a vtkCellLocator),
// started from the same mirror image, on the TCIA mandible (12,212 points)
// and the bundled CT head's skull at 300 HU (560,686 triangles). Each is
// timed three times in the same run; the ratio is of the medians. VTK's
// registration gives no plane by itself: its plane is taken the filter's way
// (the reflection nearest the motion), so the two planes can be compared.
//
// usage: bench_symmetry SAMPLE_DATA_DIR
#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKSymmetryPlaneFilter.h"

#include <vtkCellLocator.h>
#include <vtkIterativeClosestPointTransform.h>
#include <vtkLandmarkTransform.h>
#include <vtkLogger.h>
#include <vtkMath.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// VTK's ICP from the mirror across x through the mean point; the normal of
/// the reflection nearest the result.
void vtkPlane(vtkPolyData* bone, double normal[3])
{
  const vtkIdType count = bone->GetNumberOfPoints();
  double centre[3] = { 0, 0, 0 };
  for (vtkIdType i = 0; i < count; ++i)
  {
    double x[3];
    bone->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
      centre[k] += x[k] / static_cast<double>(count);
  }
  vtkNew<vtkPoints> mirrored;
  mirrored->SetNumberOfPoints(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    double x[3];
    bone->GetPoint(i, x);
    x[0] = 2.0 * centre[0] - x[0];
    mirrored->SetPoint(i, x);
  }
  vtkNew<vtkPolyData> source;
  source->SetPoints(mirrored);
  vtkNew<vtkCellLocator> locator;
  locator->SetDataSet(bone);
  locator->BuildLocator();
  vtkNew<vtkIterativeClosestPointTransform> icp;
  icp->SetSource(source);
  icp->SetTarget(bone);
  icp->SetLocator(locator);
  icp->GetLandmarkTransform()->SetModeToRigidBody();
  icp->SetMaximumNumberOfIterations(100);
  icp->SetMaximumNumberOfLandmarks(2000);
  icp->StartByMatchingCentroidsOff();
  icp->CheckMeanDistanceOn();
  icp->SetMeanDistanceModeToAbsoluteValue();
  double bounds[6];
  bone->GetBounds(bounds);
  icp->SetMaximumMeanDistance(1e-5 * std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
                                        (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
                                        (bounds[5] - bounds[4]) * (bounds[5] - bounds[4])));
  icp->Update();
  // The motion after the mirror: its linear part times diag(-1, 1, 1).
  double symmetric[3][3], values[3], vectors[3][3];
  double* rows[3] = { symmetric[0], symmetric[1], symmetric[2] };
  double* vectorRows[3] = { vectors[0], vectors[1], vectors[2] };
  vtkMatrix4x4* m = icp->GetMatrix();
  auto linear = [&](int r, int c) { return m->GetElement(r, c) * (c == 0 ? -1.0 : 1.0); };
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      symmetric[r][c] = 0.5 * (linear(r, c) + linear(c, r));
  vtkMath::Jacobi(rows, values, vectorRows);
  for (int k = 0; k < 3; ++k)
    normal[k] = vectors[k][2];
  if (normal[0] < 0.0)
    vtkMath::MultiplyScalar(normal, -1.0);
}

void run(const std::string& name, const std::string& file, double iso)
{
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(file.c_str());
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  bone->SetInputConnection(reader->GetOutputPort());
  bone->SetIsoValue(iso);
  bone->Update();
  vtkPolyData* surface = bone->GetOutput();
  if (surface->GetNumberOfPoints() == 0)
  {
    std::fprintf(stderr, "error: no surface from %s\n", file.c_str());
    return;
  }
  std::vector<double> ours, anchor;
  double n[3] = { 0, 0, 0 }, m[3] = { 0, 0, 0 }, kept = 0.0;
  for (int run = 0; run < 3; ++run)
  {
    auto t = Clock::now();
    vtkNew<vtkLKSymmetryPlaneFilter> filter;
    filter->SetInputData(surface);
    filter->Update();
    ours.push_back(seconds(t));
    filter->GetPlaneNormal(n);
    kept = filter->GetKeptFraction();
    t = Clock::now();
    vtkPlane(surface, m);
    anchor.push_back(seconds(t));
  }
  std::printf("%s (%lld points): vtkLKSymmetryPlaneFilter median %.2f s (%.2f of the points kept); anchor "
              "vtkIterativeClosestPointTransform median %.2f s; ratio %.2f; planes %.3f degrees apart\n",
    name.c_str(), static_cast<long long>(surface->GetNumberOfPoints()), median(ours), kept, median(anchor),
    median(ours) / median(anchor), vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(n, m)));
}
} // namespace

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: bench_symmetry SAMPLE_DATA_DIR\n");
    return 2;
  }
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_ERROR);
  const std::string data = argv[1];
  run("mandible 1", data + "/mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd", 0.5);
  run("skull", data + "/cthead/cthead_hu_approx.nii.gz", 300.0);
  return 0;
}
