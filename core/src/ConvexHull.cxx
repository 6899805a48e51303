#include "latticekit/ConvexHull.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <limits>

namespace lk
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
} // namespace

ConvexHull::ConvexHull(const std::vector<Vec3>& points)
{
  std::vector<Point> input;
  input.reserve(points.size());
  for (const Vec3& p : points)
    if (p.allFinite())
      input.emplace_back(p.x(), p.y(), p.z());
  // Into a surface mesh, as CGAL's own examples do: its indexed triangle
  // set output (vertices and index triples) corrupted the heap inside the
  // planner and latticekit-cut on mandibles ("free(): invalid pointer", in
  // most runs of two tests; not reproduced outside them). Points on a line
  // give isolated vertices, points on one plane a flat polygon: no volume,
  // left empty below.
  Mesh hull;
  CGAL::convex_hull_3(input.begin(), input.end(), hull);
  if (hull.number_of_vertices() < 4)
    return;
  auto vec = [](const Point& p) { return Vec3(p.x(), p.y(), p.z()); };

  // Each face's plane, turned to face away from the hull's vertices' centre
  // (inside any convex hull with volume).
  Vec3 centre = Vec3::Zero();
  for (const Mesh::Vertex_index v : hull.vertices())
    centre += vec(hull.point(v));
  centre /= static_cast<double>(hull.number_of_vertices());
  double size = 0.0;
  for (const Mesh::Vertex_index v : hull.vertices())
    size = std::max(size, (vec(hull.point(v)) - centre).norm());
  double thickest = 0.0;
  for (const Mesh::Face_index f : hull.faces())
  {
    std::vector<Vec3> corners;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(hull.halfedge(f), hull))
      corners.push_back(vec(hull.point(v)));
    if (corners.size() != 3)
      continue; // a flat hull's polygon
    Vec3 n = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
    const double length = n.norm();
    if (!(length > 0.0))
      continue; // a sliver of the quickhull's output: its neighbours bound the hull
    n /= length;
    double offset = n.dot(corners[0]);
    if (offset - n.dot(centre) < 0.0)
    {
      n = -n;
      offset = -offset;
    }
    thickest = std::max(thickest, offset - n.dot(centre));
    faces.push_back({ n, offset });
  }
  // All the points on one plane: every face passes through the centre.
  if (faces.size() < 4 || !(thickest > 1e-9 * size))
    faces.clear();
}

double ConvexHull::depth(const Vec3& x) const
{
  if (faces.empty() || !x.allFinite())
    return std::numeric_limits<double>::quiet_NaN();
  double least = std::numeric_limits<double>::infinity();
  for (const Face& f : faces)
    least = std::min(least, f.offset - f.normal.dot(x));
  return least;
}

} // namespace lk
