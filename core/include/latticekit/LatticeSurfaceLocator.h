#pragma once
/// \file LatticeSurfaceLocator.h
/// Closest point on a lattice surface. A CGAL AABB tree over a tessellation
/// gives a surface point whose distance bounds the answer; every patch whose
/// control-point box (which contains the patch) lies within that bound is
/// searched: from its nearest grid sample, Gauss-Newton steps clamped to the
/// parameter square, then a pattern search, on the exact Gregory surface.

#include "latticekit/ClosestPointTree.h"
#include "latticekit/LatticeSurface.h"

#include <array>
#include <memory>

namespace lk
{

class LatticeSurfaceLocator
{
public:
  struct Result
  {
    std::size_t patch = 0;
    double u = 0.0, v = 0.0;
    Vec3 point{ Vec3::Zero() };
    double distance = 0.0;
  };

  /// The surface must outlive the locator. `resolution` is the tessellation
  /// the search starts from (segments per patch side).
  explicit LatticeSurfaceLocator(const LatticeSurface& surface, int resolution = 8);

  Result closest(const Vec3& query) const;

private:
  void refine(const Vec3& query, Result& r) const;

  const LatticeSurface& surface_;
  int resolution_;
  TriangleMesh mesh_;
  std::vector<Box3> boxes_; ///< control-point box of each patch (it contains the patch)
  std::unique_ptr<ClosestPointTree> tree_;
};

} // namespace lk
