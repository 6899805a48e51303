#include "TestMeshes.h"
#include "latticekit/EdgePath.h"
#include "latticekit/ManifoldRepair.h"
#include "latticekit/MeshCut.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

namespace
{
lk::TriangleMesh asTriangles(const lk::PolygonMesh& p)
{
  lk::TriangleMesh m;
  m.points = p.points;
  for (const auto& f : p.faces)
    for (std::size_t i = 1; i + 1 < f.size(); ++i)
      m.triangles.push_back({ f[0], f[i], f[i + 1] });
  return m;
}

std::vector<std::int64_t> circleLoop(const lk::TriangleMesh& m, double z, double r)
{
  std::vector<lk::Vec3> stroke;
  for (int k = 0; k <= 24; ++k)
  {
    const double a = 2.0 * 3.14159265358979 * (k % 24) / 24.0;
    stroke.emplace_back(r * std::cos(a), r * std::sin(a), z);
  }
  return lk::edgePathThrough(m, stroke);
}
} // namespace

TEST(MeshCut, LoopSplitsTheSphereIntoTwoPiecesWithCoincidingBorders)
{
  const lk::TriangleMesh sphere = lktest::icosphere(3, 1.0);
  const auto loop = circleLoop(sphere, 0.3, std::sqrt(1 - 0.09));
  const auto cut = lk::cutAlongLoops(lk::asPolygonMesh(sphere), { loop }, false);
  ASSERT_EQ(cut.pieces.size(), 2u);
  double area = 0.0;
  std::size_t border = 0;
  for (const auto& p : cut.pieces)
  {
    const lk::TriangleMesh t = asTriangles(p);
    EXPECT_EQ(lk::cgalSurfaceMeshProblem(t), "");
    area += lk::surfaceArea(t);
    border += lk::countBoundaryEdges(t);
  }
  EXPECT_NEAR(area, lk::surfaceArea(sphere), 1e-9 * lk::surfaceArea(sphere));
  EXPECT_EQ(border, 2 * (loop.size() - 1));
  // The loop's vertices appear in both pieces at the same positions.
  for (std::size_t i = 0; i + 1 < loop.size(); ++i)
  {
    int found = 0;
    for (std::size_t p = 0; p < 2; ++p)
      for (std::size_t v = 0; v < cut.vertexOrigin[p].size(); ++v)
        if (cut.vertexOrigin[p][v] == loop[i])
        {
          EXPECT_EQ(cut.pieces[p].points[v], sphere.points[static_cast<std::size_t>(loop[i])]);
          ++found;
        }
    EXPECT_EQ(found, 2);
  }
}

TEST(MeshCut, CappedPiecesAreClosedAndTheirVolumesSumToTheWhole)
{
  const lk::TriangleMesh sphere = lktest::icosphere(3, 1.0);
  const auto loop = circleLoop(sphere, 0.3, std::sqrt(1 - 0.09));
  const auto cut = lk::cutAlongLoops(lk::asPolygonMesh(sphere), { loop }, true);
  ASSERT_EQ(cut.pieces.size(), 2u);
  double volume = 0.0;
  for (const auto& p : cut.pieces)
  {
    const lk::TriangleMesh t = asTriangles(p);
    EXPECT_EQ(lk::cgalSurfaceMeshProblem(t), "");
    EXPECT_EQ(lk::countBoundaryEdges(t), 0u);
    EXPECT_GT(lk::signedVolume(t), 0.0);
    volume += lk::signedVolume(t);
  }
  std::printf("capped volumes sum to %.9f of the sphere's %.9f\n", volume, lk::signedVolume(sphere));
  EXPECT_NEAR(volume, lk::signedVolume(sphere), 1e-9);
  EXPECT_EQ(cut.capCrossings, std::vector<std::size_t>(cut.pieces.size(), 0u));
}

