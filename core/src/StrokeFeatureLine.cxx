#include "latticekit/StrokeFeatureLine.h"

#include "latticekit/ClosestPointTree.h"
#include "latticekit/EdgePath.h"

#include "SurfaceMeshConversion.h"

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <map>
#include <queue>
#include <set>
#include <stdexcept>
#include <string>

namespace lk
{
namespace
{
Vec3 closestOnPolyline(const std::vector<Vec3>& line, const Vec3& p)
{
  Vec3 best = line.front();
  double bd = (best - p).squaredNorm();
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
  {
    const Vec3 d = line[i + 1] - line[i];
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - line[i]).dot(d) / len2, 0.0, 1.0) : 0.0;
    const Vec3 q = line[i] + t * d;
    const double qd = (q - p).squaredNorm();
    if (qd < bd)
    {
      bd = qd;
      best = q;
    }
  }
  return best;
}

/// Closest point on segment (p, q) to segment (a, b): the parameter on (p, q).
double segmentParameter(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b)
{
  const Vec3 d1 = q - p, d2 = b - a, r = p - a;
  const double A = d1.dot(d1), E = d2.dot(d2), F = d2.dot(r);
  if (A <= 0.0)
    return 0.0;
  const double C = d1.dot(r), B = d1.dot(d2);
  const double den = A * E - B * B;
  double s = den > 1e-300 ? std::clamp((B * F - C * E) / den, 0.0, 1.0) : 0.0;
  double t = E > 0 ? (B * s + F) / E : 0.0;
  if (t < 0.0)
    s = std::clamp(-C / A, 0.0, 1.0);
  else if (t > 1.0)
    s = std::clamp((B - C) / A, 0.0, 1.0);
  return s;
}

using SMesh = cgal::SurfaceMesh;

