#include "TestMeshes.h"
#include "latticekit/MeshCut.h"
#include "latticekit/StrokeFeatureLine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace
{
const std::vector<lk::Vec3> kStroke = { { 0.12, 0.2, 0.0 }, { 0.5, 0.45, 0.0 }, { 0.9, 0.62, 0.0 } };
} // namespace

TEST(StrokeFeatureLine, NearestEdgesGiveAConnectedSimpleEdgePath)
{
  const lk::TriangleMesh grid = lktest::grid(20, 1.0, 0.0);
  const auto r = lk::strokeToFeatureLine(grid, kStroke, {});
  const auto edges = lktest::edgesOf(grid);
  ASSERT_GT(r.line.size(), 10u);
  EXPECT_FALSE(r.closed);
  std::set<std::int64_t> seen;
  for (std::size_t i = 0; i < r.line.size(); ++i)
  {
    EXPECT_TRUE(seen.insert(r.line[i]).second) << "vertex visited twice";
    if (i + 1 < r.line.size())
      EXPECT_TRUE(edges.count(lk::edgeKey(r.line[i], r.line[i + 1])));
  }
  // Ends at the grid vertices nearest the stroke's ends.
  EXPECT_LT((grid.points[static_cast<std::size_t>(r.line.front())] - kStroke.front()).norm(), 0.05);
  EXPECT_LT((grid.points[static_cast<std::size_t>(r.line.back())] - kStroke.back()).norm(), 0.05);
  EXPECT_EQ(r.featureEdges.size(), r.line.size() - 1);
}

TEST(StrokeFeatureLine, SnapMovesOnlyPathVerticesOntoTheStrokeWithoutFlatteningTriangles)
{
  const lk::TriangleMesh grid = lktest::grid(20, 1.0, 0.0);
  lk::StrokeOptions o;
  o.mode = lk::StrokeMode::Snap;
  const auto r = lk::strokeToFeatureLine(grid, kStroke, o);
  EXPECT_EQ(r.mesh.triangles, grid.triangles); // connectivity unchanged
  const std::set<std::int64_t> path(r.line.begin(), r.line.end());
  EXPECT_EQ(r.movedVertices.size(), path.size());
  ASSERT_EQ(r.snapGaps.size(), r.movedVertices.size());
  auto toStroke = [](const lk::Vec3& p) {
    double d = 1e9;
    for (std::size_t i = 0; i + 1 < kStroke.size(); ++i)
    {
      const lk::Vec3 s = kStroke[i + 1] - kStroke[i];
      const double t = std::clamp((p - kStroke[i]).dot(s) / s.squaredNorm(), 0.0, 1.0);
      d = std::min(d, (kStroke[i] + t * s - p).norm());
    }
    return d;
  };
  std::size_t onStroke = 0;
  for (std::size_t i = 0; i < r.movedVertices.size(); ++i)
  {
    const lk::Vec3 p = r.mesh.points[static_cast<std::size_t>(r.movedVertices[i])];
    // On the stroke polyline (the plane is the surface, so the projected
    // stroke is the stroke), or as far from it as the gap reported.
    EXPECT_NEAR(toStroke(p), r.snapGaps[i], 1e-12);
    EXPECT_LT(r.snapGaps[i], 0.05 * 0.05); // a twentieth of an edge at most
    onStroke += r.snapGaps[i] == 0.0 ? 1 : 0;
  }
  EXPECT_GT(2 * onStroke, path.size());
  for (std::size_t v = 0; v < grid.points.size(); ++v)
    if (!path.count(static_cast<std::int64_t>(v)))
      EXPECT_EQ(r.mesh.points[v], grid.points[v]);
  // The stroke is straight within each segment and the path zigzags across
  // it, so some triangles have all three corners on the path: snapped fully
  // they would lie flat on the stroke (the earlier snap left 0 area there).
  // Every triangle keeps its side up and at least 1 % of its area.
  int thin = 0;
  for (const auto& t : grid.triangles)
  {
    auto normal = [&](const std::vector<lk::Vec3>& p) {
      return lk::Vec3((p[static_cast<std::size_t>(t[1])] - p[static_cast<std::size_t>(t[0])])
                        .cross(p[static_cast<std::size_t>(t[2])] - p[static_cast<std::size_t>(t[0])]));
    };
    const double before = normal(grid.points).z(), after = normal(r.mesh.points).z();
    EXPECT_GE(after, 0.01 * before * (1 - 1e-9));
    thin += after < 0.02 * before ? 1 : 0;
  }
  EXPECT_GT(thin, 0); // the case arises here
}

