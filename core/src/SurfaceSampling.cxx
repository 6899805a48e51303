#include "latticekit/SurfaceSampling.h"

#include <algorithm>
#include <cmath>
#include <random>
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

void addSample(SampleSet& set, const Vec3& p, double w, SampleKind kind, std::int64_t face)
{
  set.points.push_back(p);
  set.weights.push_back(w);
  set.kinds.push_back(kind);
  set.faces.push_back(face);
}

void sampleVertices(const TriangleMesh& mesh, SampleSet& set)
{
  std::vector<std::int64_t> firstFace(mesh.points.size(), -1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
  {
    for (auto id : mesh.triangles[t])
    {
      auto& f = firstFace[static_cast<std::size_t>(id)];
      if (f < 0)
      {
        f = static_cast<std::int64_t>(t);
      }
    }
  }
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
  {
    if (firstFace[i] >= 0)
    {
      addSample(set, mesh.points[i], 0.0, SampleKind::Vertex, firstFace[i]);
    }
  }
}

void sampleEdges(const TriangleMesh& mesh, double spacing, SampleSet& set)
{
  std::vector<std::pair<std::pair<std::int64_t, std::int64_t>, std::int64_t>> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
  {
    const Triangle& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      std::int64_t a = tri[k], b = tri[(k + 1) % 3];
      if (a > b)
      {
        std::swap(a, b);
      }
      edges.push_back({ { a, b }, static_cast<std::int64_t>(t) });
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end(),
                [](const auto& x, const auto& y) { return x.first == y.first; }),
    edges.end());
  // Restore triangle order so the samples stay coherent with the face samples.
  std::stable_sort(edges.begin(), edges.end(),
    [](const auto& x, const auto& y) { return x.second < y.second; });
  for (const auto& e : edges)
  {
    const Vec3& a = mesh.points[static_cast<std::size_t>(e.first.first)];
    const Vec3& b = mesh.points[static_cast<std::size_t>(e.first.second)];
    const double len = (b - a).norm();
    const auto n = static_cast<int>(std::floor(len / spacing));
    for (int i = 1; i <= n; ++i)
    {
      const double s = static_cast<double>(i) / (n + 1);
      addSample(set, a + s * (b - a), 0.0, SampleKind::Edge, e.second);
    }
  }
}

void sampleFacesSimilarTriangles(const TriangleMesh& mesh, double density, SampleSet& set)
{
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
  {
    const Triangle& tri = mesh.triangles[t];
    const Vec3& a = mesh.points[static_cast<std::size_t>(tri[0])];
    const Vec3& b = mesh.points[static_cast<std::size_t>(tri[1])];
    const Vec3& c = mesh.points[static_cast<std::size_t>(tri[2])];
    const double area = triangleArea(mesh, t);
    const int k = std::max(1, static_cast<int>(std::lround(std::sqrt(area * density))));
    const double w = area / (static_cast<double>(k) * k);
    const Vec3 u = (b - a) / k;
    const Vec3 v = (c - a) / k;
    const auto face = static_cast<std::int64_t>(t);
    for (int i = 0; i < k; ++i)
    {
      for (int j = 0; i + j < k; ++j)
      {
        // Upward sub-triangle (i,j),(i+1,j),(i,j+1): centroid.
        addSample(set, a + (i + 1.0 / 3.0) * u + (j + 1.0 / 3.0) * v, w, SampleKind::Face, face);
        if (i + j < k - 1)
        {
          // Downward sub-triangle (i+1,j),(i,j+1),(i+1,j+1).
          addSample(
            set, a + (i + 2.0 / 3.0) * u + (j + 2.0 / 3.0) * v, w, SampleKind::Face, face);
        }
      }
    }
  }
}

void sampleFacesMonteCarlo(
  const TriangleMesh& mesh, double density, std::uint64_t seed, SampleSet& set)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double w = 1.0 / density;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
  {
    const Triangle& tri = mesh.triangles[t];
    const Vec3& a = mesh.points[static_cast<std::size_t>(tri[0])];
    const Vec3& b = mesh.points[static_cast<std::size_t>(tri[1])];
    const Vec3& c = mesh.points[static_cast<std::size_t>(tri[2])];
    const double expected = triangleArea(mesh, t) * density;
    auto n = static_cast<long>(std::floor(expected));
    if (unit(rng) < expected - static_cast<double>(n))
    {
      ++n;
    }
    for (long i = 0; i < n; ++i)
    {
      // Uniform on the triangle: the square-root warp of two uniform numbers.
      const double r1 = std::sqrt(unit(rng));
      const double r2 = unit(rng);
      const Vec3 p = (1.0 - r1) * a + r1 * (1.0 - r2) * b + r1 * r2 * c;
      addSample(set, p, w, SampleKind::Face, static_cast<std::int64_t>(t));
    }
  }
}

} // namespace

SampleSet sampleSurface(const TriangleMesh& mesh, const SamplingOptions& options)
{
  SampleSet set;
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
  const std::size_t expected = static_cast<std::size_t>(area * density) + mesh.points.size() +
    mesh.triangles.size();
  set.points.reserve(expected);
  set.weights.reserve(expected);
  set.kinds.reserve(expected);
  set.faces.reserve(expected);
  if (options.vertexSamples)
  {
    sampleVertices(mesh, set);
  }
  if (options.edgeSamples)
  {
    sampleEdges(mesh, 1.0 / std::sqrt(density), set);
  }
  if (options.faceSamples)
  {
    if (options.method == FaceSamplingMethod::SimilarTriangles)
    {
      sampleFacesSimilarTriangles(mesh, density, set);
    }
    else
    {
      sampleFacesMonteCarlo(mesh, density, options.seed, set);
    }
  }
  return set;
}

} // namespace lk