TEST(MeshCut, AWavyLoopGetsACapThatFollowsItWithoutCrossings)
{
  // A loop that leaves its fitting plane by more than 5 % of its size (a
  // wave of height 0.25 on the unit sphere) is closed by a minimal-weight
  // triangulation; a planar one by a flat cap (above). The faired cap used
  // before crossed the sphere or itself at 134 and 149 pairs of triangles.
  const lk::TriangleMesh sphere = lktest::icosphere(4, 1.0);
  std::vector<lk::Vec3> stroke;
  for (int k = 0; k <= 48; ++k)
  {
    const double a = 2.0 * 3.14159265358979 * (k % 48) / 48.0, z = 0.25 * std::cos(2.0 * a);
    const double r = std::sqrt(1.0 - z * z);
    stroke.emplace_back(r * std::cos(a), r * std::sin(a), z);
  }
  const auto loop = lk::edgePathThrough(sphere, stroke);
  const auto cut = lk::cutAlongLoops(lk::asPolygonMesh(sphere), { loop }, true);
  ASSERT_EQ(cut.pieces.size(), 2u);
  double volume = 0.0, capLift = 0.0;
  for (std::size_t p = 0; p < 2; ++p)
  {
    const lk::TriangleMesh t = asTriangles(cut.pieces[p]);
    EXPECT_EQ(lk::cgalSurfaceMeshProblem(t), "");
    EXPECT_EQ(lk::countBoundaryEdges(t), 0u);
    volume += lk::signedVolume(t);
    for (std::size_t v = 0; v < t.points.size(); ++v)
      if (cut.vertexOrigin[p][v] < 0)
        capLift = std::max(capLift, std::abs(t.points[v].z()));
  }
  EXPECT_NEAR(volume, lk::signedVolume(sphere), 1e-9);
  EXPECT_EQ(cut.capCrossings, std::vector<std::size_t>({ 0u, 0u }));
  // The cap follows the wave (a flat one would stay near z = 0).
  EXPECT_GT(capLift, 0.05);
}

TEST(MeshCut, TwoLoopsCutOutASegment)
{
  const lk::TriangleMesh sphere = lktest::icosphere(3, 1.0);
  const auto a = circleLoop(sphere, 0.3, std::sqrt(1 - 0.09));
  const auto b = circleLoop(sphere, -0.4, std::sqrt(1 - 0.16));
  const auto cut = lk::cutAlongLoops(lk::asPolygonMesh(sphere), { a, b }, true);
  EXPECT_EQ(cut.pieces.size(), 3u);
  for (const auto& p : cut.pieces)
    EXPECT_EQ(lk::countBoundaryEdges(asTriangles(p)), 0u);
}

TEST(MeshCut, BadLoopsAreRefused)
{
  const lk::TriangleMesh sphere = lktest::icosphere(2, 1.0);
  auto message = [&](const std::vector<std::vector<std::int64_t>>& loops) -> std::string {
    try
    {
      lk::cutAlongLoops(lk::asPolygonMesh(sphere), loops, false);
    }
    catch (const std::invalid_argument& e)
    {
      return e.what();
    }
    return "";
  };
  const auto t = sphere.triangles[0];
  // One triangle's boundary is a closed loop that separates that triangle.
  EXPECT_EQ(message({ { t[0], t[1], t[2] } }), "");
  EXPECT_NE(message({ { t[0], t[1] } }).find("fewer than 3"), std::string::npos);
  EXPECT_NE(message({}).find("no loop"), std::string::npos);
  // Not joined by edges: an open line.
  EXPECT_NE(message({ { 0, 1, 2, 3, 4 } }).find("not closed along mesh edges"), std::string::npos);
  // The same vertex twice: a self-crossing loop.
  EXPECT_NE(message({ { t[0], t[1], t[2], t[0], t[1], t[2] } }).find("crosses itself"), std::string::npos);
}

namespace
{
/// Both halves of a torus cut in the plane z = 0 are closed, consistently
/// oriented, and their cap faces lie in the plane between the equators (radii
/// 2 and 4), at least one per segment of an equator of n.
void expectHalvesClosedByAnAnnulus(const lk::CutResult& cut, int n, double flatness)
{
  ASSERT_EQ(cut.pieces.size(), 2u);
  for (std::size_t p = 0; p < 2; ++p)
  {
    const lk::PolygonMesh& piece = cut.pieces[p];
    // Closed and consistently oriented: every directed edge once, and its twin.
    std::map<std::pair<std::int64_t, std::int64_t>, int> edges;
    std::size_t capFaces = 0;
    for (std::size_t f = 0; f < piece.faces.size(); ++f)
    {
      const auto& face = piece.faces[f];
      for (std::size_t i = 0; i < face.size(); ++i)
        ++edges[{ face[i], face[(i + 1) % face.size()] }];
      if (cut.faceOrigin[p][f] >= 0)
        continue;
      ++capFaces;
      for (auto v : face)
      {
        const lk::Vec3& q = piece.points[static_cast<std::size_t>(v)];
        EXPECT_NEAR(q.z(), 0.0, flatness);
        EXPECT_GT(std::hypot(q.x(), q.y()), 2.0 - 1e-9);
        EXPECT_LT(std::hypot(q.x(), q.y()), 4.0 + 1e-9);
      }
    }
    EXPECT_GE(capFaces, 2u * static_cast<std::size_t>(n));
    for (const auto& [edge, count] : edges)
    {
      EXPECT_EQ(count, 1);
      EXPECT_EQ(edges.count({ edge.second, edge.first }), 1u) << "piece " << p << " is open";
    }
  }
}
} // namespace