TEST(StrokeFeatureLine, PaintReturnsExactlyTheEdgesOfTheCoveredFaces)
{
  const lk::TriangleMesh grid = lktest::grid(20, 1.0, 0.0);
  lk::StrokeOptions o;
  o.mode = lk::StrokeMode::Paint;
  o.brushRadius = 0.06;
  o.spacing = 0.01;
  const auto r = lk::strokeToFeatureLine(grid, kStroke, o);
  std::set<lk::EdgeKey> expected;
  for (auto f : r.paintedFaces)
    for (int i = 0; i < 3; ++i)
      expected.insert(lk::edgeKey(grid.triangles[static_cast<std::size_t>(f)][static_cast<std::size_t>(i)],
        grid.triangles[static_cast<std::size_t>(f)][static_cast<std::size_t>((i + 1) % 3)]));
  EXPECT_EQ(std::set<lk::EdgeKey>(r.featureEdges.begin(), r.featureEdges.end()), expected);
  // Every face whose centroid is within the radius minus a margin of the
  // stroke is painted, and none farther than the radius plus a face.
  for (std::size_t f = 0; f < grid.triangles.size(); ++f)
  {
    const auto& t = grid.triangles[f];
    const lk::Vec3 c = (grid.points[static_cast<std::size_t>(t[0])] + grid.points[static_cast<std::size_t>(t[1])] +
                         grid.points[static_cast<std::size_t>(t[2])]) /
      3.0;
    double d = 1e9;
    for (std::size_t i = 0; i + 1 < kStroke.size(); ++i)
    {
      const lk::Vec3 s = kStroke[i + 1] - kStroke[i];
      const double u = std::clamp((c - kStroke[i]).dot(s) / s.squaredNorm(), 0.0, 1.0);
      d = std::min(d, (kStroke[i] + u * s - c).norm());
    }
    const bool painted = std::count(r.paintedFaces.begin(), r.paintedFaces.end(), static_cast<std::int64_t>(f)) > 0;
    if (d < 0.06 - 0.02)
      EXPECT_TRUE(painted) << f;
    if (d > 0.06 + 0.06)
      EXPECT_FALSE(painted) << f;
  }
}

TEST(StrokeFeatureLine, ClosedStrokeCutsTheSphere)
{
  const lk::TriangleMesh sphere = lktest::icosphere(3, 1.0);
  std::vector<lk::Vec3> stroke;
  for (int k = 0; k <= 40; ++k)
  {
    const double a = 2.0 * 3.14159265358979 * k / 40.0;
    stroke.emplace_back(0.95 * std::cos(a), 0.95 * std::sin(a), 0.2);
  }
  const auto r = lk::strokeToFeatureLine(sphere, stroke, {});
  ASSERT_TRUE(r.closed);
  EXPECT_EQ(r.line.front(), r.line.back());
  const auto edges = lktest::edgesOf(sphere);
  std::set<std::int64_t> seen;
  for (std::size_t i = 0; i + 1 < r.line.size(); ++i)
  {
    EXPECT_TRUE(edges.count(lk::edgeKey(r.line[i], r.line[i + 1])));
    EXPECT_TRUE(seen.insert(r.line[i]).second);
  }
  EXPECT_GT(r.line.size(), 30u);
  EXPECT_EQ(lk::cutAlongLoops(lk::asPolygonMesh(sphere), { r.line }, false).pieces.size(), 2u);
}

