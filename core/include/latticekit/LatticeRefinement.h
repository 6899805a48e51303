#pragma once
/// \file LatticeRefinement.h
/// Global refinement of a fitted lattice (beyond seed 004): lattice vertices
/// move so that the lattice surface passes closer to the original mesh. The
/// paper's QEM places each vertex once, locally; and quad pairing loses
/// accuracy because the positions were optimised for triangles (its first
/// open problem). This refinement works on the finished lattice, triangles
/// and quads alike.
///
/// Energy: E(X) = sum_s d(p_s, S_X)^2 over samples p_s of the original mesh
/// (Metro's samples: vertices, edges, faces), S_X the lattice surface of
/// control points X; with the original mesh given, plus the other direction,
/// w sum_r d(S_X(patch_r, u_r, v_r), M)^2 over nine fixed parameter points of
/// every patch, to the original mesh M. Metro is symmetric: a bulge of the
/// surface away from the original, where no sample of the original lies, is
/// invisible to the first sum alone. w makes the two sums weigh the same
/// (samples / reverse points, times reverseWeight).
///
/// Each outer iteration (Gauss-Newton with closest points re-found, like ICP):
/// 1. build the surface, find every sample's foot point (patch, u, v) and the
///    surface normal n_s there (closest point on a tessellation, CGAL AABB
///    tree, then Gauss-Newton on the patch);
/// 2. linearise the surface point at (patch, u, v) in X. The exact surface is
///    not affine in X (tangent planes, normalised basis vectors), but it passes
///    exactly through points that are: each vertex's rounded point V' (eq.
///    2.1, area weights frozen), each face's centre (the mean of its Doo-Sabin
///    points, i.e. its centroid), and, up to the tangent-plane projection,
///    each edge curve's midpoint (Q + R) / 2. A sample's point is modelled as
///    the blend of its patch's anchors: biquadratic (Lagrange) over the 3 x 3
///    nodes of a quad's patch (corners V', side midpoints, centre), bilinear
///    over the four corners of a split face's patch;
/// 3. solve the linear least-squares problem
///      min sum_s (n_s . (S_s + J_s dX - p_s))^2 + lambda sum_v |dX_v|^2
///    with Ceres (sparse normal Cholesky); the damping lambda is relative to
///    the mean squared residual weight, and point-to-plane residuals leave
///    the tangential drift to it. Where the error is not along the normal (a
///    foot point on a border, the sample beyond it) the residual is the whole
///    vector S_s + J_s dX - p_s instead. The reverse points give the same
///    residuals with the original's closest point and triangle normal. The
///    residuals of one face are compressed into one block by a QR
///    decomposition (exact for this linear step), so Ceres sees one block
///    per face instead of one per sample;
/// 4. apply dX and rebuild; Levenberg-Marquardt on the exact energy: a step
///    that lowers it is kept and lambda halves (down to 1e-4), one that does
///    not is retried with lambda four times larger (up to four times), then
///    the refinement stops.
/// A step may not fold the surface (the fold guard, beyond the paper): the
/// linear model sees the surface through points of it, not the shape of the
/// lattice, and a step could turn a small lattice face over between its
/// neighbours or fold a patch into a thin fin along the original, where the
/// surface passes through itself. Vertices whose step turns a face over
/// (normals more than 150 degrees from a neighbour's, and further than
/// before; creases excepted) or makes a face's patches turn more of their
/// normals away from the face's normal at the start have their step halved,
/// the fifth time zeroed; faces where the original is itself folded (bent by
/// more than 120 degrees) are left free (LatticeRefinement.cxx, FoldGuard).
/// The energy also carries a tail penalty, mu sum max(0, d - tau)^2 over both
/// directions' points, a soft bound on the largest distance (see
/// RefinementOptions::tailWeight); its residuals join the same blocks.
/// Vertices flagged fixed (locked feature vertices) do not move, so feature
/// edges stay exactly where they were. The surface fitted is the one of the
/// given rounding weights (the fit filter gives feature vertices weight 0, so
/// the surface passes through them).

#include "latticekit/LatticeSurface.h"
#include "latticekit/PolygonMesh.h"
#include "latticekit/TriangleMesh.h"