TEST(MeshCut, ALoopAroundAHandleIsRefusedAndTheMessageSaysWhy)
{
  // A torus (16 x 8 quads, split): one loop around the tube leaves it in one
  // piece, as a loop around a bone does when a canal joins its two sides;
  // two such loops cut it in two.
  const int n = 16, m = 8;
  lk::TriangleMesh torus;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j)
    {
      const double u = 2.0 * 3.14159265358979 * i / n, v = 2.0 * 3.14159265358979 * j / m;
      // sin(pi) is 1.2e-16, not 0: the inner equator is put in the plane z = 0
      // exactly, as the outer one is.
      torus.points.emplace_back(
        (3.0 + std::cos(v)) * std::cos(u), (3.0 + std::cos(v)) * std::sin(u), 2 * j == m ? 0.0 : std::sin(v));
    }
  auto id = [&](int i, int j) { return static_cast<std::int64_t>((i % n) * m + (j % m)); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j)
    {
      torus.triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      torus.triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  auto tube = [&](int i) {
    std::vector<std::int64_t> loop;
    for (int j = 0; j < m; ++j)
      loop.push_back(id(i, j));
    return loop;
  };
  std::string message;
  try
  {
    lk::cutAlongLoops(lk::asPolygonMesh(torus), { tube(0) }, false);
  }
  catch (const std::invalid_argument& e)
  {
    message = e.what();
  }
  EXPECT_NE(message.find("do not separate"), std::string::npos) << message;
  EXPECT_NE(message.find("has 1 handle"), std::string::npos) << message;
  EXPECT_EQ(lk::cutAlongLoops(lk::asPolygonMesh(torus), { tube(0), tube(8) }, false).pieces.size(), 2u);
  // Beside a second torus that two loops cut in two, the first torus's one
  // loop stays a slit: its two sides are in one piece, and the result names
  // it (the pieces are the slit torus and the two halves).
  lk::TriangleMesh two = torus;
  const auto offset = static_cast<std::int64_t>(torus.points.size());
  for (const auto& p : torus.points)
    two.points.push_back(p + lk::Vec3(20.0, 0.0, 0.0));
  for (const auto& t : torus.triangles)
    two.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  auto shifted = [&](std::vector<std::int64_t> loop) {
    for (auto& v : loop)
      v += offset;
    return loop;
  };
  const auto slit = lk::cutAlongLoops(lk::asPolygonMesh(two), { tube(0), shifted(tube(0)), shifted(tube(8)) }, true);
  EXPECT_EQ(slit.pieces.size(), 3u);
  EXPECT_EQ(slit.loopsInOnePiece, std::vector<std::size_t>({ 0u }));
  EXPECT_TRUE(lk::cutAlongLoops(lk::asPolygonMesh(torus), { tube(0), tube(8) }, true).loopsInOnePiece.empty());

  // Open, as a CT surface is where the scan ends: two triangles away from
  // the loop taken out (one border loop). The handle is still named: the
  // genus counts the border loops (it was silent on every open surface).
  lk::TriangleMesh open = torus;
  open.triangles.erase(open.triangles.begin() + 2 * (8 * m + 2), open.triangles.begin() + 2 * (8 * m + 2) + 2);
  message.clear();
  try
  {
    lk::cutAlongLoops(lk::asPolygonMesh(open), { tube(0) }, false);
  }
  catch (const std::invalid_argument& e)
  {
    message = e.what();
  }
  EXPECT_NE(message.find("has 1 handle"), std::string::npos) << message;

  // The outer and the inner equator, nested in the plane z = 0, cut the torus
  // into a top and a bottom half, as lines around the outer and the inner
  // wall cut a hollow bone. They share one cap, an annulus (two discs would
  // overlap): each half comes out closed, and the cap lies in the plane,
  // between the equators. In either order, either direction.
  std::vector<std::int64_t> outer, inner;
  for (int i = 0; i < n; ++i)
  {
    outer.push_back(id(i, 0));
    inner.push_back(id(i, m / 2));
  }
  std::vector<std::int64_t> innerReversed(inner.rbegin(), inner.rend());
  for (const auto& loops : { std::vector<std::vector<std::int64_t>>{ outer, inner },
         std::vector<std::vector<std::int64_t>>{ innerReversed, outer } })
  {
    const auto nested = lk::cutAlongLoops(lk::asPolygonMesh(torus), loops, true);
    ASSERT_EQ(nested.pieces.size(), 2u);
    EXPECT_EQ(nested.capCrossings, std::vector<std::size_t>({ 0u, 0u }));
    expectHalvesClosedByAnAnnulus(nested, n, 1e-9);
  }

  // The outer equator alone does not separate the torus (the hole joins its
  // sides, as the marrow cavity does a bone's). Through the inner walls, the
  // cut also takes the torus's section by the equator's plane inside it: the
  // inner equator, moved off the plane by a hair since its vertices lie on it.
  EXPECT_THROW(lk::cutAlongLoops(lk::asPolygonMesh(torus), { outer }, true), std::invalid_argument);
  const auto walls = lk::cutAlongLoops(lk::asPolygonMesh(torus), { outer }, true, true);
  EXPECT_EQ(walls.innerWallLoops, 1u);
  ASSERT_EQ(walls.pieces.size(), 2u);
  EXPECT_EQ(walls.capCrossings, std::vector<std::size_t>({ 0u, 0u }));
  expectHalvesClosedByAnAnnulus(walls, n, 1e-3);
  // Every new vertex is on the plane; split triangles keep their input face.
  for (std::size_t p = 0; p < 2; ++p)
    for (std::size_t v = 0; v < walls.pieces[p].points.size(); ++v)
      if (walls.vertexOrigin[p][v] < 0)
        EXPECT_NEAR(walls.pieces[p].points[v].z(), 0.0, 1e-3);
  for (const auto& origins : walls.faceOrigin)
    for (auto f : origins)
      EXPECT_LT(f, static_cast<std::int64_t>(torus.triangles.size()));
  // Capped along two tubes, the caps are clean.
  const auto clean = lk::cutAlongLoops(lk::asPolygonMesh(torus), { tube(0), tube(8) }, true);
  EXPECT_EQ(clean.capCrossings, std::vector<std::size_t>({ 0u, 0u }));
}

