#include "latticekit/ConvexHull.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
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
  // Four points not on one plane, or no volume: a hull without volume has
  // no inside. (CGAL 5.5 gives points on one plane a flat polygon, which as
  // an indexed triangle set numbers its corners from 1, one past its
  // points.)
  auto differs = std::find_if(input.begin(), input.end(), [&](const Point& p) { return p != input.front(); });
  if (differs == input.end())
    return;
  auto offLine = std::find_if(input.begin(), input.end(),
    [&](const Point& p) { return !CGAL::collinear(input.front(), *differs, p); });
  if (offLine == input.end())
    return;
  if (std::none_of(input.begin(), input.end(),
        [&](const Point& p) { return CGAL::orientation(input.front(), *differs, *offLine, p) != CGAL::COPLANAR; }))
    return;
  // Into a surface mesh, as CGAL's own examples do: its indexed triangle
  // set output (vertices and index triples) corrupted the heap inside the
  // planner and latticekit-cut on mandibles ("free(): invalid pointer", in
  // most runs of two tests; not reproduced outside them).
  Mesh hull;
  CGAL::convex_hull_3(input.begin(), input.end(), hull);
  std::vector<Point> vertices;
  for (const Mesh::Vertex_index v : hull.vertices())
    vertices.push_back(hull.point(v));
  std::vector<std::array<Point, 3>> triangles;
  for (const Mesh::Face_index f : hull.faces())
  {
    std::array<Point, 3> corners;
    int k = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(hull.halfedge(f), hull))
    {
      if (k < 3)
        corners[static_cast<std::size_t>(k)] = hull.point(v);
      ++k;
    }
    if (k == 3)
      triangles.push_back(corners);
  }
  if (triangles.size() < 4 || vertices.empty())
    return;

  // Each face's plane, turned to face away from the hull's vertices' centre
  // (inside any convex hull with volume).
  Vec3 centre = Vec3::Zero();
  for (const Point& v : vertices)
    centre += Vec3(v.x(), v.y(), v.z());
  centre /= static_cast<double>(vertices.size());
  double size = 0.0;
  for (const Point& v : vertices)
    size = std::max(size, (Vec3(v.x(), v.y(), v.z()) - centre).norm());
  double thickest = 0.0;
  for (const auto& t : triangles)
  {
    const Vec3 a(t[0].x(), t[0].y(), t[0].z());
    const Vec3 b(t[1].x(), t[1].y(), t[1].z());
    const Vec3 c(t[2].x(), t[2].y(), t[2].z());
    Vec3 n = (b - a).cross(c - a);
    const double length = n.norm();
    if (!(length > 0.0))
      continue; // a sliver of the quickhull's output: its neighbours bound the hull
    n /= length;
    double offset = n.dot(a);
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
