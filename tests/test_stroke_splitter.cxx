#include "TestMeshes.h"
#include "latticekit/ManifoldRepair.h"
#include "latticekit/MeshCut.h"
#include "latticekit/LatticeSimplification.h"
#include "latticekit/StrokeSplitter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace
{
void expectConnectedLine(const lk::TriangleMesh& m, const std::vector<std::int64_t>& line)
{
  const auto edges = lktest::edgesOf(m);
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
    EXPECT_TRUE(edges.count(lk::edgeKey(line[i], line[i + 1]))) << "line vertices " << i << " and " << i + 1;
}
} // namespace

TEST(StrokeSplitter, SegmentsAddEdgesOnTheStrokeOfAPlane)
{
  const lk::TriangleMesh grid = lktest::grid(20, 1.0, 0.0);
  lk::StrokeSplitter splitter(grid);
  const std::vector<lk::Vec3> stroke = { { 0.113, 0.207, 0.0 }, { 0.371, 0.333, 0.0 }, { 0.5, 0.6, 0.0 },
    { 0.871, 0.633, 0.0 } };
  for (const auto& p : stroke)
    EXPECT_GE(splitter.addPoint(p), 1u);
  const lk::TriangleMesh m = splitter.mesh();
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  EXPECT_NEAR(lk::surfaceArea(m), 1.0, 1e-12);
  const auto& line = splitter.line();
  ASSERT_GT(line.size(), 20u);
  expectConnectedLine(m, line);
  // Every line vertex lies on the stroke polyline (the plane is the surface).
  for (std::size_t i = 0; i < line.size(); ++i)
  {
    const lk::Vec3 p = m.points[static_cast<std::size_t>(line[i])];
    double d = 1e9;
    for (std::size_t k = 0; k + 1 < stroke.size(); ++k)
    {
      const lk::Vec3 s = stroke[k + 1] - stroke[k];
      const double t = std::clamp((p - stroke[k]).dot(s) / s.squaredNorm(), 0.0, 1.0);
      d = std::min(d, (stroke[k] + t * s - p).norm());
    }
    EXPECT_LT(d, 1e-9) << "line vertex " << i;
  }
  // The stroke points are line vertices, in order.
  std::size_t k = 0;
  for (auto v : line)
    if (k < stroke.size() && (m.points[static_cast<std::size_t>(v)] - stroke[k]).norm() < 1e-12)
      ++k;
  EXPECT_EQ(k, stroke.size());
  // Only line vertices were added (the line may also pass through grid vertices).
  const std::set<std::int64_t> onLine(line.begin(), line.end());
  for (std::size_t v = grid.points.size(); v < m.points.size(); ++v)
    EXPECT_TRUE(onLine.count(static_cast<std::int64_t>(v))) << "vertex " << v << " is not on the line";
}

TEST(StrokeSplitter, ClosedStrokeOnTheSphereSplitsItIntoTwoPieces)
{
  const lk::TriangleMesh sphere = lktest::icosphere(3, 1.0);
  lk::StrokeSplitter splitter(sphere);
  for (int k = 0; k < 40; ++k)
  {
    const double a = 2.0 * 3.14159265358979 * k / 40.0;
    splitter.addPoint({ 0.95 * std::cos(a), 0.95 * std::sin(a), 0.2 });
  }
  splitter.close();
  ASSERT_TRUE(splitter.closed());
  const lk::TriangleMesh m = splitter.mesh();
  const auto& line = splitter.line();
  EXPECT_EQ(line.front(), line.back());
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  EXPECT_EQ(lk::countBoundaryEdges(m), 0u);
  EXPECT_NEAR(lk::signedVolume(m), lk::signedVolume(sphere), 1e-12);
  expectConnectedLine(m, line);
  std::set<std::int64_t> once(line.begin(), line.end() - 1);
  EXPECT_EQ(once.size(), line.size() - 1) << "the loop crosses itself";
  EXPECT_EQ(lk::cutAlongLoops(lk::asPolygonMesh(m), { line }, false).pieces.size(), 2u);
}

