// Screen strokes: display points plus a camera, picked onto the nearest
// visible surface along the eye rays (vtkLKStrokeFeatureLineFilter).
#include "TestSupport.h"
#include "vtkLKStrokeFeatureLineFilter.h"

#include <vtkCamera.h>
#include <vtkFieldData.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSphereSource.h>

#include <cmath>

namespace
{
const int kSize[2] = { 400, 300 };

vtkSmartPointer<vtkPolyData> sphere()
{
  vtkNew<vtkSphereSource> s;
  s->SetRadius(1.0);
  s->SetThetaResolution(96);
  s->SetPhiResolution(64);
  s->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(s->GetOutput());
  return out;
}

/// World to display pixels, as VTK's renderer maps them.
lk::Vec3 toDisplay(vtkCamera* camera, const lk::Vec3& p)
{
  vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(double(kSize[0]) / kSize[1], -1, 1);
  const double in[4] = { p.x(), p.y(), p.z(), 1.0 };
  double v[4];
  m->MultiplyPoint(in, v);
  return { (v[0] / v[3] + 1.0) * 0.5 * kSize[0], (v[1] / v[3] + 1.0) * 0.5 * kSize[1], 0.0 };
}

vtkSmartPointer<vtkPolyData> pointsPd(const std::vector<lk::Vec3>& pts)
{
  vtkNew<vtkPoints> p;
  for (const auto& q : pts)
    p->InsertNextPoint(q.data());
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(p);
  return pd;
}
} // namespace

TEST(ScreenStroke, PixelsArePickedOntoTheNearestVisibleSurface)
{
  auto ball = sphere();
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.3, -0.2, 6.0);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(0.1, 4.0); // the far plane cuts the sphere: picking must not depend on it
  // A closed circle on the visible cap (z > 0), drawn as the pixels it shows at.
  std::vector<lk::Vec3> world, screen;
  for (int k = 0; k <= 48; ++k)
  {
    const double a = 2.0 * 3.14159265358979 * k / 48.0;
    const lk::Vec3 p(0.5 * std::cos(a), 0.5 * std::sin(a), std::sqrt(1.0 - 0.25));
    world.push_back(p);
    screen.push_back(toDisplay(camera, p));
  }
  vtkNew<vtkLKStrokeFeatureLineFilter> f;
  f->SetInputData(ball);
  f->SetStrokeData(pointsPd(screen));
  f->SetCamera(camera);
  f->SetViewportSize(kSize[0], kSize[1]);
  lktest::ErrorRecorder errors(f);
  f->Update();
  ASSERT_EQ(errors.errors, 0) << errors.messages;
  EXPECT_EQ(errors.warnings, 0) << errors.warningMessages;
  vtkPolyData* picked = f->GetPickedStroke();
  ASSERT_EQ(picked->GetNumberOfPoints(), static_cast<vtkIdType>(world.size()));
  for (vtkIdType i = 0; i < picked->GetNumberOfPoints(); ++i)
  {
    double p[3];
    picked->GetPoint(i, p);
    // On the near side (the far side lies behind it on the same ray), on the
    // tessellated sphere within its chord error.
    EXPECT_LT((lk::Vec3(p[0], p[1], p[2]) - world[static_cast<std::size_t>(i)]).norm(), 5e-3) << i;
  }
  vtkPolyData* line = f->GetFeatureLineOutput();
  EXPECT_EQ(line->GetFieldData()->GetArray("Closed")->GetComponent(0, 0), 1.0);
  ASSERT_GT(line->GetNumberOfPoints(), 20);
  for (vtkIdType i = 0; i < line->GetNumberOfPoints(); ++i)
  {
    double p[3];
    line->GetPoint(i, p);
    EXPECT_GT(p[2], 0.7);
  }
  // Moving the camera re-executes the filter (its MTime counts).
  camera->SetPosition(0.3, -0.2, -6.0);
  f->Update();
  double p[3];
  f->GetPickedStroke()->GetPoint(0, p);
  EXPECT_LT(p[2], 0.0) << "the camera behind the sphere sees its back";
}

TEST(ScreenStroke, MissesAndMissingViewportAreReported)
{
  auto ball = sphere();
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0, 0, 6);
  camera->SetFocalPoint(0, 0, 0);
  // Two pixels in a corner: both rays miss.
  vtkNew<vtkLKStrokeFeatureLineFilter> f;
  f->SetInputData(ball);
  f->SetStrokeData(pointsPd({ { 2, 2, 0 }, { 10, 3, 0 } }));
  f->SetCamera(camera);
  f->SetViewportSize(kSize[0], kSize[1]);
  {
    lktest::ErrorRecorder errors(f);
    f->Update();
    EXPECT_NE(errors.messages.find("misses the surface"), std::string::npos) << errors.messages;
    EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
  }
  // Some pixels miss: skipped with a warning.
  f->SetStrokeData(pointsPd({ { 2, 2, 0 }, { 190, 140, 0 }, { 210, 150, 0 }, { 220, 160, 0 } }));
  {
    lktest::ErrorRecorder errors(f);
    f->Update();
    EXPECT_EQ(errors.errors, 0) << errors.messages;
    EXPECT_NE(errors.warningMessages.find("1 of 4 screen points missed"), std::string::npos) << errors.warningMessages;
    EXPECT_EQ(f->GetPickedStroke()->GetNumberOfPoints(), 3);
  }
  f->SetViewportSize(0, 0);
  {
    lktest::ErrorRecorder errors(f);
    f->Update();
    EXPECT_NE(errors.messages.find("viewport size"), std::string::npos) << errors.messages;
  }
}

// The default close tolerance the filter reports is the one it closes with:
// an equator stroke whose ends are 0.9 of it apart is closed, 1.1 is open.
// The planner continues a stroke drawn in parts within the same distance.
TEST(ScreenStroke, DefaultCloseToleranceIsWhereAStrokeCloses)
{
  auto ball = sphere();
  const double tolerance = vtkLKStrokeFeatureLineFilter::DefaultCloseTolerance(ball);
  ASSERT_GT(tolerance, 0.0);
  EXPECT_LT(tolerance, 0.2); // twice the mean edge of a 96 x 64 unit sphere
  for (const double fraction : { 0.9, 1.1 })
  {
    // The gap is a chord of the unit equator: 2 sin(gap angle / 2).
    const double gapAngle = 2.0 * std::asin(0.5 * fraction * tolerance);
    std::vector<lk::Vec3> stroke;
    const int n = 200;
    for (int k = 0; k <= n; ++k)
    {
      const double a = (2.0 * M_PI - gapAngle) * k / n;
      stroke.emplace_back(std::cos(a), std::sin(a), 0.0);
    }
    vtkNew<vtkLKStrokeFeatureLineFilter> f;
    f->SetInputData(ball);
    f->SetStrokeData(pointsPd(stroke));
    f->SetModeToNearestEdges();
    lktest::ErrorRecorder errors(f);
    f->Update();
    ASSERT_EQ(errors.errors, 0) << errors.messages;
    const double closed = f->GetFeatureLineOutput()->GetFieldData()->GetArray("Closed")->GetComponent(0, 0);
    EXPECT_EQ(closed > 0.5, fraction < 1.0) << "ends " << fraction << " of the tolerance apart";
  }
  // Surfaces the filter refuses have none.
  vtkNew<vtkPolyData> empty;
  EXPECT_EQ(vtkLKStrokeFeatureLineFilter::DefaultCloseTolerance(empty), 0.0);
  EXPECT_EQ(vtkLKStrokeFeatureLineFilter::DefaultCloseTolerance(nullptr), 0.0);
}
