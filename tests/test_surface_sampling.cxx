#include "TestMeshes.h"
#include "latticekit/SurfaceSampling.h"

#include <gtest/gtest.h>

#include <numeric>

namespace
{
double sumWeights(const lk::SampleSet& s)
{
  return std::accumulate(s.weights.begin(), s.weights.end(), 0.0);
}

/// Distance of p from triangle t's plane, and whether it is inside the triangle.
bool onTriangle(const lk::TriangleMesh& m, std::int64_t t, const lk::Vec3& p)
{
  const auto& tri = m.triangles[static_cast<std::size_t>(t)];
  const lk::Vec3 a = m.points[static_cast<std::size_t>(tri[0])];
  const lk::Vec3 b = m.points[static_cast<std::size_t>(tri[1])];
  const lk::Vec3 c = m.points[static_cast<std::size_t>(tri[2])];
  const lk::Vec3 n = (b - a).cross(c - a);
  const double area2 = n.norm();
  if (std::abs(n.normalized().dot(p - a)) > 1e-12)
  {
    return false;
  }
  const double u = (c - b).cross(p - b).dot(n) / (area2 * area2);
  const double v = (a - c).cross(p - c).dot(n) / (area2 * area2);
  const double w = 1.0 - u - v;
  return u >= -1e-12 && v >= -1e-12 && w >= -1e-12;
}
} // namespace

TEST(SurfaceSampling, SimilarTrianglesWeightsAddUpToTheArea)
{
  const lk::TriangleMesh m = lktest::icosphere(2, 3.0);
  lk::SamplingOptions o;
  o.targetSamples = 20000;
  o.method = lk::FaceSamplingMethod::SimilarTriangles;
  o.vertexSamples = o.edgeSamples = false;
  const lk::SampleSet s = lk::sampleSurface(m, o);
  EXPECT_NEAR(sumWeights(s), lk::surfaceArea(m), 1e-9 * lk::surfaceArea(m));
  // Every face is cut into k*k similar triangles: a perfect square per face.
  std::vector<int> perFace(m.triangles.size(), 0);
  for (auto f : s.faces)
  {
    ++perFace[static_cast<std::size_t>(f)];
  }
  for (int n : perFace)
  {
    const int k = static_cast<int>(std::lround(std::sqrt(n)));
    EXPECT_EQ(k * k, n);
  }
  // Close to the target.
  EXPECT_NEAR(static_cast<double>(s.size()), 20000.0, 0.35 * 20000.0);
}