namespace
{
/// The closed surface swept by revolving `profile` (radius, height) about
/// the z axis in n steps; the profile starts and ends on the axis (poles).
/// Faces point outwards for a profile that runs out along the bottom.
lk::TriangleMesh revolved(const std::vector<std::pair<double, double>>& profile, int n)
{
  lk::TriangleMesh m;
  const std::size_t rings = profile.size() - 2;
  for (std::size_t k = 1; k + 1 < profile.size(); ++k)
    for (int i = 0; i < n; ++i)
    {
      const double a = 2.0 * 3.14159265358979 * i / n;
      m.points.emplace_back(profile[k].first * std::cos(a), profile[k].first * std::sin(a), profile[k].second);
    }
  const auto bottom = static_cast<std::int64_t>(m.points.size());
  m.points.emplace_back(0.0, 0.0, profile.front().second);
  const auto top = static_cast<std::int64_t>(m.points.size());
  m.points.emplace_back(0.0, 0.0, profile.back().second);
  auto id = [&](std::size_t k, int i) { return static_cast<std::int64_t>(k * static_cast<std::size_t>(n) + static_cast<std::size_t>(i % n)); };
  for (int i = 0; i < n; ++i)
  {
    m.triangles.push_back({ bottom, id(0, i + 1), id(0, i) });
    for (std::size_t k = 0; k + 1 < rings; ++k)
    {
      m.triangles.push_back({ id(k, i), id(k, i + 1), id(k + 1, i + 1) });
      m.triangles.push_back({ id(k, i), id(k + 1, i + 1), id(k + 1, i) });
    }
    m.triangles.push_back({ top, id(rings - 1, i), id(rings - 1, i + 1) });
  }
  return m;
}

/// A cut of a revolved solid by its ring at z = 1, through the inner walls:
/// one inner line, two closed pieces without crossings, one on each side of
/// the plane, whose caps lie in the plane outside the inner wall (radius 0.5
/// or more, a polygon of it inside), and whose volumes sum to the whole's.
void expectClosedPiecesOnEitherSideOfAnAnnulus(const lk::CutResult& cut, double wholeVolume)
{
  EXPECT_EQ(cut.innerWallLoops, 1u);
  ASSERT_EQ(cut.pieces.size(), 2u);
  EXPECT_EQ(cut.capCrossings, std::vector<std::size_t>({ 0u, 0u }));
  double volume = 0.0;
  for (std::size_t p = 0; p < 2; ++p)
  {
    const lk::TriangleMesh t = asTriangles(cut.pieces[p]);
    EXPECT_EQ(lk::cgalSurfaceMeshProblem(t), "") << "piece " << p;
    EXPECT_EQ(lk::countBoundaryEdges(t), 0u) << "piece " << p;
    EXPECT_GT(lk::signedVolume(t), 0.0);
    volume += lk::signedVolume(t);
    double low = 1e9, high = -1e9;
    for (const auto& q : cut.pieces[p].points)
    {
      low = std::min(low, q.z());
      high = std::max(high, q.z());
    }
    EXPECT_TRUE(high < 1.0 + 1e-3 || low > 1.0 - 1e-3) << "piece " << p << " spans " << low << " to " << high;
    for (std::size_t f = 0; f < cut.pieces[p].faces.size(); ++f)
      if (cut.faceOrigin[p][f] < 0)
        for (auto v : cut.pieces[p].faces[f])
        {
          const lk::Vec3& q = cut.pieces[p].points[static_cast<std::size_t>(v)];
          EXPECT_NEAR(q.z(), 1.0, 1e-3);
          EXPECT_GT(std::hypot(q.x(), q.y()), 0.45);
        }
  }
  EXPECT_NEAR(volume, wholeVolume, 1e-6 * wholeVolume);
}
} // namespace

