#pragma once
/// \file SurfaceSampling.h
/// Metro-style surface sampling (Cignoni, Rocchini, Scopigno, "Metro: measuring
/// error on simplified surfaces", 1998): samples on the vertices, on the edges
/// and inside the faces of a triangle mesh.
///
/// Face samples carry a weight, the area they stand for, so that the mean and
/// RMS distances computed from them are estimates of the surface integrals
/// (1/A) \int d and sqrt((1/A) \int d^2). Vertex and edge samples have weight 0:
/// they only tighten the maximum (the Hausdorff distance), which is attained
/// on vertices and edges more often than inside faces.

#include "latticekit/TriangleMesh.h"

#include <cstdint>
#include <vector>

namespace lk
{

enum class FaceSamplingMethod
{
  /// Each face is cut into k*k similar triangles and the centroid of each is a
  /// sample (k = round(sqrt(area * density)), at least 1). Deterministic.
  SimilarTriangles,
  /// Each face gets floor(area * density) uniform random samples, plus one more
  /// with probability equal to the fractional part. Deterministic for a seed.
  MonteCarlo
};

enum class SampleKind : std::uint8_t
{
  Vertex = 0,
  Edge = 1,
  Face = 2
};

struct SamplingOptions
{
  /// Target number of face samples. Ignored when density > 0.
  std::size_t targetSamples = 0;
  /// Face samples per unit area. When 0, targetSamples / area is used.
  double density = 0.0;
  bool vertexSamples = true;
  bool edgeSamples = true;
  bool faceSamples = true;
  FaceSamplingMethod method = FaceSamplingMethod::SimilarTriangles;
  std::uint64_t seed = 5489u;
};

struct SampleSet
{
  std::vector<Vec3> points;
  std::vector<double> weights; ///< area represented (face samples), 0 otherwise
  std::vector<SampleKind> kinds;
  std::vector<std::int64_t> faces; ///< triangle the sample lies on (vertex samples: -1)
  std::size_t count(SampleKind kind) const;
  std::size_t size() const { return points.size(); }
};

/// Metro's default: ten face samples per triangle of the larger mesh.
std::size_t defaultSampleCount(std::size_t facesA, std::size_t facesB);

/// Samples the mesh. Vertex samples come first (one per used point, in point
/// order), then edge samples (each undirected edge once, spacing
/// 1/sqrt(density), end points excluded), then face samples in triangle
/// order, so consecutive samples are spatially coherent.
SampleSet sampleSurface(const TriangleMesh& mesh, const SamplingOptions& options);

} // namespace lk
