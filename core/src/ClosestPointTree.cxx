#include "latticekit/ClosestPointTree.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <mutex>
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

void validate(const TriangleMesh& mesh)
{
  const std::string problem = validateTriangleMesh(mesh);
  if (!problem.empty())
    throw std::invalid_argument("ClosestPointTree: " + problem);
}
} // namespace

struct ClosestPointTree::Impl
{
  std::vector<CgalTriangle> triangles;
  Tree tree;
  /// A tree over part of a mesh: its faces' ids on the mesh (ascending, in
  /// the order of `triangles`), the box the part meets, the whole mesh and
  /// the tree over all of it, once a query needs it.
  std::vector<std::int64_t> faceIds;
  Vec3 lo{ Vec3::Zero() }, hi{ Vec3::Zero() };
  const TriangleMesh* mesh = nullptr;
  mutable std::once_flag wholeBuilt;
  mutable std::unique_ptr<ClosestPointTree> whole;

  void build()
  {
    tree.insert(triangles.begin(), triangles.end());
    tree.build();
    // Queries are chained through hints (see distances()), so CGAL's internal
    // k-d tree of hints is not worth building. Forcing the lazy construction of
    // the tree now keeps later queries read-only, hence thread-safe.
    tree.do_not_accelerate_distance_queries();
    tree.closest_point(triangles.front().vertex(0));
  }

  Hit makeHit(const Vec3& query, const Tree::Point_and_primitive_id& pp) const
  {
    Hit hit;
    hit.point = Vec3(pp.first.x(), pp.first.y(), pp.first.z());
    const auto local = static_cast<std::size_t>(pp.second - triangles.begin());
    hit.face = faceIds.empty() ? static_cast<std::int64_t>(local) : faceIds[local];
    hit.distance = (hit.point - query).norm();
    return hit;
  }

  /// Whether no face outside the box can be as close to `query` as `hit`:
  /// the ball through the hit lies inside the box, and every face left out
  /// lies wholly outside it.
  bool settled(const Vec3& query, const Hit& hit) const
  {
    return mesh == nullptr ||
      ((query.array() - hit.distance > lo.array()).all() && (query.array() + hit.distance < hi.array()).all());
  }

  const ClosestPointTree& wholeTree() const
  {
    std::call_once(wholeBuilt, [this] { whole = std::make_unique<ClosestPointTree>(*mesh); });
    return *whole;
  }
};

ClosestPointTree::ClosestPointTree(const TriangleMesh& mesh)
  : impl_(std::make_unique<Impl>())
{
  validate(mesh);
  impl_->triangles.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
  {
    impl_->triangles.emplace_back(toPoint(mesh.points[static_cast<std::size_t>(t[0])]),
      toPoint(mesh.points[static_cast<std::size_t>(t[1])]),
      toPoint(mesh.points[static_cast<std::size_t>(t[2])]));
  }
  impl_->build();
}

ClosestPointTree::ClosestPointTree(const TriangleMesh& mesh, const Vec3& lo, const Vec3& hi)
  : impl_(std::make_unique<Impl>())
{
  validate(mesh);
  if (!lo.allFinite() || !hi.allFinite() || !(lo.array() <= hi.array()).all())
  {
    throw std::invalid_argument("ClosestPointTree: the box is not a box (lo above hi, or not finite)");
  }
  impl_->mesh = &mesh;
  impl_->lo = lo;
  impl_->hi = hi;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
  {
    const Triangle& t = mesh.triangles[f];
    const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh.points[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh.points[static_cast<std::size_t>(t[2])];
    if ((a.cwiseMin(b).cwiseMin(c).array() <= hi.array()).all() &&
      (a.cwiseMax(b).cwiseMax(c).array() >= lo.array()).all())
    {
      impl_->faceIds.push_back(static_cast<std::int64_t>(f));
      impl_->triangles.emplace_back(toPoint(a), toPoint(b), toPoint(c));
    }
  }
  if (!impl_->triangles.empty())
    impl_->build();
}

ClosestPointTree::~ClosestPointTree() = default;

ClosestPointTree::Hit ClosestPointTree::closest(const Vec3& query) const
{
  const Impl& s = *impl_;
  if (s.triangles.empty())
    return s.wholeTree().closest(query);
  const Hit hit = s.makeHit(query, s.tree.closest_point_and_primitive(toPoint(query)));
  return s.settled(query, hit) ? hit : s.wholeTree().closest(query);
}

ClosestPointTree::Hit ClosestPointTree::closest(const Vec3& query, const Hit& hint) const
{
  const Impl& s = *impl_;
  if (hint.face < 0 || s.triangles.empty())
  {
    return closest(query);
  }
  std::size_t local = static_cast<std::size_t>(hint.face);
  if (s.mesh)
  {
    const auto it = std::lower_bound(s.faceIds.begin(), s.faceIds.end(), hint.face);
    if (it == s.faceIds.end() || *it != hint.face)
      return closest(query);
    local = static_cast<std::size_t>(it - s.faceIds.begin());
  }
  // The closest point of the previous hit's triangle bounds the search far
  // more tightly than the previous hit point itself.
  const auto tri = s.triangles.begin() + static_cast<std::ptrdiff_t>(local);
  const Point q = toPoint(query);
  const Tree::Point_and_primitive_id h(closestPointOnTriangle(*tri, q), tri);
  const Hit hit = s.makeHit(query, s.tree.closest_point_and_primitive(q, h));
  return s.settled(query, hit) ? hit : s.wholeTree().closest(query, hint);
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
