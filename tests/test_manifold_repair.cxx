#include "TestMeshes.h"
#include "latticekit/ManifoldRepair.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <vector>

namespace
{
lk::TriangleMesh translated(lk::TriangleMesh m, const lk::Vec3& d)
{
  for (auto& p : m.points)
  {
    p += d;
  }
  return m;
}

lk::TriangleMesh merged(const lk::TriangleMesh& a, const lk::TriangleMesh& b)
{
  lk::TriangleMesh m = a;
  const auto offset = static_cast<std::int64_t>(a.points.size());
  m.points.insert(m.points.end(), b.points.begin(), b.points.end());
  for (auto t : b.triangles)
  {
    m.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  return m;
}
/// Every triangle with its own three points, as marching cubes writes them;
/// with `minusZeroes`, every other point's zero coordinates are -0.0.
lk::TriangleMesh looseTriangles(const lk::TriangleMesh& m, bool minusZeroes = false)
{
  lk::TriangleMesh soup;
  for (const auto& t : m.triangles)
  {
    const auto base = static_cast<std::int64_t>(soup.points.size());
    for (auto id : t)
    {
      lk::Vec3 p = m.points[static_cast<std::size_t>(id)];
      if (minusZeroes && soup.points.size() % 2 == 1)
        for (int k = 0; k < 3; ++k)
          if (p[k] == 0.0)
            p[k] = -0.0;
      soup.points.push_back(p);
    }
    soup.triangles.push_back({ base, base + 1, base + 2 });
  }
  return soup;
}
} // namespace

TEST(ManifoldRepair, CleanMeshIsUnchangedAndValid)
{
  lk::TriangleMesh m = lktest::icosphere(2, 1.0);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  const double volume = lk::signedVolume(m);
  const lk::RepairReport r = lk::repairToManifold(m);
  EXPECT_EQ(r.outputTriangles, r.inputTriangles);
  EXPECT_EQ(r.mergedPoints, 0u);
  EXPECT_EQ(r.splitNonManifold, 0u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_TRUE(r.closed);
  EXPECT_NEAR(lk::signedVolume(m), volume, 1e-12);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
}

TEST(ManifoldRepair, TrianglesWithoutSharedPointsAreWelded)
{
  lk::TriangleMesh soup = looseTriangles(lktest::cube());
  EXPECT_EQ(lk::countBoundaryEdges(soup), 36u); // twelve loose triangles
  const lk::RepairReport r = lk::repairToManifold(soup);
  EXPECT_EQ(r.mergedPoints, 36u - 8u);
  EXPECT_EQ(soup.points.size(), 8u);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(soup), "");
  EXPECT_NEAR(lk::signedVolume(soup), 1.0, 1e-12);
}

TEST(ManifoldRepair, PointsAtMinusZeroAreWeldedToThoseAtZero)
{
  // -0.0 equals 0.0: a soup whose copies of a corner differ only in the
  // zero's sign is still one closed cube (the hash must not tell them apart).
  lk::TriangleMesh soup = looseTriangles(lktest::cube(), true);
  ASSERT_TRUE(std::signbit(soup.points[1].x()));
  const lk::RepairReport r = lk::repairToManifold(soup);
  EXPECT_EQ(r.mergedPoints, 36u - 8u);
  EXPECT_EQ(soup.points.size(), 8u);
  EXPECT_TRUE(r.closed);
  EXPECT_NEAR(lk::signedVolume(soup), 1.0, 1e-12);
}

TEST(ManifoldRepair, InsideOutMeshIsTurnedOutward)
{
  lk::TriangleMesh m = lktest::cube();
  for (auto& t : m.triangles)
  {
    std::swap(t[1], t[2]);
  }
  ASSERT_NEAR(lk::signedVolume(m), -1.0, 1e-12);
  lk::repairToManifold(m);
  EXPECT_NEAR(lk::signedVolume(m), 1.0, 1e-12);
}

TEST(ManifoldRepair, InconsistentOrientationIsMadeConsistent)
{
  lk::TriangleMesh m = lktest::icosphere(1, 1.0);
  std::swap(m.triangles[5][1], m.triangles[5][2]);
  std::swap(m.triangles[17][1], m.triangles[17][2]);
  EXPECT_NE(lk::cgalSurfaceMeshProblem(m), "");
  lk::repairToManifold(m);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  EXPECT_GT(lk::signedVolume(m), 0.0);
  EXPECT_EQ(lk::countBoundaryEdges(m), 0u);
}

TEST(ManifoldRepair, PinchedVertexIsSplit)
{
  // Two cubes touching at one corner: the shared vertex is non-manifold.
  lk::TriangleMesh a = lktest::cube();
  lk::TriangleMesh b = translated(lktest::cube(), lk::Vec3(1, 1, 1));
  lk::TriangleMesh m = merged(a, b);
  // Weld the touching corner (a's vertex 7 at (1,1,1) and b's vertex 0).
  for (auto& t : m.triangles)
  {
    for (auto& id : t)
    {
      if (id == 8)
      {
        id = 7;
      }
    }
  }
  EXPECT_NE(lk::cgalSurfaceMeshProblem(m), "");
  const lk::RepairReport r = lk::repairToManifold(m);
  EXPECT_GE(r.splitNonManifold, 1u);
  EXPECT_EQ(r.components, 2u);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  EXPECT_NEAR(lk::signedVolume(m), 2.0, 1e-12);
}

TEST(ManifoldRepair, NonManifoldEdgeIsSeparated)
{
  // Three triangles on one edge (a book with three pages).
  lk::TriangleMesh m;
  m.points = { lk::Vec3(0, 0, 0), lk::Vec3(0, 0, 1), lk::Vec3(1, 0, 0), lk::Vec3(0, 1, 0),
    lk::Vec3(-1, -1, 0) };
  m.triangles = { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } };
  EXPECT_NE(lk::cgalSurfaceMeshProblem(m), "");
  lk::repairToManifold(m);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  EXPECT_EQ(m.triangles.size(), 3u);
}

