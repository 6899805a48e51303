#pragma once
/// \file ClosestPointTree.h
/// Closest point on a triangle mesh through CGAL's AABB tree. Queries are
/// const and thread-safe once the tree is built. For spatially coherent
/// queries (Metro's samples) pass the previous hit as a hint: it bounds the
/// search from the start, as Metro's grid walk does.

#include "latticekit/SurfaceSampling.h"
#include "latticekit/TriangleMesh.h"

#include <memory>

namespace lk
{

class ClosestPointTree
{
public:
  struct Hit
  {
    Vec3 point{ Vec3::Zero() };
    std::int64_t face{ -1 };
    double distance{ 0.0 };
  };

  /// Builds the tree. The mesh must pass validateTriangleMesh.
  explicit ClosestPointTree(const TriangleMesh& mesh);
  /// A tree over the faces of `mesh` that meet the box [lo, hi] only, for
  /// queries in and near it (a stroke on a skull of 1.5 million faces meets
  /// a few thousand). A query whose answer a face outside the box could
  /// change (its distance reaches the box's side) goes to a tree over the
  /// whole mesh, built the first time one does; so every answer is the
  /// closest point on the whole mesh (between faces at the same distance the
  /// face may differ). `mesh` must outlive the tree.
  ClosestPointTree(const TriangleMesh& mesh, const Vec3& lo, const Vec3& hi);
  ~ClosestPointTree();
  ClosestPointTree(const ClosestPointTree&) = delete;
  ClosestPointTree& operator=(const ClosestPointTree&) = delete;

  /// Closest point, with no hint (slower: the search starts from an arbitrary triangle).
  Hit closest(const Vec3& query) const;
  /// Closest point, starting from a hint (any earlier hit on this mesh).
  Hit closest(const Vec3& query, const Hit& hint) const;

  /// Distances of samples [begin, end) to the surface, written to out[i],
  /// chaining each hit as the hint of the next query.
  void distances(const SampleSet& samples, std::size_t begin, std::size_t end, double* out) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace lk