TEST(SurfaceSampling, SimilarTrianglesCentroidsOfAUnitTriangle)
{
  lk::TriangleMesh m;
  m.points = { lk::Vec3(0, 0, 0), lk::Vec3(3, 0, 0), lk::Vec3(0, 3, 0) };
  m.triangles = { { 0, 1, 2 } };
  lk::SamplingOptions o;
  o.density = 9.0 / 4.5; // k = 3: 9 sub-triangles of side 1
  o.method = lk::FaceSamplingMethod::SimilarTriangles;
  o.vertexSamples = o.edgeSamples = false;
  const lk::SampleSet s = lk::sampleSurface(m, o);
  ASSERT_EQ(s.size(), 9u);
  // The centroids' mean is the triangle's centroid (exact quadrature of a linear function).
  lk::Vec3 mean = lk::Vec3::Zero();
  for (const auto& p : s.points)
  {
    mean += p / 9.0;
  }
  EXPECT_NEAR((mean - lk::Vec3(1, 1, 0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(s.points.front().x(), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(s.points.front().y(), 1.0 / 3.0, 1e-15);
}

TEST(SurfaceSampling, MonteCarloIsOnTheSurfaceDeterministicAndNearTheTarget)
{
  const lk::TriangleMesh m = lktest::icosphere(3, 1.0);
  lk::SamplingOptions o;
  o.targetSamples = 50000;
  o.method = lk::FaceSamplingMethod::MonteCarlo;
  o.seed = 7;
  const lk::SampleSet a = lk::sampleSurface(m, o);
  const lk::SampleSet b = lk::sampleSurface(m, o);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    ASSERT_EQ(a.points[i], b.points[i]);
  }
  const std::size_t faces = a.count(lk::SampleKind::Face);
  EXPECT_NEAR(static_cast<double>(faces), 50000.0, 5.0 * std::sqrt(50000.0));
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    if (a.kinds[i] == lk::SampleKind::Face)
    {
      ASSERT_TRUE(onTriangle(m, a.faces[i], a.points[i])) << "sample " << i;
    }
  }
  o.seed = 8;
  const lk::SampleSet c = lk::sampleSurface(m, o);
  EXPECT_NE(c.points.back(), a.points.back());
}

TEST(SurfaceSampling, MonteCarloIsUniformOverTheArea)
{
  // Two triangles of area 1 and 3: the samples split 1:3.
  lk::TriangleMesh m;
  m.points = { lk::Vec3(0, 0, 0), lk::Vec3(1, 0, 0), lk::Vec3(0, 2, 0), lk::Vec3(10, 0, 0),
    lk::Vec3(13, 0, 0), lk::Vec3(10, 2, 0) };
  m.triangles = { { 0, 1, 2 }, { 3, 4, 5 } };
  lk::SamplingOptions o;
  o.density = 10000.0;
  o.method = lk::FaceSamplingMethod::MonteCarlo;
  o.vertexSamples = o.edgeSamples = false;
  const lk::SampleSet s = lk::sampleSurface(m, o);
  EXPECT_EQ(s.size(), 40000u);
  // Uniform inside a triangle: the mean x of the first one is its centroid's, 1/3.
  double meanX = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    if (s.faces[i] == 0)
    {
      meanX += s.points[i].x();
      ++n;
    }
  }
  EXPECT_EQ(n, 10000u);
  EXPECT_NEAR(meanX / static_cast<double>(n), 1.0 / 3.0, 0.01);
}

TEST(SurfaceSampling, VertexAndEdgeSamples)
{
  const lk::TriangleMesh m = lktest::grid(1, 1.0, 0.0); // 4 points, 5 edges, 2 faces
  lk::SamplingOptions o;
  o.density = 100.0; // edge spacing 0.1
  o.faceSamples = false;
  const lk::SampleSet s = lk::sampleSurface(m, o);
  EXPECT_EQ(s.count(lk::SampleKind::Vertex), 4u);
  // floor(length / spacing) inner samples per edge (end points excluded):
  // 10 on each unit edge, floor(14.14) = 14 on the diagonal.
  EXPECT_EQ(s.count(lk::SampleKind::Edge), 4u * 10u + 14u);
  EXPECT_EQ(sumWeights(s), 0.0);
}

TEST(SurfaceSampling, RejectsImpossibleRequests)
{
  lk::SamplingOptions o;
  EXPECT_THROW(lk::sampleSurface(lktest::cube(), o), std::invalid_argument); // no count, no density
  lk::TriangleMesh flat;
  flat.points = { lk::Vec3(0, 0, 0), lk::Vec3(1, 0, 0), lk::Vec3(2, 0, 0) };
  flat.triangles = { { 0, 1, 2 } };
  o.targetSamples = 10;
  EXPECT_THROW(lk::sampleSurface(flat, o), std::invalid_argument); // zero area
}

// A mesh too densely sampled to hold at once is measured a block at a time:
// the blocks cover the plan's samples once, in order, and each fills exactly
// the samples the whole set holds there.
TEST(SurfaceSampling, BlocksCoverThePlanOnceAndFillAsTheWholeSet)
{
  const lk::TriangleMesh m = lktest::icosphere(2, 3.0);
  for (const auto method : { lk::FaceSamplingMethod::SimilarTriangles, lk::FaceSamplingMethod::MonteCarlo })
  {
    lk::SamplingOptions o;
    o.targetSamples = 5000;
    o.method = method;
    const lk::SamplingPlan plan = lk::planSampling(m, o);
    const lk::SampleSet whole = lk::sampleSurface(m, o);
    ASSERT_EQ(whole.size(), plan.total);
    for (const std::size_t maxSamples : { std::size_t(1), std::size_t(7), std::size_t(100), plan.total + 1 })
    {
      const std::vector<lk::SampleBlock> blocks = lk::sampleBlocks(plan, maxSamples);
      std::size_t next = 0;
      std::size_t compared = 0;
      for (const lk::SampleBlock& b : blocks)
      {
        EXPECT_EQ(b.first, next) << "blocks in the plan's order, none missing or overlapping";
        EXPECT_GT(b.count, 0u);
        // Only a single element may hold more than the bound (a face's k^2 samples).
        EXPECT_TRUE(b.count <= maxSamples || b.end == b.begin + 1) << b.count << " in " << b.end - b.begin;
        next = b.first + b.count;
        lk::SampleSet s;
        lk::allocateSamples(b, s);
        lk::fillBlockSamples(m, plan, o, b, b.begin, b.end, s);
        for (std::size_t i = 0; i < s.size(); ++i, ++compared)
        {
          const std::size_t j = b.first + i;
          EXPECT_EQ(s.kinds[i], b.kind);
          ASSERT_EQ(s.kinds[i], whole.kinds[j]);
          ASSERT_EQ(s.points[i], whole.points[j]);
          ASSERT_EQ(s.weights[i], whole.weights[j]);
          ASSERT_EQ(s.faces[i], whole.faces[j]);
        }
      }
      EXPECT_EQ(next, plan.total);
      EXPECT_EQ(compared, plan.total);
      if (maxSamples > plan.total)
      {
        EXPECT_EQ(blocks.size(), 3u) << "one block each of vertices, edges and faces";
      }
    }
  }
  EXPECT_THROW(lk::sampleBlocks(lk::planSampling(m, lk::SamplingOptions{ 100 }), 0), std::invalid_argument);
}
