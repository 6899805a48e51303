#include "latticekit/AdaptivePatchMesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <stdexcept>

namespace
{
/// An n x n grid of unit squares in z = 0, two triangles each.
lk::TriangleMesh grid(int n)
{
  lk::TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      m.points.emplace_back(i, j, 0.0);
  auto id = [&](int i, int j) { return i + (n + 1) * j; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      m.triangles.push_back({ { id(i, j), id(i + 1, j), id(i + 1, j + 1) } });
      m.triangles.push_back({ { id(i, j), id(i + 1, j + 1), id(i, j + 1) } });
    }
  return m;
}

/// Conformity: every edge has one or two triangles, the border is the grid's
/// border, and no used vertex lies inside another triangle's edge (base
/// positions: the output is planar there).
void expectConforming(const lk::AdaptivePatchMesh& mesh, int n)
{
  const auto tris = mesh.triangles();
  std::map<std::pair<int, int>, int> use;
  std::set<int> used;
  for (const auto& t : tris)
    for (int e = 0; e < 3; ++e)
    {
      const int a = t[e], b = t[(e + 1) % 3];
      ++use[{ std::min(a, b), std::max(a, b) }];
      used.insert(a);
    }
  double borderLength = 0.0;
  for (const auto& [e, count] : use)
  {
    ASSERT_LE(count, 2);
    if (count == 1)
    {
      const lk::Vec3 a = mesh.basePosition(e.first), b = mesh.basePosition(e.second);
      const lk::Vec3 mid = 0.5 * (a + b);
      ASSERT_TRUE(mid.x() < 1e-12 || mid.y() < 1e-12 || mid.x() > n - 1e-12 || mid.y() > n - 1e-12)
        << "an inner edge with one triangle: a crack";
      borderLength += (b - a).norm();
    }
  }
  EXPECT_NEAR(borderLength, 4.0 * n, 1e-9);
  // Refinement puts new vertices at dyadic points of edges, so a vertex
  // inside an edge (a T-junction) would sit at one of its k/16 points.
  std::map<std::array<long long, 2>, int> at;
  auto q = [](const lk::Vec3& p) { return std::array<long long, 2>{ { std::llround(p.x() * 1e6), std::llround(p.y() * 1e6) } }; };
  for (int v : used)
    at[q(mesh.basePosition(v))] = v;
  for (const auto& [e, count] : use)
  {
    const lk::Vec3 a = mesh.basePosition(e.first), b = mesh.basePosition(e.second);
    for (int k = 1; k < 16; ++k)
    {
      const auto it = at.find(q(a + (k / 16.0) * (b - a)));
      if (it != at.end())
        FAIL() << "vertex " << it->second << " lies on edge (" << e.first << ", " << e.second << "): a T-junction";
    }
  }
  // The triangles tile the square: their base areas add up to n^2.
  double area = 0.0;
  for (const auto& t : tris)
    area += 0.5 * (mesh.basePosition(t[1]) - mesh.basePosition(t[0]))
                    .cross(mesh.basePosition(t[2]) - mesh.basePosition(t[0]))
                    .norm();
  EXPECT_NEAR(area, double(n) * n, 1e-9);
}
} // namespace

TEST(AdaptivePatchMesh, FigureTwoTransitionTriangles)
{
  lk::AdaptivePatchMesh mesh(grid(2), 4);
  ASSERT_EQ(mesh.triangles().size(), 8u);
  // 2 a: split triangle 0 (cell (0, 0), lower right); its neighbours across
  // the diagonal (1) and across x = 1 (3) become transition triangles (two
  // output triangles each); its third edge is on the border.
  ASSERT_TRUE(mesh.split(0));
  EXPECT_EQ(mesh.vertexCount(), 9u + 3u);
  EXPECT_EQ(mesh.triangles().size(), 8u - 1u + 4u + 2u);
  expectConforming(mesh, 2);
  // 2 d: splitting the transition triangle reuses its midpoint (two new vertices).
  ASSERT_TRUE(mesh.split(1));
  EXPECT_EQ(mesh.vertexCount(), 12u + 2u);
  expectConforming(mesh, 2);
  // 2 e, f: splitting triangle 2 gives transition triangle 3 a second
  // hanging midpoint, so 3 is split as well.
  const auto isLeaf = [&](int t) {
    const auto l = mesh.leaves();
    return std::find(l.begin(), l.end(), t) != l.end();
  };
  ASSERT_TRUE(isLeaf(3));
  const std::size_t before = mesh.leafCount();
  ASSERT_TRUE(mesh.split(2));
  EXPECT_FALSE(isLeaf(3));
  EXPECT_EQ(mesh.leafCount(), before + 6);
  expectConforming(mesh, 2);
}

