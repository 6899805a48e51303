// vtkLKSymmetryPlaneFilter: a bone's plane of symmetry and its mirror image,
// on a shape symmetric about one tilted plane only (exact answer), on the
// TCIA mandible, and on bad input.
#include "TestSupport.h"

#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKSymmetryPlaneFilter.h"

#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCleanPolyData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkMath.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataNormals.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>
#include <vtkStripper.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
/// An ellipsoid (30, 20, 12) with a ball of radius 4 on it at (0, 15, 8):
/// symmetric about the plane x = 0 and about no other. Then turned 12
/// degrees about z and 6 about y and moved by (5, -3, 100), with point
/// normals and field data SPACE = LPS. With `lesion`, a ball of that radius
/// on one side only, at (22, -6, 6) before the move.
struct TiltedShape
{
  vtkSmartPointer<vtkPolyData> surface;
  vtkNew<vtkTransform> motion;
  explicit TiltedShape(double lesion = 0.0)
  {
    vtkNew<vtkSphereSource> body;
    body->SetThetaResolution(64);
    body->SetPhiResolution(32);
    body->SetRadius(1.0);
    vtkNew<vtkTransform> scale;
    scale->Scale(30, 20, 12);
    vtkNew<vtkTransformPolyDataFilter> ellipsoid;
    ellipsoid->SetInputConnection(body->GetOutputPort());
    ellipsoid->SetTransform(scale);
    vtkNew<vtkSphereSource> ball;
    ball->SetThetaResolution(32);
    ball->SetPhiResolution(16);
    ball->SetRadius(4.0);
    ball->SetCenter(0, 15, 8);
    vtkNew<vtkAppendPolyData> both;
    both->AddInputConnection(ellipsoid->GetOutputPort());
    both->AddInputConnection(ball->GetOutputPort());
    vtkNew<vtkSphereSource> growth;
    growth->SetThetaResolution(32);
    growth->SetPhiResolution(16);
    growth->SetRadius(lesion);
    growth->SetCenter(22, -6, 6);
    if (lesion > 0.0)
      both->AddInputConnection(growth->GetOutputPort());
    motion->PostMultiply();
    motion->RotateZ(12);
    motion->RotateY(6);
    motion->Translate(5, -3, 100);
    vtkNew<vtkTransformPolyDataFilter> place;
    place->SetInputConnection(both->GetOutputPort());
    place->SetTransform(motion);
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputConnection(place->GetOutputPort());
    normals->SplittingOff();
    normals->Update();
    surface = normals->GetOutput();
    vtkNew<vtkStringArray> space;
    space->SetName("SPACE");
    space->InsertNextValue("LPS");
    surface->GetFieldData()->AddArray(space);
  }
};
} // namespace

