#pragma once
/// \file StrokeSplitter.h
/// The split mode of section 3.1.4 while the stroke is being drawn: the mesh
/// is held as a half-edge mesh and each new stroke segment is cut into it
/// locally, in time proportional to the faces the segment crosses (nothing
/// is rebuilt per segment). The planner's pen and the latency benchmark use
/// it; strokeToFeatureLine's Split mode does the same for a whole stroke at
/// once.
///
/// Each stroke point is projected onto the surface (the closest point of the
/// mesh as given; splitting never moves the surface, so the tree built once
/// stays valid). The segment from the previous line vertex to that point is
/// followed across the faces in the plane that holds the segment and the
/// mean of the two surface normals: where the plane crosses an edge, the
/// edge is split (a new vertex exactly in that plane and on the edge); where
/// it passes through a vertex, the vertex joins the line; the point itself
/// becomes a vertex inside its face. Faces are split between consecutive
/// line vertices and re-triangulated, so the mesh stays a manifold triangle
/// mesh and the new edges follow the stroke (section 3.1.4, eq. 3.13's
/// crossings).
///
/// The walk ends only on the point itself: where the plane's section passes
/// the point's place along the segment at a distance (the far side of a
/// ridge, between points far apart), the plane is refused. A segment that no
/// plane follows (the mean normal's, or either end's) is walked in halves,
/// cut at the surface point nearest its midpoint, or first along the edge
/// that points most nearly at the point, a few levels deep; so sparse
/// points (a script's, 10-25 mm apart round a mandible) mostly make a line,
/// and those that cannot are refused in bounded time.
///
/// Every addPoint is a transaction: the walk is planned on the unchanged
/// mesh first and applied only when it succeeds, so a point that misses the
/// surface or a walk that leaves the mesh at a border throws
/// std::invalid_argument and leaves the mesh and the line as they were.

#include "latticekit/TriangleMesh.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace lk
{

class StrokeSplitter
{
public:
  /// Builds the half-edge mesh and the closest-point tree (once per mesh).
  /// `maxDistance`: stroke points farther from the surface miss it (0: five
  /// mean edge lengths). Throws std::invalid_argument for an invalid or
  /// non-manifold mesh.
  explicit StrokeSplitter(const TriangleMesh& mesh, double maxDistance = 0.0);
  ~StrokeSplitter();
  StrokeSplitter(const StrokeSplitter&) = delete;
  StrokeSplitter& operator=(const StrokeSplitter&) = delete;

  /// Adds the next stroke point. The first point becomes a vertex in its
  /// face; every later one is joined to the line by the walk described
  /// above. Returns how many vertices joined the line (0 when the point
  /// projects onto the line's last vertex).
  std::size_t addPoint(const Vec3& point);

  /// Joins the line's last vertex back to its first (a closed feature line;
  /// the line then repeats its first vertex). Throws when the line has fewer
  /// than three vertices or the walk fails (the line stays open then).
  void close();

  /// The feature line: vertex ids of mesh(), in stroke order.
  const std::vector<std::int64_t>& line() const;
  bool closed() const;

  /// The current mesh (vertex ids are stable: the input's vertices keep
  /// their ids and new vertices follow). O(mesh size).
  TriangleMesh mesh() const;
  std::size_t numberOfTriangles() const;
  double meanEdgeLength() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace lk
