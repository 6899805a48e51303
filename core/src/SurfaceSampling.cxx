#include "latticekit/SurfaceSampling.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace lk
{

std::size_t SampleSet::count(SampleKind kind) const
{
  return static_cast<std::size_t>(std::count(kinds.begin(), kinds.end(), kind));
}

std::size_t defaultSampleCount(std::size_t facesA, std::size_t facesB)
{
  return 10 * std::max(facesA, facesB);
}

namespace
{

/// SplitMix64: a counter-based generator, so that the random numbers of a
/// face depend only on the seed and the face, not on the thread that draws them.
struct SplitMix64
{
  std::uint64_t state;
  std::uint64_t next()
  {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); }
};

SplitMix64 faceGenerator(std::uint64_t seed, std::size_t face)
{
  SplitMix64 g{ seed * 0xD1B54A32D192ED03ull + static_cast<std::uint64_t>(face) * 0x9E3779B97F4A7C15ull };
  g.next();
  return g;
}

int similarTrianglesDivisions(double area, double density)
{
  return std::max(1, static_cast<int>(std::lround(std::sqrt(area * density))));
}

void put(SampleSet& set, std::size_t planIndex, const Vec3& p, double w, SampleKind kind, std::int64_t face)
{
  const std::size_t i = planIndex - set.first;
  set.points[i] = p;
  set.weights[i] = w;
  set.kinds[i] = kind;
  set.faces[i] = face;
}

} // namespace

SamplingPlan planSampling(const TriangleMesh& mesh, const SamplingOptions& options)
{
  SamplingPlan plan;
  const double area = surfaceArea(mesh);
  double density = options.density;
  if (density <= 0.0)
  {
    if (options.targetSamples == 0)
    {
      throw std::invalid_argument("sampleSurface: give a sample count or a density");
    }
    density = area > 0.0 ? static_cast<double>(options.targetSamples) / area : 0.0;
  }
  if (!(density > 0.0) || !std::isfinite(density))
  {
    throw std::invalid_argument("sampleSurface: the mesh has zero area");
  }
  plan.density = density;

  if (options.vertexSamples)
  {
    std::vector<char> used(mesh.points.size(), 0);
    for (const Triangle& t : mesh.triangles)
    {
      for (auto id : t)
      {
        used[static_cast<std::size_t>(id)] = 1;
      }
    }
    for (std::size_t i = 0; i < used.size(); ++i)
    {
      if (used[i])
      {
        plan.vertices.push_back(static_cast<std::int64_t>(i));
      }
    }
  }
  plan.edgeBegin = plan.vertices.size();

  plan.edgeOffset.assign(1, plan.edgeBegin);
  if (options.edgeSamples)
  {
    auto& edges = plan.edges;
    edges.reserve(3 * mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    {
      const Triangle& tri = mesh.triangles[t];
      for (int k = 0; k < 3; ++k)
      {
        edges.push_back({ std::min(tri[k], tri[(k + 1) % 3]), std::max(tri[k], tri[(k + 1) % 3]),
          static_cast<std::int64_t>(t) });
      }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end(),
                  [](const auto& x, const auto& y) { return x[0] == y[0] && x[1] == y[1]; }),
      edges.end());
    // Triangle order keeps the edge samples coherent with the face samples.
    std::stable_sort(
      edges.begin(), edges.end(), [](const auto& x, const auto& y) { return x[2] < y[2]; });
    const double spacing = 1.0 / std::sqrt(density);
    plan.edgeOffset.resize(edges.size() + 1);
    for (std::size_t e = 0; e < edges.size(); ++e)
    {
      const double len = (mesh.points[static_cast<std::size_t>(edges[e][1])] -
        mesh.points[static_cast<std::size_t>(edges[e][0])])
                           .norm();
      plan.edgeOffset[e + 1] = plan.edgeOffset[e] + static_cast<std::size_t>(std::floor(len / spacing));
    }
  }
  plan.faceBegin = plan.edgeOffset.back();

  plan.faceOffset.assign(mesh.triangles.size() + 1, plan.faceBegin);
  if (options.faceSamples)
  {
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    {
      const double a = triangleArea(mesh, t);
      std::size_t n;
      if (options.method == FaceSamplingMethod::SimilarTriangles)
      {
        const auto k = static_cast<std::size_t>(similarTrianglesDivisions(a, density));
        n = k * k;
      }
      else
      {
        const double expected = a * density;
        n = static_cast<std::size_t>(std::floor(expected));
        SplitMix64 g = faceGenerator(options.seed, t);
        if (g.uniform() < expected - static_cast<double>(n))
        {
          ++n;
        }
      }
      plan.faceOffset[t + 1] = plan.faceOffset[t] + n;
    }
  }
  plan.total = plan.faceOffset.back();
  return plan;
}

void allocateSamples(const SamplingPlan& plan, SampleSet& set)
{
  set.first = 0;
  set.points.resize(plan.total);
  set.weights.resize(plan.total);
  set.kinds.resize(plan.total);
  set.faces.resize(plan.total);
}

