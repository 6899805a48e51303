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
double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0.0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

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
      const double d = distanceToSegment(p, a, b);
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

} // namespace lk
