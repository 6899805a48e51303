#include "latticekit/SolidBooleans.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <map>

namespace lk
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

/// The solid as a CGAL surface, or the reason it is none.
std::string toSurface(const TriangleMesh& solid, Mesh& mesh)
{
  if (solid.triangles.empty())
    return "it has no triangles";
  std::vector<Mesh::Vertex_index> id(solid.points.size());
  for (std::size_t i = 0; i < solid.points.size(); ++i)
  {
    const Vec3& p = solid.points[i];
    if (!p.allFinite())
      return "a point is not finite";
    id[i] = mesh.add_vertex(Point(p.x(), p.y(), p.z()));
  }
  for (const Triangle& t : solid.triangles)
  {
    for (const std::int64_t v : t)
      if (v < 0 || static_cast<std::size_t>(v) >= solid.points.size())
        return "a triangle's vertex is out of range";
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
      mesh.add_face(id[static_cast<std::size_t>(t[0])], id[static_cast<std::size_t>(t[1])],
        id[static_cast<std::size_t>(t[2])]) == Mesh::null_face())
      return "its triangles do not make a manifold, consistently oriented surface";
  }
  return {};
}

/// `solid` as a CGAL surface ready for corefinement (degenerate faces
/// removed, oriented outward), or why it cannot be one, after "cannot
/// <verb> <which>: ".
std::string prepared(const TriangleMesh& solid, Mesh& mesh)
{
  if (const std::string why = toSurface(solid, mesh); !why.empty())
    return why;
  PMP::remove_degenerate_faces(mesh);
  PMP::remove_isolated_vertices(mesh);
  mesh.collect_garbage();
  if (!CGAL::is_closed(mesh))
    return "it is not closed";
  if (!CGAL::is_triangle_mesh(mesh))
    return "it is not a triangle mesh";
  if (PMP::does_self_intersect(mesh))
    return "it crosses itself";
  if (!PMP::does_bound_a_volume(mesh))
    return "it does not bound a volume";
  PMP::orient_to_bound_a_volume(mesh);
  return {};
}

/// The CGAL surface as a triangle mesh.
TriangleMesh fromSurface(Mesh& mesh)
{
  TriangleMesh result;
  mesh.collect_garbage();
  std::map<Mesh::Vertex_index, std::int64_t> index;
  for (const Mesh::Vertex_index v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    index[v] = static_cast<std::int64_t>(result.points.size());
    result.points.emplace_back(p.x(), p.y(), p.z());
  }
  for (const Mesh::Face_index f : mesh.faces())
  {
    Triangle t{};
    std::size_t k = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      if (k < 3)
        t[k++] = index[v];
    if (k == 3)
      result.triangles.push_back(t);
  }
  return result;
}
} // namespace

std::string solidUnion(const std::vector<TriangleMesh>& solids, TriangleMesh& result)
{
  result = TriangleMesh{};
  if (solids.empty())
    return "there is no solid to join";
  Mesh all;
  for (std::size_t k = 0; k < solids.size(); ++k)
  {
    Mesh mesh;
    const std::string which = "solid " + std::to_string(k + 1) + " of " + std::to_string(solids.size());
    if (const std::string why = prepared(solids[k], mesh); !why.empty())
      return "cannot join " + which + ": " + why;
    if (k == 0)
    {
      all = mesh;
      continue;
    }
    Mesh joined;
    if (!PMP::corefine_and_compute_union(all, mesh, joined))
      return "cannot join " + which + " to the solids before it: CGAL's union failed";
    all = std::move(joined);
  }
  result = fromSurface(all);
  return {};
}

std::string solidDifference(
  const TriangleMesh& solid, const std::vector<TriangleMesh>& cutters, TriangleMesh& result)
{
  result = TriangleMesh{};
  Mesh left;
  if (const std::string why = prepared(solid, left); !why.empty())
    return "cannot cut the solid: " + why;
  for (std::size_t k = 0; k < cutters.size(); ++k)
  {
    Mesh cutter;
    const std::string which = "cutter " + std::to_string(k + 1) + " of " + std::to_string(cutters.size());
    if (const std::string why = prepared(cutters[k], cutter); !why.empty())
      return "cannot cut with " + which + ": " + why;
    Mesh rest;
    if (!PMP::corefine_and_compute_difference(left, cutter, rest))
      return "cannot cut with " + which + ": CGAL's difference failed";
    left = std::move(rest);
  }
  result = fromSurface(left);
  return {};
}

} // namespace lk
