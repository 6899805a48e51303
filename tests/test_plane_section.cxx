// A plane's section of a surface (apps/common/PlaneSection): the loops of a
// hollow cylinder's wall, and which points of the plane they enclose.
#include "common/PlaneSection.h"

#include <gtest/gtest.h>

#include <vtkAppendPolyData.h>
#include <vtkCylinderSource.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cmath>

namespace
{
/// A tube along y: an outer cylinder of radius 10 and an inner wall of
/// radius 4, each closed at its ends (two shells, as a bone's cortex and
/// its marrow's wall), 20 long.
vtkSmartPointer<vtkPolyData> tube()
{
  vtkNew<vtkAppendPolyData> both;
  for (double r : { 10.0, 4.0 })
  {
    vtkNew<vtkCylinderSource> c;
    c->SetRadius(r);
    c->SetHeight(20.0);
    c->SetResolution(64);
    c->Update();
    both->AddInputData(c->GetOutput());
  }
  both->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(both->GetOutput());
  return out;
}
} // namespace

TEST(PlaneSection, AHollowTubeCutAcrossGivesTwoLoops)
{
  const auto loops = lkapp::planeSectionLoops(tube(), { 0, 1.5, 0 }, { 0, 1, 0 });
  ASSERT_EQ(loops.size(), 2u);
  for (const auto& loop : loops)
  {
    EXPECT_EQ(loop.front(), loop.back());
    for (const auto& p : loop)
      EXPECT_NEAR(p[1], 1.5, 1e-6); // (float points)
  }
}

// A plane through the tube's end caps (a piece's cap in its cut's plane)
// has no defined section there (vtkCutter gives none here); taken 0.05
// beside, inside along the normal, it gives two clean circles.
TEST(PlaneSection, APlaneThroughACapGivesTheOutlineBesideIt)
{
  const auto loops = lkapp::planeSectionLoops(tube(), { 0, 10, 0 }, { 0, -1, 0 }, 0.05);
  ASSERT_EQ(loops.size(), 2u);
  for (const auto& loop : loops)
  {
    const double r = std::hypot(loop.front()[0], loop.front()[2]);
    EXPECT_TRUE(std::abs(r - 10.0) < 0.1 || std::abs(r - 4.0) < 0.1) << r;
    for (const auto& p : loop)
    {
      EXPECT_NEAR(std::hypot(p[0], p[2]), r, 0.1);
      EXPECT_NEAR(p[1], 9.95, 1e-5);
    }
  }
}

TEST(PlaneSection, LoopsEncloseTheWallAndTheMarrow)
{
  const lkapp::Point3 normal{ 0, 1, 0 };
  const auto loops = lkapp::planeSectionLoops(tube(), { 0, 1.5, 0 }, normal);
  ASSERT_EQ(loops.size(), 2u);
  auto enclosedBy = [&](const lkapp::Point3& p) {
    int n = 0;
    for (const auto& loop : loops)
      n += lkapp::loopEncloses(loop, p, normal) ? 1 : 0;
    return n;
  };
  EXPECT_EQ(enclosedBy({ 7, 1.5, 0 }), 1);     // in the wall: the outer loop only
  EXPECT_EQ(enclosedBy({ 0, 1.5, -6.5 }), 1);  // the wall, another side
  EXPECT_EQ(enclosedBy({ 0, 1.5, 0 }), 2);     // the marrow: both
  EXPECT_EQ(enclosedBy({ 2, 1.5, 2 }), 2);
  EXPECT_EQ(enclosedBy({ 12, 1.5, 0 }), 0);    // outside
  EXPECT_EQ(enclosedBy({ -7.2, 1.5, 7.2 }), 0); // outside, beyond a diagonal
  // The normal's sign and length do not matter.
  EXPECT_TRUE(lkapp::loopEncloses(loops[0], { 0, 1.5, 0 }, { 0, -3, 0 }));
}

TEST(PlaneSection, NoLoopEnclosesWithoutANormalOrPoints)
{
  const auto loops = lkapp::planeSectionLoops(tube(), { 0, 1.5, 0 }, { 0, 1, 0 });
  ASSERT_FALSE(loops.empty());
  EXPECT_FALSE(lkapp::loopEncloses(loops[0], { 0, 1.5, 0 }, { 0, 0, 0 }));
  EXPECT_FALSE(lkapp::loopEncloses({}, { 0, 1.5, 0 }, { 0, 1, 0 }));
  EXPECT_FALSE(lkapp::loopEncloses(loops[0], { NAN, 1.5, 0 }, { 0, 1, 0 }));
}