TEST(SymmetryPlaneFilter, FindsTheOnePlaneOfATiltedShapeAndMirrorsItOutwardFacing)
{
  TiltedShape shape;
  vtkNew<vtkLKSymmetryPlaneFilter> filter;
  filter->SetInputData(shape.surface);
  lktest::ProgressRecorder progress(filter);
  filter->Update();
  EXPECT_DOUBLE_EQ(progress.progress.back(), 1.0);
  double expected[3];
  const double xAxis[3] = { 1.0, 0.0, 0.0 };
  shape.motion->TransformNormal(xAxis, expected);
  double normal[3], origin[3];
  filter->GetPlaneNormal(normal);
  filter->GetPlaneOrigin(origin);
  EXPECT_NEAR(vtkMath::Norm(normal), 1.0, 1e-12);
  // Started 12.4 degrees off (the x axis); ends on the plane.
  EXPECT_LT(vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(normal, expected)), 0.05);
  const double moved[3] = { 5, -3, 100 };
  double apart[3];
  vtkMath::Subtract(origin, moved, apart);
  EXPECT_LT(std::abs(vtkMath::Dot(apart, expected)), 0.01);
  // Symmetric: its mirror image lies on it (the facets' own mismatch).
  EXPECT_LT(filter->GetMeanDistance(), 0.01);
  EXPECT_LT(filter->GetMaximumDistance(), 0.1);

  vtkPolyData* image = filter->GetOutput();
  ASSERT_EQ(image->GetNumberOfPoints(), shape.surface->GetNumberOfPoints());
  ASSERT_EQ(image->GetNumberOfPolys(), shape.surface->GetNumberOfPolys());
  // Faces still point out: the same positive volume.
  const double volume = lktest::signedVolume(shape.surface);
  EXPECT_GT(volume, 0.0);
  EXPECT_NEAR(lktest::signedVolume(image), volume, 1e-9 * volume);
  // Each point is the reflection of its own, and its normal the reflected
  // normal (still outward).
  vtkDataArray* normalsIn = shape.surface->GetPointData()->GetNormals();
  vtkDataArray* normalsOut = image->GetPointData()->GetNormals();
  ASSERT_NE(normalsOut, nullptr);
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); i += 97)
  {
    double x[3], y[3], d[3], m[3], a[3], b[3];
    shape.surface->GetPoint(i, x);
    image->GetPoint(i, y);
    vtkMath::Subtract(y, x, d);
    vtkMath::Cross(d, normal, m); // the point moves along the normal
    EXPECT_LT(vtkMath::Norm(m), 1e-9);
    for (int k = 0; k < 3; ++k)
      m[k] = 0.5 * (x[k] + y[k]) - origin[k];
    EXPECT_NEAR(vtkMath::Dot(m, normal), 0.0, 1e-9);
    normalsIn->GetTuple(i, a);
    normalsOut->GetTuple(i, b);
    const double along = vtkMath::Dot(a, normal);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(b[k], a[k] - 2.0 * along * normal[k], 1e-6);
  }
  // Field data: the input's, and the plane.
  EXPECT_NE(image->GetFieldData()->GetAbstractArray("SPACE"), nullptr);
  vtkDataArray* fitted = image->GetFieldData()->GetArray("SymmetryPlaneNormal");
  ASSERT_NE(fitted, nullptr);
  EXPECT_EQ(fitted->GetNumberOfComponents(), 3);
  EXPECT_DOUBLE_EQ(fitted->GetComponent(0, 1), normal[1]);
  ASSERT_NE(image->GetFieldData()->GetArray("SymmetryMeanDistance"), nullptr);
  EXPECT_DOUBLE_EQ(image->GetFieldData()->GetArray("SymmetryMeanDistance")->GetTuple1(0), filter->GetMeanDistance());
}

TEST(SymmetryPlaneFilter, TheNormalFollowsTheInitialNormalsSide)
{
  TiltedShape shape;
  vtkNew<vtkLKSymmetryPlaneFilter> filter;
  filter->SetInputData(shape.surface);
  filter->SetInitialNormal(-2.0, 0.1, 0.0);
  filter->Update();
  double expected[3], normal[3];
  const double minusX[3] = { -1.0, 0.0, 0.0 };
  shape.motion->TransformNormal(minusX, expected);
  filter->GetPlaneNormal(normal);
  EXPECT_LT(vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(normal, expected)), 0.05);
}

TEST(SymmetryPlaneFilter, StripsAndLinesFindTheSamePlane)
{
  // The same shape as triangle strips, with a line and a vertex beside it:
  // the strips are split, the line and the vertex left out.
  TiltedShape shape;
  vtkNew<vtkStripper> strips;
  strips->SetInputData(shape.surface);
  strips->Update();
  vtkNew<vtkPolyData> mixed;
  mixed->DeepCopy(strips->GetOutput());
  ASSERT_GT(mixed->GetNumberOfStrips(), 0);
  vtkNew<vtkCellArray> lines, verts;
  const vtkIdType line[2] = { 0, 1 }, vert[1] = { 2 };
  lines->InsertNextCell(2, line);
  verts->InsertNextCell(1, vert);
  mixed->SetLines(lines);
  mixed->SetVerts(verts);
  double normals[2][3];
  vtkPolyData* inputs[2] = { shape.surface, mixed };
  for (int k = 0; k < 2; ++k)
  {
    vtkNew<vtkLKSymmetryPlaneFilter> filter;
    filter->SetInputData(inputs[k]);
    lktest::ErrorRecorder rec(filter);
    filter->Update();
    EXPECT_EQ(rec.errors, 0) << rec.messages;
    filter->GetPlaneNormal(normals[k]);
  }
  EXPECT_LT(vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(normals[0], normals[1])), 1e-6);
}

