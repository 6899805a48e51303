// lk::solidUnion: overlapping cubes (exact volumes), inward-facing and
// degenerate input accepted, open or crossing solids refused.
// lk::solidDifference: a slot through a block, a block cut in two, the
// same refusals.
#include "latticekit/SolidBooleans.h"

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

TEST(SolidDifference, ASlotThroughABlockAndABlockCutInTwoHaveTheirExactVolumes)
{
  // A 4 x 2 x 1 block less a 1-wide slot through its height, 2 long,
  // open at neither end: a ring of volume 8 - 2.
  lk::TriangleMesh wide = lktest::cube();
  for (lk::Vec3& p : wide.points)
    p = { 4.0 * p.x(), 2.0 * p.y(), p.z() };
  lk::TriangleMesh slot = lktest::cube();
  for (lk::Vec3& p : slot.points)
    p = { 1.0 + 2.0 * p.x(), 0.5 + p.y(), -0.5 + 2.0 * p.z() };
  lk::TriangleMesh left;
  ASSERT_EQ(lk::solidDifference(wide, { slot }, left), "");
  EXPECT_NEAR(volume(left), 8.0 - 2.0, 1e-12);
  EXPECT_EQ(badEdges(left), 0);
  // A second cutter across the whole width parts the ring in two; a cutter
  // apart from the block takes nothing.
  lk::TriangleMesh across = lktest::cube();
  for (lk::Vec3& p : across.points)
    p = { 3.25 + 0.5 * p.x(), -1.0 + 4.0 * p.y(), -0.5 + 2.0 * p.z() };
  ASSERT_EQ(lk::solidDifference(wide, { slot, across, moved(lktest::cube(), { 10.0, 0.0, 0.0 }) }, left), "");
  EXPECT_NEAR(volume(left), 8.0 - 2.0 - 1.0, 1e-12);
  EXPECT_EQ(badEdges(left), 0);
  // Everything taken: nothing left, and that is no error.
  ASSERT_EQ(lk::solidDifference(lktest::cube(), { moved(lktest::cube(), { -1, -1, -1 }, 3.0) }, left), "");
  EXPECT_TRUE(left.triangles.empty());
}

TEST(SolidDifference, OpenOrBrokenSolidsAndCuttersAreRefusedByName)
{
  lk::TriangleMesh open = lktest::cube();
  open.triangles.pop_back();
  lk::TriangleMesh left;
  EXPECT_NE(lk::solidDifference(open, { lktest::cube() }, left).find("cannot cut the solid: it is not closed"),
    std::string::npos);
  EXPECT_NE(lk::solidDifference(lktest::cube(), { lktest::cube(), open }, left)
              .find("cannot cut with cutter 2 of 2: it is not closed"),
    std::string::npos);
  EXPECT_TRUE(left.triangles.empty());
  lk::TriangleMesh nan = lktest::cube();
  nan.points[0].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(lk::solidDifference(nan, {}, left).find("not finite"), std::string::npos);
  // No cutter: the solid itself, oriented outward.
  ASSERT_EQ(lk::solidDifference(lktest::cube(), {}, left), "");
  EXPECT_NEAR(volume(left), 1.0, 1e-12);
}
