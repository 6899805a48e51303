// Parameters that VTK's setters let through: vtkSetClampMacro keeps a NaN
// (every comparison with it is false), and a plain vtkSetMacro keeps
// anything. Each filter checks the ones it uses when it runs and refuses a
// NaN (or an infinite or out-of-range value where that would be taken
// silently, take all memory or crash) with a clear error and an empty
// output. Found by setting every numeric parameter of every filter to NaN,
// infinities, zero, -1 and huge values from Python: an infinite
// ImageSmoothing crashed vtkImageGaussianSmooth, and these were taken
// silently as "off" or "automatic".
#include "TestSupport.h"

#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKLatticeFitFilter.h"
#include "vtkLKLatticeSurfaceFilter.h"
#include "vtkLKMeshRepairFilter.h"
#include "vtkLKMetroFilter.h"
#include "vtkLKStrokeFeatureLineFilter.h"
#include "vtkLKWrinklyNetSource.h"

#include <vtkCellArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace
{
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

/// Runs `filter` and expects one error naming `text`, and an empty output.
void expectRefused(vtkAlgorithm* filter, const std::string& text)
{
  lktest::ErrorRecorder rec(filter);
  filter->Update();
  EXPECT_EQ(rec.errors, 1) << text;
  EXPECT_NE(rec.messages.find(text), std::string::npos) << rec.messages;
  auto* out = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(out->GetNumberOfPoints(), 0) << text;
}

/// Runs `filter` and expects no error and a non-empty output.
void expectAccepted(vtkAlgorithm* filter)
{
  lktest::ErrorRecorder rec(filter);
  filter->Update();
  EXPECT_EQ(rec.errors, 0) << rec.messages;
  auto* out = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
  ASSERT_NE(out, nullptr);
  EXPECT_GT(out->GetNumberOfPoints(), 0);
}

/// A closed sphere of radius 10 (the seam welded).
vtkSmartPointer<vtkPolyData> sphere(int resolution = 16)
{
  vtkNew<vtkSphereSource> s;
  s->SetRadius(10.0);
  s->SetThetaResolution(resolution);
  s->SetPhiResolution(resolution);
  vtkNew<vtkLKMeshRepairFilter> repair;
  repair->SetInputConnection(s->GetOutputPort());
  repair->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(repair->GetOutput());
  return out;
}
} // namespace

TEST(ParameterChecks, BoneSurfaceImageSmoothingAndSeedPoint)
{
  // A ball of 1000 in a volume of 0, radius 7 voxels.
  vtkNew<vtkImageData> ball;
  ball->SetDimensions(24, 24, 24);
  ball->AllocateScalars(VTK_SHORT, 1);
  for (int z = 0; z < 24; ++z)
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 24; ++x)
        ball->SetScalarComponentFromDouble(x, y, z, 0,
          (x - 12) * (x - 12) + (y - 12) * (y - 12) + (z - 12) * (z - 12) < 49 ? 1000.0 : 0.0);
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  bone->SetInputData(ball);
  // An infinite or huge standard deviation crashed vtkImageGaussianSmooth
  // (a kernel of 3 sigma voxels); NaN was taken as no smoothing.
  for (const double sigma : { kInf, 1e12, 20.5, kNaN })
  {
    bone->SetImageSmoothing(sigma);
    expectRefused(bone, "ImageSmoothing must be a standard deviation from 0 to 20 voxels");
  }
  bone->SetImageSmoothing(2.0);
  expectAccepted(bone);
  bone->SetImageSmoothing(-1.0); // automatic
  expectAccepted(bone);
  // The automatic Gaussian of a label map, checked as the one given.
  for (const double sigma : { kInf, 20.5, -0.5, kNaN })
  {
    bone->SetLabelMapImageSmoothing(sigma);
    expectRefused(bone, "LabelMapImageSmoothing must be a standard deviation from 0 to 20 voxels");
  }
  bone->SetLabelMapImageSmoothing(1.0);
  expectAccepted(bone);
  // A seed is checked only where it is used.
  bone->SetSeedPoint(kNaN, 0.0, 0.0);
  expectAccepted(bone);
  bone->SetExtractionModeToSeededComponent();
  expectRefused(bone, "The SeedPoint (nan, 0, 0) must be finite");
  bone->SetSeedPoint(12.0, 12.0, 12.0);
  expectAccepted(bone);
}

TEST(ParameterChecks, LatticeFitMaximumError)
{
  vtkNew<vtkLKLatticeFitFilter> fit;
  fit->SetInputData(sphere());
  fit->SetTargetNumberOfVertices(0);
  fit->SetMaximumError(kNaN); // was taken as 0, no bound: a fit at the default reduction
  expectRefused(fit, "MaximumError must be a number (0: no error bound), not NaN");
}

TEST(ParameterChecks, LatticeSurfaceChordalTolerance)
{
  vtkNew<vtkLKLatticeSurfaceFilter> surface;
  surface->SetInputData(sphere(8));
  surface->SetChordalTolerance(kNaN); // was taken as 0, Resolution's surface
  expectRefused(surface, "ChordalTolerance must be a distance (0: use Resolution), not NaN");
  surface->SetChordalTolerance(0.1);
  expectAccepted(surface);
}

TEST(ParameterChecks, MetroColorMaximum)
{
  vtkNew<vtkLKMetroFilter> metro;
  metro->SetInputData(sphere(16));
  metro->SetTargetData(sphere(8));
  metro->SetColorMaximum(kNaN); // was taken as 0, the percentile
  expectRefused(metro, "ColorMaximum must be a finite distance (0: the 99th percentile), not nan");
  metro->SetColorMaximum(0.5);
  expectAccepted(metro);
}

TEST(ParameterChecks, StrokeBrushRadiusAndCloseTolerance)
{
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 40; ++i)
    points->InsertNextPoint(10.0 * std::cos(2 * M_PI * i / 40), 10.0 * std::sin(2 * M_PI * i / 40), 0.3);
  vtkNew<vtkCellArray> line;
  line->InsertNextCell(41);
  for (vtkIdType i = 0; i <= 40; ++i)
    line->InsertCellPoint(i % 40);
  vtkNew<vtkPolyData> ring;
  ring->SetPoints(points);
  ring->SetLines(line);
  vtkNew<vtkLKStrokeFeatureLineFilter> stroke;
  stroke->SetInputData(sphere(24));
  stroke->SetStrokeData(ring);
  stroke->SetModeToPaint();
  stroke->SetBrushRadius(kNaN); // was taken as 0, the automatic brush
  expectRefused(stroke, "BrushRadius and CloseTolerance must be finite lengths");
  stroke->SetBrushRadius(0.0);
  stroke->SetCloseTolerance(kNaN);
  expectRefused(stroke, "not 0 and nan");
  stroke->SetCloseTolerance(0.0);
  expectAccepted(stroke);
}

TEST(ParameterChecks, WrinklyNetSpacingAndHeightAmplitude)
{
  vtkNew<vtkLKWrinklyNetSource> net;
  net->SetHeightAmplitude(kInf); // gave infinite heights
  expectRefused(net, "Spacing and HeightAmplitude must be finite numbers");
  net->SetHeightAmplitude(kNaN);
  expectRefused(net, "Spacing and HeightAmplitude must be finite numbers");
  net->SetHeightAmplitude(1.0);
  net->SetSpacing(kNaN);
  expectRefused(net, "Spacing and HeightAmplitude must be finite numbers");
  net->SetSpacing(1.0);
  expectAccepted(net);
}