TEST(SymmetryPlaneFilter, AOneSidedLesionDoesNotPullThePlane)
{
  // What mirror-image planning is for: one side is not as the other. Plain
  // ICP lets the lesion pull the plane; the trimmed registrations leave its
  // points out.
  TiltedShape shape(9.0);
  double expected[3];
  const double xAxis[3] = { 1.0, 0.0, 0.0 };
  shape.motion->TransformNormal(xAxis, expected);
  const double moved[3] = { 5, -3, 100 };
  auto fitted = [&](double trim, double& degrees, double& offset) {
    vtkNew<vtkLKSymmetryPlaneFilter> filter;
    filter->SetInputData(shape.surface);
    filter->SetTrimFraction(trim);
    filter->Update();
    double normal[3], origin[3], apart[3];
    filter->GetPlaneNormal(normal);
    filter->GetPlaneOrigin(origin);
    degrees = vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(normal, expected));
    vtkMath::Subtract(origin, moved, apart);
    offset = std::abs(vtkMath::Dot(apart, expected));
  };
  double plainDegrees, plainOffset, trimmedDegrees, trimmedOffset;
  fitted(0.0, plainDegrees, plainOffset);
  fitted(0.2, trimmedDegrees, trimmedOffset);
  std::printf("lesion: plain ICP %.3f degrees, %.3f off; trimmed %.3f degrees, %.3f off\n", plainDegrees, plainOffset,
    trimmedDegrees, trimmedOffset);
  EXPECT_GT(plainDegrees, 1.0); // measured 2.9
  EXPECT_LT(trimmedDegrees, 0.05);
  EXPECT_LT(trimmedOffset, 0.01);
}

TEST(SymmetryPlaneFilter, TheMandiblesMidSagittalPlane)
{
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(lktest::sampleData("mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd").c_str());
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  bone->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkLKSymmetryPlaneFilter> filter;
  filter->SetInputConnection(bone->GetOutputPort());
  filter->Update();
  double normal[3], origin[3], bounds[6];
  filter->GetPlaneNormal(normal);
  filter->GetPlaneOrigin(origin);
  bone->GetOutput()->GetBounds(bounds);
  const double x[3] = { 1, 0, 0 };
  const double tilt = vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(normal, x));
  std::printf("mandible: normal (%.4f, %.4f, %.4f), %.2f degrees from x, through x = %.2f (bounds %.2f to %.2f); "
              "mean %.3f mm, max %.3f mm to its mirror image\n",
    normal[0], normal[1], normal[2], tilt, origin[0], bounds[0], bounds[1], filter->GetMeanDistance(),
    filter->GetMaximumDistance());
  // Left-right, near the middle, and a mirror image close to the bone (a
  // plane off by a few degrees would put the condyles centimetres apart).
  EXPECT_LT(tilt, 10.0);
  EXPECT_NEAR(origin[0], 0.5 * (bounds[0] + bounds[1]), 0.1 * (bounds[1] - bounds[0]));
  EXPECT_LT(filter->GetMeanDistance(), 1.5);
  // Better than the first guess: the plane x = centre, with the same measure.
  vtkNew<vtkLKSymmetryPlaneFilter> once;
  once->SetInputConnection(bone->GetOutputPort());
  once->SetMaximumNumberOfIterations(1);
  once->Update();
  EXPECT_LT(filter->GetMeanDistance(), once->GetMeanDistance());
  EXPECT_NEAR(lktest::signedVolume(filter->GetOutput()), lktest::signedVolume(bone->GetOutput()), 1e-6 * lktest::signedVolume(bone->GetOutput()));
}

