// The core of the Metro measure on exact cases: closest points through the
// AABB tree and the statistics of sampled distances.
#include "TestMeshes.h"
#include "latticekit/ClosestPointTree.h"
#include "latticekit/DistanceStatistics.h"
#include "latticekit/SurfaceSampling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace
{
lk::DistanceStatistics measure(const lk::TriangleMesh& from, const lk::TriangleMesh& to,
  std::size_t samples, lk::FaceSamplingMethod method = lk::FaceSamplingMethod::MonteCarlo)
{
  lk::SamplingOptions o;
  o.targetSamples = samples;
  o.method = method;
  const lk::SampleSet s = lk::sampleSurface(from, o);
  const lk::ClosestPointTree tree(to);
  std::vector<double> d(s.size());
  tree.distances(s, 0, s.size(), d.data());
  return lk::summarizeDistances(s, d);
}

/// Brute force over every triangle, with the classic region test.
double bruteForceDistance(const lk::TriangleMesh& m, const lk::Vec3& p)
{
  double best = std::numeric_limits<double>::max();
  for (const auto& t : m.triangles)
  {
    const lk::Vec3 a = m.points[static_cast<std::size_t>(t[0])];
    const lk::Vec3 b = m.points[static_cast<std::size_t>(t[1])];
    const lk::Vec3 c = m.points[static_cast<std::size_t>(t[2])];
    // Ericson, Real-Time Collision Detection, 5.1.5.
    const lk::Vec3 ab = b - a, ac = c - a, ap = p - a;
    lk::Vec3 q;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    const lk::Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    const lk::Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (d1 <= 0 && d2 <= 0)
      q = a;
    else if (d3 >= 0 && d4 <= d3)
      q = b;
    else if (vc <= 0 && d1 >= 0 && d3 <= 0)
      q = a + d1 / (d1 - d3) * ab;
    else if (d6 >= 0 && d5 <= d6)
      q = c;
    else if (vb <= 0 && d2 >= 0 && d6 <= 0)
      q = a + d2 / (d2 - d6) * ac;
    else if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
      q = b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    else
    {
      const double denom = 1.0 / (va + vb + vc);
      q = a + ab * (vb * denom) + ac * (vc * denom);
    }
    best = std::min(best, (p - q).norm());
  }
  return best;
}
} // namespace

TEST(ClosestPointTree, AgreesWithBruteForceWithAndWithoutHints)
{
  const lk::TriangleMesh m = lktest::icosphere(2, 1.0);
  const lk::ClosestPointTree tree(m);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  lk::ClosestPointTree::Hit hint;
  for (int i = 0; i < 2000; ++i)
  {
    const lk::Vec3 p(u(rng), u(rng), u(rng));
    const double exact = bruteForceDistance(m, p);
    EXPECT_NEAR(tree.closest(p).distance, exact, 1e-12);
    hint = tree.closest(p, hint); // a hint far from p must not change the answer
    EXPECT_NEAR(hint.distance, exact, 1e-12);
    EXPECT_NEAR((hint.point - p).norm(), hint.distance, 1e-12);
  }
}

TEST(ClosestPointTree, ATreeOverTheFacesInABoxAnswersForTheWholeMesh)
{
  // A stroke's tree holds the faces near it; a query whose answer could lie
  // outside goes to the whole mesh. Every answer is the whole mesh's closest
  // point: inside the box, near it, far away, with and without hints.
  const lk::TriangleMesh m = lktest::icosphere(3, 1.0);
  const lk::Vec3 lo(0.2, -0.3, 0.5), hi(0.6, 0.1, 1.1);
  const lk::ClosestPointTree part(m, lo, hi);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> near(-0.1, 1.2), far(-3.0, 3.0);
  lk::ClosestPointTree::Hit hint;
  for (int i = 0; i < 3000; ++i)
  {
    const lk::Vec3 p = i % 3 == 2 ? lk::Vec3(far(rng), far(rng), far(rng)) : lk::Vec3(near(rng), near(rng) - 0.4, near(rng));
    const double exact = bruteForceDistance(m, p);
    const auto hit = part.closest(p);
    EXPECT_NEAR(hit.distance, exact, 1e-12) << p.transpose();
    ASSERT_GE(hit.face, 0);
    ASSERT_LT(hit.face, static_cast<std::int64_t>(m.triangles.size()));
    // The face is the mesh's own (its id on the whole mesh, not in the box's part).
    const lk::Triangle& t = m.triangles[static_cast<std::size_t>(hit.face)];
    const lk::Vec3 onFace = lk::closestPointOnTriangle(p, m.points[static_cast<std::size_t>(t[0])],
      m.points[static_cast<std::size_t>(t[1])], m.points[static_cast<std::size_t>(t[2])]);
    EXPECT_NEAR((onFace - hit.point).norm(), 0.0, 1e-12);
    hint = part.closest(p, hint);
    EXPECT_NEAR(hint.distance, exact, 1e-12);
  }
  // A box that meets no face: every query goes to the whole mesh.
  const lk::ClosestPointTree none(m, lk::Vec3(5, 5, 5), lk::Vec3(6, 6, 6));
  EXPECT_NEAR(none.closest(lk::Vec3(5.5, 5.5, 5.5)).distance, bruteForceDistance(m, lk::Vec3(5.5, 5.5, 5.5)), 1e-12);
  EXPECT_THROW(lk::ClosestPointTree(m, hi, lo), std::invalid_argument);
  EXPECT_THROW(lk::ClosestPointTree(m, lo, lk::Vec3(1, std::nan(""), 1)), std::invalid_argument);
}