TEST(StrokeFeatureLine, AStrokeThatJumpsAGapBetweenItsPointsIsSaidToDoSo)
{
  // Both points lie on a sphere of radius 10, on opposite sides: the line
  // between them runs through its middle, as a fast drag that slips over a
  // bone's edge to its far side. The message names where, and why.
  const lk::TriangleMesh sphere = lktest::icosphere(3, 10.0);
  try
  {
    lk::strokeToFeatureLine(sphere, { sphere.points[0], -sphere.points[0] }, {});
    FAIL() << "a stroke through the sphere's middle was accepted";
  }
  catch (const std::invalid_argument& e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find("misses the surface between its points 1 and 2 (20.0"), std::string::npos) << what;
    EXPECT_NE(what.find("draw there more slowly, or in two strokes"), std::string::npos) << what;
  }
}

TEST(StrokeFeatureLine, BadStrokesAreRefused)
{
  const lk::TriangleMesh grid = lktest::grid(10, 1.0, 0.0);
  EXPECT_THROW(lk::strokeToFeatureLine(grid, { { 0.5, 0.5, 0 } }, {}), std::invalid_argument);
  EXPECT_THROW(lk::strokeToFeatureLine(grid, { { 0.5, 0.5, 0 }, { std::nan(""), 0, 0 } }, {}), std::invalid_argument);
  // A point beyond 1e15 (the meshes' limit) is named, not measured: its
  // distance to the surface overflowed ("a stroke point lies inf from it").
  for (const auto mode : { lk::StrokeMode::NearestEdges, lk::StrokeMode::Split })
  {
    lk::StrokeOptions o;
    o.mode = mode;
    try
    {
      lk::strokeToFeatureLine(grid, { { 0.5, 0.5, 0 }, { 0.6, 0.5, 0 }, { 1e308, 0.5, 0 } }, o);
      FAIL() << "a stroke point at 1e308 was accepted";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_EQ(std::string(e.what()), "stroke point 3 has a coordinate beyond 1e15 (a corrupt file or an overflow)");
    }
  }
  try
  {
    lk::strokeToFeatureLine(grid, { { 0.5, 0.5, 5 }, { 0.6, 0.5, 5 } }, {});
    FAIL() << "a stroke far from the surface was accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("misses the surface"), std::string::npos);
  }
  // A click or a tiny stroke maps onto one mesh point. Its ends meet, so it
  // counts as closed: a loop of fewer than three vertices is refused (it was
  // a one-point line before, which VTK cannot hold as a line cell); with a
  // closing tolerance below its length it is open, and covers no edge.
  auto refusal = [&](lk::StrokeMode mode, double closeTolerance) -> std::string {
    lk::StrokeOptions o;
    o.mode = mode;
    o.closeTolerance = closeTolerance;
    try
    {
      lk::strokeToFeatureLine(grid, { { 0.51, 0.5, 0 }, { 0.52, 0.5, 0 } }, o);
    }
    catch (const std::invalid_argument& e)
    {
      return e.what();
    }
    return "";
  };
  for (const auto mode : { lk::StrokeMode::NearestEdges, lk::StrokeMode::Snap, lk::StrokeMode::Split })
  {
    // With the reason and what to do, in every mode (split mode said only
    // "a closed line needs at least three vertices").
    EXPECT_NE(refusal(mode, 0.0).find("a closed line needs at least three vertices: the stroke's loop covers 1 "),
      std::string::npos)
      << refusal(mode, 0.0);
    EXPECT_NE(refusal(mode, 0.0).find("counts as closed: draw a larger loop"), std::string::npos);
  }
  for (const auto mode : { lk::StrokeMode::NearestEdges, lk::StrokeMode::Snap })
  {
    EXPECT_NE(refusal(mode, 1e-6).find("covers no mesh edge: all its points are nearest mesh point"), std::string::npos);
  }
  // A short straight split stroke counts as closed (its ends lie within the
  // closing tolerance), and its line goes out and back along the same edges:
  // three vertices, but a loop around nothing, which a cut refused as "not
  // closed", failing every other line's cut with it (a random planner
  // session on the mandible). It is refused with the reason.
  {
    lk::StrokeOptions o;
    o.mode = lk::StrokeMode::Split;
    try
    {
      const auto r = lk::strokeToFeatureLine(grid, { { 0.43, 0.52, 0 }, { 0.47, 0.52, 0 }, { 0.51, 0.52, 0 }, { 0.45, 0.52, 0 } }, o);
      ADD_FAILURE() << "a line back along itself was accepted, " << r.line.size() << " vertices";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find("the closed line runs back along itself"), std::string::npos) << e.what();
    }
  }
  // A small circle around one vertex covers that vertex alone.
  std::vector<lk::Vec3> circle;
  for (int i = 0; i <= 12; ++i)
    circle.push_back({ 0.5 + 0.02 * std::cos(i * M_PI / 6), 0.5 + 0.02 * std::sin(i * M_PI / 6), 0 });
  EXPECT_THROW(lk::strokeToFeatureLine(grid, circle, {}), std::invalid_argument);
}

