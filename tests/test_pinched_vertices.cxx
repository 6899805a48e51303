#include "TestMeshes.h"
#include "latticekit/ManifoldRepair.h"
#include "latticekit/PinchedVertices.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace
{
std::vector<lk::IndexTriangle> indexTriangles(const lk::TriangleMesh& m, std::size_t offset = 0)
{
  std::vector<lk::IndexTriangle> t;
  for (const auto& tri : m.triangles)
    t.push_back({ static_cast<std::size_t>(tri[0]) + offset, static_cast<std::size_t>(tri[1]) + offset,
      static_cast<std::size_t>(tri[2]) + offset });
  return t;
}

/// The soup as a mesh whose point i + n copies point copies[i].
lk::TriangleMesh withCopies(std::vector<lk::Vec3> points, const std::vector<lk::IndexTriangle>& triangles,
  const std::vector<std::size_t>& copies)
{
  lk::TriangleMesh m;
  for (std::size_t v : copies)
    points.push_back(points[v]);
  m.points = points;
  for (const auto& t : triangles)
    m.triangles.push_back({ static_cast<std::int64_t>(t[0]), static_cast<std::int64_t>(t[1]), static_cast<std::int64_t>(t[2]) });
  return m;
}
} // namespace

TEST(PinchedVertices, AClosedOrientedSurfaceIsLeftAsItIs)
{
  const lk::TriangleMesh sphere = lktest::icosphere(2, 1.0);
  std::vector<lk::IndexTriangle> t = indexTriangles(sphere);
  const auto before = t;
  const auto copies = lk::splitPinchedVerticesOfOrientedSoup(t, sphere.points.size());
  ASSERT_TRUE(copies.has_value());
  EXPECT_TRUE(copies->empty());
  EXPECT_EQ(t, before);
}

TEST(PinchedVertices, TwoConesMeetingAtTheirTipsGetOneTipEach)
{
  // Tip 0; cone A opens upwards over points 1-4, cone B downwards over
  // points 5-8 (each an open fan, oriented outward). B's first triangle is
  // the soup's first: B keeps the tip, A gets the copy (point 9).
  const std::vector<lk::IndexTriangle> a = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 4 }, { 0, 4, 1 } };
  const std::vector<lk::IndexTriangle> b = { { 0, 6, 5 }, { 0, 7, 6 }, { 0, 8, 7 }, { 0, 5, 8 } };
  std::vector<lk::IndexTriangle> t = { b[0], a[0], a[1], a[2], a[3], b[1], b[2], b[3] };
  const auto copies = lk::splitPinchedVerticesOfOrientedSoup(t, 9);
  ASSERT_TRUE(copies.has_value());
  EXPECT_EQ(*copies, std::vector<std::size_t>{ 0 });
  for (std::size_t i : { 0, 5, 6, 7 })
    EXPECT_EQ(t[i][0], 0u) << i;
  for (std::size_t i : { 1, 2, 3, 4 })
    EXPECT_EQ(t[i][0], 9u) << i;
}

TEST(PinchedVertices, TwoClosedSurfacesOnOneEdgeArePulledApart)
{
  // Two cubes sharing the edge from (1,1,0) to (1,1,1): that edge has four
  // triangles, two each way. It is cut, and both its ends are copied for the
  // second cube, which then is a closed surface of its own.
  const lk::TriangleMesh a = lktest::cube();
  lk::TriangleMesh b = lktest::cube();
  std::vector<lk::Vec3> points = a.points;
  std::vector<std::size_t> map(b.points.size());
  for (std::size_t i = 0; i < b.points.size(); ++i)
  {
    const lk::Vec3 p = b.points[i] + lk::Vec3(1, 1, 0);
    map[i] = points.size();
    for (std::size_t j = 0; j < a.points.size(); ++j)
      if ((a.points[j] - p).norm() == 0.0)
        map[i] = j;
    if (map[i] == points.size())
      points.push_back(p);
  }
  ASSERT_EQ(points.size(), 14u); // two points shared
  std::vector<lk::IndexTriangle> t = indexTriangles(a);
  for (const auto& tri : b.triangles)
    t.push_back({ map[static_cast<std::size_t>(tri[0])], map[static_cast<std::size_t>(tri[1])],
      map[static_cast<std::size_t>(tri[2])] });
  const auto copies = lk::splitPinchedVerticesOfOrientedSoup(t, points.size());
  ASSERT_TRUE(copies.has_value());
  ASSERT_EQ(copies->size(), 2u);
  for (std::size_t v : *copies)
    EXPECT_NEAR(points[v].x(), 1.0, 0.0);
  const lk::TriangleMesh m = withCopies(points, t, *copies);
  EXPECT_EQ(lk::countBoundaryEdges(m), 0u);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  EXPECT_NEAR(lk::signedVolume(m), 2.0, 1e-12);
  // The first cube keeps its points.
  for (std::size_t i = 0; i < a.triangles.size(); ++i)
    EXPECT_EQ(t[i], indexTriangles(a)[i]);
}

TEST(PinchedVertices, AnEdgeWithThreeTrianglesSeparatesThem)
{
  // A book with three pages: the spine (points 0 and 1) is copied twice at
  // each end, and every page stands alone.
  std::vector<lk::IndexTriangle> t = { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } };
  const auto copies = lk::splitPinchedVerticesOfOrientedSoup(t, 5);
  ASSERT_TRUE(copies.has_value());
  EXPECT_EQ(*copies, (std::vector<std::size_t>{ 0, 0, 1, 1 }));
  std::vector<std::size_t> uses(9, 0);
  for (const auto& tri : t)
    for (std::size_t v : tri)
      ++uses[v];
  for (std::size_t v = 0; v < uses.size(); ++v)
    EXPECT_EQ(uses[v], 1u) << v;
}

TEST(PinchedVertices, TrianglesFacingEachOtherAcrossAnEdgeNeedOrienting)
{
  lk::TriangleMesh sphere = lktest::icosphere(1, 1.0);
  std::swap(sphere.triangles[7][1], sphere.triangles[7][2]);
  std::vector<lk::IndexTriangle> t = indexTriangles(sphere);
  const auto before = t;
  EXPECT_FALSE(lk::splitPinchedVerticesOfOrientedSoup(t, sphere.points.size()).has_value());
  EXPECT_EQ(t, before);
  // The repair orients it instead.
  lk::repairToManifold(sphere);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(sphere), "");
  EXPECT_GT(lk::signedVolume(sphere), 0.0);
}

TEST(PinchedVertices, BadTrianglesAreRefused)
{
  std::vector<lk::IndexTriangle> beyond = { { 0, 1, 5 } };
  EXPECT_THROW(lk::splitPinchedVerticesOfOrientedSoup(beyond, 5), std::invalid_argument);
  std::vector<lk::IndexTriangle> repeated = { { 0, 1, 1 } };
  EXPECT_THROW(lk::splitPinchedVerticesOfOrientedSoup(repeated, 5), std::invalid_argument);
  std::vector<lk::IndexTriangle> none;
  EXPECT_TRUE(lk::splitPinchedVerticesOfOrientedSoup(none, 0).has_value());
}