/// Split mode: see the header.
void splitAlongStroke(const TriangleMesh& mesh, const ClosestPointTree& tree, const std::vector<Vec3>& projected,
  const std::vector<ClosestPointTree::Hit>& hits, StrokeResult& result)
{
  struct Crossing
  {
    std::int64_t u = -1, v = -1; ///< edge, or u alone for a vertex
    double t = 0.0;              ///< along u -> v
    Vec3 x;
  };
  auto sharedEdge = [&](std::int64_t fa, std::int64_t fb, std::int64_t& u, std::int64_t& v) {
    const Triangle& A = mesh.triangles[static_cast<std::size_t>(fa)];
    const Triangle& B = mesh.triangles[static_cast<std::size_t>(fb)];
    for (int i = 0; i < 3; ++i)
    {
      const auto a = A[static_cast<std::size_t>(i)], b = A[static_cast<std::size_t>((i + 1) % 3)];
      for (int j = 0; j < 3; ++j)
        if (B[static_cast<std::size_t>(j)] == b && B[static_cast<std::size_t>((j + 1) % 3)] == a)
        {
          u = a;
          v = b;
          return true;
        }
    }
    return false;
  };
  std::vector<Crossing> crossings;
  std::function<void(const Vec3&, std::int64_t, const Vec3&, std::int64_t, int)> cross =
    [&](const Vec3& a, std::int64_t fa, const Vec3& b, std::int64_t fb, int depth) {
      if (fa == fb)
        return;
      std::int64_t u, v;
      if (sharedEdge(fa, fb, u, v))
      {
        const Vec3 pu = mesh.points[static_cast<std::size_t>(u)], pv = mesh.points[static_cast<std::size_t>(v)];
        const double t = segmentParameter(pu, pv, a, b);
        crossings.push_back({ u, v, t, pu + t * (pv - pu) });
        return;
      }
      if (depth < 12)
      {
        const auto hm = tree.closest(0.5 * (a + b));
        cross(a, fa, hm.point, hm.face, depth + 1);
        cross(hm.point, hm.face, b, fb, depth + 1);
        return;
      }
      // Faces that touch at a vertex: cross there.
      for (auto x : mesh.triangles[static_cast<std::size_t>(fa)])
        for (auto y : mesh.triangles[static_cast<std::size_t>(fb)])
          if (x == y)
          {
            crossings.push_back({ x, -1, 0.0, mesh.points[static_cast<std::size_t>(x)] });
            return;
          }
      throw std::invalid_argument("the stroke jumps between faces that do not touch");
    };
  for (std::size_t i = 0; i + 1 < projected.size(); ++i)
    cross(projected[i], hits[i].face, projected[i + 1], hits[i + 1].face, 0);

  SMesh m;
  if (!cgal::toSurfaceMesh(mesh, m))
    throw std::invalid_argument("split mode needs a manifold, consistently oriented triangle mesh");
  auto setPoint = [&](SMesh::Vertex_index v, const Vec3& x) { m.point(v) = cgal::Point(x.x(), x.y(), x.z()); };
  std::vector<std::int64_t> pathVertices;
  auto centre = [&](std::int64_t face, const Vec3& x) {
    const auto h = CGAL::Euler::add_center_vertex(m.halfedge(SMesh::Face_index(static_cast<SMesh::size_type>(face))), m);
    setPoint(m.target(h), x);
    return static_cast<std::int64_t>(static_cast<std::size_t>(m.target(h)));
  };
  std::int64_t startVertex = -1, endVertex = -1;
  if (!result.closed)
  {
    startVertex = centre(hits.front().face, projected.front());
    if (hits.back().face != hits.front().face)
      endVertex = centre(hits.back().face, projected.back());
  }
  const double eps = 1e-9;
  std::map<EdgeKey, std::vector<std::pair<double, std::int64_t>>> onEdge; // t from the smaller id
  if (startVertex >= 0)
    pathVertices.push_back(startVertex);
  for (const Crossing& c : crossings)
  {
    std::int64_t vertex;
    if (c.v < 0 || c.t <= eps)
      vertex = c.u;
    else if (c.t >= 1.0 - eps)
      vertex = c.v;
    else
    {
      const EdgeKey key = edgeKey(c.u, c.v);
      const double t = c.u == key.first ? c.t : 1.0 - c.t;
      auto& list = onEdge[key];
      bool existing = false;
      vertex = -1;
      for (const auto& [tt, w] : list)
        if (std::abs(tt - t) <= eps)
        {
          vertex = w;
          existing = true;
        }
      // The sub-edge holding t: the nearest inserted points below and above.
      std::int64_t hi = key.second;
      double best = 2.0;
      for (const auto& [tt, w] : list)
        if (tt > t + eps && tt < best)
        {
          best = tt;
          hi = w;
        }
      double below = -1.0;
      std::int64_t lo = key.first;
      for (const auto& [tt, w] : list)
        if (tt < t - eps && tt > below)
        {
          below = tt;
          lo = w;
        }
      if (!existing)
      {
        const auto h = CGAL::halfedge(SMesh::Vertex_index(static_cast<SMesh::size_type>(lo)),
          SMesh::Vertex_index(static_cast<SMesh::size_type>(hi)), m);
        if (!h.second)
          throw std::invalid_argument("internal: lost a crossed edge while splitting");
        const auto hnew = CGAL::Euler::split_edge(h.first, m);
        setPoint(m.target(hnew), c.x);
        vertex = static_cast<std::int64_t>(static_cast<std::size_t>(m.target(hnew)));
        list.emplace_back(t, vertex);
      }
    }
    if (pathVertices.empty() || pathVertices.back() != vertex)
      pathVertices.push_back(vertex);
  }
  if (endVertex >= 0 && pathVertices.back() != endVertex)
    pathVertices.push_back(endVertex);
  if (result.closed && pathVertices.size() > 2 && pathVertices.back() != pathVertices.front())
    pathVertices.push_back(pathVertices.front());
  // Connect consecutive path vertices through the face they share.
  for (std::size_t i = 0; i + 1 < pathVertices.size(); ++i)
  {
    const SMesh::Vertex_index a(static_cast<SMesh::size_type>(pathVertices[i]));
    const SMesh::Vertex_index b(static_cast<SMesh::size_type>(pathVertices[i + 1]));
    if (CGAL::halfedge(a, b, m).second)
      continue;
    bool done = false;
    for (auto h : CGAL::halfedges_around_target(m.halfedge(a), m))
    {
      if (m.is_border(h))
        continue;
      for (auto g : CGAL::halfedges_around_face(h, m))
      {
        if (m.target(g) == b && g != m.next(h) && h != m.next(g))
        {
          CGAL::Euler::split_face(h, g, m);
          done = true;
          break;
        }
      }
      if (done)
        break;
    }
    if (!done)
      throw std::invalid_argument("the stroke could not be followed across the mesh (consecutive crossings share no face)");
  }
  CGAL::Polygon_mesh_processing::triangulate_faces(m);
  result.mesh = cgal::fromSurfaceMesh(m); // nothing was removed: ids stay
  result.line = pathVertices;
  for (std::size_t i = 0; i + 1 < pathVertices.size(); ++i)
    result.featureEdges.push_back(edgeKey(pathVertices[i], pathVertices[i + 1]));
}
} // namespace

