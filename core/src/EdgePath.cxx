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

std::vector<std::int64_t> dijkstra(const TriangleMesh& mesh, const std::vector<std::vector<std::int64_t>>& adj,
  std::int64_t a, std::int64_t b)
{
  const std::size_t n = mesh.points.size();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> prev(n, -1);
  using Item = std::pair<double, std::int64_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  dist[static_cast<std::size_t>(a)] = 0.0;
  heap.push({ 0.0, a });
  while (!heap.empty())
  {
    const auto [d, v] = heap.top();
    heap.pop();
    if (d > dist[static_cast<std::size_t>(v)])
      continue;
    if (v == b)
      break;
    for (auto w : adj[static_cast<std::size_t>(v)])
    {
      const double nd =
        d + (mesh.points[static_cast<std::size_t>(v)] - mesh.points[static_cast<std::size_t>(w)]).norm();
      if (nd < dist[static_cast<std::size_t>(w)])
      {
        dist[static_cast<std::size_t>(w)] = nd;
        prev[static_cast<std::size_t>(w)] = v;
        heap.push({ nd, w });
      }
    }
  }
  if (!(dist[static_cast<std::size_t>(b)] < std::numeric_limits<double>::infinity()))
    return {};
  std::vector<std::int64_t> path;
  for (std::int64_t v = b; v != -1; v = prev[static_cast<std::size_t>(v)])
    path.push_back(v);
  std::reverse(path.begin(), path.end());
  return path;
}
} // namespace

std::vector<std::int64_t> shortestEdgePath(const TriangleMesh& mesh, std::int64_t a, std::int64_t b)
{
  return dijkstra(mesh, adjacency(mesh), a, b);
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
  std::vector<std::int64_t> path;
  if (!anchors.empty())
    path.push_back(anchors[0]);
  for (std::size_t i = 1; i < anchors.size(); ++i)
  {
    const auto leg = dijkstra(mesh, adj, anchors[i - 1], anchors[i]);
    if (leg.empty())
      throw std::invalid_argument("two points of the line lie on parts of the mesh no edge path joins");
    path.insert(path.end(), leg.begin() + 1, leg.end());
  }
  return path;
}

} // namespace lk