TEST(MeshCut, ACanalOpenAtOneEndThatCrossesTheCapIsCutThroughToo)
{
  // A cylinder (radius 2, height 2) with a blind hole (radius 0.5) drilled
  // from the top down to z = 0.3, cut by the outer ring at z = 1: a canal
  // open at one end only that crosses the saw's plane. The line separates
  // the top from the bottom, but the top's flat cap runs through the hole.
  const int n = 16;
  const lk::TriangleMesh solid = revolved({ { 0.0, 0.0 }, { 2.0, 0.0 }, { 2.0, 0.5 }, { 2.0, 1.0 }, { 2.0, 1.5 },
                                            { 2.0, 2.0 }, { 0.5, 2.0 }, { 0.5, 1.5 }, { 0.5, 0.7 }, { 0.5, 0.3 },
                                            { 0.0, 0.3 } },
    n);
  ASSERT_EQ(lk::cgalSurfaceMeshProblem(solid), "");
  ASSERT_GT(lk::signedVolume(solid), 0.0);
  std::vector<std::int64_t> ring;
  for (int i = 0; i < n; ++i)
    ring.push_back(2 * n + i); // the profile's third ring: (2, 1)
  const auto plain = lk::cutAlongLoops(lk::asPolygonMesh(solid), { ring }, true);
  ASSERT_EQ(plain.pieces.size(), 2u);
  EXPECT_GT(plain.capCrossings[0] + plain.capCrossings[1], 0u);

  // Through the inner walls the hole's section joins the cut: the cap is an
  // annulus (radii 0.5 to 2), the top keeps the hole's upper part, and the
  // hole's bottom (z 0.3 to 1) goes with the bottom piece, as a dimple.
  expectClosedPiecesOnEitherSideOfAnAnnulus(
    lk::cutAlongLoops(lk::asPolygonMesh(solid), { ring }, true, true), lk::signedVolume(solid));

  // A closed cavity (an inner surface of its own, facing inwards) that the
  // plane crosses: before, a third piece, and the caps ran through it. Now
  // its halves join the pieces on their sides: two pieces, each with a
  // dimple, closed, no crossings.
  lk::TriangleMesh hollow = revolved({ { 0.0, 0.0 }, { 2.0, 0.0 }, { 2.0, 0.5 }, { 2.0, 1.0 }, { 2.0, 1.5 },
                                       { 2.0, 2.0 }, { 0.0, 2.0 } },
    n);
  const lk::TriangleMesh cavity =
    revolved({ { 0.0, 1.6 }, { 0.6, 1.6 }, { 0.6, 1.2 }, { 0.6, 0.8 }, { 0.0, 0.8 } }, n); // runs down: faces in
  const auto offset = static_cast<std::int64_t>(hollow.points.size());
  hollow.points.insert(hollow.points.end(), cavity.points.begin(), cavity.points.end());
  for (auto t : cavity.triangles)
    hollow.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  ASSERT_LT(lk::signedVolume(cavity), 0.0);
  expectClosedPiecesOnEitherSideOfAnAnnulus(
    lk::cutAlongLoops(lk::asPolygonMesh(hollow), { ring }, true, true), lk::signedVolume(hollow));
  EXPECT_EQ(lk::cutAlongLoops(lk::asPolygonMesh(hollow), { ring }, true).pieces.size(), 3u);
}

