#pragma once
/// \file MeshCut.h
/// Cutting a mesh along closed feature lines (seed 004, section 3.2): the
/// loops' vertices are duplicated, the faces on each side keep their own
/// copies, and the regions the loops separate come out as pieces whose cut
/// boundaries coincide exactly. Works on any polygon mesh: a bone surface or
/// a fitted lattice (whose feature edges are lattice edges), so "lattice,
/// then cut" works as well as "cut, then lattice".
///
/// Capping (beyond the paper; surgeons 3D-print the pieces): each loop is
/// closed once by a hole-filling surface (CGAL's triangulate and refine): a
/// loop within 5 % of its size of its fitting plane (an osteotomy's section; a
/// saw cut is flat) by a 2D constrained Delaunay triangulation in that plane,
/// any other loop by a minimal-weight triangulation; both refined to the
/// density of the loop. Flat loops nested in one plane (lines around the outer
/// and the inner wall of a hollow bone) share one cap with holes, an annulus:
/// a 2D constrained Delaunay triangulation of the region inside an odd number
/// of them, refined inside. The same cap goes into both pieces beside the
/// loop, with opposite orientations, so both come out watertight and fit each
/// other.

#include "latticekit/PolygonMesh.h"

#include <vector>

namespace lk
{

struct CutResult
{
  std::vector<PolygonMesh> pieces;
  /// For each piece: the input vertex of each of its vertices (-1 for cap
  /// vertices and for the vertices of inner-wall loops).
  std::vector<std::vector<std::int64_t>> vertexOrigin;
  /// For each piece: the input face of each of its faces (-1 for cap faces).
  std::vector<std::vector<std::int64_t>> faceOrigin;
  /// For each capped piece: pairs of its triangles that intersect, at least
  /// one of them a cap triangle (0 when the caps are clean; empty without
  /// capping). A cap crosses the surface where a loop is far from planar, or
  /// where nested loops could not share one cap (their projections cross, or
  /// their sides are not the same two pieces): such a piece is not a valid
  /// solid for printing.
  std::vector<std::size_t> capCrossings;
  /// For each capped piece: the deepest of those pairs' overlaps, how far
  /// each triangle reaches through the other's plane on its shallower side,
  /// the smaller of the two (0 without crossings). Micrometres mean triangles
  /// that graze each other beside a line.
  std::vector<double> capCrossingDepths;
  /// For each capped piece: edges at its caps shared by more than two faces,
  /// or twice in one direction (0 for a manifold solid; empty without
  /// capping). A loop along mesh edges can detour around a stretch of bone
  /// that the cap then covers too: where the stretch's faces are all spanned
  /// by loop vertices, they and the cap's triangles over them enclose nothing
  /// and are taken out of the piece (a pocket); otherwise the cap's edge that
  /// lies on a bone edge is split at its midpoint. The count says so if an
  /// edge still has too many faces.
  std::vector<std::size_t> capNonManifoldEdges;
  /// The loops (by index) whose two sides ended in one piece: the mesh joins
  /// around them (on a bone, a ring or a handle joins the two sides of the
  /// line), so each stays a slit, with its two caps back to back, while other
  /// loops separate the pieces (when none does, the cut throws instead).
  std::vector<std::size_t> loopsInOnePiece;
  /// Loops added on inner walls (see throughInnerWalls); 0 when none were needed.
  std::size_t innerWallLoops = 0;
  /// Capped pieces left without a face, which are not returned: every face
  /// of the region was spanned by loop vertices and coincided with a cap
  /// triangle (a loop around one or two triangles encloses nothing).
  std::size_t emptyPieces = 0;
};

/// Cuts along the loops (vertex ids; a loop may repeat its first vertex at
/// the end). Throws std::invalid_argument, with the reason, for an invalid
/// mesh, a loop that is open (fewer than 3 vertices, or consecutive vertices
/// not joined by an edge), crosses itself (a vertex twice), or loops that do
/// not separate the mesh.
///
/// throughInnerWalls: where the loops do not separate the mesh, and a loop is
/// flat, the mesh is also cut where the loop's plane meets its inner walls
/// inside the loop (on a hollow bone, the marrow cavity or a canal that a line
/// drawn around the outside does not reach: a saw cuts through them). The
/// triangles there are split along the plane, the new loops join the cut, and
/// with capping each inner loop shares the outer loop's flat cap (an annulus).
/// The sections must lie inside the loop and away from it, in triangles.
/// With capping, the same is tried where the loops separate the mesh but a
/// cap crosses it (a canal open at one end only, or a dip of the surface
/// inside the loop, reaching through the plane) or a piece gets no cap (a
/// closed cavity, an inner surface of its own): each part beyond the plane is
/// joined to the piece on the cap's side it lies on (a dimple in it), and that
/// cut is returned if its caps cross less than the plain cut's, or as much
/// with fewer pieces.
CutResult cutAlongLoops(const PolygonMesh& mesh, const std::vector<std::vector<std::int64_t>>& loops, bool cap,
  bool throughInnerWalls = false);

} // namespace lk
