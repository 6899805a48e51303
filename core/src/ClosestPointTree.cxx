#include "latticekit/ClosestPointTree.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace lk
{

namespace
{
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using CgalTriangle = Kernel::Triangle_3;

/// The closest point of a triangle to p by Voronoi-region tests (Ericson,
/// "Real-Time Collision Detection", 5.1.5): a handful of dot products, where
/// the kernel's generic projection builds planes and segments (it took about
/// half of every query).
Point closestPointOnTriangle(const CgalTriangle& t, const Point& p)
{
  const double ax = t[0].x(), ay = t[0].y(), az = t[0].z();
  const double abx = t[1].x() - ax, aby = t[1].y() - ay, abz = t[1].z() - az;
  const double acx = t[2].x() - ax, acy = t[2].y() - ay, acz = t[2].z() - az;
  const double apx = p.x() - ax, apy = p.y() - ay, apz = p.z() - az;
  const double d1 = abx * apx + aby * apy + abz * apz;
  const double d2 = acx * apx + acy * apy + acz * apz;
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return t[0];
  }
  const double bpx = p.x() - t[1].x(), bpy = p.y() - t[1].y(), bpz = p.z() - t[1].z();
  const double d3 = abx * bpx + aby * bpy + abz * bpz;
  const double d4 = acx * bpx + acy * bpy + acz * bpz;
  if (d3 >= 0.0 && d4 <= d3)
  {
    return t[1];
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    const double v = d1 / (d1 - d3);
    return Point(ax + v * abx, ay + v * aby, az + v * abz);
  }
  const double cpx = p.x() - t[2].x(), cpy = p.y() - t[2].y(), cpz = p.z() - t[2].z();
  const double d5 = abx * cpx + aby * cpy + abz * cpz;
  const double d6 = acx * cpx + acy * cpy + acz * cpz;
  if (d6 >= 0.0 && d5 <= d6)
  {
    return t[2];
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    const double w = d2 / (d2 - d6);
    return Point(ax + w * acx, ay + w * acy, az + w * acz);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return Point(t[1].x() + w * (t[2].x() - t[1].x()), t[1].y() + w * (t[2].y() - t[1].y()),
      t[1].z() + w * (t[2].z() - t[1].z()));
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return Point(ax + abx * v + acx * w, ay + aby * v + acy * w, az + abz * v + acz * w);
}

/// The kernel CGAL's AABB traits see: Simple_cartesian<double> with the
/// triangle projection above. CGAL's tree and traversal are unchanged.
struct ProjectionKernel : Kernel
{
  struct Construct_projected_point_3 : Kernel::Construct_projected_point_3
  {
    using Kernel::Construct_projected_point_3::operator();
    Point operator()(const CgalTriangle& t, const Point& p) const { return closestPointOnTriangle(t, p); }
  };
  Construct_projected_point_3 construct_projected_point_3_object() const { return {}; }
};

using TriangleIterator = std::vector<CgalTriangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Traits = CGAL::AABB_traits<ProjectionKernel, Primitive>;
using Tree = CGAL::AABB_tree<Traits>;

Point toPoint(const Vec3& v)
{
  return Point(v.x(), v.y(), v.z());
}
} // namespace

struct ClosestPointTree::Impl
{
  std::vector<CgalTriangle> triangles;
  Tree tree;

  Hit makeHit(const Vec3& query, const Tree::Point_and_primitive_id& pp) const
  {
    Hit hit;
    hit.point = Vec3(pp.first.x(), pp.first.y(), pp.first.z());
    hit.face = static_cast<std::int64_t>(pp.second - triangles.begin());
    hit.distance = (hit.point - query).norm();
    return hit;
  }
};

ClosestPointTree::ClosestPointTree(const TriangleMesh& mesh)
  : impl_(std::make_unique<Impl>())
{
  const std::string problem = validateTriangleMesh(mesh);
  if (!problem.empty())
  {
    throw std::invalid_argument("ClosestPointTree: " + problem);
  }
  impl_->triangles.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
  {
    impl_->triangles.emplace_back(toPoint(mesh.points[static_cast<std::size_t>(t[0])]),
      toPoint(mesh.points[static_cast<std::size_t>(t[1])]),
      toPoint(mesh.points[static_cast<std::size_t>(t[2])]));
  }
  impl_->tree.insert(impl_->triangles.begin(), impl_->triangles.end());
  impl_->tree.build();
  // Queries are chained through hints (see distances()), so CGAL's internal
  // k-d tree of hints is not worth building. Forcing the lazy construction of
  // the tree now keeps later queries read-only, hence thread-safe.
  impl_->tree.do_not_accelerate_distance_queries();
  impl_->tree.closest_point(impl_->triangles.front().vertex(0));
}

ClosestPointTree::~ClosestPointTree() = default;

ClosestPointTree::Hit ClosestPointTree::closest(const Vec3& query) const
{
  return impl_->makeHit(query, impl_->tree.closest_point_and_primitive(toPoint(query)));
}

ClosestPointTree::Hit ClosestPointTree::closest(const Vec3& query, const Hit& hint) const
{
  if (hint.face < 0)
  {
    return closest(query);
  }
  // The closest point of the previous hit's triangle bounds the search far
  // more tightly than the previous hit point itself.
  const auto tri = impl_->triangles.begin() + static_cast<std::ptrdiff_t>(hint.face);
  const Point q = toPoint(query);
  const Tree::Point_and_primitive_id h(closestPointOnTriangle(*tri, q), tri);
  return impl_->makeHit(query, impl_->tree.closest_point_and_primitive(q, h));
}

void ClosestPointTree::distances(
  const SampleSet& samples, std::size_t begin, std::size_t end, double* out) const
{
  Hit hint;
  for (std::size_t i = begin; i < end; ++i)
  {
    hint = closest(samples.points[i], hint);
    out[i] = hint.distance;
  }
}

} // namespace lk
