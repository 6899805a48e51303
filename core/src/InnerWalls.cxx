#include "InnerWalls.h"

#include "CutCaps.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace lk
{
namespace cut
{

InnerWalls splitAlongInnerWalls(const PolygonMesh& mesh, const std::vector<std::int64_t>& loop,
  const std::vector<char>& onLoop)
{
  InnerWalls out;
  std::vector<Vec3> points;
  for (auto v : loop)
    points.push_back(mesh.points[static_cast<std::size_t>(v)]);
  const LoopPlane plane = fitLoopPlane(points);
  if (!plane.flat)
    return out;
  // A kept section lies inside the loop: crossings whose point falls outside
  // the loop's box in the plane are not needed (on a large mesh the plane's
  // whole section would be).
  const LoopOutline outline(points, plane);
  // Crossing edges (a < b) and their parameter along a -> b.
  std::vector<double> d(mesh.points.size());
  std::map<std::pair<std::int64_t, std::int64_t>, double> crossing;
  auto pointAt = [&](std::int64_t a, std::int64_t b, double t) -> Vec3 {
    return (1.0 - t) * mesh.points[static_cast<std::size_t>(a)] + t * mesh.points[static_cast<std::size_t>(b)];
  };
  // Whether the plane passes between the face's vertices: only such faces
  // have crossed edges (most of a large mesh does not; no lookups there).
  auto crossesPlane = [&](const std::vector<std::int64_t>& face) {
    const bool side = d[static_cast<std::size_t>(face[0])] >= 0.0;
    return std::any_of(face.begin() + 1, face.end(), [&](std::int64_t v) { return (d[static_cast<std::size_t>(v)] >= 0.0) != side; });
  };
  for (int attempt = 0; attempt < 8; ++attempt)
  {
    const double offset = attempt * 1e-3 * plane.tolerance;
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
      d[v] = plane.normal.dot(mesh.points[v] - plane.centre) - offset;
    crossing.clear();
    bool clean = true;
    for (const auto& face : mesh.faces)
    {
      if (!crossesPlane(face))
        continue;
      for (std::size_t i = 0; i < face.size(); ++i)
      {
        const auto a = std::min(face[i], face[(i + 1) % face.size()]);
        const auto b = std::max(face[i], face[(i + 1) % face.size()]);
        const double da = d[static_cast<std::size_t>(a)], db = d[static_cast<std::size_t>(b)];
        if ((da >= 0.0) == (db >= 0.0))
          continue;
        const double t = da / (da - db);
        if (!outline.inBox(pointAt(a, b, t)))
          continue;
        crossing[{ a, b }] = t;
        if (t > 1e-4 && t < 1.0 - 1e-4)
          continue;
        // A new vertex would fall on an old one; it matters only where a
        // section could be kept: inside the loop, away from it.
        if (onLoop[static_cast<std::size_t>(a)] || onLoop[static_cast<std::size_t>(b)])
          continue;
        if (outline.side(pointAt(a, b, t)) != LoopOutline::Side::Outside)
          clean = false;
      }
    }
    if (clean)
      break;
    if (attempt == 7)
      return out;
  }
  // The section graph: each crossed triangle joins its two crossed edges.
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::size_t>> facesOfEdge;
  auto key = [](std::int64_t a, std::int64_t b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    const auto& face = mesh.faces[f];
    if (!crossesPlane(face))
      continue;
    for (std::size_t i = 0; i < face.size(); ++i)
    {
      const auto e = key(face[i], face[(i + 1) % face.size()]);
      if (crossing.count(e))
        facesOfEdge[e].push_back(f);
    }
  }
  std::set<std::pair<std::int64_t, std::int64_t>> visited;
  std::vector<std::vector<std::pair<std::int64_t, std::int64_t>>> cycles;
  for (const auto& [start, startFaces] : facesOfEdge)
  {
    if (visited.count(start) || startFaces.size() != 2)
      continue;
    std::vector<std::pair<std::int64_t, std::int64_t>> cycle{ start };
    visited.insert(start);
    std::size_t through = startFaces[0];
    auto edge = start;
    bool closed = false;
    for (;;)
    {
      const auto& face = mesh.faces[through];
      if (face.size() != 3)
        break;
      std::pair<std::int64_t, std::int64_t> next{ -1, -1 };
      for (std::size_t i = 0; i < 3; ++i)
      {
        const auto e = key(face[i], face[(i + 1) % 3]);
        if (e != edge && crossing.count(e))
          next = e;
      }
      if (next.first < 0)
        break;
      if (next == start)
      {
        closed = true;
        break;
      }
      if (!visited.insert(next).second)
        break;
      const auto& fs = facesOfEdge[next];
      if (fs.size() != 2)
        break;
      cycle.push_back(next);
      edge = next;
      through = fs[0] == through ? fs[1] : fs[0];
    }
    if (closed)
      cycles.push_back(std::move(cycle));
  }
  // Keep the sections inside the loop that do not come near it.
  auto crossingPoint = [&](const std::pair<std::int64_t, std::int64_t>& e) {
    return pointAt(e.first, e.second, crossing.at(e));
  };
  std::vector<std::vector<std::pair<std::int64_t, std::int64_t>>> kept;
  for (const auto& cycle : cycles)
  {
    bool keep = true;
    for (const auto& e : cycle)
    {
      keep = keep && outline.side(crossingPoint(e)) == LoopOutline::Side::Inside;
      for (auto f : facesOfEdge[e])
        for (auto v : mesh.faces[f]) // the crossed triangles, hence the edge's ends too
          keep = keep && !onLoop[static_cast<std::size_t>(v)];
    }
    if (keep)
      kept.push_back(cycle);
  }
  if (kept.empty())
    return out;
  out.mesh.points = mesh.points;
  std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> newVertex;
  for (const auto& cycle : kept)
  {
    std::vector<std::int64_t> ids;
    for (const auto& e : cycle)
    {
      newVertex[e] = static_cast<std::int64_t>(out.mesh.points.size());
      ids.push_back(newVertex[e]);
      out.mesh.points.push_back(crossingPoint(e));
    }
    out.loops.push_back(std::move(ids));
  }
  // Split every triangle that a kept section crosses: the vertex alone on its
  // side keeps a triangle, the other two a quad, cut in two.
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    const auto& face = mesh.faces[f];
    std::size_t lone = 3;
    if (face.size() == 3 && crossesPlane(face))
      for (std::size_t i = 0; i < 3; ++i)
      {
        const auto e1 = key(face[i], face[(i + 1) % 3]), e2 = key(face[i], face[(i + 2) % 3]);
        if (newVertex.count(e1) && newVertex.count(e2))
          lone = i;
      }
    if (lone == 3)
    {
      out.mesh.faces.push_back(face);
      out.faceParent.push_back(static_cast<std::int64_t>(f));
      continue;
    }
    const auto a = face[lone], b = face[(lone + 1) % 3], c = face[(lone + 2) % 3];
    const auto p = newVertex.at(key(a, b)), q = newVertex.at(key(a, c));
    for (const auto& t : { std::vector<std::int64_t>{ a, p, q }, std::vector<std::int64_t>{ p, b, c },
           std::vector<std::int64_t>{ p, c, q } })
    {
      out.mesh.faces.push_back(t);
      out.faceParent.push_back(static_cast<std::int64_t>(f));
    }
  }
  return out;
}

} // namespace cut
} // namespace lk
