#include "latticekit/FeatureChains.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <stdexcept>
#include <string>

namespace lk
{
namespace
{
/// A chain of fewer edges is never a crease: one or two edges (a short piece
/// between junctions) are too few for their mean to tell a sharp line from
/// the fold of one facet; on the decimated head a one-edge piece of a line
/// across the face bends by 63 degrees, its neighbours by 14-31 on average.
constexpr std::size_t kFewestCreaseEdges = 3;

bool lexicographicallyBelow(const Vec3& a, const Vec3& b)
{
  return std::make_tuple(a.x(), a.y(), a.z()) < std::make_tuple(b.x(), b.y(), b.z());
}

/// Douglas-Peucker on chain[first..last] (both kept). With `atLeastOne`, the
/// farthest inner vertex is kept even when it is within the tolerance.
void keepWithin(const std::vector<Vec3>& points, const std::vector<std::int64_t>& chain, std::size_t first,
  std::size_t last, double tolerance, bool atLeastOne, std::vector<char>& keep)
{
  std::vector<std::pair<std::size_t, std::size_t>> todo{ { first, last } };
  bool forced = atLeastOne;
  while (!todo.empty())
  {
    const auto [i, j] = todo.back();
    todo.pop_back();
    if (j <= i + 1)
      continue;
    const Vec3& a = points[static_cast<std::size_t>(chain[i])];
    const Vec3& b = points[static_cast<std::size_t>(chain[j])];
    // Ties (a symmetric line) go to the smaller point, not to the first
    // met, so that the choice does not depend on the way the line runs.
    const double tie = 1e-9 * (b - a).norm();
    double worst = -1.0;
    std::size_t at = i;
    for (std::size_t k = i + 1; k < j; ++k)
    {
      const Vec3& p = points[static_cast<std::size_t>(chain[k])];
      const double d = (p - closestPointOnSegment(p, a, b)).norm();
      if (d > worst + tie ||
        (d >= worst - tie && lexicographicallyBelow(p, points[static_cast<std::size_t>(chain[at])])))
      {
        worst = std::max(worst, d);
        at = k;
      }
    }
    if (worst > tolerance || forced)
    {
      forced = false;
      keep[at] = 1;
      todo.push_back({ i, at });
      todo.push_back({ at, j });
    }
  }
}

} // namespace

std::vector<std::vector<std::int64_t>> featureChains(const std::vector<std::pair<std::int64_t, std::int64_t>>& edges)
{
  std::map<std::int64_t, std::vector<std::size_t>> at; // vertex -> its edges
  for (std::size_t e = 0; e < edges.size(); ++e)
  {
    at[edges[e].first].push_back(e);
    at[edges[e].second].push_back(e);
  }
  std::vector<char> used(edges.size(), 0);
  std::vector<std::vector<std::int64_t>> chains;
  auto other = [&](std::size_t e, std::int64_t v) { return edges[e].first == v ? edges[e].second : edges[e].first; };
  auto walk = [&](std::int64_t start, std::size_t e) {
    std::vector<std::int64_t> chain{ start };
    std::int64_t v = start;
    while (true)
    {
      used[e] = 1;
      v = other(e, v);
      chain.push_back(v);
      const auto& here = at[v];
      if (here.size() != 2 || v == start)
        break;
      const std::size_t next = here[0] == e ? here[1] : here[0];
      if (used[next])
        break;
      e = next;
    }
    chains.push_back(std::move(chain));
  };
  // Open chains from their ends first, then the closed loops left.
  for (const auto& [v, es] : at)
  {
    if (es.size() == 2)
      continue;
    for (std::size_t e : es)
      if (!used[e])
        walk(v, e);
  }
  for (const auto& [v, es] : at)
  {
    for (std::size_t e : es)
      if (!used[e])
        walk(v, e);
  }
  return chains;
}

std::vector<char> chainVerticesToKeep(
  const std::vector<Vec3>& points, const std::vector<std::int64_t>& chain, double tolerance)
{
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
    throw std::invalid_argument("the feature tolerance must be a finite distance >= 0");
  for (std::int64_t id : chain)
    if (id < 0 || static_cast<std::size_t>(id) >= points.size())
      throw std::invalid_argument("chain vertex " + std::to_string(id) + " is outside the points 0.." +
        std::to_string(static_cast<long long>(points.size()) - 1));
  std::vector<char> keep(chain.size(), 0);
  if (chain.size() <= 2)
  {
    std::fill(keep.begin(), keep.end(), 1);
    return keep;
  }
  const bool closed = chain.front() == chain.back();
  if (!closed)
  {
    keep.front() = keep.back() = 1;
    keepWithin(points, chain, 0, chain.size() - 1, tolerance, false, keep);
    return keep;
  }
  // A loop: n distinct vertices, chain[n] == chain[0]. Cut it at its smallest
  // point s and at the vertex f farthest from s, the same whichever vertex
  // the ids start at and whichever way the loop runs.
  const std::size_t n = chain.size() - 1;
  auto p = [&](std::size_t k) -> const Vec3& { return points[static_cast<std::size_t>(chain[k % n])]; };
  std::size_t s = 0;
  for (std::size_t k = 1; k < n; ++k)
    if (lexicographicallyBelow(p(k), p(s)))
      s = k;
  std::size_t f = s;
  double farthest = -1.0;
  for (std::size_t k = 0; k < n; ++k)
  {
    const double d = (p(k) - p(s)).norm();
    const double tie = 1e-9 * std::max(d, farthest);
    if (d > farthest + tie || (d >= farthest - tie && lexicographicallyBelow(p(k), p(f))))
    {
      farthest = std::max(farthest, d);
      f = k;
    }
  }
  // The loop from s round to s again, as an open chain of n + 1 entries.
  std::vector<std::int64_t> rotated(n + 1);
  for (std::size_t k = 0; k <= n; ++k)
    rotated[k] = chain[(s + k) % n];
  const std::size_t fr = (f + n - s) % n;
  std::vector<char> keepRotated(n + 1, 0);
  keepRotated[0] = keepRotated[n] = keepRotated[fr] = 1;
  keepWithin(points, rotated, 0, fr, tolerance, true, keepRotated);
  keepWithin(points, rotated, fr, n, tolerance, true, keepRotated);
  for (std::size_t k = 0; k < n; ++k)
    keep[(s + k) % n] = keepRotated[k];
  keep[n] = keep[0];
  return keep;
}

std::size_t featureVerticesToKeep(const std::vector<Vec3>& points,
  const std::vector<std::pair<std::int64_t, std::int64_t>>& edges, double tolerance)
{
  std::set<std::int64_t> kept;
  for (const std::vector<std::int64_t>& chain : featureChains(edges))
  {
    const std::vector<char> keep = chainVerticesToKeep(points, chain, tolerance);
    for (std::size_t k = 0; k < chain.size(); ++k)
      if (keep[k])
        kept.insert(chain[k]);
  }
  return kept.size();
}

std::vector<double> edgeBends(
  const TriangleMesh& mesh, const std::vector<std::pair<std::int64_t, std::int64_t>>& edges)
{
  const auto n = static_cast<std::int64_t>(mesh.points.size());
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::size_t>> faces; // edge -> its triangles
  for (const auto& [a, b] : edges)
  {
    if (a < 0 || b < 0 || a >= n || b >= n)
      throw std::invalid_argument("edge " + std::to_string(a) + "-" + std::to_string(b) +
        " names a point outside the mesh's 0.." + std::to_string(n - 1));
    faces[{ std::min(a, b), std::max(a, b) }];
  }
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k)
    {
      const std::int64_t a = mesh.triangles[f][static_cast<std::size_t>(k)];
      const std::int64_t b = mesh.triangles[f][static_cast<std::size_t>((k + 1) % 3)];
      const auto it = faces.find({ std::min(a, b), std::max(a, b) });
      if (it != faces.end())
        it->second.push_back(f);
    }
  auto normal = [&](std::size_t f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
    return Vec3((mesh.points[static_cast<std::size_t>(t[1])] - a).cross(mesh.points[static_cast<std::size_t>(t[2])] - a));
  };
  std::vector<double> bends(edges.size(), 0.0);
  for (std::size_t e = 0; e < edges.size(); ++e)
  {
    const auto& at = faces[{ std::min(edges[e].first, edges[e].second), std::max(edges[e].first, edges[e].second) }];
    if (at.size() != 2)
      continue;
    const Vec3 u = normal(at[0]), v = normal(at[1]);
    const double lengths = u.norm() * v.norm();
    if (!(lengths > 0.0) || !std::isfinite(lengths))
      continue;
    // atan2 of |u x v| and u.v: accurate near 0 and 180 degrees, where acos is not.
    bends[e] = std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / kPi;
  }
  return bends;
}