TEST(MeshCut, MeshesThatAreNotManifoldSurfacesAreRefused)
{
  auto message = [](const lk::PolygonMesh& m) -> std::string {
    try
    {
      lk::cutAlongLoops(m, { { 0, 1, 2 } }, false);
    }
    catch (const std::invalid_argument& e)
    {
      return e.what();
    }
    return "";
  };
  // Two triangles that touch only at vertex 0: two fans there.
  lk::PolygonMesh pinched;
  pinched.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 }, { 0, -1, 0 } };
  pinched.faces = { { 0, 1, 2 }, { 0, 3, 4 } };
  EXPECT_NE(message(pinched).find("pinched vertex"), std::string::npos) << message(pinched);
  // Two closed tetrahedra that share vertex 0: two closed fans (cycles) there.
  lk::PolygonMesh bowtie;
  bowtie.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { -1, 0, 0 }, { 0, -1, 0 }, { 0, 0, -1 } };
  bowtie.faces = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 }, { 0, 5, 4 }, { 0, 4, 6 }, { 0, 6, 5 },
    { 4, 5, 6 } };
  EXPECT_NE(message(bowtie).find("vertex 0 in more than one fan"), std::string::npos) << message(bowtie);
  // Three triangles on one edge.
  lk::PolygonMesh fin;
  fin.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 } };
  fin.faces = { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } };
  EXPECT_NE(message(fin).find("more than two faces"), std::string::npos) << message(fin);
  // A zero-area face and an isolated point, as latticeProblem reports them.
  lk::PolygonMesh flat;
  flat.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 } };
  flat.faces = { { 0, 1, 2 } };
  EXPECT_NE(message(flat).find("zero area"), std::string::npos) << message(flat);
  lk::PolygonMesh isolated = lk::asPolygonMesh(lktest::icosphere(1, 1.0));
  isolated.points.push_back({ 5, 5, 5 });
  EXPECT_NE(message(isolated).find("isolated"), std::string::npos) << message(isolated);
}