TEST(StrokeSplitter, AStrokeAlongARingOfEdgesMakesNoFlatTriangles)
{
  // The planner's stroke around the tube of tests/data/torus.obj, 0.05 beside
  // the ring of edges at angle 0 (the mesh points there have y = 0): its
  // points project to either side, so the walk crosses the ring's edges
  // again and again, and one edge can get two new vertices. A fan of the
  // face beside it then held three collinear vertices: a zero-area
  // triangle, which the cut refused ("face 351 has zero area").
  const lk::TriangleMesh torus = lktest::torus(16, 8, 3.0, 1.0);
  lk::StrokeSplitter splitter(torus);
  auto smallestArea = [](const lk::TriangleMesh& m) {
    double smallest = 1e300;
    for (const lk::Triangle& t : m.triangles)
    {
      const lk::Vec3 &a = m.points[static_cast<std::size_t>(t[0])], &b = m.points[static_cast<std::size_t>(t[1])],
                     &c = m.points[static_cast<std::size_t>(t[2])];
      smallest = std::min(smallest, 0.5 * (b - a).cross(c - a).norm());
    }
    return smallest;
  };
  const double pi = 3.14159265358979323846;
  for (int k = 0; k <= 40; ++k)
  {
    const double v = 2 * pi * k / 40;
    splitter.addPoint({ 3 + 1.05 * std::cos(v), 0.05, 1.05 * std::sin(v) });
    ASSERT_GT(smallestArea(splitter.mesh()), 1e-8) << "after stroke point " << k;
  }
  // Point 40 is point 0 again: the line is back on its first vertex, and
  // close() has no walk left to do (it threw "the stroke segment runs along
  // the surface normal").
  ASSERT_EQ(splitter.line().front(), splitter.line().back());
  EXPECT_NO_THROW(splitter.close());
  EXPECT_TRUE(splitter.closed());
  const lk::TriangleMesh m = splitter.mesh();
  EXPECT_GT(smallestArea(m), 1e-8);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  EXPECT_NEAR(lk::signedVolume(m), lk::signedVolume(torus), 1e-9);
  expectConnectedLine(m, splitter.line());
}

TEST(StrokeSplitter, AFailedPointLeavesTheMeshAndLineUnchanged)
{
  const lk::TriangleMesh grid = lktest::grid(10, 1.0, 0.0);
  lk::StrokeSplitter splitter(grid);
  splitter.addPoint({ 0.21, 0.33, 0.0 });
  splitter.addPoint({ 0.52, 0.41, 0.0 });
  const auto before = splitter.mesh();
  const auto line = splitter.line();
  EXPECT_THROW(splitter.addPoint({ 0.5, 0.5, 3.0 }), std::invalid_argument);    // misses
  EXPECT_THROW(splitter.addPoint({ 0.5, std::nan(""), 0 }), std::invalid_argument); // not finite
  EXPECT_EQ(splitter.line(), line);
  EXPECT_EQ(splitter.mesh().triangles, before.triangles);
  EXPECT_THROW(lk::StrokeSplitter(lk::TriangleMesh{}), std::invalid_argument);
  lk::StrokeSplitter two(grid);
  two.addPoint({ 0.21, 0.33, 0.0 });
  EXPECT_THROW(two.close(), std::invalid_argument); // fewer than three vertices
}

TEST(StrokeSplitter, ASegmentNoWayRoundFollowsLeavesTheMeshAndLineAsTheyWere)
{
  // A disc 0.06 thick: the last point lies on its far side. Every way round
  // (halves, steps along edges) splits faces before it fails, and each is
  // taken back from a journal of what it changed, not from a copy of the mesh.
  lk::TriangleMesh disc = lktest::icosphere(3, 1.0);
  for (auto& p : disc.points)
    p.z() *= 0.03;
  for (const double x : { 0.1, 0.3, 0.5 })
  {
    lk::StrokeSplitter splitter(disc);
    splitter.addPoint({ -0.3, 0.05, 0.03 });
    splitter.addPoint({ 0.0, 0.07, 0.03 });
    const lk::TriangleMesh before = splitter.mesh();
    const auto line = splitter.line();
    EXPECT_THROW(splitter.addPoint({ x, 0.1, -0.03 }), std::invalid_argument) << x;
    const lk::TriangleMesh after = splitter.mesh();
    EXPECT_EQ(after.triangles, before.triangles) << x;
    EXPECT_EQ(after.points, before.points) << x;
    EXPECT_EQ(splitter.line(), line) << x;
    EXPECT_EQ(lk::cgalSurfaceMeshProblem(after), "");
    // The splitter goes on from where it was.
    EXPECT_GE(splitter.addPoint({ 0.2, 0.1, 0.03 }), 1u);
    EXPECT_EQ(lk::cgalSurfaceMeshProblem(splitter.mesh()), "");
    expectConnectedLine(splitter.mesh(), splitter.line());
  }
}

TEST(StrokeSplitter, AStrokeThatCrossesItsOwnLineKeepsTheLineConnected)
{
  const lk::TriangleMesh grid = lktest::grid(20, 1.0, 0.0);
  lk::StrokeSplitter splitter(grid);
  for (const lk::Vec3& p : std::vector<lk::Vec3>{ { 0.1, 0.5, 0 }, { 0.9, 0.5, 0 }, { 0.9, 0.8, 0 }, { 0.5, 0.8, 0 },
         { 0.5, 0.2, 0 } })
    splitter.addPoint(p);
  const lk::TriangleMesh m = splitter.mesh();
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  expectConnectedLine(m, splitter.line());
}
