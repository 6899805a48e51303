#pragma once
/// \file AdaptivePatchMesh.h
/// Real-time deformation of adaptively refined micro planar patches (seed
/// 002, Futagami, Mizuguchi and Morita).
///
/// Refinement (figures 1 and 2). A triangle splits into four at its edge
/// midpoints. A leaf triangle with one split neighbour has a hanging midpoint
/// on that edge: it is a transition triangle and is output as two triangles
/// through the midpoint (figure 2 c), so it stays planar when the midpoint
/// moves (2 b). When it is split itself, the existing midpoint is reused
/// (2 d); when a second neighbour splits, it is split too (2 e, f). A
/// triangle is split only after the neighbours across its edges are at its
/// own level (a coarser neighbour is split first), so no midpoint ever lies
/// inside a longer edge: the output is conforming at every moment (every
/// interior edge has exactly two triangles, no vertex lies on another
/// triangle's edge). Splitting never changes the shape: a new midpoint starts
/// at the middle of its edge's current end points. Depth is bounded by
/// maxLevel.
///
/// Deformations move vertices; every vertex keeps its base (original)
/// position and the original surface normal there (interpolated at
/// midpoints), and its displacement from the base:
/// - functional (eq. 1): a vertex at distance d <= D from the picked point c
///   moves by f(d) = k exp(-a d^2) along its original normal (d measured on
///   the current surface positions);
/// - range: every vertex inside an axis-aligned box moves by one vector;
/// - smoothing (eq. 2): inside a ball, each vertex's displacement becomes
///   (1/n) sum over R of k_j z_j, R the vertex and its neighbours (n of them),
///   z_j their displacements, k_j = selfWeight for the vertex itself and 1
///   for the neighbours, normalised so that the weights sum to n (a constant
///   displacement field is kept).
/// Refinement happens only where the deformation needs it: before moving
/// anything, leaf triangles in the deformation's reach are split while the
/// new displacement bends one of their edges by more than `tolerance` (the
/// displacement at the edge's midpoint against the mean of its ends) and
/// they are above maxLevel; a range deformation splits the triangles its box
/// border crosses.

#include "latticekit/TriangleMesh.h"

#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

namespace lk
{

/// The most smoothing iterations one smoothing deformation may ask for.
constexpr int kMaximumSmoothingIterations = 10000;

class AdaptivePatchMesh
{
public:
  /// A manifold (possibly open) triangle mesh without degenerate triangles.
  /// Throws std::invalid_argument otherwise, or for maxLevel outside 0..12.
  explicit AdaptivePatchMesh(const TriangleMesh& base, int maxLevel = 4);

  int maxLevel() const { return maxLevel_; }

  /// Splits a leaf triangle (with whatever the conformity rules then need).
  /// Returns false if it is not a leaf or is at maxLevel.
  bool split(int triangle);

  /// Eq. 1 around `centre`; returns the number of vertices moved.
  int functionalDeformation(const Vec3& centre, double k, double a, double D, double tolerance);
  /// Every vertex inside [boxMin, boxMax] moves by `move`; triangles crossing
  /// the box border are refined to maxLevel first when refine is set.
  int rangeDeformation(const Vec3& boxMin, const Vec3& boxMax, const Vec3& move, bool refine = true);
  /// Eq. 2 inside the ball (centre, D), `iterations` times (0 to
  /// kMaximumSmoothingIterations; throws std::invalid_argument otherwise).
  int smoothingDeformation(const Vec3& centre, double D, int iterations = 1, double selfWeight = 1.0);

  std::size_t vertexCount() const { return base_.size(); }
  Vec3 position(int v) const { return base_[v] + displacement_[v]; }
  const Vec3& basePosition(int v) const { return base_[v]; }
  const Vec3& baseNormal(int v) const { return normal_[v]; }
  const Vec3& displacement(int v) const { return displacement_[v]; }

  /// The conforming output: leaves, transition leaves as two triangles.
  std::vector<std::array<int, 3>> triangles() const;
  /// Per output triangle: the level of its leaf.
  std::vector<int> triangleLevels() const;
  /// Per output triangle: the input triangle it lies in (its root's index).
  std::vector<int> triangleOrigins() const;
  /// The input mesh's vertices are the first inputVertexCount(); every later
  /// vertex is the midpoint of the edge between midpointEnds(v), two earlier
  /// vertices ({-1, -1} for an input vertex).
  std::size_t inputVertexCount() const { return inputVertexCount_; }
  std::array<int, 2> midpointEnds(int v) const;
  std::vector<int> leaves() const;
  int level(int triangle) const { return tris_[triangle].level; }
  std::size_t leafCount() const { return leafCount_; }
  /// Splits done so far.
  std::size_t splitCount() const { return splits_; }

private:
  struct Tri
  {
    std::array<int, 3> v;
    std::array<int, 3> mid{ { -1, -1, -1 } }; ///< midpoint of edge (v[e], v[e + 1]), once made
    int parent = -1;
    int firstChild = -1; ///< children are firstChild .. firstChild + 3
    int level = 0;
  };
  using Key = std::uint64_t;
  static Key key(int a, int b);
  int midpoint(int a, int b) const;
  int makeMidpoint(int a, int b);
  void addEdges(int t);
  int neighbour(int t, int a, int b) const;
  bool splitNow(int t);
  int hanging(int t) const;
  void refine(std::vector<int> candidates, const std::function<bool(int)>& needsSplit);
  std::vector<int> leavesNear(const Vec3& lo, const Vec3& hi) const;

  int maxLevel_;
  std::vector<Vec3> base_, normal_, displacement_;
  std::size_t inputVertexCount_ = 0;
  std::vector<std::array<int, 2>> midpointEnds_; ///< per vertex after the input's
  std::vector<Tri> tris_;
  std::unordered_map<Key, int> midpoints_;
  std::unordered_map<Key, std::array<int, 2>> edgeTris_;
  std::size_t leafCount_ = 0, splits_ = 0;
};

} // namespace lk