namespace
{
/// A closed tube (rings of 12 around the z axis, closed by fans at both
/// ends) with a lip: the ring at z = 1.05 has radius `lip`. The quad between
/// ring z = 1 and the lip at angles 0 and 30 degrees is cut by the diagonal
/// from (z = 1, 0 deg) to (lip, 30 deg), or the other one, or fanned
/// around a vertex in its middle (quad 2).
lk::TriangleMesh lippedTube(double lip, int quad)
{
  const bool otherDiagonal = quad == 1;
  const double zs[] = { 0.0, 1.0, 1.05, 2.0 };
  const double rs[] = { 1.0, 1.0, lip, 1.0 };
  lk::TriangleMesh m;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 12; ++i)
      m.points.emplace_back(rs[j] * std::cos(i * M_PI / 6), rs[j] * std::sin(i * M_PI / 6), zs[j]);
  m.points.emplace_back(0, 0, 0);
  m.points.emplace_back(0, 0, 2);
  if (quad == 2)
    m.points.emplace_back(1.05 * std::cos(M_PI / 12), 1.05 * std::sin(M_PI / 12), 1.025); // 50: the quad's middle
  auto id = [](int j, int i) { return static_cast<std::int64_t>(12 * j + (i + 12) % 12); };
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 12; ++i)
    {
      if (j == 1 && i == 0 && quad == 2)
      {
        m.triangles.push_back({ id(j, i), id(j, i + 1), 50 });
        m.triangles.push_back({ id(j, i + 1), id(j + 1, i + 1), 50 });
        m.triangles.push_back({ id(j + 1, i + 1), id(j + 1, i), 50 });
        m.triangles.push_back({ id(j + 1, i), id(j, i), 50 });
      }
      else if (j == 1 && i == 0 && otherDiagonal)
      {
        m.triangles.push_back({ id(j, i), id(j, i + 1), id(j + 1, i) });
        m.triangles.push_back({ id(j, i + 1), id(j + 1, i + 1), id(j + 1, i) });
      }
      else
      {
        m.triangles.push_back({ id(j, i), id(j, i + 1), id(j + 1, i + 1) });
        m.triangles.push_back({ id(j, i), id(j + 1, i + 1), id(j + 1, i) });
      }
    }
  for (int i = 0; i < 12; ++i)
  {
    m.triangles.push_back({ 48, id(0, i + 1), id(0, i) });
    m.triangles.push_back({ 49, id(3, i), id(3, i + 1) });
  }
  return m;
}
} // namespace

TEST(MeshCut, ALoopThatDetoursAroundABoneEdgeGivesManifoldCappedPieces)
{
  // The loop runs along ring z = 1 but goes round the quad between angles 0
  // and 30 degrees over the lip: (1, 0) -> (lip, 0) -> (lip, 30) -> (1, 30)
  // -> ring. The ring's edge between 0 and 30 degrees stays a bone edge of
  // the lower piece, inside the flat cap; the quad's two bone faces and the
  // cap's triangles over it enclose nothing. Before, the edge could get the
  // bone's two faces and the cap's two (a non-manifold piece, which the
  // lattice fit refuses); now such a pocket is taken out of the piece. With a
  // vertex inside the quad there is no pocket to take out: the cap's edge is
  // split beside the bone's instead.
  for (const int quad : { 0, 1, 2 })
  {
    const lk::TriangleMesh tube = lippedTube(1.1, quad);
    ASSERT_EQ(lk::cgalSurfaceMeshProblem(tube), "");
    std::vector<std::int64_t> loop = { 12, 24, 25, 13 };
    for (int i = 2; i < 12; ++i)
      loop.push_back(12 + i);
    const auto cut = lk::cutAlongLoops(lk::asPolygonMesh(tube), { loop }, true);
    ASSERT_EQ(cut.pieces.size(), 2u);
    double volume = 0.0;
    for (std::size_t p = 0; p < 2; ++p)
    {
      const lk::TriangleMesh piece = asTriangles(cut.pieces[p]);
      EXPECT_EQ(lk::cgalSurfaceMeshProblem(piece), "") << "piece " << p << ", quad " << quad;
      EXPECT_EQ(lk::countBoundaryEdges(piece), 0u);
      EXPECT_EQ(cut.capNonManifoldEdges[p], 0u);
      EXPECT_EQ(cut.capCrossings[p], 0u);
      EXPECT_GT(lk::signedVolume(piece), 0.0);
      volume += lk::signedVolume(piece);
      // The lower piece: with the quad spanned by loop vertices (0, 1), the
      // pocket between its faces and the cap is taken out, so nothing of the
      // lip is left in it; with a vertex in the quad (2) the stretch stays,
      // and the cap's edge along the ring is split beside it.
      bool lower = false, lip = false;
      for (const auto& q : piece.points)
      {
        lower = lower || q.z() < 0.5;
        lip = lip || q.z() > 1.04;
      }
      if (lower)
        EXPECT_EQ(lip, quad == 2) << "quad " << quad;
    }
    EXPECT_NEAR(volume, lk::signedVolume(tube), 1e-9 * lk::signedVolume(tube));
  }
}
