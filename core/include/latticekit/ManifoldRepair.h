#pragma once
/// \file ManifoldRepair.h
/// Turns a triangle soup (marching cubes output, a file from elsewhere) into
/// a manifold, consistently oriented triangle mesh that CGAL's Surface_mesh
/// accepts, using CGAL's Polygon Mesh Processing repair functions:
///  1. repair_polygon_soup's steps for triangles: merge duplicate points (as
///     merge_duplicate_points_in_polygon_soup does, from a hash table), drop
///     triangles with repeated vertices, duplicate triangles and isolated
///     points;
///  2. orient_polygon_soup: orient consistently, splitting non-manifold
///     vertices and edges where that is impossible. A soup oriented already
///     (marching cubes) only has its pinched vertices split, as
///     orient_polygon_soup would (PinchedVertices.h), in a thirtieth of the time;
///  3. remove_degenerate_faces: collapse or flip away zero-area triangles;
///  4. duplicate_non_manifold_vertices: split any pinched vertex left;
///  5. orientation: closed components bound a volume (normals outward); open
///     components are flipped when their signed volume is negative.

#include "latticekit/TriangleMesh.h"

#include <functional>
#include <string>

namespace lk
{

struct RepairReport
{
  std::size_t inputTriangles = 0;
  std::size_t outputTriangles = 0;
  std::size_t outputPoints = 0;
  std::size_t mergedPoints = 0;           ///< duplicate points merged
  std::size_t removedSoupPolygons = 0;    ///< polygons dropped by the soup repair
  std::size_t removedDegenerateFaces = 0; ///< zero-area faces removed
  std::size_t splitNonManifold = 0;       ///< vertices duplicated to make it manifold
  std::size_t components = 0;
  std::size_t boundaryEdges = 0;
  bool closed = false;
  bool stopped = false; ///< `progress` asked to stop: the mesh is as it was
};

/// Repairs the mesh in place. `progress` gets the fraction of the work done
/// after each step (a CGAL step itself reports nothing: on a CT's 3
/// million triangles the whole repair takes about 5 s on one core) and may
/// return false to stop, leaving the mesh unchanged. Throws
/// std::invalid_argument for an empty mesh, out-of-range ids or non-finite
/// coordinates, and std::runtime_error when nothing is left after the repair.
RepairReport repairToManifold(TriangleMesh& mesh, const std::function<bool(double)>& progress = {});

/// Empty when the mesh loads into a valid CGAL Surface_mesh (manifold, no
/// pinched vertices, consistently oriented), otherwise the reason it does not.
std::string cgalSurfaceMeshProblem(const TriangleMesh& mesh);

/// Number of edges with exactly one incident triangle (0 for a closed mesh).
std::size_t countBoundaryEdges(const TriangleMesh& mesh);

/// Signed volume enclosed (divergence theorem); positive for an outward closed mesh.
double signedVolume(const TriangleMesh& mesh);

} // namespace lk
