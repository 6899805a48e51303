#pragma once
/// \file StrokeFeatureLine.h
/// Pen strokes on a triangle mesh to feature lines (seed 004, section 3.1).
/// The stroke is a polyline of world points on or near the surface (the
/// planner picks screen points onto the nearest visible surface first).
/// It is resampled at `spacing` and each sample projected to its closest
/// surface point (CGAL AABB tree); a sample farther than `maxDistance` from
/// the surface means the stroke misses it.
///
/// Modes:
/// - Paint (3.1.1): every edge of the faces the stroke covers; a face is
///   covered when it lies within `brushRadius` of a projected sample (region
///   growing from the sample's face).
/// - NearestEdges (3.1.2): the nearest mesh vertex of each projected sample,
///   consecutive vertices joined by shortest edge paths (Dijkstra); where
///   the path would revisit a vertex, the detour between the two visits is
///   dropped, so the line does not intersect itself.
/// - Snap (3.1.3): the same path, each of its vertices moved to the closest
///   point of the projected stroke polyline; connectivity is unchanged.
///   (Eq. 3.12 slides a vertex along one of its edges towards the next
///   input point; the closest point on the stroke is the same aim without
///   being limited to one edge. Only path vertices move.) A move that would
///   fold the mesh (turn a triangle around the vertex by more than 60
///   degrees from the input's, or leave it less than 1 % of its area, as
///   three line vertices of one triangle on a straight stroke would) stops
///   short, at the farthest point of the move that keeps them; such
///   vertices are retried after the others, and `snapGaps` says how far
///   each one is left from the stroke (eq. 3.12 can fold there too).
/// - Split (3.1.4): new vertices where the projected stroke crosses mesh edges
///   (the point of the edge nearest the stroke segment between two samples
///   on either side, eq. 3.13's foot point), and at the stroke's two ends
///   (each splits its face into a fan); faces are split between consecutive
///   new vertices and re-triangulated, so the new edges follow the stroke
///   and the mesh stays a manifold triangle mesh (CGAL Euler operations).
/// A stroke whose ends are within `closeTolerance` of each other gives a
/// closed line (its last vertex repeats the first).

#include "latticekit/LatticeSimplification.h"
#include "latticekit/TriangleMesh.h"

#include <vector>

namespace lk
{

enum class StrokeMode
{
  Paint,
  NearestEdges,
  Snap,
  Split
};

struct StrokeOptions
{
  StrokeMode mode = StrokeMode::NearestEdges;
  double spacing = 0.0;        ///< resampling step; 0: a quarter of the mean edge length
  double brushRadius = 0.0;    ///< paint; 0: half the mean edge length
  double closeTolerance = 0.0; ///< ends closer than this close the line; 0: twice the mean edge length
  double maxDistance = 0.0;    ///< samples farther from the surface miss it; 0: 5 mean edge lengths
};

struct StrokeResult
{
  TriangleMesh mesh;                       ///< the mesh (vertices moved in Snap mode)
  std::vector<EdgeKey> featureEdges;       ///< sorted, unique
  std::vector<std::int64_t> line;          ///< the vertex path (NearestEdges, Snap)
  std::vector<std::int64_t> paintedFaces;  ///< Paint: the covered faces
  std::vector<std::int64_t> movedVertices; ///< Snap: the path's vertices
  std::vector<double> snapGaps;            ///< Snap: per moved vertex, its distance left to the stroke (0: on it)
  bool closed = false;
};

/// The mean length of the mesh's edges, each triangle's three counted: the
/// unit of StrokeOptions' defaults (0 for a mesh without triangles).
double meanEdgeLength(const TriangleMesh& mesh);

/// The closeTolerance a stroke on this mesh gets when it is 0: twice the
/// mean edge length. (The planner continues a stroke drawn in parts from a
/// press this near an end of its open line, so that continues and closes
/// mean the same nearness.)
double defaultCloseTolerance(const TriangleMesh& mesh);

/// A closed vertex path (first vertex repeated last) without its spurs:
/// where it goes out along edges and straight back (b, c, b), the way out
/// and back is left out (b), also across the first vertex. A loop round
/// nothing (a, b, c, b, a) comes back as fewer than four entries. Closed
/// lines are made so in every mode but paint (nearest edges and snap before
/// their detour rule).
std::vector<std::int64_t> withoutSpurs(const std::vector<std::int64_t>& closedLine);

/// A closed vertex path (first vertex repeated last) without its small
/// loops: where it comes back to a vertex it passed, the shorter of the two
/// loops that vertex makes is left out when it is at most `longest` round
/// (edge lengths on `points`); a larger pair is left as it is. Closed lines
/// are made so after withoutSpurs, with twice the closing tolerance.
std::vector<std::int64_t> withoutSmallLoops(
  const std::vector<std::int64_t>& closedLine, const std::vector<Vec3>& points, double longest);

/// Throws std::invalid_argument for an invalid mesh, a stroke of fewer than
/// two points or with non-finite points, or a stroke that misses the surface.
StrokeResult strokeToFeatureLine(const TriangleMesh& mesh, const std::vector<Vec3>& stroke, const StrokeOptions& options);

/// Lines drawn earlier (vertex paths on the mesh a stroke started from),
/// carried onto `after`, the mesh the stroke made: every mode keeps the
/// vertex ids of the mesh before (`verticesBefore` of them) and appends new
/// ones. Split mode cuts the edges its stroke crosses, so an earlier line
/// edge (a, b) may no longer be an edge; it is replaced by the new vertices
/// on the segment from a to b, in order (a chain of edges of `after`). Every
/// other pair of consecutive vertices is kept as it is.
std::vector<std::vector<std::int64_t>> carryLines(
  const TriangleMesh& after, std::size_t verticesBefore, const std::vector<std::vector<std::int64_t>>& lines);

} // namespace lk