TEST(SymmetryPlaneFilter, AMissingRamusDoesNotTiltThePlane)
{
  // The case mirror-image reconstruction is for: one side of the mandible
  // gone (a ball of radius 22 mm taken out of the label map at the middle
  // of its right quarter: the largest piece left lacks the ramus, a quarter
  // of the bone). The mirror of the healthy ramus then lands over the gap;
  // plain ICP turns the plane about 29 degrees toward the rest, trimmed ICP
  // keeps it about 1 degree from the intact bone's.
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(lktest::sampleData("mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd").c_str());
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  bone->SetInputConnection(reader->GetOutputPort());
  bone->Update();
  vtkNew<vtkPolyData> intact;
  intact->DeepCopy(bone->GetOutput());
  auto plane = [](vtkPolyData* surface, double trim, double normal[3], double origin[3], int iterations = 200) {
    vtkNew<vtkLKSymmetryPlaneFilter> filter;
    filter->SetInputData(surface);
    filter->SetTrimFraction(trim);
    filter->SetMaximumNumberOfIterations(iterations);
    filter->Update();
    filter->GetPlaneNormal(normal);
    filter->GetPlaneOrigin(origin);
    return filter->GetKeptFraction();
  };
  double n0[3], o0[3];
  EXPECT_GT(plane(intact, 0.5, n0, o0), 0.9); // a symmetric bone keeps nearly all

  // The middle of the points in the quarter of lowest x, in voxels.
  double bounds[6], centre[3] = { 0, 0, 0 };
  intact->GetBounds(bounds);
  vtkIdType inQuarter = 0;
  for (vtkIdType i = 0; i < intact->GetNumberOfPoints(); ++i)
  {
    double x[3];
    intact->GetPoint(i, x);
    if (x[0] < bounds[0] + 0.25 * (bounds[1] - bounds[0]))
    {
      vtkMath::Add(centre, x, centre);
      ++inQuarter;
    }
  }
  vtkMath::MultiplyScalar(centre, 1.0 / static_cast<double>(inQuarter));
  vtkNew<vtkMatrix4x4> toData;
  vtkMatrix4x4::Invert(reader->GetPatientMatrix(), toData);
  const double p[4] = { centre[0], centre[1], centre[2], 1.0 };
  double d[4];
  toData->MultiplyPoint(p, d);
  vtkImageData* volume = reader->GetOutput();
  double spacing[3], start[3];
  int dims[3];
  volume->GetSpacing(spacing);
  volume->GetOrigin(start);
  volume->GetDimensions(dims);
  vtkDataArray* labels = volume->GetPointData()->GetScalars();
  const double radius = 22.0;
  int lo[3], hi[3]; // the ball's box of voxels
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = std::max(0, static_cast<int>(std::floor((d[a] - radius - start[a]) / spacing[a])));
    hi[a] = std::min(dims[a] - 1, static_cast<int>(std::ceil((d[a] + radius - start[a]) / spacing[a])));
  }
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i)
      {
        const double dx = start[0] + i * spacing[0] - d[0], dy = start[1] + j * spacing[1] - d[1],
                     dz = start[2] + k * spacing[2] - d[2];
        if (dx * dx + dy * dy + dz * dz <= radius * radius)
          labels->SetTuple1(i + static_cast<vtkIdType>(dims[0]) * (j + static_cast<vtkIdType>(dims[1]) * k), 0);
      }
  labels->Modified();
  volume->Modified();
  bone->Modified();
  bone->Update();
  vtkPolyData* lacking = bone->GetOutput();
  ASSERT_LT(lacking->GetNumberOfPoints(), 0.8 * intact->GetNumberOfPoints());

  auto apart = [&](const double n[3]) { return vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(n, n0)); };
  double n[3], o[3];
  const double kept = plane(lacking, 0.5, n, o);
  std::printf("without the ramus: trimmed %.2f degrees from the intact plane (%.2f of the points kept)", apart(n),
    kept);
  EXPECT_LT(apart(n), 2.0);
  EXPECT_LT(kept, 0.8);
  double shift[3];
  vtkMath::Subtract(o, o0, shift);
  EXPECT_LT(std::abs(vtkMath::Dot(shift, n0)), 1.0); // mm
  plane(lacking, 0.0, n, o, 40); // far off already
  std::printf(", plain ICP %.2f degrees\n", apart(n));
  EXPECT_GT(apart(n), 10.0);
}

TEST(SymmetryPlaneFilter, AGivenPlaneIsUsedAsItIs)
{
  // A plane set by hand: the true one gives a mirror on the bone; one turned
  // 5 degrees gives it farther off; the plane is reported as given.
  TiltedShape shape;
  double truth[3], turned[3];
  const double xAxis[3] = { 1.0, 0.0, 0.0 }, tilted[3] = { std::cos(vtkMath::RadiansFromDegrees(5.0)),
                                                 std::sin(vtkMath::RadiansFromDegrees(5.0)), 0.0 };
  shape.motion->TransformNormal(xAxis, truth);
  shape.motion->TransformNormal(tilted, turned);
  const double through[3] = { 5, -3, 100 };
  double means[2];
  const double* normals[2] = { truth, turned };
  for (int k = 0; k < 2; ++k)
  {
    vtkNew<vtkLKSymmetryPlaneFilter> filter;
    filter->SetInputData(shape.surface);
    filter->FitPlaneOff();
    filter->SetGivenPlaneOrigin(through[0], through[1], through[2]);
    filter->SetGivenPlaneNormal(2.0 * normals[k][0], 2.0 * normals[k][1], 2.0 * normals[k][2]);
    lktest::ErrorRecorder rec(filter);
    filter->Update();
    EXPECT_EQ(rec.errors, 0) << rec.messages;
    double normal[3], origin[3];
    filter->GetPlaneNormal(normal);
    filter->GetPlaneOrigin(origin);
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_NEAR(normal[i], normals[k][i], 1e-12);
      EXPECT_DOUBLE_EQ(origin[i], through[i]);
    }
    EXPECT_EQ(filter->GetKeptFraction(), 0.0);
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), shape.surface->GetNumberOfPoints());
    means[k] = filter->GetMeanDistance();
  }
  EXPECT_LT(means[0], 0.01);
  EXPECT_GT(means[1], 0.5);

  vtkNew<vtkLKSymmetryPlaneFilter> filter;
  filter->SetInputData(shape.surface);
  filter->FitPlaneOff();
  filter->SetGivenPlaneNormal(0, 0, 0);
  lktest::ErrorRecorder rec(filter);
  filter->Update();
  EXPECT_EQ(rec.errors, 1);
  EXPECT_NE(rec.messages.find("Cannot mirror across the given plane"), std::string::npos) << rec.messages;
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(SymmetryPlaneFilter, StopsWhenAsked)
{
  TiltedShape shape;
  // In the registration's first iteration, and once the mirror is made.
  for (const double at : { 0.1, 0.85 })
  {
    vtkNew<vtkLKSymmetryPlaneFilter> filter;
    filter->SetInputData(shape.surface);
    lktest::ProgressRecorder progress(filter);
    progress.stopAt = at;
    lktest::ErrorRecorder rec(filter);
    filter->Update();
    EXPECT_EQ(rec.errors, 0) << at;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << at;
    EXPECT_LT(progress.progress.back(), 1.0) << at;
  }
}