TEST(ClosestPointTree, ADegenerateTriangleIsTheSegmentItSpans)
{
  // Two corners in one place, all three in one place, three on a line: the
  // closest point is on the segment they span (it was NaN for the first,
  // and a mesh with one such triangle made Metro's mean NaN).
  const lk::Vec3 a(0, 0, 0), c(2, 0, 0), mid(1, 0, 0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int i = 0; i < 500; ++i)
  {
    const lk::Vec3 p(u(rng), u(rng), u(rng));
    const lk::Vec3 onSegment(std::clamp(p.x(), 0.0, 2.0), 0.0, 0.0);
    for (const auto& [x, y, z] : { std::array<lk::Vec3, 3>{ a, a, c }, std::array<lk::Vec3, 3>{ a, c, c },
           std::array<lk::Vec3, 3>{ c, a, a }, std::array<lk::Vec3, 3>{ a, c, a }, std::array<lk::Vec3, 3>{ a, mid, c },
           std::array<lk::Vec3, 3>{ mid, a, c }, std::array<lk::Vec3, 3>{ a, c, mid } })
    {
      const lk::Vec3 q = lk::closestPointOnTriangle(p, x, y, z);
      ASSERT_TRUE(q.allFinite()) << p.transpose();
      EXPECT_NEAR((q - onSegment).norm(), 0.0, 1e-12) << p.transpose();
    }
    EXPECT_EQ(lk::closestPointOnTriangle(p, mid, mid, mid), mid);
  }
  // In a mesh: a sphere with one triangle that repeats a vertex.
  lk::TriangleMesh m = lktest::icosphere(2, 1.0);
  const auto t = m.triangles[0];
  m.triangles.push_back({ t[0], t[0], t[1] });
  const lk::ClosestPointTree tree(m);
  for (int i = 0; i < 500; ++i)
  {
    const lk::Vec3 p(u(rng), u(rng), u(rng));
    const auto hit = tree.closest(p);
    ASSERT_TRUE(std::isfinite(hit.distance)) << p.transpose();
    EXPECT_NEAR(hit.distance, std::abs(p.norm() - 1.0), 0.1); // the icosphere is within 0.1 of the unit sphere
  }
}

TEST(ClosestPointTree, RejectsInvalidMeshes)
{
  lk::TriangleMesh m = lktest::cube();
  m.points[3].x() = std::nan("");
  EXPECT_THROW(lk::ClosestPointTree{ m }, std::invalid_argument);
  m = lktest::cube();
  m.triangles[0][1] = 99;
  EXPECT_THROW(lk::ClosestPointTree{ m }, std::invalid_argument);
  EXPECT_THROW(lk::ClosestPointTree{ lk::TriangleMesh() }, std::invalid_argument);
  // An overflowed coordinate (vtkOBJReader stores 1e309 as 3.4e38) is refused
  // as well: closest-point searches there cannot prune and never end.
  m = lktest::cube();
  m.points[3].x() = 3.4e38;
  EXPECT_NE(lk::validateTriangleMesh(m).find("beyond 1e15"), std::string::npos);
  EXPECT_THROW(lk::ClosestPointTree{ m }, std::invalid_argument);
  m.points[3].x() = -lk::kLargestCoordinate;
  EXPECT_EQ(lk::validateTriangleMesh(m), "");
}