TEST(AdaptivePatchMesh, ConformingAfterAnySequence)
{
  std::mt19937 rng(7);
  lk::AdaptivePatchMesh mesh(grid(6), 4);
  for (int step = 0; step < 60; ++step)
  {
    const int what = static_cast<int>(rng() % 4);
    const lk::Vec3 c(std::uniform_real_distribution<double>(0, 6)(rng), std::uniform_real_distribution<double>(0, 6)(rng), 0);
    if (what == 0)
    {
      const auto leaves = mesh.leaves();
      mesh.split(leaves[rng() % leaves.size()]);
    }
    else if (what == 1)
      mesh.functionalDeformation(c, 0.5, 2.0, 1.5, 0.01);
    else if (what == 2)
      mesh.rangeDeformation(c - lk::Vec3(0.7, 0.5, 1), c + lk::Vec3(0.7, 0.5, 1), lk::Vec3(0, 0, 0.2));
    else
      mesh.smoothingDeformation(c, 1.2, 2);
    expectConforming(mesh, 6);
    if (HasFatalFailure() || HasFailure())
      FAIL() << "after step " << step << " (operation " << what << ")";
  }
  int deepest = 0;
  for (int t : mesh.leaves())
    deepest = std::max(deepest, mesh.level(t));
  EXPECT_EQ(deepest, 4); // depth is bounded, and reached
}

TEST(AdaptivePatchMesh, EveryNewVertexIsAMidpointAndEveryTriangleKnowsItsInputTriangle)
{
  // What the filter needs to carry the input's attributes: each new vertex's
  // base position is the middle of its two ends, and each output triangle
  // lies in the input triangle it names (its base centre is inside it).
  const lk::TriangleMesh input = grid(4);
  lk::AdaptivePatchMesh mesh(input, 4);
  mesh.functionalDeformation(lk::Vec3(1.3, 2.2, 0), 0.8, 3.0, 1.5, 0.01);
  ASSERT_EQ(mesh.inputVertexCount(), input.points.size());
  ASSERT_GT(mesh.vertexCount(), 2 * input.points.size()); // it refined
  for (int v = 0; v < static_cast<int>(mesh.vertexCount()); ++v)
  {
    const auto ends = mesh.midpointEnds(v);
    if (v < static_cast<int>(input.points.size()))
    {
      EXPECT_EQ(ends[0], -1);
      continue;
    }
    ASSERT_GE(ends[0], 0);
    ASSERT_LT(ends[0], v); // made before it: one pass in index order interpolates
    ASSERT_LT(ends[1], v);
    EXPECT_LT((mesh.basePosition(v) - 0.5 * (mesh.basePosition(ends[0]) + mesh.basePosition(ends[1]))).norm(), 1e-12);
  }
  const auto tris = mesh.triangles();
  const auto origins = mesh.triangleOrigins();
  ASSERT_EQ(origins.size(), tris.size());
  std::set<int> seen;
  for (std::size_t t = 0; t < tris.size(); ++t)
  {
    ASSERT_GE(origins[t], 0);
    ASSERT_LT(origins[t], static_cast<int>(input.triangles.size()));
    seen.insert(origins[t]);
    const lk::Vec3 c = (mesh.basePosition(tris[t][0]) + mesh.basePosition(tris[t][1]) + mesh.basePosition(tris[t][2])) / 3.0;
    const auto& in = input.triangles[static_cast<std::size_t>(origins[t])];
    const lk::Vec3 a = input.points[in[0]], b = input.points[in[1]], d = input.points[in[2]];
    // Inside in the plane z = 0: the same side of all three edges.
    auto side = [&](const lk::Vec3& p, const lk::Vec3& q) { return (q - p).cross(c - p).z(); };
    EXPECT_GT(side(a, b), 0.0) << "triangle " << t;
    EXPECT_GT(side(b, d), 0.0) << "triangle " << t;
    EXPECT_GT(side(d, a), 0.0) << "triangle " << t;
  }
  EXPECT_EQ(seen.size(), input.triangles.size()); // every input triangle is covered
}

TEST(AdaptivePatchMesh, FunctionalDeformationIsLocalWithPeakK)
{
  lk::AdaptivePatchMesh mesh(grid(10), 5);
  const lk::Vec3 c(5, 5, 0); // a grid vertex
  const double k = 0.8, a = 3.0, D = 2.0;
  const int moved = mesh.functionalDeformation(c, k, a, D, 0.005);
  EXPECT_GT(moved, 10);
  double peak = 0.0;
  for (int v = 0; v < static_cast<int>(mesh.vertexCount()); ++v)
  {
    const lk::Vec3 d = mesh.displacement(v);
    const double dist = (mesh.basePosition(v) - c).norm();
    if (dist > D + 1e-12)
      EXPECT_EQ(d.norm(), 0.0) << "vertex " << v << " at " << dist;
    else
    {
      EXPECT_NEAR(d.z(), k * std::exp(-a * dist * dist), 1e-12); // along the normal
      EXPECT_EQ(d.x(), 0.0);
    }
    peak = std::max(peak, d.norm());
  }
  EXPECT_DOUBLE_EQ(peak, k);
  // Refinement stays where the deformation is.
  int refinedFar = 0, refinedNear = 0;
  const auto tris = mesh.triangles();
  const auto levels = mesh.triangleLevels();
  ASSERT_EQ(tris.size(), levels.size());
  for (std::size_t i = 0; i < tris.size(); ++i)
  {
    const lk::Vec3 centroid = (mesh.basePosition(tris[i][0]) + mesh.basePosition(tris[i][1]) +
                                mesh.basePosition(tris[i][2])) / 3.0;
    if (levels[i] > 0)
      ((centroid - c).norm() > D + 1.5 ? refinedFar : refinedNear) += 1;
  }
  EXPECT_EQ(refinedFar, 0);
  EXPECT_GT(refinedNear, 50);
  expectConforming(mesh, 10);
}