#include <functional>
#include <string>
#include <vector>

namespace lk
{

struct RefinementOptions
{
  int iterations = 8;
  double damping = 1e-2;          ///< initial lambda, relative
  std::vector<char> fixed;        ///< per lattice vertex; empty: none fixed
  int locatorResolution = 4;      ///< tessellation the closest-point search starts from
  /// The original mesh, for the reverse direction (surface to original);
  /// nullptr: the samples' direction only.
  const TriangleMesh* original = nullptr;
  double reverseWeight = 1.0;     ///< of the reverse sum against the samples' (0: off)
  /// The tail penalty mu sum max(0, d - tau)^2 (both directions, the reverse
  /// points with their weight): Metro's max is one point, which the squared
  /// sum trades for the mean. tau = tailThreshold x the samples' RMS distance
  /// before the refinement; mu = tailWeight (0: off, the default: it lowers
  /// the max on the first TCIA mandible but not on the second, and costs the
  /// head skin mean at 100; see NOTES, issue 4).
  double tailWeight = 0.0;
  double tailThreshold = 4.0;
  /// The rounding weights of the surface being fitted (LatticeSurface.h); the
  /// linear model follows the vertex weights, the edge weights only the
  /// exact energy that accepts or refuses each step.
  LatticeWeights weights;
  /// Called with the fraction done: after the set-up (the foot points, and
  /// with `original` the reverse points; together weighed as half an
  /// iteration), then twice per iteration (after the solve and after the
  /// step is measured). Returning false stops there, and a step not yet
  /// measured is undone.
  std::function<bool(double)> progress;
  /// Worker threads: 0, every hardware thread; the chunked work (foot
  /// points, reverse points, the face blocks) uses at most 8. The result does
  /// not depend on the count (tested), so a fit is the same on every machine.
  int threads = 0;
};

struct RefinementReport
{
  double initialRms = 0.0; ///< sqrt(E / samples) before
  double finalRms = 0.0;   ///< and after
  /// After: the mean distance (the two directions' means averaged when the
  /// original is given) and the largest, over the samples and the surface's
  /// reverse points; a cheap stand-in for Metro's mean and max.
  double finalMean = 0.0;
  double finalMax = 0.0;
  int iterations = 0;      ///< outer iterations that lowered the energy
};

/// Why `options` cannot drive a refinement, or "" when they can: the checks
/// that need neither the lattice nor the samples (iterations, reverse weight,
/// tail penalty). refineLatticeFit makes them too; a caller can make them
/// before the work that comes first.
std::string refinementOptionsProblem(const RefinementOptions& options);

/// Moves the points of `lattice` in place. `samples` are points of the
/// original surface (its vertices). Throws std::invalid_argument for a lattice
/// that cannot carry a surface, no samples, or a `fixed` of the wrong size.
RefinementReport refineLatticeFit(PolygonMesh& lattice, const std::vector<Vec3>& samples,
  const RefinementOptions& options);

/// Vertices for the largest distances (beyond the paper). Metro's max is one
/// point, typically where the original has a detail narrower than the lattice
/// spacing (a thin process, a concave slice step), which a G1 surface rounds
/// off and a flat mesh can put a vertex on. Each of the `count` samples
/// farthest from the lattice surface (each in a different face, none closer
/// than twice the mean lattice edge length to another) gets a new lattice
/// vertex: the edge of its foot point's triangle nearest to it is split at
/// its midpoint. Never split: edges in `keep` (features), edges with a
/// rounding weight, border edges and edges of quads. A refinement with the
/// tail penalty then spends the new vertices on those places (the fit filter's
/// RefinementInsertions). `weights.vertex` and `fixed`, when not empty, grow
/// by 1 and 0 per new vertex. Returns the vertices inserted: fewer than
/// `count` where no edge qualifies.
int insertVerticesAtLargestDistances(PolygonMesh& lattice, const std::vector<Vec3>& samples, int count,
  const std::vector<std::pair<std::int64_t, std::int64_t>>& keep, LatticeWeights& weights,
  std::vector<char>& fixed, int locatorResolution = 4, int threads = 0);

} // namespace lk
