#include "latticekit/EdgePath.h"

#include "latticekit/ClosestPointTree.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>

namespace lk
{
namespace
{
std::vector<std::vector<std::int64_t>> adjacency(const TriangleMesh& mesh)
{
  std::vector<std::vector<std::int64_t>> adj(mesh.points.size());
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
    {
      const auto a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
      adj[static_cast<std::size_t>(a)].push_back(b);
      adj[static_cast<std::size_t>(b)].push_back(a);
    }
  for (auto& n : adj)
  {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  return adj;
}

/// Shortest edge paths on one mesh, one pair of vertices after another.
/// The distances and the predecessors are kept between searches, and only
/// the entries a search set are put back: a stroke on a skull joins dozens
/// of pairs a few edges apart, on 750,000 vertices.
class Dijkstra
{
public:
  Dijkstra(const TriangleMesh& mesh, const std::vector<std::vector<std::int64_t>>& adj)
    : mesh_(mesh)
    , adj_(adj)
    , dist_(mesh.points.size(), std::numeric_limits<double>::infinity())
    , prev_(mesh.points.size(), -1)
  {
  }

  std::vector<std::int64_t> path(std::int64_t a, std::int64_t b)
  {
    using Item = std::pair<double, std::int64_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
    set(a, 0.0, -1);
    heap.push({ 0.0, a });
    while (!heap.empty())
    {
      const auto [d, v] = heap.top();
      heap.pop();
      if (d > dist_[static_cast<std::size_t>(v)])
        continue;
      if (v == b)
        break;
      for (auto w : adj_[static_cast<std::size_t>(v)])
      {
        const double nd =
          d + (mesh_.points[static_cast<std::size_t>(v)] - mesh_.points[static_cast<std::size_t>(w)]).norm();
        if (nd < dist_[static_cast<std::size_t>(w)])
        {
          set(w, nd, v);
          heap.push({ nd, w });
        }
      }
    }
    std::vector<std::int64_t> out;
    if (dist_[static_cast<std::size_t>(b)] < std::numeric_limits<double>::infinity())
    {
      for (std::int64_t v = b; v != -1; v = prev_[static_cast<std::size_t>(v)])
        out.push_back(v);
      std::reverse(out.begin(), out.end());
    }
    for (const auto v : touched_)
    {
      dist_[static_cast<std::size_t>(v)] = std::numeric_limits<double>::infinity();
      prev_[static_cast<std::size_t>(v)] = -1;
    }
    touched_.clear();
    return out;
  }

private:
  void set(std::int64_t v, double d, std::int64_t from)
  {
    if (dist_[static_cast<std::size_t>(v)] == std::numeric_limits<double>::infinity())
      touched_.push_back(v);
    dist_[static_cast<std::size_t>(v)] = d;
    prev_[static_cast<std::size_t>(v)] = from;
  }

  const TriangleMesh& mesh_;
  const std::vector<std::vector<std::int64_t>>& adj_;
  std::vector<double> dist_;
  std::vector<std::int64_t> prev_;
  std::vector<std::int64_t> touched_;
};
} // namespace

std::vector<std::int64_t> shortestEdgePath(const TriangleMesh& mesh, std::int64_t a, std::int64_t b)
{
  const auto adj = adjacency(mesh);
  return Dijkstra(mesh, adj).path(a, b);
}

std::vector<std::int64_t> edgePathThrough(const TriangleMesh& mesh, const std::vector<Vec3>& points)
{
  const std::string problem = validateTriangleMesh(mesh);
  if (!problem.empty())
    throw std::invalid_argument(problem);
  for (const Vec3& p : points)
    if (!p.allFinite())
      throw std::invalid_argument("a point of the line is not finite");
  const ClosestPointTree tree(mesh);
  return edgePathThrough(mesh, tree, points);
}

std::vector<std::int64_t> edgePathThrough(
  const TriangleMesh& mesh, const ClosestPointTree& tree, const std::vector<Vec3>& points)
{
  for (const Vec3& p : points)
    if (!p.allFinite())
      throw std::invalid_argument("a point of the line is not finite");
  std::vector<std::int64_t> anchors;
  for (const Vec3& p : points)
  {
    const auto hit = tree.closest(p);
    const Triangle& t = mesh.triangles[static_cast<std::size_t>(hit.face)];
    std::int64_t best = t[0];
    for (auto v : t)
      if ((mesh.points[static_cast<std::size_t>(v)] - p).squaredNorm() <
        (mesh.points[static_cast<std::size_t>(best)] - p).squaredNorm())
        best = v;
    if (anchors.empty() || anchors.back() != best)
      anchors.push_back(best);
  }
  const auto adj = adjacency(mesh);
  Dijkstra search(mesh, adj);
  std::vector<std::int64_t> path;
  if (!anchors.empty())
    path.push_back(anchors[0]);
  for (std::size_t i = 1; i < anchors.size(); ++i)
  {
    const auto leg = search.path(anchors[i - 1], anchors[i]);
    if (leg.empty())
      throw std::invalid_argument("two points of the line lie on parts of the mesh no edge path joins");
    path.insert(path.end(), leg.begin() + 1, leg.end());
  }
  return path;
}

} // namespace lk
