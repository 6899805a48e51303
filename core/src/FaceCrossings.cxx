#include "latticekit/FaceCrossings.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace lk
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

CGAL::Bbox_3 faceBox(const PolygonMesh& mesh, std::size_t f)
{
  CGAL::Bbox_3 b;
  for (const auto v : mesh.faces[f])
  {
    const Vec3& q = mesh.points[static_cast<std::size_t>(v)];
    b += CGAL::Bbox_3(q.x(), q.y(), q.z(), q.x(), q.y(), q.z());
  }
  return b;
}
} // namespace

FaceCrossings markedFaceCrossings(const PolygonMesh& piece, const std::vector<char>& marked)
{
  if (marked.size() != piece.faces.size() || std::none_of(marked.begin(), marked.end(), [](char c) { return c != 0; }))
    return {};
  auto box = [&](std::size_t f) { return faceBox(piece, f); };
  CGAL::Bbox_3 markedBox, all;
  for (std::size_t f = 0; f < piece.faces.size(); ++f)
    if (marked[f])
      markedBox += box(f);
  for (const Vec3& q : piece.points)
    all += CGAL::Bbox_3(q.x(), q.y(), q.z(), q.x(), q.y(), q.z());
  double depth = 0.0;
  const double touching = 1e-6 * std::sqrt(CGAL::square(all.xmax() - all.xmin()) +
    CGAL::square(all.ymax() - all.ymin()) + CGAL::square(all.zmax() - all.zmin()));
  auto count = [&](bool nearOnly, std::size_t& crossings) {
    Mesh sm;
    std::vector<Mesh::Vertex_index> id(piece.points.size());
    std::vector<char> isMarked; // per triangle of sm
    for (std::size_t f = 0; f < piece.faces.size(); ++f)
    {
      if (nearOnly && !CGAL::do_overlap(box(f), markedBox))
        continue;
      const auto& face = piece.faces[f];
      for (const auto v : face)
        if (id[static_cast<std::size_t>(v)] == Mesh::null_vertex())
        {
          const Vec3& q = piece.points[static_cast<std::size_t>(v)];
          id[static_cast<std::size_t>(v)] = sm.add_vertex(Point(q.x(), q.y(), q.z()));
        }
      for (std::size_t i = 1; i + 1 < face.size(); ++i)
      {
        if (sm.add_face(id[static_cast<std::size_t>(face[0])], id[static_cast<std::size_t>(face[i])],
              id[static_cast<std::size_t>(face[i + 1])]) == Mesh::null_face())
          return false;
        isMarked.push_back(marked[f]);
      }
    }
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
    PMP::self_intersections(sm, std::back_inserter(pairs));
    crossings = 0;
    depth = 0.0;
    auto triangle = [&](Mesh::Face_index f) {
      std::array<Point, 3> t;
      std::size_t k = 0;
      for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm))
        t[k++] = sm.point(v);
      return Kernel::Triangle_3(t[0], t[1], t[2]);
    };
    for (const auto& [a, b] : pairs)
    {
      if (!isMarked[static_cast<std::size_t>(a)] && !isMarked[static_cast<std::size_t>(b)])
        continue;
      const Kernel::Triangle_3 ta = triangle(a), tb = triangle(b);
      // How far t reaches through the plane of u on its shallower side.
      auto through = [](const Kernel::Triangle_3& t, const Kernel::Triangle_3& u) {
        const Kernel::Vector_3 n = CGAL::normal(u.vertex(0), u.vertex(1), u.vertex(2));
        const double length = std::sqrt(CGAL::to_double(n.squared_length()));
        if (!(length > 0.0))
          return 0.0;
        double above = 0.0, below = 0.0;
        for (int i = 0; i < 3; ++i)
        {
          const double d = CGAL::to_double((t.vertex(i) - u.vertex(0)) * n) / length;
          above = std::max(above, d);
          below = std::max(below, -d);
        }
        return std::min(above, below);
      };
      const double reach = std::min(through(ta, tb), through(tb, ta));
      if (reach <= touching)
        continue; // they touch (CGAL counts a shared point), to a millionth of the size
      ++crossings;
      depth = std::max(depth, reach);
    }
    return true;
  };
  std::size_t crossings = 0;
  if (!count(true, crossings) && !count(false, crossings))
    return { 0, 0.0, false };
  return { crossings, depth, true };
}

FaceCrossings crossingsInBox(const PolygonMesh& mesh, const Vec3& low, const Vec3& high)
{
  const CGAL::Bbox_3 region(low.x(), low.y(), low.z(), high.x(), high.y(), high.z());
  std::vector<char> marked(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    marked[f] = CGAL::do_overlap(faceBox(mesh, f), region);
  return markedFaceCrossings(mesh, marked);
}

} // namespace lk
