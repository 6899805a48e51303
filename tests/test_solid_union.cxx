// lk::solidUnion: overlapping cubes (exact volumes), inward-facing and
// degenerate input accepted, open or crossing solids refused.
#include "latticekit/SolidUnion.h"

#include "TestMeshes.h"

#include <gtest/gtest.h>

#include <limits>
#include <map>

namespace
{
/// The volume a closed triangle mesh encloses, signed (positive: outward).
double volume(const lk::TriangleMesh& m)
{
  double v = 0.0;
  for (const lk::Triangle& t : m.triangles)
    v += m.points[static_cast<std::size_t>(t[0])].dot(
           m.points[static_cast<std::size_t>(t[1])].cross(m.points[static_cast<std::size_t>(t[2])])) /
      6.0;
  return v;
}

/// Edges used by other than two triangles, or twice the same way.
int badEdges(const lk::TriangleMesh& m)
{
  std::map<std::pair<std::int64_t, std::int64_t>, int> uses;
  for (const lk::Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k)
      ++uses[{ t[k], t[(k + 1) % 3] }];
  int bad = 0;
  for (const auto& [edge, count] : uses)
    if (count != 1 || uses.count({ edge.second, edge.first }) == 0)
      ++bad;
  return bad;
}

lk::TriangleMesh moved(lk::TriangleMesh m, const lk::Vec3& by, double scale = 1.0)
{
  for (lk::Vec3& p : m.points)
    p = p * scale + by;
  return m;
}
} // namespace

TEST(SolidUnion, OverlappingCubesMakeOneClosedSolidOfTheRightVolume)
{
  // Two unit cubes overlapping by half, and a third apart from both.
  const std::vector<lk::TriangleMesh> solids{ lktest::cube(), moved(lktest::cube(), { 0.5, 0.25, 0.0 }),
    moved(lktest::cube(), { 5.0, 0.0, 0.0 }, 2.0) };
  lk::TriangleMesh joined;
  ASSERT_EQ(lk::solidUnion(solids, joined), "");
  EXPECT_NEAR(volume(joined), 1.0 + 1.0 - 0.5 * 0.75 + 8.0, 1e-12);
  EXPECT_EQ(badEdges(joined), 0);
  // A cube inside another adds nothing.
  ASSERT_EQ(lk::solidUnion({ moved(lktest::cube(), { -1, -1, -1 }, 3.0), moved(lktest::cube(), { 0.2, 0.2, 0.2 }, 0.5) },
              joined),
    "");
  EXPECT_NEAR(volume(joined), 27.0, 1e-12);
}

TEST(SolidUnion, InwardFacesAndDegenerateTrianglesAreTakenAsTheyAre)
{
  lk::TriangleMesh inward = moved(lktest::cube(), { 0.5, 0.5, 0.5 });
  for (lk::Triangle& t : inward.triangles)
    std::swap(t[1], t[2]);
  // A triangle of no area on the cube's bottom: the triangle 0-3-1 split
  // at the middle of its edge 0-3, and the needle 0-3-mid closing the gap
  // that leaves beside 0-2-3.
  lk::TriangleMesh slivered = lktest::cube();
  slivered.points.emplace_back(0.5, 0.5, 0.0);
  ASSERT_EQ(slivered.triangles[1], (lk::Triangle{ 0, 3, 1 }));
  slivered.triangles[1] = { 0, 8, 1 };
  slivered.triangles.push_back({ 8, 3, 1 });
  slivered.triangles.push_back({ 0, 3, 8 });
  lk::TriangleMesh joined;
  ASSERT_EQ(lk::solidUnion({ slivered, inward }, joined), "");
  EXPECT_NEAR(volume(joined), 2.0 - 0.125, 1e-12);
  EXPECT_EQ(badEdges(joined), 0);
}

TEST(SolidUnion, OpenOrCrossingSolidsAreRefused)
{
  lk::TriangleMesh joined;
  lk::TriangleMesh open = lktest::cube();
  open.triangles.pop_back();
  EXPECT_NE(lk::solidUnion({ lktest::cube(), open }, joined).find("solid 2 of 2: it is not closed"), std::string::npos);
  EXPECT_TRUE(joined.triangles.empty());
  EXPECT_NE(lk::solidUnion({}, joined).find("no solid"), std::string::npos);
  lk::TriangleMesh outOfRange = lktest::cube();
  outOfRange.triangles[0][0] = 99;
  EXPECT_NE(lk::solidUnion({ outOfRange }, joined).find("out of range"), std::string::npos);
  // Two cubes in one mesh that cross each other.
  lk::TriangleMesh crossing = lktest::cube();
  const lk::TriangleMesh second = moved(lktest::cube(), { 0.5, 0.5, 0.5 });
  for (const lk::Vec3& p : second.points)
    crossing.points.push_back(p);
  for (lk::Triangle t : second.triangles)
  {
    for (auto& v : t)
      v += 8;
    crossing.triangles.push_back(t);
  }
  EXPECT_NE(lk::solidUnion({ crossing }, joined).find("crosses itself"), std::string::npos);
  lk::TriangleMesh nan = lktest::cube();
  nan.points[3].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(lk::solidUnion({ nan }, joined).find("not finite"), std::string::npos);
}