TEST(ManifoldRepair, EachMeshASurfaceMeshCannotHoldIsNamedWhateverTheTrianglesOrder)
{
  // The check builds the Surface_mesh face by face: the order of the
  // triangles must not decide whether a manifold mesh loads.
  const std::string notAMesh = "the triangles do not form a manifold, consistently oriented mesh "
                               "(non-manifold edge or vertex, or inconsistent orientation)";
  lk::TriangleMesh sphere = lktest::icosphere(2, 1.0);
  std::mt19937 rng(4);
  for (int round = 0; round < 50; ++round)
  {
    std::shuffle(sphere.triangles.begin(), sphere.triangles.end(), rng);
    ASSERT_EQ(lk::cgalSurfaceMeshProblem(sphere), "") << "order " << round;
    lk::TriangleMesh open = sphere; // the upper half, a disc: fans that meet late
    open.triangles.erase(std::remove_if(open.triangles.begin(), open.triangles.end(),
                           [&](const lk::Triangle& t) {
                             return open.points[static_cast<std::size_t>(t[0])].z() +
                               open.points[static_cast<std::size_t>(t[1])].z() +
                               open.points[static_cast<std::size_t>(t[2])].z() < 0.1;
                           }),
      open.triangles.end());
    std::vector<std::int64_t> newId(open.points.size(), -1);
    std::vector<lk::Vec3> kept;
    for (auto& tri : open.triangles)
      for (auto& id : tri)
      {
        auto& n = newId[static_cast<std::size_t>(id)];
        if (n < 0)
        {
          n = static_cast<std::int64_t>(kept.size());
          kept.push_back(open.points[static_cast<std::size_t>(id)]);
        }
        id = n;
      }
    open.points = kept; // no point left alone (a lone vertex is no valid Surface_mesh)
    ASSERT_EQ(lk::cgalSurfaceMeshProblem(open), "") << "order " << round;
  }

  lk::TriangleMesh flipped = sphere;
  std::swap(flipped.triangles[7][0], flipped.triangles[7][1]);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(flipped), notAMesh);

  lk::TriangleMesh pinched = merged(lktest::cube(), translated(lktest::cube(), lk::Vec3(1, 1, 1)));
  for (auto& t : pinched.triangles)
    for (auto& id : t)
      if (id == 8)
        id = 7; // the cubes share a corner, each whole
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(pinched), notAMesh);

  lk::TriangleMesh book;
  book.points = { lk::Vec3(0, 0, 0), lk::Vec3(0, 0, 1), lk::Vec3(1, 0, 0), lk::Vec3(0, 1, 0), lk::Vec3(-1, -1, 0) };
  book.triangles = { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } };
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(book), notAMesh);

  lk::TriangleMesh twice = sphere;
  twice.triangles.push_back(twice.triangles[3]);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(twice), notAMesh);

  lk::TriangleMesh repeats = sphere;
  repeats.triangles[5][2] = repeats.triangles[5][0];
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(repeats), "a triangle repeats a vertex");

  lk::TriangleMesh flat = sphere;
  const auto t = flat.triangles[9];
  flat.points[static_cast<std::size_t>(t[2])] = flat.points[static_cast<std::size_t>(t[0])];
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(flat), "the mesh has a degenerate (zero-area) triangle");

  lk::TriangleMesh outOfRange = sphere;
  outOfRange.triangles[0][1] = static_cast<std::int64_t>(outOfRange.points.size());
  EXPECT_NE(lk::cgalSurfaceMeshProblem(outOfRange), "");
}

