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

#include <array>
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
  /// The plan's index of the first sample here: 0 for a whole set, the
  /// block's first sample for a block (allocateSamples(block, set)).
  std::size_t first = 0;
  std::size_t count(SampleKind kind) const;
  std::size_t size() const { return points.size(); }
};

/// Metro's default: ten face samples per triangle of the larger mesh.
std::size_t defaultSampleCount(std::size_t facesA, std::size_t facesB);

/// Where every sample goes: the sampling is planned first (counts and
/// offsets, serial and cheap), then filled, which may run in parallel on
/// disjoint ranges of vertices, edges and faces.
struct SamplingPlan
{
  double density = 0.0;
  std::vector<std::int64_t> vertices;                ///< sampled vertex ids
  std::vector<std::array<std::int64_t, 3>> edges;    ///< (a, b, triangle), each edge once
  std::vector<std::size_t> edgeOffset;               ///< size edges+1
  std::vector<std::size_t> faceOffset;               ///< size triangles+1
  std::size_t vertexBegin = 0, edgeBegin = 0, faceBegin = 0, total = 0;
};

SamplingPlan planSampling(const TriangleMesh& mesh, const SamplingOptions& options);

/// Allocates the sample set for a plan.
void allocateSamples(const SamplingPlan& plan, SampleSet& set);

/// A run of the plan's samples small enough to hold at once: the samples of
/// elements [begin, end) of one kind (vertices, edges or faces), which are the
/// plan's samples [first, first + count).
struct SampleBlock
{
  SampleKind kind = SampleKind::Vertex;
  std::size_t begin = 0, end = 0;
  std::size_t first = 0, count = 0;
};

/// The plan cut into blocks of at most maxSamples samples each, in the
/// plan's order, so that a mesh's samples can be measured a block at a time
/// instead of all held together (an element with more samples than that
/// alone, a face sampled very densely, has a block of its own). Elements
/// without samples are left out; every sample is in exactly one block.
std::vector<SampleBlock> sampleBlocks(const SamplingPlan& plan, std::size_t maxSamples);

/// Allocates `set` for one block's samples (set.first = block.first); the
/// fill functions below then fill it from the block's element range.
void allocateSamples(const SampleBlock& block, SampleSet& set);

/// Fills the samples of vertices [v0, v1), edges [e0, e1) and faces [f0, f1)
/// (into a set allocated for the whole plan, or for a block holding them).
/// Disjoint ranges may be filled concurrently. Monte Carlo samples of face f
/// depend only on (seed, f), so the result does not depend on the ranges.
void fillVertexSamples(const TriangleMesh& mesh, const SamplingPlan& plan, std::size_t v0, std::size_t v1, SampleSet& set);
void fillEdgeSamples(const TriangleMesh& mesh, const SamplingPlan& plan, std::size_t e0, std::size_t e1, SampleSet& set);
void fillFaceSamples(const TriangleMesh& mesh, const SamplingPlan& plan, const SamplingOptions& options,
  std::size_t f0, std::size_t f1, SampleSet& set);

/// Fills the samples of the block's elements [e0, e1) (a part of
/// [block.begin, block.end)), of the block's kind, into a set allocated for
/// the block: fillVertexSamples, fillEdgeSamples or fillFaceSamples.
void fillBlockSamples(const TriangleMesh& mesh, const SamplingPlan& plan, const SamplingOptions& options,
  const SampleBlock& block, std::size_t e0, std::size_t e1, SampleSet& set);

/// Samples the mesh serially. Vertex samples come first (one per used point,
/// in point order), then edge samples (each undirected edge once, spacing
/// 1/sqrt(density), end points excluded), then face samples in triangle
/// order, so consecutive samples are spatially coherent.
SampleSet sampleSurface(const TriangleMesh& mesh, const SamplingOptions& options);

} // namespace lk
