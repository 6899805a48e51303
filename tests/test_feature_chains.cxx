// Feature edges as chains, and the vertices that hold a chain within a
// tolerance (what a locked line keeps with a feature tolerance).
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