TEST(ManifoldRepair, DegenerateTrianglesAreRemoved)
{
  lk::TriangleMesh m = lktest::icosphere(1, 1.0);
  // A triangle repeating a vertex, and a duplicate of an existing triangle.
  m.triangles.push_back({ 0, 0, 1 });
  m.triangles.push_back(m.triangles[3]);
  lk::repairToManifold(m);
  EXPECT_EQ(m.triangles.size(), 80u);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
}

TEST(ManifoldRepair, ZeroAreaTriangleIsCollapsed)
{
  // A flat fan whose centre vertex sits on an edge: the sliver has zero area.
  lk::TriangleMesh m;
  m.points = { lk::Vec3(0, 0, 0), lk::Vec3(2, 0, 0), lk::Vec3(1, 0, 0), lk::Vec3(1, 1, 0),
    lk::Vec3(1, -1, 0) };
  m.triangles = { { 0, 2, 3 }, { 2, 1, 3 }, { 0, 4, 1 }, { 0, 1, 2 } };
  ASSERT_EQ(lk::triangleArea(m, 3), 0.0);
  const lk::RepairReport report = lk::repairToManifold(m);
  EXPECT_EQ(report.removedDegenerateFaces, 1u); // counted though the flip keeps four faces
  // CGAL removes the cap by flipping the edge under it (or collapsing it):
  // no zero-area triangle is left and the surface is unchanged.
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
  {
    EXPECT_GT(lk::triangleArea(m, t), 0.0) << "triangle " << t;
  }
  EXPECT_NEAR(lk::surfaceArea(m), 2.0, 1e-12);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
}

TEST(ManifoldRepair, ProgressRisesAndCanStopTheRepair)
{
  // Every step reports, in order; a stop leaves the mesh as it was.
  const lk::TriangleMesh soup = merged(lktest::icosphere(2, 1.0), translated(lktest::icosphere(1, 1.0), { 5, 0, 0 }));
  lk::TriangleMesh m = soup;
  std::vector<double> seen;
  const lk::RepairReport r = lk::repairToManifold(m, [&](double f) {
    seen.push_back(f);
    return true;
  });
  EXPECT_FALSE(r.stopped);
  ASSERT_EQ(seen.size(), 6u);
  for (std::size_t i = 1; i < seen.size(); ++i)
    EXPECT_GT(seen[i], seen[i - 1]);
  EXPECT_GT(seen.front(), 0.0);
  EXPECT_LT(seen.back(), 1.0);
  EXPECT_EQ(r.components, 2u);

  for (int stopAt = 0; stopAt < 6; ++stopAt)
  {
    lk::TriangleMesh n = soup;
    int calls = 0;
    const lk::RepairReport s = lk::repairToManifold(n, [&](double) { return calls++ < stopAt; });
    EXPECT_TRUE(s.stopped) << stopAt;
    EXPECT_EQ(calls, stopAt + 1);
    EXPECT_EQ(n.triangles, soup.triangles) << stopAt;
    EXPECT_EQ(n.points.size(), soup.points.size()) << stopAt;
  }
}

TEST(ManifoldRepair, BadInputThrows)
{
  lk::TriangleMesh empty;
  EXPECT_THROW(lk::repairToManifold(empty), std::invalid_argument);
  lk::TriangleMesh nan = lktest::cube();
  nan.points[0].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(lk::repairToManifold(nan), std::invalid_argument);
  lk::TriangleMesh allDegenerate;
  allDegenerate.points = { lk::Vec3(0, 0, 0), lk::Vec3(1, 0, 0) };
  allDegenerate.triangles = { { 0, 0, 1 } };
  EXPECT_THROW(lk::repairToManifold(allDegenerate), std::runtime_error);
}