TEST(MetroDistance, ParallelPlanes)
{
  // Two 10 x 10 squares 0.25 apart: every sample of one is 0.25 from the other.
  const lk::TriangleMesh a = lktest::grid(4, 10.0, 0.0), b = lktest::grid(7, 10.0, 0.25);
  for (auto method : { lk::FaceSamplingMethod::MonteCarlo, lk::FaceSamplingMethod::SimilarTriangles })
  {
    const lk::DistanceStatistics ab = measure(a, b, 10000, method);
    const lk::DistanceStatistics ba = measure(b, a, 10000, method);
    for (const auto& s : { ab, ba })
    {
      EXPECT_NEAR(s.max, 0.25, 1e-12);
      EXPECT_NEAR(s.mean, 0.25, 1e-12);
      EXPECT_NEAR(s.rms, 0.25, 1e-12);
      EXPECT_NEAR(s.area, 100.0, method == lk::FaceSamplingMethod::MonteCarlo ? 3.0 : 1e-9);
    }
  }
}

TEST(MetroDistance, TiltedPlaneHasTheAnalyticMeanAndRms)
{
  // A unit square tilted by z = x/2 against the flat unit square: the distance
  // from a point (x, y, x/2) to the plane z = 0 is x/2, so over the tilted
  // square (uniform in x) the mean is 1/4, the RMS sqrt(1/12) and the max 1/2.
  lk::TriangleMesh tilted = lktest::grid(8, 1.0, 0.0);
  for (auto& p : tilted.points)
  {
    p.z() = 0.5 * p.x();
  }
  const lk::TriangleMesh flat = lktest::grid(3, 1.0, 0.0);
  const lk::DistanceStatistics mc = measure(tilted, flat, 400000);
  EXPECT_NEAR(mc.max, 0.5, 1e-12); // attained at vertices
  EXPECT_NEAR(mc.mean, 0.25, 0.002);
  EXPECT_NEAR(mc.rms, std::sqrt(1.0 / 12.0), 0.002);
  // Centroids of similar triangles integrate a linear function exactly.
  const lk::DistanceStatistics st =
    measure(tilted, flat, 100000, lk::FaceSamplingMethod::SimilarTriangles);
  EXPECT_NEAR(st.mean, 0.25, 1e-12);
  EXPECT_NEAR(st.rms, std::sqrt(1.0 / 12.0), 1e-3);
}

TEST(MetroDistance, MeshAgainstItselfIsZero)
{
  const lk::TriangleMesh m = lktest::icosphere(3, 5.0);
  const lk::DistanceStatistics s = measure(m, m, 100000);
  EXPECT_LT(s.max, 1e-12);
  EXPECT_LT(s.mean, 1e-13);
}

TEST(MetroDistance, ConcentricSpheres)
{
  // Fine icospheres of radius 1 and 2. Every distance lies within the two
  // tessellations' sagittas (below 0.0015 here) of the analytic 1, both ways.
  const lk::TriangleMesh inner = lktest::icosphere(5, 1.0), outer = lktest::icosphere(4, 2.0);
  // Queries a whole radius away from the surface are the AABB tree's worst
  // case (large balls overlap many boxes), so the sample count stays modest.
  const lk::DistanceStatistics out2in = measure(outer, inner, 40000);
  const lk::DistanceStatistics in2out = measure(inner, outer, 40000);
  for (const auto& s : { out2in, in2out })
  {
    EXPECT_NEAR(s.mean, 1.0, 0.003);
    EXPECT_NEAR(s.rms, 1.0, 0.003);
    EXPECT_NEAR(s.max, 1.0, 0.003);
    EXPECT_GE(s.rms, s.mean);
    EXPECT_GE(s.max, s.rms);
  }
}

TEST(MetroDistance, SymmetricStatisticsTakeTheWorseDirection)
{
  lk::DistanceStatistics ab, ba;
  ab.max = 1.0;
  ab.mean = 0.2;
  ab.rms = 0.3;
  ba.max = 0.5;
  ba.mean = 0.4;
  ba.rms = 0.25;
  const lk::DistanceStatistics s = lk::symmetricStatistics(ab, ba);
  EXPECT_EQ(s.max, 1.0);
  EXPECT_EQ(s.mean, 0.4);
  EXPECT_EQ(s.rms, 0.3);
}

