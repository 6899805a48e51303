#pragma once
/// \file LatticeSurfaceLocator.h
/// Closest point on a lattice surface: a CGAL AABB tree over a fine
/// tessellation gives the starting patch and (u, v); Gauss-Newton steps on
/// that patch (clamped to its parameter square) refine the point onto the
/// exact Gregory surface.

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
  Result start(const Vec3& probe) const;
  void refine(const Vec3& query, Result& r) const;

  const LatticeSurface& surface_;
  int resolution_;
  TriangleMesh mesh_;
  std::vector<std::array<double, 6>> uv_; ///< (u, v) of each triangle's three corners
  std::vector<std::size_t> patchOf_;
  std::unique_ptr<ClosestPointTree> tree_;
};

} // namespace lk
