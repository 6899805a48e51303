#pragma once
/// \file EdgePath.h
/// A path along mesh edges through given points near the surface: each point
/// goes to its nearest mesh vertex (the nearest corner of its closest
/// triangle) and consecutive vertices are joined by shortest edge paths
/// (Dijkstra, Euclidean edge lengths). This is how scripted feature lines
/// (world-space polylines) become feature edges for the lattice fit; a
/// polyline whose last point repeats its first gives a closed loop.

#include "latticekit/ClosestPointTree.h"
#include "latticekit/TriangleMesh.h"

#include <vector>

namespace lk
{

/// Vertex ids of the path, consecutive ids joined by mesh edges, no vertex
/// repeated twice in a row. Throws std::invalid_argument for an invalid mesh,
/// a non-finite point, or points on parts of the mesh that no edge path joins.
std::vector<std::int64_t> edgePathThrough(const TriangleMesh& mesh, const std::vector<Vec3>& points);

/// The same with `tree`, a ClosestPointTree built on `mesh` (the same
/// path: building another on a bone of a million faces took a second).
std::vector<std::int64_t> edgePathThrough(
  const TriangleMesh& mesh, const ClosestPointTree& tree, const std::vector<Vec3>& points);

/// Shortest edge path from vertex a to vertex b (both included); empty when
/// no path exists.
std::vector<std::int64_t> shortestEdgePath(const TriangleMesh& mesh, std::int64_t a, std::int64_t b);

} // namespace lk