std::vector<char> creaseFeatureEdges(const std::vector<Vec3>& inputPoints,
  const std::vector<std::pair<std::int64_t, std::int64_t>>& inputEdges, const std::vector<double>& bends,
  const std::vector<std::pair<std::int64_t, std::int64_t>>& latticeEdges, const std::vector<std::int64_t>& inputVertex,
  double angleDegrees)
{
  if (bends.size() != inputEdges.size())
    throw std::invalid_argument("creaseFeatureEdges: " + std::to_string(bends.size()) + " bends for " +
      std::to_string(inputEdges.size()) + " feature edges");
  const auto points = static_cast<std::int64_t>(inputPoints.size());
  auto key = [](std::int64_t a, std::int64_t b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  std::map<std::pair<std::int64_t, std::int64_t>, double> bendOf;
  for (std::size_t e = 0; e < inputEdges.size(); ++e)
  {
    const auto [a, b] = inputEdges[e];
    if (a < 0 || b < 0 || a >= points || b >= points)
      throw std::invalid_argument("creaseFeatureEdges: feature edge " + std::to_string(a) + "-" + std::to_string(b) +
        " names a point outside 0.." + std::to_string(points - 1));
    bendOf[key(a, b)] = bends[e];
  }
  // Each chain's mean bend, by length, and the chains each vertex is on.
  const std::vector<std::vector<std::int64_t>> chains = featureChains(inputEdges);
  std::vector<char> sharp(chains.size(), 0);
  std::map<std::int64_t, std::vector<std::size_t>> chainsOf;
  for (std::size_t c = 0; c < chains.size(); ++c)
  {
    double sum = 0.0, length = 0.0, plain = 0.0;
    for (std::size_t k = 0; k + 1 < chains[c].size(); ++k)
    {
      const std::int64_t a = chains[c][k], b = chains[c][k + 1];
      const double l = (inputPoints[static_cast<std::size_t>(b)] - inputPoints[static_cast<std::size_t>(a)]).norm();
      sum += bendOf[key(a, b)] * l;
      length += l;
      plain += bendOf[key(a, b)];
    }
    const double mean = length > 0.0 ? sum / length : plain / static_cast<double>(chains[c].size() - 1);
    sharp[c] = chains[c].size() > kFewestCreaseEdges && mean > angleDegrees ? 1 : 0;
    for (const std::int64_t v : chains[c])
    {
      auto& on = chainsOf[v];
      if (on.empty() || on.back() != c)
        on.push_back(c);
    }
  }
  auto inputOf = [&](std::int64_t v) {
    if (v < 0 || static_cast<std::size_t>(v) >= inputVertex.size())
      throw std::invalid_argument("creaseFeatureEdges: lattice vertex " + std::to_string(v) +
        " has no input vertex (" + std::to_string(inputVertex.size()) + " given)");
    return inputVertex[static_cast<std::size_t>(v)];
  };
  std::vector<char> crease(latticeEdges.size(), 0);
  for (std::size_t e = 0; e < latticeEdges.size(); ++e)
  {
    const auto a = chainsOf.find(inputOf(latticeEdges[e].first)), b = chainsOf.find(inputOf(latticeEdges[e].second));
    if (a == chainsOf.end() || b == chainsOf.end())
      continue;
    for (const std::size_t c : a->second)
      if (std::find(b->second.begin(), b->second.end(), c) != b->second.end())
      {
        crease[e] = sharp[c];
        break;
      }
  }
  return crease;
}

} // namespace lk
