#include "CutCaps.h"

#include "latticekit/FaceCrossings.h"

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_mesh_processing/refine.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>

namespace lk
{
namespace cut
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Point2 = Kernel::Point_2;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

/// A point in the plane's coordinates (u, v).
Point2 projected(const Vec3& p, const LoopPlane& plane)
{
  return { plane.u.dot(p - plane.centre), plane.v.dot(p - plane.centre) };
}

std::vector<Point2> projected(const std::vector<Vec3>& loop, const LoopPlane& plane)
{
  std::vector<Point2> out;
  out.reserve(loop.size());
  for (const Vec3& p : loop)
    out.push_back(projected(p, plane));
  return out;
}

/// The cap made of `faces` of `m`: the loops' vertices `loop` become ids
/// -(i+1), the vertices `added` by the filling new points.
template <typename Faces>
Cap capOf(const Mesh& m, const std::vector<Mesh::Vertex_index>& loop, const std::vector<Mesh::Vertex_index>& added,
  const Faces& faces)
{
  Cap cap;
  std::map<Mesh::Vertex_index, std::int64_t> id;
  for (std::size_t i = 0; i < loop.size(); ++i)
    id[loop[i]] = -static_cast<std::int64_t>(i) - 1;
  for (auto v : added)
  {
    id[v] = static_cast<std::int64_t>(cap.points.size());
    const Point& p = m.point(v);
    cap.points.emplace_back(p.x(), p.y(), p.z());
  }
  for (auto face : faces)
  {
    std::array<std::int64_t, 3> t{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(m.halfedge(face), m))
      if (k < 3)
        t[static_cast<std::size_t>(k++)] = id.at(v);
    if (k == 3)
      cap.triangles.push_back(t);
  }
  return cap;
}
} // namespace

