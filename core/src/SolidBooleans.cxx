#include "latticekit/SolidBooleans.h"

#include "SurfaceMeshConversion.h"

#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>

namespace lk
{
namespace
{
using Mesh = cgal::SurfaceMesh;
namespace PMP = CGAL::Polygon_mesh_processing;

/// The solid as a CGAL surface, or the reason it is none.
std::string toSurface(const TriangleMesh& solid, Mesh& mesh)
{
  if (solid.triangles.empty())
    return "it has no triangles";
  for (const Vec3& p : solid.points)
    if (!p.allFinite())
      return "a point is not finite";
  for (const Triangle& t : solid.triangles)
  {
    for (const std::int64_t v : t)
      if (v < 0 || static_cast<std::size_t>(v) >= solid.points.size())
        return "a triangle's vertex is out of range";
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      return "its triangles do not make a manifold, consistently oriented surface";
  }
  if (!cgal::toSurfaceMesh(solid, mesh))
    return "its triangles do not make a manifold, consistently oriented surface";
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

/// The union of `solids` into `all` (each prepared first): empty, or why
/// not, after "cannot <verb> <noun> k of n: " (the solid that failed) or
/// `failedUnion` for CGAL's union (after that solid's name too).
std::string unionOf(const std::vector<TriangleMesh>& solids, const std::string& verb, const std::string& noun,
  const std::string& failedUnion, Mesh& all)
{
  for (std::size_t k = 0; k < solids.size(); ++k)
  {
    Mesh mesh;
    const std::string which = noun + " " + std::to_string(k + 1) + " of " + std::to_string(solids.size());
    if (const std::string why = prepared(solids[k], mesh); !why.empty())
      return "cannot " + verb + " " + which + ": " + why;
    if (k == 0)
    {
      all = std::move(mesh);
      continue;
    }
    Mesh joined;
    if (!PMP::corefine_and_compute_union(all, mesh, joined))
      return "cannot " + verb + " " + which + failedUnion;
    all = std::move(joined);
  }
  return {};
}

} // namespace

std::string solidUnion(const std::vector<TriangleMesh>& solids, TriangleMesh& result)
{
  result = TriangleMesh{};
  if (solids.empty())
    return "there is no solid to join";
  Mesh all;
  if (std::string why = unionOf(solids, "join", "solid", " to the solids before it: CGAL's union failed", all);
      !why.empty())
    return why;
  result = cgal::fromSurfaceMesh(all);
  return {};
}

std::string solidDifference(
  const TriangleMesh& solid, const std::vector<TriangleMesh>& cutters, TriangleMesh& result)
{
  result = TriangleMesh{};
  Mesh left;
  if (const std::string why = prepared(solid, left); !why.empty())
    return "cannot cut the solid: " + why;
  // The cutters joined first (small, and the solid is usually the large
  // one), then one cut: each corefinement with the solid costs about as
  // much as the solid is large.
  Mesh cutter;
  if (std::string why = unionOf(cutters, "cut with", "cutter", ": CGAL's union of the cutters failed", cutter);
      !why.empty())
    return why;
  if (!cutters.empty())
  {
    Mesh rest;
    if (!PMP::corefine_and_compute_difference(left, cutter, rest))
      return "cannot cut the solid: CGAL's difference failed";
    left = std::move(rest);
  }
  result = cgal::fromSurfaceMesh(left);
  return {};
}

} // namespace lk