#include "latticekit/ManifoldRepair.h"

TEST(StrokeFeatureLine, SplitAddsEdgesThatLieOnTheStroke)
{
  const lk::TriangleMesh grid = lktest::grid(20, 1.0, 0.0);
  const std::vector<lk::Vec3> straight = { { 0.113, 0.207, 0.0 }, { 0.871, 0.633, 0.0 } };
  lk::StrokeOptions o;
  o.mode = lk::StrokeMode::Split;
  const auto r = lk::strokeToFeatureLine(grid, straight, o);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(r.mesh), "");
  EXPECT_NEAR(lk::surfaceArea(r.mesh), 1.0, 1e-12);
  EXPECT_GT(r.mesh.points.size(), grid.points.size() + 20);
  const auto edges = lktest::edgesOf(r.mesh);
  const lk::Vec3 d = (straight[1] - straight[0]).normalized();
  ASSERT_GT(r.line.size(), 20u);
  for (std::size_t i = 0; i < r.line.size(); ++i)
  {
    const lk::Vec3 p = r.mesh.points[static_cast<std::size_t>(r.line[i])];
    const lk::Vec3 q = p - straight[0];
    EXPECT_LT((q - q.dot(d) * d).norm(), 1e-12) << "vertex " << i << " is off the stroke";
    if (i + 1 < r.line.size())
      EXPECT_TRUE(edges.count(lk::edgeKey(r.line[i], r.line[i + 1])));
  }
  EXPECT_EQ(r.mesh.points[static_cast<std::size_t>(r.line.front())], straight.front());
  EXPECT_EQ(r.mesh.points[static_cast<std::size_t>(r.line.back())], straight.back());
}

TEST(StrokeFeatureLine, ClosedSplitStrokeCutsTheSphere)
{
  const lk::TriangleMesh sphere = lktest::icosphere(3, 1.0);
  std::vector<lk::Vec3> stroke;
  for (int k = 0; k <= 40; ++k)
  {
    const double a = 2.0 * 3.14159265358979 * k / 40.0;
    stroke.emplace_back(0.95 * std::cos(a), 0.95 * std::sin(a), 0.2);
  }
  lk::StrokeOptions o;
  o.mode = lk::StrokeMode::Split;
  const auto r = lk::strokeToFeatureLine(sphere, stroke, o);
  ASSERT_TRUE(r.closed);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(r.mesh), "");
  EXPECT_EQ(lk::countBoundaryEdges(r.mesh), 0u);
  EXPECT_NEAR(lk::signedVolume(r.mesh), lk::signedVolume(sphere), 1e-12);
  EXPECT_EQ(lk::cutAlongLoops(lk::asPolygonMesh(r.mesh), { r.line }, false).pieces.size(), 2u);
}

