// lkapp::PickLocators: the planner's picks on a large surface go through a
// cell locator, and land where vtkCellPicker's exhaustive test puts them.
// Renders: run under xvfb-run.
#include "common/AppSupport.h"
#include "common/PickLocators.h"

#include <vtkActor.h>
#include <vtkCellPicker.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
struct Scene
{
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  vtkNew<vtkActor> actor;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  explicit Scene(int resolution)
  {
    sphere->SetThetaResolution(resolution);
    sphere->SetPhiResolution(resolution);
    sphere->SetRadius(10.0);
    mapper->SetInputConnection(sphere->GetOutputPort());
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
    window->SetDisplayId(lkapp::openDisplay());
    window->SetOffScreenRendering(1);
    window->SetSize(400, 400);
    window->AddRenderer(renderer);
    renderer->ResetCamera();
    window->Render();
  }
};
} // namespace

TEST(PickLocators, PicksOnALargeSurfaceGoThroughALocatorAndLandWhereTheExhaustiveTestPutsThem)
{
  ASSERT_NE(lkapp::openDisplay(), nullptr) << "run under xvfb-run";
  // A sphere of 19,602 triangles, given a locator from 10,000 cells on (the
  // planner's threshold is 50,000): the exhaustive picks stay quick.
  Scene scene(100);
  vtkNew<vtkCellPicker> exhaustive, located;
  exhaustive->SetTolerance(0.0005);
  located->SetTolerance(0.0005);
  lkapp::PickLocators locators(10000);
  locators.update(scene.renderer, located);
  ASSERT_EQ(locators.size(), 1u);
  // Every fifth pixel of the sphere's disc (radius about 115 pixels) and
  // around it: the same hits and misses, the same points up to the picker's
  // tolerance (a ray near an edge may hit either triangle; at the rim the
  // ray grazes the surface), and always the near side: the camera looks
  // down -z at the +z cap. (VTK 9.1's vtkCellLocator gave one pixel of
  // these the far side, 15 away.)
  int picks = 0;
  for (int x = 70; x <= 330; x += 5)
    for (int y = 70; y <= 330; y += 5)
    {
      const bool hit = exhaustive->Pick(x, y, 0, scene.renderer) && exhaustive->GetCellId() >= 0;
      ASSERT_EQ(located->Pick(x, y, 0, scene.renderer) && located->GetCellId() >= 0, hit) << x << ", " << y;
      if (!hit)
        continue;
      const double* a = exhaustive->GetPickPosition();
      const double* b = located->GetPickPosition();
      // The tolerance, 0.0005 of the window's 566-pixel diagonal, is a
      // quarter of a pixel: 0.025 on this sphere (0.087 a pixel).
      EXPECT_LT(std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]), 0.025) << x << ", " << y;
      EXPECT_GT(b[2], 0.0) << x << ", " << y;
      ++picks;
    }
  EXPECT_GT(picks, 1400);
  // A changed surface gets a new locator: the picks follow the new radius.
  scene.sphere->SetRadius(8.0);
  locators.update(scene.renderer, located);
  ASSERT_TRUE(located->Pick(200, 200, 0, scene.renderer));
  const double* p = located->GetPickPosition();
  EXPECT_NEAR(std::hypot(p[0], p[1], p[2]), 8.0, 1e-3);
  // Hidden, or no longer large: no locator. The planner's threshold.
  scene.actor->VisibilityOff();
  locators.update(scene.renderer, located);
  EXPECT_EQ(locators.size(), 0u);
  scene.actor->VisibilityOn();
  scene.sphere->SetThetaResolution(40);
  scene.sphere->SetPhiResolution(40);
  locators.update(scene.renderer, located);
  EXPECT_EQ(locators.size(), 0u);
  lkapp::PickLocators planners;
  planners.update(scene.renderer, located);
  EXPECT_EQ(planners.size(), 0u);
  scene.sphere->SetThetaResolution(200); // 79,202 triangles
  scene.sphere->SetPhiResolution(200);
  planners.update(scene.renderer, located);
  EXPECT_EQ(planners.size(), 1u);
}
