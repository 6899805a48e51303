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
/// closed once by a hole-filling surface (CGAL's triangulate, refine and fair:
/// a minimal-weight triangulation of the loop, refined to the density of its
/// border, then faired, i.e. made smooth, by a bi-Laplacian solve with the
/// loop fixed). The same cap goes into both pieces beside the loop, with
/// opposite orientations, so both come out watertight and fit each other.

#include "latticekit/PolygonMesh.h"

#include <vector>

namespace lk
{

struct CutResult
{
  std::vector<PolygonMesh> pieces;
  /// For each piece: the input vertex of each of its vertices (-1 for cap vertices).
  std::vector<std::vector<std::int64_t>> vertexOrigin;
  /// For each piece: the input face of each of its faces (-1 for cap faces).
  std::vector<std::vector<std::int64_t>> faceOrigin;
  std::size_t capFailures = 0; ///< caps whose fairing failed (refined but not faired)
};

/// Cuts along the loops (vertex ids; a loop may repeat its first vertex at
/// the end). Throws std::invalid_argument, with the reason, for an invalid
/// mesh, a loop that is open (fewer than 3 vertices, or consecutive vertices
/// not joined by an edge), crosses itself (a vertex twice), or loops that do
/// not separate the mesh.
CutResult cutAlongLoops(const PolygonMesh& mesh, const std::vector<std::vector<std::int64_t>>& loops, bool cap);

} // namespace lk