std::vector<SampleBlock> sampleBlocks(const SamplingPlan& plan, std::size_t maxSamples)
{
  if (maxSamples == 0)
  {
    throw std::invalid_argument("sampleBlocks: a block must hold at least one sample");
  }
  std::vector<SampleBlock> blocks;
  // Elements [0, n) of one kind, element k's samples [offset(k), offset(k + 1)).
  auto cut = [&](SampleKind kind, std::size_t n, auto offset) {
    std::size_t k = 0;
    while (k < n)
    {
      while (k < n && offset(k + 1) == offset(k))
        ++k; // no samples
      if (k == n)
        break;
      SampleBlock b;
      b.kind = kind;
      b.begin = k;
      b.first = offset(k);
      ++k; // at least one element, however many samples it has
      while (k < n && offset(k + 1) - b.first <= maxSamples)
        ++k;
      b.end = k;
      b.count = offset(k) - b.first;
      blocks.push_back(b);
    }
  };
  cut(SampleKind::Vertex, plan.vertices.size(), [&](std::size_t k) { return plan.vertexBegin + k; });
  cut(SampleKind::Edge, plan.edges.size(), [&](std::size_t k) { return plan.edgeOffset[k]; });
  cut(SampleKind::Face, plan.faceOffset.empty() ? 0 : plan.faceOffset.size() - 1, [&](std::size_t k) { return plan.faceOffset[k]; });
  return blocks;
}

void allocateSamples(const SampleBlock& block, SampleSet& set)
{
  set.first = block.first;
  set.points.resize(block.count);
  set.weights.resize(block.count);
  set.kinds.resize(block.count);
  set.faces.resize(block.count);
}

void fillVertexSamples(
  const TriangleMesh& mesh, const SamplingPlan& plan, std::size_t v0, std::size_t v1, SampleSet& set)
{
  for (std::size_t i = v0; i < v1; ++i)
  {
    put(set, plan.vertexBegin + i, mesh.points[static_cast<std::size_t>(plan.vertices[i])], 0.0,
      SampleKind::Vertex, -1);
  }
}

void fillEdgeSamples(
  const TriangleMesh& mesh, const SamplingPlan& plan, std::size_t e0, std::size_t e1, SampleSet& set)
{
  for (std::size_t e = e0; e < e1; ++e)
  {
    const auto& edge = plan.edges[e];
    const Vec3& a = mesh.points[static_cast<std::size_t>(edge[0])];
    const Vec3& b = mesh.points[static_cast<std::size_t>(edge[1])];
    const std::size_t n = plan.edgeOffset[e + 1] - plan.edgeOffset[e];
    for (std::size_t i = 1; i <= n; ++i)
    {
      const double s = static_cast<double>(i) / static_cast<double>(n + 1);
      put(set, plan.edgeOffset[e] + i - 1, a + s * (b - a), 0.0, SampleKind::Edge, edge[2]);
    }
  }
}

void fillFaceSamples(const TriangleMesh& mesh, const SamplingPlan& plan, const SamplingOptions& options,
  std::size_t f0, std::size_t f1, SampleSet& set)
{
  for (std::size_t t = f0; t < f1; ++t)
  {
    const std::size_t n = plan.faceOffset[t + 1] - plan.faceOffset[t];
    if (n == 0)
    {
      continue;
    }
    const Triangle& tri = mesh.triangles[t];
    const Vec3& a = mesh.points[static_cast<std::size_t>(tri[0])];
    const Vec3& b = mesh.points[static_cast<std::size_t>(tri[1])];
    const Vec3& c = mesh.points[static_cast<std::size_t>(tri[2])];
    const auto face = static_cast<std::int64_t>(t);
    std::size_t out = plan.faceOffset[t];
    if (options.method == FaceSamplingMethod::SimilarTriangles)
    {
      // k*k similar sub-triangles; each centroid stands for area/k^2.
      const int k = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
      const double w = triangleArea(mesh, t) / static_cast<double>(n);
      const Vec3 u = (b - a) / k;
      const Vec3 v = (c - a) / k;
      for (int i = 0; i < k; ++i)
      {
        for (int j = 0; i + j < k; ++j)
        {
          put(set, out++, a + (i + 1.0 / 3.0) * u + (j + 1.0 / 3.0) * v, w, SampleKind::Face, face);
          if (i + j < k - 1)
          {
            put(set, out++, a + (i + 2.0 / 3.0) * u + (j + 2.0 / 3.0) * v, w, SampleKind::Face, face);
          }
        }
      }
    }
    else
    {
      SplitMix64 g = faceGenerator(options.seed, t);
      g.uniform(); // the draw that rounded the count
      const double w = 1.0 / plan.density;
      for (std::size_t i = 0; i < n; ++i)
      {
        // Uniform on the triangle: the square-root warp of two uniform numbers.
        const double r1 = std::sqrt(g.uniform());
        const double r2 = g.uniform();
        put(set, out++, (1.0 - r1) * a + r1 * (1.0 - r2) * b + r1 * r2 * c, w, SampleKind::Face, face);
      }
    }
  }
}

void fillBlockSamples(const TriangleMesh& mesh, const SamplingPlan& plan, const SamplingOptions& options,
  const SampleBlock& block, std::size_t e0, std::size_t e1, SampleSet& set)
{
  switch (block.kind)
  {
    case SampleKind::Vertex:
      fillVertexSamples(mesh, plan, e0, e1, set);
      break;
    case SampleKind::Edge:
      fillEdgeSamples(mesh, plan, e0, e1, set);
      break;
    case SampleKind::Face:
      fillFaceSamples(mesh, plan, options, e0, e1, set);
      break;
  }
}

SampleSet sampleSurface(const TriangleMesh& mesh, const SamplingOptions& options)
{
  const SamplingPlan plan = planSampling(mesh, options);
  SampleSet set;
  allocateSamples(plan, set);
  fillVertexSamples(mesh, plan, 0, plan.vertices.size(), set);
  fillEdgeSamples(mesh, plan, 0, plan.edges.size(), set);
  fillFaceSamples(mesh, plan, options, 0, mesh.triangles.size(), set);
  return set;
}

} // namespace lk
