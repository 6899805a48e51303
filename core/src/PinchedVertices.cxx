#include "latticekit/PinchedVertices.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace lk
{

std::optional<std::vector<std::size_t>> splitPinchedVerticesOfOrientedSoup(
  std::vector<IndexTriangle>& triangles, std::size_t pointCount)
{
  // The triangle corners at each vertex (compressed rows, in triangle order).
  const std::size_t n = pointCount;
  std::vector<std::size_t> start(n + 1, 0);
  for (const IndexTriangle& t : triangles)
  {
    if (t[0] >= n || t[1] >= n || t[2] >= n || t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      throw std::invalid_argument("splitPinchedVerticesOfOrientedSoup: a triangle repeats a point or "
                                  "refers to one beyond the " + std::to_string(n) + " points");
    for (std::size_t v : t)
      ++start[v + 1];
  }
  for (std::size_t v = 0; v < n; ++v)
    start[v + 1] += start[v];
  std::vector<std::size_t> corners(start[n]);
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < triangles.size(); ++t)
      for (std::size_t k = 0; k < 3; ++k)
        corners[fill[triangles[t][k]]++] = 3 * t + k;
  }
  // Around vertex v, triangle (v, a, b) is the link edge a -> b: it has the
  // directed edges v -> a and b -> v. At a link vertex a, the link edges
  // starting there count the triangles with v -> a, those ending there the
  // triangles with a -> v.
  struct LinkEdge
  {
    std::size_t from, to, corner;
  };
  const auto byFrom = [](const LinkEdge& x, const LinkEdge& y) { return x.from < y.from; };
  std::vector<LinkEdge> link;
  std::vector<std::size_t> ends, parent, fanOf, firstTriangle, order;
  std::vector<std::size_t> copied;                          // the point each new point copies
  std::vector<std::pair<std::size_t, std::size_t>> renamed; // (corner, new point)
  const auto root = [&parent](std::size_t i) {
    while (parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t v = 0; v < n; ++v)
  {
    const std::size_t degree = start[v + 1] - start[v];
    link.clear();
    ends.clear();
    for (std::size_t i = start[v]; i < start[v + 1]; ++i)
    {
      const IndexTriangle& t = triangles[corners[i] / 3];
      const std::size_t k = corners[i] % 3;
      link.push_back({ t[(k + 1) % 3], t[(k + 2) % 3], corners[i] });
      ends.push_back(t[(k + 2) % 3]);
    }
    std::stable_sort(link.begin(), link.end(), byFrom);
    std::sort(ends.begin(), ends.end());
    const auto starting = [&](std::size_t a) {
      return std::equal_range(link.begin(), link.end(), LinkEdge{ a, 0, 0 }, byFrom);
    };
    const auto ending = [&](std::size_t a) {
      const auto r = std::equal_range(ends.begin(), ends.end(), a);
      return static_cast<std::size_t>(r.second - r.first);
    };
    // Two triangles on the edge v-a in the same direction: to be oriented.
    for (const LinkEdge& e : link)
      for (const std::size_t a : { e.from, e.to })
      {
        const auto out = starting(a);
        const std::size_t outCount = static_cast<std::size_t>(out.second - out.first);
        if (outCount + ending(a) == 2 && outCount != 1)
          return std::nullopt;
      }
    if (degree < 2)
      continue;
    // Fans: link edges joined where an edge v-b has one triangle each way.
    parent.resize(degree);
    for (std::size_t i = 0; i < degree; ++i)
      parent[i] = i;
    for (std::size_t i = 0; i < degree; ++i)
    {
      const auto out = starting(link[i].to);
      if (out.second - out.first == 1 && ending(link[i].to) == 1)
        parent[root(i)] = root(static_cast<std::size_t>(out.first - link.begin()));
    }
    // Fans in the order of their lowest triangles; the first keeps v.
    fanOf.assign(degree, degree);
    firstTriangle.clear();
    std::size_t fans = 0;
    for (std::size_t i = 0; i < degree; ++i)
    {
      const std::size_t r = root(i);
      if (fanOf[r] == degree)
      {
        fanOf[r] = fans++;
        firstTriangle.push_back(link[i].corner / 3);
      }
      else
        firstTriangle[fanOf[r]] = std::min(firstTriangle[fanOf[r]], link[i].corner / 3);
    }
    if (fans == 1)
      continue;
    order.resize(fans);
    for (std::size_t f = 0; f < fans; ++f)
      order[f] = f;
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return firstTriangle[x] < firstTriangle[y]; });
    std::vector<std::size_t> idOfFan(fans);
    idOfFan[order[0]] = v;
    for (std::size_t f = 1; f < fans; ++f)
    {
      idOfFan[order[f]] = n + copied.size();
      copied.push_back(v);
    }
    for (std::size_t i = 0; i < degree; ++i)
    {
      const std::size_t id = idOfFan[fanOf[root(i)]];
      if (id != v)
        renamed.emplace_back(link[i].corner, id);
    }
  }
  for (const auto& [corner, id] : renamed)
    triangles[corner / 3][corner % 3] = id;
  return copied;
}

} // namespace lk
