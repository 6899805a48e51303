#pragma once
/// \file BezierIFS.h
/// Bezier curves and surfaces as attractors of iterated function systems
/// (seed 003, Horie, Mochizuki, Nagamine and Cai).
///
/// The Bernstein curve of degree n is B(t) = (B_0^n(t), ..., B_n^n(t)) in
/// R^(n+1). For a sub-interval [a, b] of [0, 1] the reparametrisation
/// t -> a + s t (s = b - a) is linear on the Bernstein coefficients:
/// B(a + s t) = M B(t), M the de Casteljau subdivision matrix. On the curve
/// 1.x = 1, so any c gives an affine map w(x) = (M - c 1^T) x + c that agrees
/// with M on the curve (the paper's remark that the (1,1) entry of w_1 "can
/// take any value"). Here c = (1 - s) B(t*), with t* = a / (1 - s) the fixed
/// point of t -> a + s t: this reproduces the paper's two 4x4 maps for the
/// cubic split at 1/2 exactly, and makes every map contractive: the
/// eigenvalues of M are 1, s, ..., s^n and the eigenvalue 1 (left
/// eigenvector 1^T) becomes 1 - 1.c = s, so the spectral radius is s < 1.
/// Surfaces of degree (n, m) live in R^((n+1)(m+1)) (the outer product
/// B(u) B(v)^T, stored u-major), with one map per pair of sub-intervals:
/// M_u (x) M_v, c = (1 - s_u s_v) B(u*, v*).
/// Plotting maps a point x of the attractor to F(x) = sum_i x_i P_i.
///
/// The direct affine IFS of a quadratic curve (section 4): two affine maps of
/// the curve's plane, each taking the control points (P0, P1, P2) to those of
/// one half (de Casteljau at t).
///
/// Drawing: the deterministic algorithm applies every composition of depth s
/// to a base figure (the segment B(0)B(1), or the square's corners
/// B(0,0)..B(1,1)); the chaos game iterates one point through maps chosen at
/// random with given probabilities. Every point carries its exact parameter
/// (composed alongside), so tests can compare it with de Casteljau.

#include "latticekit/TriangleMesh.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace lk
{

/// One affine map x -> A x + c, with the parameter map t -> a + s t
/// (per direction for surfaces).
struct IfsMap
{
  Eigen::MatrixXd A;
  Eigen::VectorXd c;
  double a[2] = { 0.0, 0.0 }; ///< parameter offset in u, v
  double s[2] = { 1.0, 1.0 }; ///< parameter scale in u, v
};

/// The most maps an IFS may have (the papers use 2 to 4; a surface's are the
/// square of its intervals): more would only exhaust memory.
constexpr std::size_t kMaximumIfsMaps = 10000;

/// Breaks b_1 < ... < b_{k-1} in (0, 1) give k sub-intervals. Throws
/// std::invalid_argument for breaks outside (0, 1) or not increasing, for
/// more than kMaximumIfsMaps maps, and for maps that would take more than
/// 1 GB (a surface's map is a matrix of ((n+1)(m+1))^2 values).
std::vector<IfsMap> bernsteinCurveMaps(int degree, const std::vector<double>& breaks);
std::vector<IfsMap> bernsteinSurfaceMaps(int degreeU, int degreeV, const std::vector<double>& breaks);

/// The Bernstein vector B(t) (curves) or B(u) B(v)^T, u-major (surfaces).
Eigen::VectorXd bernsteinCurve(int degree, double t);
Eigen::VectorXd bernsteinSurface(int degreeU, int degreeV, double u, double v);

/// De Casteljau evaluation of a curve, and of a surface with control points
/// u-major ((degreeU + 1) x (degreeV + 1)), for the exactness checks.
Vec3 deCasteljau(const std::vector<Vec3>& control, double t);
Vec3 deCasteljauSurface(const std::vector<Vec3>& control, int degreeU, int degreeV, double u, double v);

/// Section 4: the two affine maps (3x3 A acting on points, c) of the plane of
/// three control points that take them to the control points of [0, t] and
/// [t, 1]. Throws std::invalid_argument for collinear control points or t
/// outside (0, 1).
std::vector<IfsMap> quadraticPlanarMaps(const std::vector<Vec3>& control, double t);

/// Spectral radius of a map's linear part (contractivity check).
double spectralRadius(const IfsMap& map);

struct IfsPoints
{
  std::vector<Vec3> points;                 ///< F(x), or the point itself for planar maps
  std::vector<std::array<double, 2>> parameters; ///< exact (u, v); v = 0 for curves
};

/// Deterministic algorithm: every composition of `depth` maps applied to the
/// base figure's vertices (`base`, in the IFS space), in the order of the
/// maps (leaf after leaf). `control` maps the IFS space to 3D (empty: the
/// space is 3D already, as for planar maps).
IfsPoints deterministicIfs(const std::vector<IfsMap>& maps, const std::vector<Eigen::VectorXd>& base,
  const std::vector<std::array<double, 2>>& baseParameters, int depth, const std::vector<Vec3>& control);

/// Chaos game: `count` points after `skip` discarded iterations, maps chosen
/// with `probabilities` (summing to 1) by a generator seeded with `seed`.
IfsPoints chaosGame(const std::vector<IfsMap>& maps, const std::vector<double>& probabilities,
  const Eigen::VectorXd& start, std::array<double, 2> startParameter, std::size_t count, std::uint64_t seed,
  const std::vector<Vec3>& control);

} // namespace lk
