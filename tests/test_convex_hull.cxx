// lk::ConvexHull: exact depths in a cube and a U-shaped arch (the inner side
// of the arch deep inside, its outer side on the hull), flat and short
// inputs empty, points that are not finite left out.
#include "latticekit/ConvexHull.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
/// The corners and a scatter of inner points of the box [0, a] x [0, b] x [0, c].
std::vector<lk::Vec3> box(double a, double b, double c)
{
  std::vector<lk::Vec3> points;
  for (int i = 0; i < 8; ++i)
    points.emplace_back(i & 1 ? a : 0.0, i & 2 ? b : 0.0, i & 4 ? c : 0.0);
  for (int i = 1; i < 10; ++i)
    points.emplace_back(a * i / 10.0, b * ((i * 7) % 10) / 10.0, c * ((i * 3) % 10) / 10.0);
  return points;
}
} // namespace

TEST(ConvexHull, DepthInABoxIsTheDistanceToItsNearestFace)
{
  const lk::ConvexHull hull(box(10.0, 20.0, 40.0));
  ASSERT_FALSE(hull.empty());
  EXPECT_EQ(hull.numberOfFaces(), 12u); // two triangles a side
  EXPECT_NEAR(hull.depth({ 5.0, 10.0, 20.0 }), 5.0, 1e-12);
  EXPECT_NEAR(hull.depth({ 1.0, 10.0, 20.0 }), 1.0, 1e-12);
  EXPECT_NEAR(hull.depth({ 5.0, 19.5, 20.0 }), 0.5, 1e-12);
  EXPECT_NEAR(hull.depth({ 10.0, 3.0, 7.0 }), 0.0, 1e-12);
  EXPECT_NEAR(hull.depth({ 13.0, 10.0, 20.0 }), -3.0, 1e-12); // 3 beyond the face x = 10
  EXPECT_NEAR(hull.depth({ 13.0, 24.0, 20.0 }), -4.0, 1e-12); // beyond two faces: the farther
}

TEST(ConvexHull, TheInnerSideOfAnArchLiesDeepInsideItsHull)
{
  // A U of three bars 4 wide (two limbs 40 long, joined by a front 48
  // wide), like a mandible seen from above: the outer faces lie on the
  // hull; the inner faces face the gap between the limbs.
  std::vector<lk::Vec3> points;
  for (double z : { 0.0, 10.0 })
    for (double y = 0.0; y <= 40.0; y += 2.0)
      for (double x : { 0.0, 4.0, 44.0, 48.0 })
        points.emplace_back(x, y, z);
  for (double z : { 0.0, 10.0 })
    for (double x = 0.0; x <= 48.0; x += 2.0)
      for (double y : { 0.0, 4.0 })
        points.emplace_back(x, y, z);
  const lk::ConvexHull hull(points);
  ASSERT_FALSE(hull.empty());
  EXPECT_NEAR(hull.depth({ 0.0, 20.0, 5.0 }), 0.0, 1e-9);  // a limb's outer face
  EXPECT_NEAR(hull.depth({ 4.0, 20.0, 5.0 }), 4.0, 1e-9);  // its inner face
  EXPECT_NEAR(hull.depth({ 24.0, 0.0, 5.0 }), 0.0, 1e-9);  // the front's outer face
  EXPECT_NEAR(hull.depth({ 24.0, 4.0, 5.0 }), 4.0, 1e-9);  // its inner face
  EXPECT_NEAR(hull.depth({ 24.0, 30.0, 5.0 }), 5.0, 1e-9); // between the limbs: the top and bottom
}

TEST(ConvexHull, PointsSpanningNoVolumeGiveAnEmptyHull)
{
  EXPECT_TRUE(lk::ConvexHull({}).empty());
  EXPECT_TRUE(lk::ConvexHull({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }).empty());
  EXPECT_TRUE(lk::ConvexHull({ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 3, 0, 0 }, { 4, 0, 0 } }).empty());
  std::vector<lk::Vec3> flat;
  for (int i = 0; i < 50; ++i)
    flat.emplace_back(std::cos(i * 0.3) * 7.0, std::sin(i * 0.7) * 3.0, 2.0);
  const lk::ConvexHull hull(flat);
  EXPECT_TRUE(hull.empty());
  EXPECT_TRUE(std::isnan(hull.depth({ 0, 0, 2 })));
}

TEST(ConvexHull, PointsThatAreNotFiniteAreLeftOut)
{
  std::vector<lk::Vec3> points = box(2.0, 2.0, 2.0);
  points.emplace_back(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  points.emplace_back(std::numeric_limits<double>::infinity(), 1.0, 1.0);
  const lk::ConvexHull hull(points);
  ASSERT_FALSE(hull.empty());
  EXPECT_NEAR(hull.depth({ 1.0, 1.0, 1.0 }), 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(hull.depth({ std::numeric_limits<double>::quiet_NaN(), 1.0, 1.0 })));
}
