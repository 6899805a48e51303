#pragma once
/// \file CutCaps.h
/// Private to the cut (MeshCut.cxx, InnerWalls.cxx): the caps that close a
/// cut piece, and the loop geometry they are made from. A loop's fitted
/// plane, the loop's outline in that plane (which side of it a point lies
/// on), one cap per loop (CGAL's hole filling, flat for a near-planar loop),
/// one shared flat cap for loops nested in one plane (an annulus), and the
/// check that a finished piece's caps do not cross its surface. CGAL stays in
/// CutCaps.cxx.

#include "latticekit/PolygonMesh.h"

#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace lk
{
namespace cut
{

/// The cap of a loop: new points and triangles (indices: < 0 means loop
/// vertex -(i+1), >= 0 a new point), oriented so that the loop runs
/// a -> b -> ... along the triangles' boundary. Empty on failure.
struct Cap
{
  std::vector<Vec3> points;
  std::vector<std::array<std::int64_t, 3>> triangles;
};

/// Loops within this fraction of their bounding-box diagonal of their
/// fitting plane get a flat cap.
constexpr double kFlatCapTolerance = 0.05;

/// A loop's least-squares plane, and whether the loop is near it.
struct LoopPlane
{
  Vec3 centre = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  Vec3 u = Vec3::UnitX(), v = Vec3::UnitY(); ///< in the plane, u x v = normal
  double deviation = 0.0;                    ///< the farthest loop point from the plane
  double tolerance = 0.0;                    ///< kFlatCapTolerance x the loop's box diagonal
  bool flat = false;
};

LoopPlane fitLoopPlane(const std::vector<Vec3>& loop);

/// A loop projected into a plane: a closed polygon in the plane's (u, v).
/// Which side of it the projection of a point lies on is CGAL's exact
/// predicate (bounded_side_2).
class LoopOutline
{
public:
  enum class Side
  {
    Inside,
    OnBorder,
    Outside
  };
  LoopOutline(const std::vector<Vec3>& loop, const LoopPlane& plane);
  ~LoopOutline();
  LoopOutline(LoopOutline&&) noexcept;
  LoopOutline& operator=(LoopOutline&&) noexcept;

  Side side(const Vec3& p) const;
  /// Whether p's projection lies in the outline's bounding box (a cheap test
  /// before side()).
  bool inBox(const Vec3& p) const
  {
    const double x = plane_.u.dot(p - plane_.centre), y = plane_.v.dot(p - plane_.centre);
    return x >= min_[0] && x <= max_[0] && y >= min_[1] && y <= max_[1];
  }

private:
  struct Polygon;
  LoopPlane plane_;
  std::array<double, 2> min_{}, max_{};
  std::unique_ptr<Polygon> polygon_;
};

/// The cap of one loop; `plane` is the loop's fitted plane (fitLoopPlane).
Cap makeCap(const std::vector<Vec3>& loop, const LoopPlane& plane);

/// One flat cap for loops nested in one plane (the outer and the inner wall
/// of a hollow bone: an annulus): a 2D constrained Delaunay triangulation of
/// the part of the plane inside an odd number of loops, then refined inside
/// (CGAL's Liepa refinement, which keeps the loops' edges). Ids < 0 are
/// -(k+1) for vertex k of the loops taken one after another. Empty when the
/// loops' projections touch or cross.
Cap makeNestedCap(const std::vector<std::vector<Vec3>>& loops, const LoopPlane& plane);

/// Pairs of intersecting triangles of a capped piece of which at least one is
/// a cap triangle (faceOrigin < 0): a cap that crosses the piece's surface or
/// another cap (nested loops around a hollow bone), and the deepest pair's
/// overlap; markedFaceCrossings with the caps marked (on the skull's
/// craniotomy CGAL's test runs on a few thousand of 563,000 faces).
std::pair<std::size_t, double> capCrossings(const PolygonMesh& piece, const std::vector<std::int64_t>& faceOrigin);

} // namespace cut
} // namespace lk