TEST(SymmetryPlaneFilter, BadInputAndParametersAreRefused)
{
  TiltedShape shape;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto refused = [](vtkLKSymmetryPlaneFilter* filter, const std::string& text) {
    lktest::ErrorRecorder rec(filter);
    filter->Update();
    EXPECT_EQ(rec.errors, 1) << text;
    EXPECT_NE(rec.messages.find(text), std::string::npos) << rec.messages;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << text;
    double n[3];
    filter->GetPlaneNormal(n);
    EXPECT_EQ(vtkMath::Norm(n), 0.0) << text;
  };
  {
    vtkNew<vtkLKSymmetryPlaneFilter> filter;
    vtkNew<vtkPolyData> empty;
    filter->SetInputData(empty);
    refused(filter, "no surface");
  }
  {
    vtkNew<vtkLKSymmetryPlaneFilter> filter;
    filter->SetInputData(shape.surface);
    filter->SetInitialNormal(0, 0, 0);
    refused(filter, "InitialNormal");
    filter->SetInitialNormal(nan, 0, 1);
    refused(filter, "InitialNormal");
    filter->SetInitialNormal(1, 0, 0);
    filter->SetMaximumNumberOfIterations(0);
    refused(filter, "MaximumNumberOfIterations");
    filter->SetMaximumNumberOfIterations(100);
    filter->SetMaximumNumberOfPoints(2);
    refused(filter, "MaximumNumberOfPoints");
    filter->SetMaximumNumberOfPoints(2000);
    filter->SetTrimFraction(nan);
    refused(filter, "TrimFraction");
    filter->SetTrimFraction(0.95);
    refused(filter, "TrimFraction");
  }
  {
    vtkNew<vtkPolyData> broken;
    broken->DeepCopy(shape.surface);
    broken->GetPoints()->SetPoint(5, nan, 0, 0);
    vtkNew<vtkLKSymmetryPlaneFilter> filter;
    filter->SetInputData(broken);
    refused(filter, "point 5 is not finite");
  }
  {
    // Points far beyond any body: their squared distances overflow.
    vtkNew<vtkPolyData> huge;
    huge->DeepCopy(shape.surface);
    vtkNew<vtkPoints> far;
    far->SetDataTypeToDouble();
    for (vtkIdType i = 0; i < huge->GetNumberOfPoints(); ++i)
    {
      double x[3];
      huge->GetPoint(i, x);
      far->InsertNextPoint(1e300 * x[0], 1e300 * x[1], 1e300 * x[2]);
    }
    huge->SetPoints(far);
    vtkNew<vtkLKSymmetryPlaneFilter> filter;
    filter->SetInputData(huge);
    refused(filter, "too large");
  }
  {
    vtkNew<vtkPolyData> flat;
    flat->DeepCopy(shape.surface);
    for (vtkIdType i = 0; i < flat->GetNumberOfPoints(); ++i)
      flat->GetPoints()->SetPoint(i, 1, 2, 3);
    vtkNew<vtkLKSymmetryPlaneFilter> filter;
    filter->SetInputData(flat);
    refused(filter, "every point is in one place");
  }
}
