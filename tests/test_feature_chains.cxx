// Feature edges as chains, and the vertices that hold a chain within a
// tolerance (what a locked line keeps with a feature tolerance).
#include "TestMeshes.h"
#include "latticekit/FeatureChains.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

namespace
{
using Edges = std::vector<std::pair<std::int64_t, std::int64_t>>;

double distanceToSegment(const lk::Vec3& p, const lk::Vec3& a, const lk::Vec3& b)
{
  const lk::Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

/// A wavy closed line of n points: a circle of radius 10 with a ripple.
std::vector<lk::Vec3> wavyLoop(int n)
{
  std::vector<lk::Vec3> p;
  for (int k = 0; k < n; ++k)
  {
    const double t = 2.0 * 3.14159265358979323846 * k / n;
    const double r = 10.0 + 0.8 * std::sin(5.0 * t);
    p.emplace_back(r * std::cos(t), r * std::sin(t), 0.3 * std::cos(3.0 * t));
  }
  return p;
}

std::set<std::tuple<double, double, double>> keptPoints(
  const std::vector<lk::Vec3>& points, const std::vector<std::int64_t>& chain, const std::vector<char>& keep)
{
  std::set<std::tuple<double, double, double>> out;
  for (std::size_t k = 0; k < chain.size(); ++k)
    if (keep[k])
    {
      const lk::Vec3& p = points[static_cast<std::size_t>(chain[k])];
      out.insert({ p.x(), p.y(), p.z() });
    }
  return out;
}
} // namespace

TEST(FeatureChains, OpenLinesLoopsAndJunctionsBecomeChains)
{
  // A Y (centre 0, arms 1-2, 3, 4-5), a separate loop 10-11-12-13 and a
  // lone edge 20-21.
  const Edges edges{ { 0, 1 }, { 1, 2 }, { 0, 3 }, { 4, 0 }, { 4, 5 }, { 10, 11 }, { 12, 11 }, { 12, 13 },
    { 13, 10 }, { 21, 20 } };
  const auto chains = lk::featureChains(edges);
  ASSERT_EQ(chains.size(), 5u);
  std::size_t edgesSeen = 0;
  int loops = 0;
  for (const auto& c : chains)
  {
    edgesSeen += c.size() - 1;
    if (c.front() == c.back())
    {
      ++loops;
      EXPECT_EQ(c.size(), 5u);
      EXPECT_EQ(std::set<std::int64_t>(c.begin(), c.end()), (std::set<std::int64_t>{ 10, 11, 12, 13 }));
    }
    else
    {
      // Open chains end at vertices without exactly two feature edges.
      for (const std::int64_t end : { c.front(), c.back() })
        EXPECT_TRUE(end == 0 || end == 2 || end == 3 || end == 5 || end == 20 || end == 21) << end;
    }
  }
  EXPECT_EQ(loops, 1);
  EXPECT_EQ(edgesSeen, edges.size()) << "every edge in exactly one chain";
  EXPECT_TRUE(lk::featureChains({}).empty());
}

TEST(FeatureChains, ALoopKeepsTheSamePointsWithinTheToleranceWhereverItStartsAndWhicheverWayItRuns)
{
  const int n = 240;
  const std::vector<lk::Vec3> points = wavyLoop(n);
  std::vector<std::int64_t> chain;
  for (int k = 0; k <= n; ++k)
    chain.push_back(k % n);
  for (const double tolerance : { 0.01, 0.05, 0.3 })
  {
    const std::vector<char> keep = lk::chainVerticesToKeep(points, chain, tolerance);
    ASSERT_EQ(keep.size(), chain.size());
    EXPECT_EQ(keep.front(), keep.back());
    const auto kept = keptPoints(points, chain, keep);
    EXPECT_GE(kept.size(), 4u);
    EXPECT_LT(kept.size(), static_cast<std::size_t>(n)) << "a smooth loop drops vertices at " << tolerance;
    // Every dropped vertex lies within the tolerance of the chord between
    // the kept vertices either side of it.
    std::vector<std::size_t> at;
    for (std::size_t k = 0; k < chain.size(); ++k)
      if (keep[k])
        at.push_back(k);
    for (std::size_t i = 0; i + 1 < at.size(); ++i)
      for (std::size_t k = at[i] + 1; k < at[i + 1]; ++k)
        EXPECT_LE(distanceToSegment(points[static_cast<std::size_t>(chain[k])],
                    points[static_cast<std::size_t>(chain[at[i]])], points[static_cast<std::size_t>(chain[at[i + 1]])]),
          tolerance);
    // The same loop started elsewhere, and run the other way: the same points.
    for (const int start : { 1, 77, 239 })
    {
      std::vector<std::int64_t> rotated, reversed;
      for (int k = 0; k <= n; ++k)
      {
        rotated.push_back((start + k) % n);
        reversed.push_back((start + n - k) % n);
      }
      EXPECT_EQ(keptPoints(points, rotated, lk::chainVerticesToKeep(points, rotated, tolerance)), kept);
      EXPECT_EQ(keptPoints(points, reversed, lk::chainVerticesToKeep(points, reversed, tolerance)), kept);
    }
  }
  // A tolerance of 0 keeps every vertex that is not exactly on a chord.
  const std::vector<char> all = lk::chainVerticesToKeep(points, chain, 0.0);
  EXPECT_EQ(std::count(all.begin(), all.end(), 1), n + 1);
}

TEST(FeatureChains, AnOpenChainKeepsItsEndsAndCorners)
{
  // An L of collinear points: only the ends and the corner are needed.
  std::vector<lk::Vec3> points;
  for (int k = 0; k <= 10; ++k)
    points.emplace_back(k, 0, 0);
  for (int k = 1; k <= 10; ++k)
    points.emplace_back(10, k, 0);
  std::vector<std::int64_t> chain;
  for (std::int64_t k = 0; k < static_cast<std::int64_t>(points.size()); ++k)
    chain.push_back(k);
  const std::vector<char> keep = lk::chainVerticesToKeep(points, chain, 1e-9);
  std::vector<std::int64_t> kept;
  for (std::size_t k = 0; k < chain.size(); ++k)
    if (keep[k])
      kept.push_back(chain[k]);
  EXPECT_EQ(kept, (std::vector<std::int64_t>{ 0, 10, 20 }));
  // Two vertices: both kept.
  EXPECT_EQ(lk::chainVerticesToKeep(points, { 3, 4 }, 5.0), (std::vector<char>{ 1, 1 }));
}

TEST(FeatureChains, BadInputIsRefused)
{
  const std::vector<lk::Vec3> points{ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 1, 0 } };
  EXPECT_THROW(lk::chainVerticesToKeep(points, { 0, 1, 2 }, -1.0), std::invalid_argument);
  EXPECT_THROW(lk::chainVerticesToKeep(points, { 0, 1, 2 }, std::nan("")), std::invalid_argument);
  EXPECT_THROW(lk::chainVerticesToKeep(points, { 0, 1, 3 }, 0.1), std::invalid_argument);
}