TEST(StrokeFeatureLine, EarlierLinesAreCarriedThroughTheEdgesASplitCuts)
{
  // A closed split line around the sphere, then an open split stroke across
  // it: the second stroke cuts the edges of the first line where it crosses.
  const lk::TriangleMesh sphere = lktest::icosphere(3, 1.0);
  std::vector<lk::Vec3> ring, across;
  for (int k = 0; k <= 40; ++k)
  {
    const double a = 2.0 * 3.14159265358979 * k / 40.0;
    ring.emplace_back(0.95 * std::cos(a), 0.95 * std::sin(a), 0.2);
  }
  for (int k = 0; k <= 10; ++k)
  {
    const double z = 0.6 - 0.09 * k; // 0.6 down to -0.3, across z = 0.2
    const double r = std::sqrt(1.0 - z * z);
    across.emplace_back(r * std::cos(0.3), r * std::sin(0.3), z);
  }
  lk::StrokeOptions o;
  o.mode = lk::StrokeMode::Split;
  const auto first = lk::strokeToFeatureLine(sphere, ring, o);
  ASSERT_TRUE(first.closed);
  const auto second = lk::strokeToFeatureLine(first.mesh, across, o);
  ASSERT_FALSE(second.closed);
  const auto edges = lktest::edgesOf(second.mesh);
  auto cutEdges = [&](const std::vector<std::int64_t>& line) {
    int missing = 0;
    for (std::size_t i = 0; i + 1 < line.size(); ++i)
      missing += edges.count(lk::edgeKey(line[i], line[i + 1])) ? 0 : 1;
    return missing;
  };
  ASSERT_GE(cutEdges(first.line), 1); // the crossing cut an edge of the ring
  const auto carried = lk::carryLines(second.mesh, first.mesh.points.size(), { first.line, { 0, 1 } });
  ASSERT_EQ(carried.size(), 2u);
  const auto& ring2 = carried[0];
  EXPECT_EQ(cutEdges(ring2), 0);
  EXPECT_EQ(ring2.size(), first.line.size() + static_cast<std::size_t>(cutEdges(first.line)));
  // The old vertices in their order, the new ones on the old segments.
  std::size_t k = 0;
  for (std::size_t i = 0; i < ring2.size(); ++i)
  {
    if (k < first.line.size() && ring2[i] == first.line[k])
    {
      ++k;
      continue;
    }
    ASSERT_GE(ring2[i], static_cast<std::int64_t>(first.mesh.points.size()));
    ASSERT_GT(k, 0u);
    const lk::Vec3 a = first.mesh.points[static_cast<std::size_t>(first.line[k - 1])];
    const lk::Vec3 b = first.mesh.points[static_cast<std::size_t>(first.line[k])];
    const lk::Vec3 p = second.mesh.points[static_cast<std::size_t>(ring2[i])];
    EXPECT_LT((p - a).cross(b - a).norm() / (b - a).squaredNorm(), 1e-9);
  }
  EXPECT_EQ(k, first.line.size());
  EXPECT_EQ(carried[1], (std::vector<std::int64_t>{ 0, 1 })); // not cut: as it was
  // The carried ring still cuts the sphere in two; the stale one is refused.
  EXPECT_EQ(lk::cutAlongLoops(lk::asPolygonMesh(second.mesh), { ring2 }, false).pieces.size(), 2u);
  EXPECT_THROW(lk::cutAlongLoops(lk::asPolygonMesh(second.mesh), { first.line }, false), std::invalid_argument);
  // Modes that keep the edges leave lines as they are.
  o.mode = lk::StrokeMode::NearestEdges;
  const auto nearest = lk::strokeToFeatureLine(first.mesh, across, o);
  EXPECT_EQ(lk::carryLines(nearest.mesh, first.mesh.points.size(), { first.line })[0], first.line);
}

TEST(StrokeFeatureLine, SpursAreLeftOutOfAClosedLine)
{
  using Line = std::vector<std::int64_t>;
  EXPECT_EQ(lk::withoutSpurs({ 1, 2, 3, 4, 1 }), (Line{ 1, 2, 3, 4, 1 }));
  // Out and back inside the loop, one edge and two.
  EXPECT_EQ(lk::withoutSpurs({ 1, 2, 9, 2, 3, 4, 1 }), (Line{ 1, 2, 3, 4, 1 }));
  EXPECT_EQ(lk::withoutSpurs({ 1, 2, 9, 8, 9, 2, 3, 4, 1 }), (Line{ 1, 2, 3, 4, 1 }));
  // Across the first vertex: the tip first, and last.
  EXPECT_EQ(lk::withoutSpurs({ 9, 1, 2, 3, 1, 9 }), (Line{ 1, 2, 3, 1 }));
  EXPECT_EQ(lk::withoutSpurs({ 1, 2, 3, 4, 9, 4, 1 }), (Line{ 1, 2, 3, 4, 1 }));
  EXPECT_EQ(lk::withoutSpurs({ 2, 9, 2, 3, 4, 2 }), (Line{ 2, 3, 4, 2 }));
  // A loop round nothing has no loop left.
  EXPECT_LT(lk::withoutSpurs({ 1, 2, 3, 2, 1 }).size(), 4u);
}

