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

/// lk::closestPointOnTriangle (Ericson's Voronoi regions) on CGAL types: a
/// handful of dot products, where the kernel's generic projection builds
/// planes and segments (it took about half of every query).
Point closestPointOnTriangle(const CgalTriangle& t, const Point& p)
{
  auto v = [](const Point& q) { return Vec3(q.x(), q.y(), q.z()); };
  const Vec3 c = lk::closestPointOnTriangle(v(p), v(t[0]), v(t[1]), v(t[2]));
  return Point(c.x(), c.y(), c.z());
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