TEST(FeatureChains, EdgeBendsAreTheAnglesBetweenTheTwoTrianglesNormals)
{
  // The unit cube: its edges bend by 90 degrees, a face's diagonal by 0.
  const lk::TriangleMesh cube = lktest::cube();
  const std::vector<double> bends = lk::edgeBends(cube, { { 0, 1 }, { 3, 1 }, { 0, 3 }, { 4, 7 } });
  ASSERT_EQ(bends.size(), 4u);
  EXPECT_NEAR(bends[0], 90.0, 1e-9);
  EXPECT_NEAR(bends[1], 90.0, 1e-9);
  EXPECT_NEAR(bends[2], 0.0, 1e-9);
  EXPECT_NEAR(bends[3], 0.0, 1e-9);
  // Two triangles folded by phi about the y axis, and the border edges of
  // one (a single triangle: no second normal, no bend).
  for (const double phi : { 0.0, 30.0, 120.0, 175.0 })
  {
    const double r = phi * 3.14159265358979323846 / 180.0;
    lk::TriangleMesh roof;
    roof.points = { { 0, 0, 0 }, { 0, 1, 0 }, { 1, 0.5, 0 }, { -std::cos(r), 0.5, std::sin(r) } };
    roof.triangles = { { 0, 1, 2 }, { 1, 0, 3 } };
    const std::vector<double> b = lk::edgeBends(roof, { { 0, 1 }, { 1, 2 }, { 0, 3 } });
    EXPECT_NEAR(b[0], phi, 1e-9) << phi;
    EXPECT_EQ(b[1], 0.0);
    EXPECT_EQ(b[2], 0.0);
  }
  EXPECT_THROW(lk::edgeBends(cube, { { 0, 8 } }), std::invalid_argument);
}

