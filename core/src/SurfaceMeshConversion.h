#pragma once
/// \file SurfaceMeshConversion.h
/// Private to the cores: lk::TriangleMesh to and from CGAL's Surface_mesh (the
/// exact-predicates, inexact-constructions kernel). Keeps CGAL out of public
/// headers; included by the few .cxx files that work on half-edges.

#include "latticekit/TriangleMesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <string>

namespace lk
{
namespace cgal
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

/// Vertex i of `mesh` becomes vertex i of `out`; false when a triangle cannot
/// be added (the mesh is not a manifold, consistently oriented one).
inline bool toSurfaceMesh(const TriangleMesh& mesh, SurfaceMesh& out)
{
  for (const Vec3& p : mesh.points)
    out.add_vertex(Point(p.x(), p.y(), p.z()));
  for (const Triangle& t : mesh.triangles)
  {
    if (out.add_face(SurfaceMesh::Vertex_index(static_cast<SurfaceMesh::size_type>(t[0])),
          SurfaceMesh::Vertex_index(static_cast<SurfaceMesh::size_type>(t[1])),
          SurfaceMesh::Vertex_index(static_cast<SurfaceMesh::size_type>(t[2]))) == SurfaceMesh::null_face())
      return false;
  }
  return true;
}

/// Empty when `mesh` loads into a valid Surface_mesh (manifold, no pinched
/// vertices, consistently oriented, no degenerate triangle), which `out` then
/// holds as toSurfaceMesh builds it; otherwise the reason it does not
/// (lk::cgalSurfaceMeshProblem's words; defined in ManifoldRepair.cxx).
std::string checkedSurfaceMesh(const TriangleMesh& mesh, SurfaceMesh& out);

/// The triangles of `sm` (garbage collected first, so ids are compact);
/// faces that are not triangles are left out.
inline TriangleMesh fromSurfaceMesh(SurfaceMesh& sm)
{
  sm.collect_garbage();
  TriangleMesh out;
  out.points.reserve(sm.number_of_vertices());
  for (auto v : sm.vertices())
  {
    const Point& p = sm.point(v);
    out.points.emplace_back(p.x(), p.y(), p.z());
  }
  out.triangles.reserve(sm.number_of_faces());
  for (auto f : sm.faces())
  {
    Triangle t{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm))
    {
      if (k < 3)
        t[static_cast<std::size_t>(k)] = static_cast<std::int64_t>(static_cast<std::size_t>(v));
      ++k;
    }
    if (k == 3)
      out.triangles.push_back(t);
  }
  return out;
}
} // namespace cgal
} // namespace lk
