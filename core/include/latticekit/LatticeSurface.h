#pragma once
/// \file LatticeSurface.h
/// The lattice surface (seed 004, section 2.1; the XVL lattice of Wakita,
/// Chiyokura et al.): a polygonal control mesh becomes a network of cubic
/// Bezier curves, one per lattice edge, filled with bicubic Gregory patches
/// that join with tangent-plane (G1) continuity.
///
/// Construction, with the choices made where the paper is silent or its
/// printed formulas lost their fractions:
/// 1. One Doo-Sabin step: in face F (n vertices) the point of vertex i is
///    sum_j a_{j-i} P_j with a_0 = (n + 5) / 4n, a_k = (3 + 2 cos(2 pi k / n)) / 4n.
/// 2. Eq. 2.1, the rounded vertex point: V' = sum_F k_F DS(F, V), k_F = area of
///    the lattice face F over the total area of the faces around V.
/// 3. Eq. 2.2, the inner control points of the edge curve V0' -> V3': with Q the
///    midpoint of the Doo-Sabin points of V0 in the two faces beside the edge
///    (the one face on a boundary edge), P1' = (4 Q - P0') / 3, and likewise
///    P2' = (4 R - P3') / 3. The printed "4/3 Q - P0'" is not affine (its
///    weights sum to 1/3); (4Q - P0')/3 is, and it makes the curve leave P0'
///    towards Q.
/// 4. Tangent planes: at a lattice vertex the plane through V' normal to the
///    area-weighted face normal; every P1' is projected into it, so all curve
///    tangents at the vertex are coplanar, as G1 needs at extraordinary
///    vertices. The projection keeps the tangent's length, and no tangent is
///    shorter than a sixth of its edge's chord or longer than 3/4 of it (on a
///    regular grid eq. 2.2 gives a third): at a vertex where two large faces
///    dominate, eq. 2.2 gives an almost zero tangent, and the patches beside
///    it fold; on a crumpled lattice it can give tangents so long that the
///    curve stops at its midpoint (the bound keeps |C'(1/2)| >= 3/8 chord).
/// 5. Quads take one Gregory patch. Other faces (triangles, pentagons, ...)
///    take n quad patches meeting at the face centre (the mean of the face's
///    Doo-Sabin points): each edge curve is split at t = 1/2 (de Casteljau) and
///    an inner curve runs from that midpoint to the centre, its end tangents
///    projected into the tangent planes there (at the centre: the plane of
///    the edge-curve midpoints; at the midpoint: the plane of the edge's
///    b(1/2) and C'(1/2)), with the same floor of a sixth of the chord.
///    Unless a quad lies beside the edge, b(1/2) is kept at least 10 degrees
///    from C'(1/2), at least half as long as b0 and b1 on average, and on the
///    side of the curve that b0 and b1 are on, within the midpoint's tangent
///    plane (on a crumpled lattice b(1/2) can be nearly zero, nearly along the
///    curve, or across it; see step 6: k(t), h(t) then blow up or change
///    sign). The midpoint's plane normal is turned like the edge's ends'
///    planes, so both faces agree on it, and each inner curve leaves the
///    midpoint into its own face, at least 10 degrees from the edge; where
///    the lattice folds sharply at an edge, the centre can lie behind it.
///    Without these, the patches beside a sharply folded edge folded over
///    each other along the edge or the inner curve.
/// 6. Interior Gregory points, Chiyokura and Kimura's basis-patch method:
///    every curve C carries a vector function b(t) = (1-t) b0 + t b1, with b0,
///    b1 in the end tangent planes and perpendicular to the curve. The
///    cross-boundary derivative of each patch along C is
///    D(t) = k(t) b(t) + h(t) C'(t) with k, h linear, fitted to the patch's
///    corner tangents. D (cubic) gives the side's two interior points. Both
///    patches beside C use the same b, so their tangent planes along C are
///    both spanned by b(t) and C'(t): G1 holds for every t, not only at
///    samples.
/// Open lattices: a boundary edge's curve is the uniform cubic B-spline of the
/// boundary polygon (a boundary vertex's point is (p + 4 V + q) / 6 with p, q
/// its boundary neighbours), so the surface ends on a C2 curve that depends
/// on the boundary alone; the vertex's tangent plane contains that curve's
/// tangent, and the interior curves there are projected into it as above.
///
/// Rounding weights (XVL's lattice weights), LatticeWeights:
/// - an edge of weight 0 is a crease, as is every boundary edge: no G1 is
///   asked across it. Around each vertex the faces fall into sectors between
///   creases, each with its own tangent plane;
/// - an edge of weight w in (0, 1) stays G1 but is rounded more tightly: its
///   eq. 2.2 point Q moves towards the lattice edge's third point,
///   Q_w = w Q + (1 - w) (2 V + X) / 3, before the projection into the
///   (unchanged) tangent plane, so the curve leans towards the lattice edge
///   as w falls;
/// - a vertex on two creases lies on the uniform cubic B-spline of the crease
///   polygon, V' = (p + 4 V + q) / 6, and both sectors' planes contain that
///   curve's tangent (q - p) / 6 (so a boundary is the B-spline of the
///   boundary polygon, and the surface ends on it);
/// - a vertex on three or more creases is a corner: V' = V, crease curves
///   leave it along the lattice edges ((b - V) / 3), and each sector's plane
///   is spanned by its two bounding crease tangents. A cube with every edge
///   at weight 0 is therefore the cube itself;
/// - a crease ending at a smooth vertex (a dart) fades into that vertex's plane;
/// - a vertex weight w in [0, 1] moves the rounded point: V' = V + w (V'_1 - V),
///   0 making the surface pass through the lattice vertex.
///
/// Tessellation by resolution or chordal tolerance is the filter's business
/// (vtkLKLatticeSurfaceFilter).