StrokeResult strokeToFeatureLine(const TriangleMesh& mesh, const std::vector<Vec3>& strokeIn, const StrokeOptions& o)
{
  const std::string problem = validateTriangleMesh(mesh);
  if (!problem.empty())
    throw std::invalid_argument(problem);
  if (strokeIn.size() < 2)
    throw std::invalid_argument("a stroke needs at least two points");
  for (const Vec3& p : strokeIn)
    if (!p.allFinite())
      throw std::invalid_argument("a stroke point is not finite");
  double meanEdge = 0.0;
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
      meanEdge += (mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>(i)])] -
                    mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>((i + 1) % 3)])])
                    .norm();
  meanEdge /= 3.0 * static_cast<double>(mesh.triangles.size());
  const double spacing = o.spacing > 0 ? o.spacing : 0.25 * meanEdge;
  const double radius = o.brushRadius > 0 ? o.brushRadius : 0.5 * meanEdge;
  const double closeTol = o.closeTolerance > 0 ? o.closeTolerance : 2.0 * meanEdge;
  const double maxDist = o.maxDistance > 0 ? o.maxDistance : 5.0 * meanEdge;

  StrokeResult result;
  result.mesh = mesh;
  result.closed = (strokeIn.front() - strokeIn.back()).norm() <= closeTol;
  // Resample (closing the stroke when its ends meet) and project.
  std::vector<Vec3> stroke = strokeIn;
  if (result.closed)
    stroke.back() = stroke.front();
  std::vector<Vec3> samples;
  for (std::size_t i = 0; i + 1 < stroke.size(); ++i)
  {
    const double len = (stroke[i + 1] - stroke[i]).norm();
    const int n = std::max(1, static_cast<int>(std::ceil(len / spacing)));
    for (int k = 0; k < n; ++k)
      samples.push_back(stroke[i] + (stroke[i + 1] - stroke[i]) * (double(k) / n));
  }
  samples.push_back(stroke.back());
  const ClosestPointTree tree(mesh);
  std::vector<ClosestPointTree::Hit> hits;
  for (const Vec3& s : samples)
  {
    hits.push_back(hits.empty() ? tree.closest(s) : tree.closest(s, hits.back()));
    if (hits.back().distance > maxDist)
      throw std::invalid_argument("the stroke misses the surface: a stroke point lies " +
        std::to_string(hits.back().distance) + " from it (more than " + std::to_string(maxDist) + ")");
  }
  std::vector<Vec3> projected;
  for (const auto& h : hits)
    projected.push_back(h.point);

  auto addFaceEdges = [&](std::size_t f) {
    const Triangle& t = mesh.triangles[f];
    for (int i = 0; i < 3; ++i)
      result.featureEdges.push_back(edgeKey(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)]));
  };

  if (o.mode == StrokeMode::Split)
  {
    splitAlongStroke(mesh, tree, projected, hits, result);
  }
  else if (o.mode == StrokeMode::Paint)
  {
    std::vector<std::vector<std::size_t>> facesOf(mesh.points.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
      for (auto v : mesh.triangles[f])
        facesOf[static_cast<std::size_t>(v)].push_back(f);
    std::vector<char> painted(mesh.triangles.size(), 0);
    for (std::size_t s = 0; s < projected.size(); ++s)
    {
      std::queue<std::size_t> q;
      std::set<std::size_t> seen{ static_cast<std::size_t>(hits[s].face) };
      q.push(static_cast<std::size_t>(hits[s].face));
      while (!q.empty())
      {
        const std::size_t f = q.front();
        q.pop();
        const Triangle& t = mesh.triangles[f];
        const Vec3 c = closestPointOnTriangle(projected[s], mesh.points[static_cast<std::size_t>(t[0])],
          mesh.points[static_cast<std::size_t>(t[1])], mesh.points[static_cast<std::size_t>(t[2])]);
        if ((c - projected[s]).norm() > radius)
          continue;
        painted[f] = 1;
        for (auto v : t)
          for (std::size_t g : facesOf[static_cast<std::size_t>(v)])
            if (seen.insert(g).second)
              q.push(g);
      }
    }
    for (std::size_t f = 0; f < painted.size(); ++f)
      if (painted[f])
      {
        result.paintedFaces.push_back(static_cast<std::int64_t>(f));
        addFaceEdges(f);
      }
  }
  else
  {
    // Nearest vertices of the projected samples, joined by shortest edge paths.
    std::vector<Vec3> anchors = projected;
    std::vector<std::int64_t> path = edgePathThrough(mesh, anchors);
    // Drop detours that revisit a vertex (keep the closing vertex of a loop).
    std::vector<std::int64_t> simple;
    std::map<std::int64_t, std::size_t> at;
    for (std::size_t i = 0; i < path.size(); ++i)
    {
      const auto v = path[i];
      if (result.closed && simple.size() > 2 && v == simple.front())
      {
        simple.push_back(v); // the loop is closed
        break;
      }
      auto it = at.find(v);
      if (it != at.end())
      {
        const std::size_t k = it->second;
        if (result.closed && 2 * k < simple.size())
        {
          // A closed line coming back near its start: the loop closes at v;
          // the part before v's first visit is dropped.
          simple.erase(simple.begin(), simple.begin() + static_cast<std::ptrdiff_t>(k));
          simple.push_back(v);
          break;
        }
        else
          simple.resize(k + 1);
        at.clear();
        for (std::size_t j = 0; j < simple.size(); ++j)
          at[simple[j]] = j;
        continue;
      }
      at[v] = simple.size();
      simple.push_back(v);
    }
    if (result.closed && simple.size() > 2 && simple.back() != simple.front())
    {
      const auto back = shortestEdgePath(mesh, simple.back(), simple.front());
      for (std::size_t k = 1; k < back.size(); ++k)
        simple.push_back(back[k]);
    }
    result.line = simple;
    for (std::size_t i = 0; i + 1 < simple.size(); ++i)
      result.featureEdges.push_back(edgeKey(simple[i], simple[i + 1]));
    if (o.mode == StrokeMode::Snap)
    {
      std::set<std::int64_t> done;
      for (auto v : simple)
      {
        if (!done.insert(v).second)
          continue;
        result.mesh.points[static_cast<std::size_t>(v)] =
          closestOnPolyline(projected, mesh.points[static_cast<std::size_t>(v)]);
        result.movedVertices.push_back(v);
      }
    }
  }
  std::sort(result.featureEdges.begin(), result.featureEdges.end());
  result.featureEdges.erase(std::unique(result.featureEdges.begin(), result.featureEdges.end()), result.featureEdges.end());
  return result;
}

} // namespace lk