TEST(FeatureChains, AWholeLineIsACreaseWhereItsMeshBendsByMoreThanTheAngleOnAverage)
{
  // Synthetic bends on three chains of unit-length edges: a loop of four
  // (0-1-2-3) bent by 90, 90, 90 and 30 degrees, an open line (4-5-6-7-8)
  // bent by 90 there and 0 elsewhere, and a line of one edge (9-10) bent by 90.
  const std::vector<lk::Vec3> points{ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 5 }, { 1, 0, 5 },
    { 2, 0, 5 }, { 3, 0, 5 }, { 4, 0, 5 }, { 0, 0, 9 }, { 1, 0, 9 } };
  const Edges input{ { 0, 1 }, { 1, 2 }, { 2, 3 }, { 0, 3 }, { 4, 5 }, { 5, 6 }, { 6, 7 }, { 7, 8 }, { 9, 10 } };
  const std::vector<double> bends{ 90, 90, 90, 30, 90, 0, 0, 0, 90 };
  // The lattice keeps input vertices 0, 2, 3 of the loop (a chord 0-2 for
  // 0-1-2), 4, 5, 8 of the line and both ends of the edge, as lattice
  // vertices 0..7; lattice edge 0-3 joins two chains (ends on no common
  // chain). The one-edge line is too short for a mean: never a crease.
  const std::vector<std::int64_t> inputVertex{ 0, 2, 3, 4, 5, 8, 9, 10 };
  const Edges lattice{ { 0, 1 }, { 1, 2 }, { 0, 2 }, { 3, 4 }, { 4, 5 }, { 0, 3 }, { 6, 7 } };
  // The loop averages 75 degrees: every one of its lattice edges is a
  // crease, the 30-degree one's included. The line averages 22.5: none is,
  // not even the lattice edge 4-5 where the mesh bends by 90.
  EXPECT_EQ(lk::creaseFeatureEdges(points, input, bends, lattice, inputVertex, 45.0),
    (std::vector<char>{ 1, 1, 1, 0, 0, 0, 0 }));
  EXPECT_EQ(lk::creaseFeatureEdges(points, input, bends, lattice, inputVertex, 20.0),
    (std::vector<char>{ 1, 1, 1, 1, 1, 0, 0 }));
  EXPECT_EQ(lk::creaseFeatureEdges(points, input, bends, lattice, inputVertex, 180.0),
    (std::vector<char>(7, 0)));
  // The mean is by length: the line's 90-degree edge made 9 long (point 4
  // at x = -8) carries it to 90 * 9 / 12 = 67.5.
  std::vector<lk::Vec3> longer = points;
  longer[4] = lk::Vec3(-8, 0, 5);
  EXPECT_EQ(lk::creaseFeatureEdges(longer, input, bends, lattice, inputVertex, 45.0),
    (std::vector<char>{ 1, 1, 1, 1, 1, 0, 0 }));
  // Bad input.
  EXPECT_THROW(lk::creaseFeatureEdges(points, input, { 90, 90 }, lattice, inputVertex, 45.0), std::invalid_argument);
  EXPECT_THROW(lk::creaseFeatureEdges(points, input, bends, { { 0, 8 } }, inputVertex, 45.0), std::invalid_argument);
  EXPECT_THROW(lk::creaseFeatureEdges(points, { { 0, 11 } }, { 0.0 }, lattice, inputVertex, 45.0),
    std::invalid_argument);
}