TEST(MetroDistance, MeanOverAllSamplesCountsEachSampleOnce)
{
  // One vertex sample at 3, one edge sample at 1, two face samples at 0 and
  // 2 standing for areas 3 and 1: area-weighted, the mean is (0*3 + 2*1)/4;
  // Metro 4's mean counts the four samples alike.
  lk::SampleSet s;
  s.points.assign(4, lk::Vec3(0, 0, 0));
  s.kinds = { lk::SampleKind::Vertex, lk::SampleKind::Edge, lk::SampleKind::Face, lk::SampleKind::Face };
  s.weights = { 0.0, 0.0, 3.0, 1.0 };
  s.faces = { -1, 0, 0, 0 };
  const std::vector<double> d = { 3.0, 1.0, 0.0, 2.0 };
  const lk::DistanceStatistics area = lk::summarizeDistances(s, d);
  EXPECT_DOUBLE_EQ(area.mean, 0.5);
  EXPECT_DOUBLE_EQ(area.rms, 1.0);
  EXPECT_DOUBLE_EQ(area.max, 3.0);
  const lk::DistanceStatistics all = lk::summarizeDistances(s, d, true);
  EXPECT_DOUBLE_EQ(all.mean, 1.5);
  EXPECT_DOUBLE_EQ(all.rms, std::sqrt(14.0 / 4.0));
  EXPECT_DOUBLE_EQ(all.max, 3.0);
  EXPECT_DOUBLE_EQ(all.area, 4.0);
  EXPECT_EQ(all.samples(), 4u);
}

TEST(MetroDistance, HausdorffOfAPartialCopyIsOneSided)
{
  // B is half of A: A->B sees the missing half (max 5), B->A sees nothing (0).
  const lk::TriangleMesh a = lktest::grid(10, 10.0, 0.0);
  lk::TriangleMesh b = lktest::grid(10, 10.0, 0.0);
  for (auto& p : b.points)
  {
    p.x() *= 0.5;
  }
  const lk::DistanceStatistics ab = measure(a, b, 50000);
  const lk::DistanceStatistics ba = measure(b, a, 50000);
  EXPECT_NEAR(ab.max, 5.0, 1e-12);
  EXPECT_NEAR(ab.mean, 1.25, 0.02); // half the area at mean distance 2.5
  EXPECT_LT(ba.max, 1e-12);
}

// Distances summed a block at a time, in the samples' order, give the same
// figures to the last bit as one summary over all of them (the Metro filter
// measures large meshes that way).
TEST(MetroDistance, BlocksAddUpToTheWholeSummary)
{
  const lk::TriangleMesh a = lktest::icosphere(3, 10.0), b = lktest::icosphere(2, 10.2);
  lk::SamplingOptions o;
  o.targetSamples = 20000;
  const lk::SamplingPlan plan = lk::planSampling(a, o);
  const lk::SampleSet whole = lk::sampleSurface(a, o);
  const lk::ClosestPointTree tree(b);
  std::vector<double> d(whole.size());
  tree.distances(whole, 0, whole.size(), d.data());
  for (const bool overAll : { false, true })
  {
    const lk::DistanceStatistics expected = lk::summarizeDistances(whole, d, overAll);
    lk::DistanceAccumulator sums;
    for (const lk::SampleBlock& block : lk::sampleBlocks(plan, 999))
    {
      lk::SampleSet s;
      lk::allocateSamples(block, s);
      lk::fillBlockSamples(a, plan, o, block, block.begin, block.end, s);
      std::vector<double> bd(s.size());
      tree.distances(s, 0, s.size(), bd.data());
      sums.add(s, bd.data());
    }
    const lk::DistanceStatistics got = sums.result(overAll);
    EXPECT_GT(got.mean, 0.05);
    EXPECT_EQ(got.max, expected.max);
    EXPECT_EQ(got.mean, expected.mean);
    EXPECT_EQ(got.rms, expected.rms);
    EXPECT_EQ(got.area, expected.area);
    EXPECT_EQ(got.vertexSamples, expected.vertexSamples);
    EXPECT_EQ(got.edgeSamples, expected.edgeSamples);
    EXPECT_EQ(got.faceSamples, expected.faceSamples);
  }
}