LoopPlane fitLoopPlane(const std::vector<Vec3>& loop)
{
  LoopPlane plane;
  for (const Vec3& p : loop)
    plane.centre += p;
  plane.centre /= static_cast<double>(loop.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  Eigen::AlignedBox3d box;
  for (const Vec3& p : loop)
  {
    cov += (p - plane.centre) * (p - plane.centre).transpose();
    box.extend(p);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(cov);
  plane.normal = eigen.eigenvectors().col(0);
  plane.u = eigen.eigenvectors().col(2);
  plane.v = plane.normal.cross(plane.u);
  for (const Vec3& p : loop)
    plane.deviation = std::max(plane.deviation, std::abs(plane.normal.dot(p - plane.centre)));
  plane.tolerance = kFlatCapTolerance * box.diagonal().norm();
  plane.flat = plane.deviation <= plane.tolerance;
  return plane;
}

struct LoopOutline::Polygon
{
  std::vector<Point2> points;
};

LoopOutline::LoopOutline(const std::vector<Vec3>& loop, const LoopPlane& plane)
  : plane_(plane)
  , polygon_(std::make_unique<Polygon>())
{
  polygon_->points = projected(loop, plane);
  const CGAL::Bbox_2 box = CGAL::bbox_2(polygon_->points.begin(), polygon_->points.end());
  min_ = { box.xmin(), box.ymin() };
  max_ = { box.xmax(), box.ymax() };
}

LoopOutline::~LoopOutline() = default;
LoopOutline::LoopOutline(LoopOutline&&) noexcept = default;
LoopOutline& LoopOutline::operator=(LoopOutline&&) noexcept = default;

LoopOutline::Side LoopOutline::side(const Vec3& p) const
{
  switch (CGAL::bounded_side_2(polygon_->points.begin(), polygon_->points.end(), projected(p, plane_), Kernel()))
  {
    case CGAL::ON_BOUNDED_SIDE:
      return Side::Inside;
    case CGAL::ON_BOUNDARY:
      return Side::OnBorder;
    default:
      return Side::Outside;
  }
}

std::pair<std::size_t, double> capCrossings(const PolygonMesh& piece, const std::vector<std::int64_t>& faceOrigin)
{
  std::vector<char> isCap(piece.faces.size());
  for (std::size_t f = 0; f < piece.faces.size(); ++f)
    isCap[f] = faceOrigin[f] < 0;
  const FaceCrossings crossings = markedFaceCrossings(piece, isCap);
  return { crossings.pairs, crossings.depth };
}

Cap makeNestedCap(const std::vector<std::vector<Vec3>>& loops, const LoopPlane& plane)
{
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Kernel>;
  using Fbi = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel, Fbi>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
  CDT cdt;
  std::vector<Vec3> points;
  for (const auto& loop : loops)
  {
    const std::vector<Point2> flat = projected(loop, plane);
    std::vector<CDT::Vertex_handle> handles;
    for (std::size_t i = 0; i < loop.size(); ++i)
    {
      const auto h = cdt.insert(flat[i]);
      h->info() = points.size();
      points.push_back(loop[i]);
      handles.push_back(h);
    }
    for (std::size_t i = 0; i < handles.size(); ++i)
      cdt.insert_constraint(handles[i], handles[(i + 1) % handles.size()]);
  }
  if (cdt.number_of_vertices() != points.size())
    return {}; // two loop points project onto one, or constraints crossed
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (v->info() >= points.size())
      return {};
  // Nesting level of each face: 0 outside every loop, +1 across each loop
  // (flood fills that stop at constrained edges, as in CGAL's examples).
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    f->info() = -1;
  std::deque<CDT::Edge> border;
  auto fill = [&](CDT::Face_handle start, int level) {
    std::deque<CDT::Face_handle> queue{ start };
    while (!queue.empty())
    {
      const CDT::Face_handle f = queue.front();
      queue.pop_front();
      if (f->info() != -1)
        continue;
      f->info() = level;
      for (int i = 0; i < 3; ++i)
      {
        const CDT::Face_handle n = f->neighbor(i);
        if (n->info() != -1)
          continue;
        if (cdt.is_constrained(CDT::Edge(f, i)))
          border.emplace_back(f, i);
        else
          queue.push_back(n);
      }
    }
  };
  fill(cdt.infinite_face(), 0);
  while (!border.empty())
  {
    const CDT::Edge e = border.front();
    border.pop_front();
    const CDT::Face_handle n = e.first->neighbor(e.second);
    if (n->info() == -1)
      fill(n, e.first->info() + 1);
  }
  Mesh m;
  std::vector<Mesh::Vertex_index> vs;
  for (const Vec3& p : points)
    vs.push_back(m.add_vertex(Point(p.x(), p.y(), p.z())));
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info() % 2 == 1)
      if (m.add_face(vs[f->vertex(0)->info()], vs[f->vertex(1)->info()], vs[f->vertex(2)->info()]) ==
        Mesh::null_face())
        return {};
  std::vector<Mesh::Face_index> faces(m.faces().begin(), m.faces().end());
  std::vector<Mesh::Face_index> newFaces;
  std::vector<Mesh::Vertex_index> newVertices;
  PMP::refine(m, faces, std::back_inserter(newFaces), std::back_inserter(newVertices),
    CGAL::parameters::density_control_factor(0.7));
  return capOf(m, vs, newVertices, m.faces());
}

Cap makeCap(const std::vector<Vec3>& loop, const LoopPlane& plane)
{
  // The hole is the border of a single fan-free face: build the loop as a mesh
  // with one polygon face, then fill its other side.
  Mesh m;
  std::vector<Mesh::Vertex_index> vs;
  for (const Vec3& p : loop)
    vs.push_back(m.add_vertex(Point(p.x(), p.y(), p.z())));
  // The polygon face runs against the loop; the hole (border) runs along it.
  std::vector<Mesh::Vertex_index> reversed(vs.rbegin(), vs.rend());
  const auto f = m.add_face(reversed);
  if (f == Mesh::null_face())
    return {};
  Mesh::Halfedge_index border;
  for (auto h : m.halfedges())
    if (m.is_border(h))
    {
      border = h;
      break;
    }
  std::vector<Mesh::Face_index> faces;
  std::vector<Mesh::Vertex_index> newVertices;
  // A near-planar loop (an osteotomy's section: a saw cut is flat) gets a
  // flat cap: a 2D constrained Delaunay triangulation in the loop's fitting
  // plane, refined. Its projection onto the plane cannot overlap itself, so
  // the cap cannot fold. Other loops get CGAL's minimal-weight triangulation,
  // refined. Neither is faired: fairing (a bi-Laplacian solve with cotangent
  // weights) folded the caps: 118 and 90 pairs of crossing triangles on the
  // main job's pieces, 134 and 149 on a wavy loop on a sphere; 0 now.
  //
  // This is CGAL's triangulate_and_refine_hole in two steps: its refine
  // requires a triangle mesh, so the polygon face goes before the refinement.
  PMP::triangulate_hole(m, border, std::back_inserter(faces),
    CGAL::parameters::use_2d_constrained_delaunay_triangulation(plane.flat).threshold_distance(plane.tolerance));
  CGAL::Euler::remove_face(m.halfedge(f), m);
  PMP::refine(m, std::vector<Mesh::Face_index>(faces), std::back_inserter(faces), std::back_inserter(newVertices),
    CGAL::parameters::density_control_factor(0.7));
  return capOf(m, vs, newVertices, faces);
}

} // namespace cut
} // namespace lk
