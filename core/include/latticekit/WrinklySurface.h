#pragma once
/// \file WrinklySurface.h
/// Wrinkly surfaces on constrained irregular meshes (seed 000, Fujimoto and
/// Ohno, eqs. 10 to 15, figures 9 to 11).
///
/// Base patches (3.4, eq. 13). Every real control point p gets a bicubic
/// Bezier patch over its local (u, v) in [0, 1]^2. Its 16 points are the
/// degree elevation of a biquadratic net whose
///   - corners are the centroids of the four cells around p (figure 9),
///   - edge points are the midpoints of p and its +-u, +-v neighbours,
///   - centre is p.
/// On a regular grid this is exactly the uniform biquadratic B-spline of the
/// control points (tested to 1e-12), and neighbouring patches share their
/// boundary curves on any mesh (same corners, same midpoint). The paper's
/// figure 10 ratios are not legible in our copy; these are the simplest
/// integer ratios with that property (1:5 along an edge after elevation).
/// Degenerate patches (figure 10 b to d): a missing link's edge point is the
/// centroid of the cell that holds its direction, which is also both corners
/// beside it, so that side of the patch collapses to a point: three-sided
/// patches for one missing link, two-sided for two.
/// Heights (eq. 14) and attributes (colour, opacity) are built the same way
/// from per-point values.
///
/// 2D IST (eqs. 10 to 12). One IteratedShuffle per group (M_U, M_V, K). A
/// step along the group-g axis through a point maps the global value
/// X = index + local by F_g^-1, wraps it on a cyclic axis or mirrors it into
/// a translation axis (IteratedShuffle::mirrorInto), and carries the other
/// local value to the new point by eq. 8 (WrinklyGlobalAxes::crossFlip).
/// F_(U->V) applies U first, so its inverse steps along V, then along U;
/// F_(V->U) the other way round. Eq. 12 blends the two:
///   [P(H)](t) = alpha0 H(F_(U->V)^-1(t)) + alpha1 H(F_(V->U)^-1(t)).
/// On a regular grid both orders equal (F_U^-1(U), F_V^-1(V)) (eq. 9).
///
/// Surface (eq. 15): R(t) = P(t) + [P(H)](t) N(t), N the unit normal of the
/// base patch, oriented with the control mesh's cells.

#include "latticekit/IteratedShuffle.h"
#include "latticekit/WrinklyGlobalAxes.h"

#include <array>
#include <functional>
#include <utility>
#include <vector>

namespace lk
{

struct WrinklyParameters
{
  int shuffleU = 1;      ///< M_U
  int shuffleV = 1;      ///< M_V
  int iterations = 3;    ///< K
  double alpha0 = 0.5;   ///< weight of the U->V order
  double alpha1 = 0.5;   ///< weight of the V->U order
};

/// A local parameter value t = (n, (u, v)) (eq. 5).
struct WrinklyLocal
{
  int point = -1;
  double u = 0.0, v = 0.0;
};

class WrinklySurface
{
public:
  /// Throws std::invalid_argument for a mesh buildWrinklyGlobalAxes refuses,
  /// negative M or K, or alphas that are not in [0, 1] with sum 1.
  WrinklySurface(const WrinklyControlMesh& mesh, const WrinklyParameters& parameters);

  const WrinklyGlobalAxes& axes() const { return axes_; }
  const WrinklyParameters& parameters() const { return parameters_; }
  /// Changes K (e.g. once wrinklyIterationsForTolerance has chosen it)
  /// without rebuilding the axes and patches; throws like IteratedShuffle.
  void setIterations(int iterations);
  int attributeComponents() const { return attributeComponents_; }
  const std::vector<int>& patchPoints() const { return axes_.patchPoints; }

  /// The bicubic Bezier points of a real point's base patch, u-major
  /// (index 4 i + j for u-degree i, v-degree j).
  std::array<Vec3, 16> basePatch(int point) const;

  Vec3 basePoint(const WrinklyLocal& t) const;
  /// Unit normal, oriented with the control mesh; where the patch is
  /// degenerate the parameter is pulled towards the patch centre.
  Vec3 baseNormal(const WrinklyLocal& t) const;
  /// +1 where the patch's u x v agrees with the control mesh's cells, else -1.
  double patchOrientation(int point) const;
  double height(const WrinklyLocal& t) const;                  ///< H (eq. 14), no IST
  void attributes(const WrinklyLocal& t, double* out) const;   ///< same, attributes

  /// One step of the 2D IST along the group's axis (F_g^-1 with eq. 8).
  WrinklyLocal inverseStep(int group, const WrinklyLocal& t) const;
  /// F_(U->V)^-1 (order 0) or F_(V->U)^-1 (order 1), eq. 11.
  WrinklyLocal inverseShuffle(int order, const WrinklyLocal& t) const;

  double wrinklyHeight(const WrinklyLocal& t) const;                 ///< eq. 12 on H
  void wrinklyAttributes(const WrinklyLocal& t, double* out) const;  ///< eq. 12 on attributes
  Vec3 surfacePoint(const WrinklyLocal& t) const;                    ///< eq. 15

  /// Largest extent of a base patch's Bezier points (for level of detail).
  double largestPatchSize() const;

private:
  int patchOf(int point) const;
  void evaluate(int patch, int channel0, int channels, double u, double v, double* out) const;
  /// out += weight * (channels channel0 ... of the patch at (u, v)).
  void accumulate(int patch, int channel0, int channels, double u, double v, double weight, double* out) const;
  /// dP/du, dP/dv of the base patch.
  std::pair<Vec3, Vec3> partials(int patch, double u, double v) const;

  WrinklyGlobalAxes axes_;
  WrinklyParameters parameters_;
  int attributeComponents_ = 0;
  int channels_ = 0; ///< x, y, z, height, attributes
  std::vector<int> patchIndex_;          ///< per point, -1 for virtual
  std::vector<double> control_;          ///< per patch: 16 x channels_
  std::vector<double> orientation_;      ///< per patch: +1 or -1
  std::array<IteratedShuffle, 2> shuffle_;
};

struct WrinklyTessellation
{
  std::vector<Vec3> points;              ///< displaced (eq. 15)
  std::vector<Vec3> normals;             ///< base normals
  std::vector<double> heights;           ///< the IST'd height of each point
  std::vector<double> attributes;        ///< points x attributeComponents
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> trianglePoint;        ///< control point whose patch holds it
};

/// Samples every base patch on a (resolution + 1)^2 grid. Each vertex takes
/// the blended IST height and attributes of the grid cell it starts (sampled
/// at the cell's centre: the IST is discontinuous at piece borders, and a
/// vertex exactly on one would depend on rounding); patch borders and
/// collapsed sides are merged, so the mesh has no cracks. `progress` gets
/// values in [0, 1] and may return false to stop (the result is then empty).
/// Throws std::invalid_argument for resolution < 1 or more than 50 million
/// triangles.
WrinklyTessellation tessellateWrinkly(const WrinklySurface& surface, int resolution,
  const std::function<bool(double)>& progress = {});

/// The smallest K whose level-K pieces are no longer than `tolerance` on the
/// largest patch (adaptive level of detail), capped at maxIterations.
int wrinklyIterationsForTolerance(const WrinklySurface& surface, double tolerance, int maxIterations = 8);

} // namespace lk