#include "latticekit/GregoryPatch.h"
#include "latticekit/PolygonMesh.h"

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace lk
{

struct LatticeSurface
{
  std::vector<GregoryPatch> patches;
  std::vector<std::int64_t> patchFace;   ///< lattice face of each patch
  std::vector<int> patchCorner;          ///< corner of the face for split faces, -1 for a quad's patch
  std::vector<Vec3> roundedPoints;       ///< V' of every lattice vertex (eq. 2.1)
  std::vector<std::array<Vec3, 4>> edgeCurves;           ///< one per lattice edge (eq. 2.2)
  std::vector<std::array<std::int64_t, 2>> edgeVertices; ///< its end vertices
  std::vector<char> edgeCrease;                          ///< per edge curve: a crease or a border (no G1 across it)
  /// (vertex, face) -> the face's sector at the vertex: the faces around a
  /// vertex fall into sectors between its creases, numbered from 0 (one
  /// sector, 0, at a vertex on no crease).
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> sectorOf;
};

/// Rounding weights: vertex weights one per lattice point (empty: all 1), edge
/// weights by vertex pair in either order (missing: 1). See above.
struct LatticeWeights
{
  std::vector<double> vertex;
  std::map<std::pair<std::int64_t, std::int64_t>, double> edge;

  /// The weight of edge (a, b), given in either order; 1 where none is.
  double edgeWeight(std::int64_t a, std::int64_t b) const
  {
    auto it = edge.find({ a, b });
    if (it == edge.end())
      it = edge.find({ b, a });
    return it == edge.end() ? 1.0 : it->second;
  }
};

/// Builds the surface. Throws std::invalid_argument with the reason (see
/// latticeProblem) for a lattice that cannot carry one, or for weights
/// outside [0, 1], of the wrong count, or on pairs that are not edges.
LatticeSurface buildLatticeSurface(const PolygonMesh& lattice, const LatticeWeights& weights = {});

/// True when the patch came from a split (non-quad) face: its sides are
/// halves of edge curves or inner curves, so tessellations use half the
/// resolution on it to keep shared sides sampled alike.
inline bool isSplitPatch(const LatticeSurface& s, std::size_t patch)
{
  return s.patchCorner[patch] >= 0;
}

} // namespace lk
