// How a moved segment meets the bone beside it (apps/common/PieceContact):
// spheres apart, overlapping and touching, a turned one, and an open one.
#include "common/PieceContact.h"

#include <gtest/gtest.h>

#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkSmartPointer.h>

#include <array>
#include <cmath>

namespace
{
vtkSmartPointer<vtkPolyData> sphere(double radius, double x = 0.0)
{
  vtkNew<vtkSphereSource> s;
  s->SetRadius(radius);
  s->SetCenter(x, 0, 0);
  s->SetThetaResolution(48);
  s->SetPhiResolution(48);
  s->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(s->GetOutput());
  return out;
}

std::array<double, 16> shift(double x, double y = 0.0, double z = 0.0)
{
  return { 1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z, 0, 0, 0, 1 };
}
} // namespace

TEST(PieceContact, SpheresApartGiveTheirGap)
{
  auto a = sphere(1.0), b = sphere(1.0);
  lkapp::ContactSurface moved(a), fixed(b);
  ASSERT_TRUE(moved.closed());
  const lkapp::Contact c = lkapp::contactOf(moved, shift(3.0), fixed, 1e-6);
  EXPECT_FALSE(c.overlap);
  EXPECT_TRUE(c.known);
  EXPECT_NEAR(c.gap, 1.0, 0.01); // centres 3 apart, radii 1
  EXPECT_EQ(lkapp::contactText(c), "1.00 mm apart");
}

TEST(PieceContact, OverlappingSpheresGiveTheirDepth)
{
  auto a = sphere(1.0), b = sphere(1.0);
  lkapp::ContactSurface moved(a), fixed(b);
  // Centres 1.5 apart: each reaches 0.5 into the other. The vertices
  // inside are given where they are shown: the moved sphere's moved.
  vtkNew<vtkPoints> inside;
  const lkapp::Contact c = lkapp::contactOf(moved, shift(0.0, 1.5), fixed, 1e-6, inside);
  EXPECT_TRUE(c.overlap);
  ASSERT_EQ(inside->GetNumberOfPoints(), c.inside);
  for (vtkIdType i = 0; i < inside->GetNumberOfPoints(); ++i)
  {
    double x[3];
    inside->GetPoint(i, x);
    EXPECT_LT(std::hypot(x[0], x[1], x[2]), 1.0 + 1e-6); // in the fixed sphere (float points)
    EXPECT_LT(std::hypot(x[0], x[1] - 1.5, x[2]), 1.0 + 1e-6); // and the moved one
  }
  EXPECT_NEAR(c.depth, 0.5, 0.02);
  EXPECT_GT(c.inside, 20);
  EXPECT_EQ(c.gap, 0.0);
  EXPECT_NE(lkapp::contactText(c).find("overlapping 0.5"), std::string::npos) << lkapp::contactText(c);
  // A small sphere wholly inside a large one: every vertex is inside, each
  // 4 - 0.5 from the large one's surface.
  auto big = sphere(4.0), small = sphere(0.5);
  lkapp::ContactSurface inner(small), outer(big);
  const lkapp::Contact d = lkapp::contactOf(inner, shift(0.0), outer, 1e-6);
  EXPECT_TRUE(d.overlap);
  EXPECT_EQ(d.inside, small->GetNumberOfPoints());
  EXPECT_NEAR(d.depth, 3.5, 0.02);
}

TEST(PieceContact, TouchingPiecesAreNoOverlap)
{
  // Two pieces of a cut before a move: the same surface, every vertex on
  // the other. Within `touch` no vertex counts as inside.
  auto a = sphere(1.0), b = sphere(1.0);
  lkapp::ContactSurface moved(a), fixed(b);
  const lkapp::Contact c = lkapp::contactOf(moved, shift(0.0), fixed, 1e-6);
  EXPECT_FALSE(c.overlap);
  EXPECT_NEAR(c.gap, 0.0, 1e-9);
}

TEST(PieceContact, ATurnedSegmentIsPlacedByItsMatrix)
{
  // A sphere at x = 3 turned 180 degrees about z (through the origin) lands
  // at x = -3, its centre 3 from the fixed sphere's at x = -6: 1 apart.
  auto a = sphere(1.0, 3.0), b = sphere(1.0, -6.0);
  lkapp::ContactSurface moved(a), fixed(b);
  const std::array<double, 16> turn{ -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  const lkapp::Contact c = lkapp::contactOf(moved, turn, fixed, 1e-6);
  EXPECT_FALSE(c.overlap);
  EXPECT_NEAR(c.gap, 1.0, 0.01);
  // Unturned it is 7 away.
  EXPECT_NEAR(lkapp::contactOf(moved, shift(0.0), fixed, 1e-6).gap, 7.0, 0.01);
}

TEST(PieceContact, AnOpenPieceGivesOnlyTheGap)
{
  auto a = sphere(1.0), b = sphere(1.0);
  a->BuildCells();
  a->DeleteCell(0);
  a->RemoveDeletedCells();
  lkapp::ContactSurface moved(a), fixed(b);
  EXPECT_FALSE(moved.closed());
  const lkapp::Contact c = lkapp::contactOf(moved, shift(0.5), fixed, 1e-6);
  EXPECT_FALSE(c.known);
  EXPECT_FALSE(c.overlap); // it would overlap, but an open surface has no inside
  EXPECT_NE(lkapp::contactText(c).find("an overlap cannot be told"), std::string::npos);
}

TEST(PieceContact, AnEmptyPieceHasNothingToMeasure)
{
  auto a = sphere(1.0);
  vtkNew<vtkPolyData> empty;
  lkapp::ContactSurface moved(a), fixed(empty);
  const lkapp::Contact c = lkapp::contactOf(moved, shift(1.0), fixed, 1e-6);
  EXPECT_FALSE(c.overlap);
  EXPECT_EQ(lkapp::contactText(c), "nothing to measure (an empty piece)");
}
