#include "latticekit/MeshCut.h"

#include "latticekit/LatticeSimplification.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>

namespace lk
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

std::size_t find(std::vector<std::size_t>& parent, std::size_t x)
{
  while (parent[x] != x)
    x = parent[x] = parent[parent[x]];
  return x;
}

/// The cap of a loop: new points and triangles (indices: < 0 means loop
/// vertex -(i+1), >= 0 a new point), oriented so that the loop runs
/// a -> b -> ... along the triangles' boundary. Empty on failure.
struct Cap
{
  std::vector<Vec3> points;
  std::vector<std::array<std::int64_t, 3>> triangles;
  bool faired = false;
};

Cap makeCap(const std::vector<Vec3>& loop)
{
  // A mesh holding only a thin collar would change the fairing; instead the
  // hole is the border of a single fan-free face: build the loop as a mesh
  // with one polygon face, then fill its other side.
  Mesh m;
  std::vector<Mesh::Vertex_index> vs;
  for (const Vec3& p : loop)
    vs.push_back(m.add_vertex(Point(p.x(), p.y(), p.z())));
  // The polygon face runs against the loop; the hole (border) runs along it.
  std::vector<Mesh::Vertex_index> reversed(vs.rbegin(), vs.rend());
  const auto f = m.add_face(reversed);
  Cap cap;
  if (f == Mesh::null_face())
    return cap;
  Mesh::Halfedge_index border;
  for (auto h : m.halfedges())
    if (m.is_border(h))
    {
      border = h;
      break;
    }
  std::vector<Mesh::Face_index> faces;
  std::vector<Mesh::Vertex_index> newVertices;
  const auto result = PMP::triangulate_refine_and_fair_hole(
    m, border, std::back_inserter(faces), std::back_inserter(newVertices));
  cap.faired = std::get<0>(result);
  std::map<Mesh::Vertex_index, std::int64_t> id;
  for (std::size_t i = 0; i < vs.size(); ++i)
    id[vs[i]] = -static_cast<std::int64_t>(i) - 1;
  for (auto v : newVertices)
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

CutResult cutAlongLoops(const PolygonMesh& mesh, const std::vector<std::vector<std::int64_t>>& loopsIn, bool cap)
{
  const std::string problem = latticeProblem(mesh);
  if (!problem.empty())
    throw std::invalid_argument(problem);
  if (loopsIn.empty())
    throw std::invalid_argument("no loop to cut along");
  // Directed edges -> face.
  std::map<std::pair<std::int64_t, std::int64_t>, std::size_t> directed;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    const auto& face = mesh.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i)
      directed[{ face[i], face[(i + 1) % face.size()] }] = f;
  }
  std::vector<std::vector<std::int64_t>> loops;
  std::set<EdgeKey> cutEdges;
  for (std::size_t l = 0; l < loopsIn.size(); ++l)
  {
    std::vector<std::int64_t> loop = loopsIn[l];
    if (loop.size() > 1 && loop.front() == loop.back())
      loop.pop_back();
    const std::string which = "loop " + std::to_string(l);
    if (loop.size() < 3)
      throw std::invalid_argument(which + " has fewer than 3 vertices: it is not a closed line");
    std::set<std::int64_t> seen;
    for (std::size_t i = 0; i < loop.size(); ++i)
    {
      const auto a = loop[i], b = loop[(i + 1) % loop.size()];
      if (a < 0 || a >= static_cast<std::int64_t>(mesh.points.size()))
        throw std::invalid_argument(which + " has a vertex id outside the mesh");
      if (!seen.insert(a).second)
        throw std::invalid_argument(which + " crosses itself (vertex " + std::to_string(a) + " twice)");
      if (!directed.count({ a, b }) && !directed.count({ b, a }))
        throw std::invalid_argument(which + " is not closed along mesh edges: " + std::to_string(a) + " and " +
          std::to_string(b) + " are not joined by an edge");
      cutEdges.insert(a < b ? EdgeKey(a, b) : EdgeKey(b, a));
    }
    loops.push_back(loop);
  }
  // Regions: faces joined across edges that are not cut.
  std::vector<std::size_t> parent(mesh.faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [e, f] : directed)
  {
    const auto back = directed.find({ e.second, e.first });
    if (back == directed.end() || cutEdges.count(e.first < e.second ? EdgeKey(e.first, e.second) : EdgeKey(e.second, e.first)))
      continue;
    parent[find(parent, f)] = find(parent, back->second);
  }
  std::map<std::size_t, std::size_t> regionOf;
  std::vector<std::size_t> faceRegion(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    const std::size_t r = find(parent, f);
    auto it = regionOf.find(r);
    if (it == regionOf.end())
      it = regionOf.emplace(r, regionOf.size()).first;
    faceRegion[f] = it->second;
  }
  // Components of the input (loops only separate within a component).
  std::vector<std::size_t> compParent(mesh.faces.size());
  std::iota(compParent.begin(), compParent.end(), 0);
  for (const auto& [e, f] : directed)
  {
    const auto back = directed.find({ e.second, e.first });
    if (back != directed.end())
      compParent[find(compParent, f)] = find(compParent, back->second);
  }
  std::set<std::size_t> components;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    components.insert(find(compParent, f));
  if (regionOf.size() <= components.size())
    throw std::invalid_argument("the loops do not separate the mesh (it stays in one piece)");

  CutResult result;
  const std::size_t pieces = regionOf.size();
  result.pieces.resize(pieces);
  result.vertexOrigin.resize(pieces);
  result.faceOrigin.resize(pieces);
  std::vector<std::map<std::int64_t, std::int64_t>> local(pieces);
  auto localId = [&](std::size_t p, std::int64_t v) {
    auto it = local[p].find(v);
    if (it != local[p].end())
      return it->second;
    const auto id = static_cast<std::int64_t>(result.pieces[p].points.size());
    result.pieces[p].points.push_back(mesh.points[static_cast<std::size_t>(v)]);
    result.vertexOrigin[p].push_back(v);
    local[p][v] = id;
    return id;
  };
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    const std::size_t p = faceRegion[f];
    std::vector<std::int64_t> face;
    for (auto v : mesh.faces[f])
      face.push_back(localId(p, v));
    result.pieces[p].faces.push_back(face);
    result.faceOrigin[p].push_back(static_cast<std::int64_t>(f));
  }
  if (!cap)
    return result;
  for (const auto& loop : loops)
  {
    std::vector<Vec3> pts;
    for (auto v : loop)
      pts.push_back(mesh.points[static_cast<std::size_t>(v)]);
    const Cap c = makeCap(pts);
    if (c.triangles.empty())
      throw std::invalid_argument("a loop could not be capped (CGAL's hole filling failed)");
    if (!c.faired)
      ++result.capFailures;
    // The cap's triangles run along the loop (a -> b); a piece whose faces
    // run a -> b takes the cap reversed, the other as it is.
    for (int side = 0; side < 2; ++side)
    {
      const auto a = loop[0], b = loop[1];
      const auto it = directed.find(side == 0 ? std::make_pair(a, b) : std::make_pair(b, a));
      if (it == directed.end())
        continue;
      const std::size_t p = faceRegion[it->second];
      const bool reverse = side == 0;
      std::vector<std::int64_t> capIds;
      for (const Vec3& q : c.points)
      {
        capIds.push_back(static_cast<std::int64_t>(result.pieces[p].points.size()));
        result.pieces[p].points.push_back(q);
        result.vertexOrigin[p].push_back(-1);
      }
      // A face of the piece spanned by loop vertices only may coincide with a
      // cap triangle: the two would enclose nothing (a doubled triangle,
      // non-manifold). Both are dropped; the piece stays closed there.
      std::map<std::array<std::int64_t, 3>, std::size_t> onLoop;
      for (std::size_t f = 0; f < result.pieces[p].faces.size(); ++f)
      {
        const auto& face = result.pieces[p].faces[f];
        if (face.size() != 3)
          continue;
        std::array<std::int64_t, 3> key{ face[0], face[1], face[2] };
        std::sort(key.begin(), key.end());
        onLoop[key] = f;
      }
      std::vector<char> dropFace(result.pieces[p].faces.size(), 0);
      for (const auto& t : c.triangles)
      {
        std::vector<std::int64_t> face;
        for (auto i : t)
          face.push_back(i < 0 ? local[p].at(loop[static_cast<std::size_t>(-i - 1)]) : capIds[static_cast<std::size_t>(i)]);
        if (reverse)
          std::reverse(face.begin(), face.end());
        std::array<std::int64_t, 3> key{ face[0], face[1], face[2] };
        std::sort(key.begin(), key.end());
        const auto twin = onLoop.find(key);
        if (twin != onLoop.end() && twin->second < dropFace.size())
        {
          dropFace[twin->second] = 1;
          continue;
        }
        result.pieces[p].faces.push_back(face);
        result.faceOrigin[p].push_back(-1);
      }
      // Compact: dropped faces out, then points no face uses.
      PolygonMesh& piece = result.pieces[p];
      std::vector<std::vector<std::int64_t>> faces;
      std::vector<std::int64_t> origin;
      for (std::size_t f = 0; f < piece.faces.size(); ++f)
      {
        if (f < dropFace.size() && dropFace[f])
          continue;
        faces.push_back(piece.faces[f]);
        origin.push_back(result.faceOrigin[p][f]);
      }
      std::vector<std::int64_t> newId(piece.points.size(), -1);
      std::vector<Vec3> points;
      std::vector<std::int64_t> vorigin;
      for (auto& face : faces)
        for (auto& v : face)
        {
          if (newId[static_cast<std::size_t>(v)] < 0)
          {
            newId[static_cast<std::size_t>(v)] = static_cast<std::int64_t>(points.size());
            points.push_back(piece.points[static_cast<std::size_t>(v)]);
            vorigin.push_back(result.vertexOrigin[p][static_cast<std::size_t>(v)]);
          }
          v = newId[static_cast<std::size_t>(v)];
        }
      for (auto& [v, id] : local[p])
        id = newId[static_cast<std::size_t>(id)];
      piece.faces = std::move(faces);
      piece.points = std::move(points);
      result.faceOrigin[p] = std::move(origin);
      result.vertexOrigin[p] = std::move(vorigin);
    }
  }
  return result;
}

} // namespace lk