TEST(StrokeFeatureLine, AClosedSplitStrokeWhoseJoinRunsBackOverItsStartCutsTheSphere)
{
  // A line drawn in parts: the last part starts near the first part's start
  // (within the closing tolerance, not on it) on the far side, so that the
  // line runs out past its start and back over its first edges. Refused as
  // running back along itself before (the planner's line all round the chin
  // in three drags, on the mandible's default surface); now the spur is left
  // out and the loop cuts the sphere in two.
  const lk::TriangleMesh sphere = lktest::icosphere(3, 1.0);
  std::vector<lk::Vec3> stroke;
  const auto at = [](double a) { return lk::Vec3(0.95 * std::cos(a), 0.95 * std::sin(a), 0.2); };
  for (int k = 0; k <= 40; ++k)
    stroke.push_back(at(2.0 * M_PI * k / 40.0));
  // Past the start by a tenth of the circle, then back to it.
  for (int k = 1; k <= 4; ++k)
    stroke.push_back(at(2.0 * M_PI * k / 40.0));
  for (int k = 3; k >= 0; --k)
    stroke.push_back(at(2.0 * M_PI * k / 40.0));
  lk::StrokeOptions o;
  o.mode = lk::StrokeMode::Split;
  const auto r = lk::strokeToFeatureLine(sphere, stroke, o);
  ASSERT_TRUE(r.closed);
  ASSERT_EQ(r.line.front(), r.line.back());
  std::set<std::int64_t> seen;
  for (std::size_t i = 0; i + 1 < r.line.size(); ++i)
    EXPECT_TRUE(seen.insert(r.line[i]).second) << "vertex " << r.line[i] << " twice";
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(r.mesh), "");
  EXPECT_EQ(lk::cutAlongLoops(lk::asPolygonMesh(r.mesh), { r.line }, false).pieces.size(), 2u);
}

TEST(StrokeFeatureLine, SmallLoopsAreLeftOutOfAClosedLineAndLargeOnesKept)
{
  using Line = std::vector<std::int64_t>;
  // A 10 x 10 square (0-3) with a small loop at corner 1 (4, 5: 0.5 round at
  // most) and, for the second case, a large one at corner 2 (6, 7: a 10 x 10
  // square beside it).
  const std::vector<lk::Vec3> p = { { 0, 0, 0 }, { 10, 0, 0 }, { 10, 10, 0 }, { 0, 10, 0 }, { 10.1, -0.1, 0 },
    { 10.2, 0, 0 }, { 20, 10, 0 }, { 20, 20, 0 } };
  EXPECT_EQ(lk::withoutSmallLoops({ 0, 1, 4, 5, 1, 2, 3, 0 }, p, 1.0), (Line{ 0, 1, 2, 3, 0 }));
  // Too large to be left out at this length: kept as drawn.
  EXPECT_EQ(lk::withoutSmallLoops({ 0, 1, 4, 5, 1, 2, 3, 0 }, p, 0.1), (Line{ 0, 1, 4, 5, 1, 2, 3, 0 }));
  // Two large loops touching at corner 2 stay; the small one goes.
  EXPECT_EQ(lk::withoutSmallLoops({ 0, 1, 4, 5, 1, 2, 6, 7, 2, 3, 0 }, p, 1.0), (Line{ 0, 1, 2, 6, 7, 2, 3, 0 }));
  // Across the first vertex: the small loop is the part that holds the start.
  EXPECT_EQ(lk::withoutSmallLoops({ 4, 5, 1, 2, 3, 0, 1, 4 }, p, 1.0), (Line{ 1, 2, 3, 0, 1 }));
  EXPECT_EQ(lk::withoutSmallLoops({ 0, 1, 2, 3, 0 }, p, 1.0), (Line{ 0, 1, 2, 3, 0 }));
}
