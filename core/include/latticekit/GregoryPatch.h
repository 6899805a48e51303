#pragma once
/// \file GregoryPatch.h
/// The bicubic Gregory patch (Chiyokura and Kimura 1983; seed 004, eqs. 2.3
/// to 2.5): 20 control points. P(i, j) for the 12 boundary points (i or j in
/// {0, 3}); the four interior positions hold two points each: inner(i, j, 0)
/// is the one the v = 0 / v = 1 boundaries use, inner(i, j, 1) the one the
/// u = 0 / u = 1 boundaries use:
///   Q11 = (u P110 + v P111) / (u + v)
///   Q12 = (u P120 + (1-v) P121) / (u + 1 - v)
///   Q21 = ((1-u) P210 + v P211) / (1 - u + v)
///   Q22 = ((1-u) P220 + (1-v) P221) / (2 - u - v)
///   S(u, v) = sum_ij B_i(u) B_j(v) Q_ij(u, v)
/// so that the cross-boundary derivative of each side is set by that side's
/// own interior points, independently of the other sides.

#include "latticekit/TriangleMesh.h"

#include <array>

namespace lk
{

struct GregoryPatch
{
  std::array<Vec3, 16> grid{};    ///< index 4*i + j; interior entries unused
  std::array<Vec3, 8> interior{}; ///< index 2*(2*(i-1) + (j-1)) + k for i, j in {1, 2}

  Vec3& P(int i, int j) { return grid[static_cast<std::size_t>(4 * i + j)]; }
  const Vec3& P(int i, int j) const { return grid[static_cast<std::size_t>(4 * i + j)]; }
  Vec3& inner(int i, int j, int k) { return interior[static_cast<std::size_t>(2 * (2 * (i - 1) + (j - 1)) + k)]; }
  const Vec3& inner(int i, int j, int k) const
  {
    return interior[static_cast<std::size_t>(2 * (2 * (i - 1) + (j - 1)) + k)];
  }

  /// Position and first derivatives at (u, v) in [0, 1]^2 (derivatives may be null).
  Vec3 evaluate(double u, double v, Vec3* du = nullptr, Vec3* dv = nullptr) const;
  /// Unit normal du x dv; at a degenerate point, the limit from inside the patch.
  Vec3 normal(double u, double v) const;
  /// The same from derivatives already evaluated at (u, v).
  Vec3 normalFrom(const Vec3& du, const Vec3& dv, double u, double v) const;
};

/// Cubic Bezier helpers.
Vec3 bezier(const std::array<Vec3, 4>& c, double t);
Vec3 bezierDerivative(const std::array<Vec3, 4>& c, double t);

} // namespace lk
