#pragma once
/// \file FeatureChains.h
/// Feature edges as chains, and which of a chain's vertices keep its shape.
///
/// A locked feature line is kept edge for edge by the lattice fit. A line
/// split into a surface (a stroke or a cut line) has a vertex wherever it
/// crosses a mesh edge, a few tenths of a millimetre apart, and locked whole
/// such a line can take a third of a lattice's vertices. A chain keeps, of
/// its vertices, those that hold it within a tolerance (Douglas-Peucker):
/// the lattice's feature edges are then chords of the line, each within the
/// tolerance of the line it replaces, through points of it kept exactly.

#include "latticekit/TriangleMesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace lk
{

/// The feature edges (pairs of vertex ids) as chains: each chain is a path
/// whose inner vertices have exactly two feature edges and whose ends have
/// another number (1, or 3 and more); a closed loop of vertices that all have
/// two is a chain whose first vertex is repeated last. Every edge is in
/// exactly one chain. The order is deterministic for a given edge list.
std::vector<std::vector<std::int64_t>> featureChains(const std::vector<std::pair<std::int64_t, std::int64_t>>& edges);

/// Which vertices of `chain` (ids into `points`) to keep so that every
/// dropped vertex lies within `tolerance` of the chord between the kept
/// vertices either side of it (Douglas-Peucker; the line between vertices
/// is straight, so the whole line lies that close to the chords). The ends
/// are kept. A closed chain (first id repeated last) is cut at the vertex
/// with the smallest point (x, then y, then z) and at the vertex farthest
/// from it, and each half keeps at least one inner vertex, so that a loop
/// keeps at least four: the choice depends on the points alone, not on the
/// ids, where the loop starts or which way it runs, so one line in two meshes
/// (the two pieces of a cut) keeps the same points in both. Returns one flag
/// per entry of `chain`. Throws std::invalid_argument for a tolerance below 0
/// or not finite, or an id outside `points`.
std::vector<char> chainVerticesToKeep(
  const std::vector<Vec3>& points, const std::vector<std::int64_t>& chain, double tolerance);

/// How many vertices the feature edges keep with that tolerance: those
/// chainVerticesToKeep keeps on every chain, each counted once (a vertex where
/// chains meet is an end of each). With tolerance 0, every vertex of the
/// edges that is not exactly on a chord.
std::size_t featureVerticesToKeep(const std::vector<Vec3>& points,
  const std::vector<std::pair<std::int64_t, std::int64_t>>& edges, double tolerance);

/// How sharply `mesh` bends across each of `edges`: the angle in degrees
/// between the normals of its two triangles (0 to 180, as vtkFeatureEdges'
/// feature angle). An edge of one triangle (a border) or of more than two,
/// or beside a triangle of no area, gets 0: no bend to measure. Throws
/// std::invalid_argument for an id outside the mesh's points.
std::vector<double> edgeBends(
  const TriangleMesh& mesh, const std::vector<std::pair<std::int64_t, std::int64_t>>& edges);

/// Which lattice feature edges are creases: those whose ends hold input
/// vertices (inputVertex[a], inputVertex[b]) of one chain of `inputEdges`
/// across which the input bends by more than `angleDegrees` on average
/// (`bends`, one per input edge, as edgeBends gives them; weighted by the
/// edges' lengths). The decision is a chain's, not an edge's: a cut rim
/// bends by 50-130 degrees from edge to edge and is a crease all round, and
/// a stroke on a marching-cubes surface, a few degrees on average, crosses
/// the odd edge bent by 60 degrees and more without a kink there. A chain of
/// one or two edges is not a crease (too few for a mean), nor is a lattice
/// edge whose ends are on no common chain. Returns one flag
/// per lattice edge. Throws std::invalid_argument where `bends` does not
/// match `inputEdges`, or an id is out of range.
std::vector<char> creaseFeatureEdges(const std::vector<Vec3>& inputPoints,
  const std::vector<std::pair<std::int64_t, std::int64_t>>& inputEdges, const std::vector<double>& bends,
  const std::vector<std::pair<std::int64_t, std::int64_t>>& latticeEdges, const std::vector<std::int64_t>& inputVertex,
  double angleDegrees);

} // namespace lk
