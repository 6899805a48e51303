#pragma once
/// \file ConvexHull.h
/// The convex hull of a point set (CGAL's quickhull), kept as the planes of
/// its faces so as to tell how deep a point lies inside it. The outer side
/// of a bone lies on its hull; the inner side of an arch (a mandible's
/// lingual side, the medial side of its ramus) lies deep inside it.

#include "latticekit/TriangleMesh.h"

#include <cstddef>
#include <vector>

namespace lk
{

class ConvexHull
{
public:
  /// The hull of `points`; points that are not finite are left out. Empty
  /// when the points span no volume (fewer than four, or all on one plane
  /// or one line).
  explicit ConvexHull(const std::vector<Vec3>& points);

  bool empty() const { return faces.empty(); }
  /// The number of the hull's (triangular) faces.
  std::size_t numberOfFaces() const { return faces.size(); }

  /// How deep `x` lies inside the hull: its distance to the hull's boundary
  /// when inside (the nearest face's plane), 0 on it; outside, minus its
  /// distance beyond the farthest face's plane (no farther than the hull
  /// itself). NaN when the hull is empty or `x` is not finite.
  double depth(const Vec3& x) const;

private:
  struct Face
  {
    Vec3 normal;   ///< unit, outward
    double offset; ///< normal . x for x on the face's plane
  };
  std::vector<Face> faces;
};

} // namespace lk
