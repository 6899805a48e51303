#include "TestMeshes.h"
#include "latticekit/QuadPairing.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
/// Two triangles (0, 1, 2) and (1, 0, 3) across the diagonal 0-1.
lk::TriangleMesh pair(const lk::Vec3& x, const lk::Vec3& y)
{
  lk::TriangleMesh m;
  m.points = { { 0, 0, 0 }, { 1, 0, 0 }, x, y };
  m.triangles = { { 0, 1, 2 }, { 1, 0, 3 } };
  return m;
}
} // namespace

TEST(QuadPairing, GridCellsBecomeSquares)
{
  const lk::TriangleMesh g = lktest::grid(6, 6.0, 0.0);
  const auto r = lk::pairTrianglesIntoQuads(g, {}, lk::QuadPairingOptions{});
  EXPECT_EQ(r.quads, 36u);
  EXPECT_EQ(r.lattice.faces.size(), 36u);
  EXPECT_EQ(lk::latticeProblem(r.lattice), "");
  for (const auto& f : r.lattice.faces)
  {
    ASSERT_EQ(f.size(), 4u);
    for (int i = 0; i < 4; ++i) // unit squares: every side has length 1
      EXPECT_NEAR((r.lattice.points[static_cast<std::size_t>(f[static_cast<std::size_t>(i)])] -
                    r.lattice.points[static_cast<std::size_t>(f[static_cast<std::size_t>((i + 1) % 4)])])
                    .norm(),
        1.0, 1e-12);
  }
  // Every triangle is used exactly once.
  std::vector<int> used(g.triangles.size(), 0);
  for (const auto& t : r.faceTriangles)
    for (auto i : t)
      ++used[static_cast<std::size_t>(i)];
  for (int u : used)
    EXPECT_EQ(u, 1);
}

TEST(QuadPairing, FeatureEdgesAreNeverDiagonals)
{
  const lk::TriangleMesh g = lktest::grid(2, 2.0, 0.0);
  // The diagonals of the grid's cells: (i,j)-(i+1,j+1). Mark cell (0,0)'s.
  std::set<lk::EdgeKey> features{ lk::edgeKey(0, 4) };
  const auto r = lk::pairTrianglesIntoQuads(g, features, lk::QuadPairingOptions{});
  EXPECT_EQ(r.quads, 3u);
  bool found = false;
  for (const auto& f : r.lattice.faces)
    if (f.size() == 3 && std::count(f.begin(), f.end(), 0) && std::count(f.begin(), f.end(), 4))
      found = true;
  EXPECT_TRUE(found);
}

TEST(QuadPairing, RightAnglesBalancedEndsAndSmallDihedral)
{
  lk::QuadPairingOptions o;
  // A unit square: paired.
  EXPECT_EQ(lk::pairTrianglesIntoQuads(pair({ 1, 1, 0 }, { 0, -1, 0 }), {}, o).quads, 0u); // wrong diagonal side
  EXPECT_EQ(lk::pairTrianglesIntoQuads(pair({ 1, 1, 0 }, { 0, -1, 0 }), {}, o).lattice.faces.size(), 2u);
  // Square with diagonal 0-1: x and y opposite corners of a square on that diagonal.
  EXPECT_EQ(lk::pairTrianglesIntoQuads(pair({ 0.5, 0.5, 0 }, { 0.5, -0.5, 0 }), {}, o).quads, 1u);
  // Fig. 3.10's kite: right angles facing the diagonal, but sharp at one end
  // (x and y near the end 1 of the diagonal, on the circle of diameter 0-1).
  const double a = 0.25; // angle of x seen from the diagonal's centre, from end 1
  const lk::Vec3 x(0.5 + 0.5 * std::cos(a), 0.5 * std::sin(a), 0), y(0.5 + 0.5 * std::cos(a), -0.5 * std::sin(a), 0);
  EXPECT_EQ(lk::pairTrianglesIntoQuads(pair(x, y), {}, o).quads, 0u);
  o.angleSumTolerance = 10.0; // without eq. 3.16 the kite would pair
  EXPECT_EQ(lk::pairTrianglesIntoQuads(pair(x, y), {}, o).quads, 1u);
  o = {};
  // A rhombus with 60 and 120 degree corners, split along its long diagonal:
  // the facing angles are 60 degrees: |cos| sums to 1 > S1.
  EXPECT_EQ(lk::pairTrianglesIntoQuads(pair({ 0.5, std::sqrt(3.0) / 6, 0 }, { 0.5, -std::sqrt(3.0) / 6, 0 }), {}, o)
              .quads,
    0u);
  // A square folded by 40 degrees along the diagonal: refused at 30, paired at 45.
  const double f = 40.0 * 3.14159265358979323846 / 180.0;
  const lk::Vec3 folded(0.5, -0.5 * std::cos(f), 0.5 * std::sin(f));
  EXPECT_EQ(lk::pairTrianglesIntoQuads(pair({ 0.5, 0.5, 0 }, folded), {}, o).quads, 0u);
  o.maxDihedralDegrees = 45.0;
  EXPECT_EQ(lk::pairTrianglesIntoQuads(pair({ 0.5, 0.5, 0 }, folded), {}, o).quads, 1u);
}

TEST(QuadPairing, BadOptionsAreRefused)
{
  const lk::TriangleMesh g = lktest::grid(2, 2.0, 0.0);
  lk::QuadPairingOptions o;
  o.rightAngleTolerance = 0.0;
  EXPECT_THROW(lk::pairTrianglesIntoQuads(g, {}, o), std::invalid_argument);
  o = {};
  o.angleSumTolerance = std::nan("");
  EXPECT_THROW(lk::pairTrianglesIntoQuads(g, {}, o), std::invalid_argument);
  o = {};
  o.maxDihedralDegrees = 200.0;
  EXPECT_THROW(lk::pairTrianglesIntoQuads(g, {}, o), std::invalid_argument);
}