TEST(AdaptivePatchMesh, RangeMovesTheBoxAndRefinesItsBorder)
{
  lk::AdaptivePatchMesh mesh(grid(8), 3);
  const lk::Vec3 lo(2.2, 2.2, -1), hi(5.7, 4.6, 1), move(0, 0, 0.5);
  mesh.rangeDeformation(lo, hi, move);
  for (int v = 0; v < static_cast<int>(mesh.vertexCount()); ++v)
  {
    const lk::Vec3 p = mesh.basePosition(v);
    const bool inside = (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
    EXPECT_EQ(mesh.displacement(v), inside ? move : lk::Vec3::Zero());
  }
  expectConforming(mesh, 8);
  int deep = 0;
  for (int t : mesh.leaves())
    deep += mesh.level(t) == 3 ? 1 : 0;
  EXPECT_GT(deep, 0);
}

TEST(AdaptivePatchMesh, SmoothingLowersRoughness)
{
  lk::AdaptivePatchMesh mesh(grid(8), 3);
  mesh.rangeDeformation(lk::Vec3(3, 3, -1), lk::Vec3(5, 5, 1), lk::Vec3(0, 0, 1), false);
  auto roughness = [&]() {
    double r = 0.0;
    for (const auto& t : mesh.triangles())
      for (int e = 0; e < 3; ++e)
        r += (mesh.displacement(t[e]) - mesh.displacement(t[(e + 1) % 3])).squaredNorm();
    return r;
  };
  const double before = roughness();
  const int inRegion = mesh.smoothingDeformation(lk::Vec3(4, 4, 0), 3.0, 3);
  EXPECT_GT(inRegion, 10);
  EXPECT_LT(roughness(), 0.5 * before);
  // Outside the region nothing changed.
  EXPECT_EQ(mesh.displacement(0), lk::Vec3::Zero());
}

TEST(AdaptivePatchMesh, BadInputIsRefused)
{
  lk::TriangleMesh empty;
  EXPECT_THROW(lk::AdaptivePatchMesh{ empty }, std::invalid_argument);
  lk::TriangleMesh nonManifold = grid(1);
  nonManifold.points.emplace_back(0.5, 0.5, 1.0);
  nonManifold.triangles.push_back({ { 0, 3, 4 } }); // a third triangle on the diagonal
  EXPECT_THROW(lk::AdaptivePatchMesh{ nonManifold }, std::invalid_argument);
  lk::TriangleMesh flat = grid(1);
  flat.triangles.push_back({ { 0, 1, 1 } });
  EXPECT_THROW(lk::AdaptivePatchMesh{ flat }, std::invalid_argument);
  lk::TriangleMesh nan = grid(1);
  nan.points[2].x() = std::nan("");
  EXPECT_THROW(lk::AdaptivePatchMesh{ nan }, std::invalid_argument);
  EXPECT_THROW(lk::AdaptivePatchMesh(grid(1), 13), std::invalid_argument);
  lk::AdaptivePatchMesh mesh(grid(2));
  EXPECT_THROW(mesh.functionalDeformation(lk::Vec3(1, 1, 0), 1.0, 1.0, -1.0, 0.01), std::invalid_argument);
  EXPECT_THROW(mesh.rangeDeformation(lk::Vec3(1, 1, 1), lk::Vec3(0, 0, 0), lk::Vec3(0, 0, 1)), std::invalid_argument);
  EXPECT_THROW(mesh.smoothingDeformation(lk::Vec3(1, 1, 0), 0.0), std::invalid_argument);
  // 2^31 - 1 iterations would run about 18 minutes on 81 vertices (10^6 took 0.5 s).
  EXPECT_THROW(mesh.smoothingDeformation(lk::Vec3(1, 1, 0), 1.0, 2147483647), std::invalid_argument);
  EXPECT_THROW(mesh.smoothingDeformation(lk::Vec3(1, 1, 0), 1.0, lk::kMaximumSmoothingIterations + 1),
    std::invalid_argument);
  EXPECT_NO_THROW(mesh.smoothingDeformation(lk::Vec3(1, 1, 0), 1.0, 100));
  EXPECT_FALSE(mesh.split(-1));
  EXPECT_FALSE(mesh.split(100));
}
