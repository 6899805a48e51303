#include "latticekit/StrokeFeatureLine.h"

#include "latticekit/ClosestPointTree.h"
#include "latticekit/EdgePath.h"

#include "latticekit/StrokeSplitter.h"

#include <algorithm>
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
void sortUnique(std::vector<EdgeKey>& edges)
{
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
}

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

/// Whether every triangle of `around` keeps its orientation and its shape at
/// the current points: its normal within 60 degrees of the input's, and at
/// least 1 % of its input area (three line vertices of one triangle on a
/// straight stroke would flatten it).
constexpr double kSnapCosTurn = 0.5;
constexpr double kSnapAreaRatio = 0.01;
bool snapKeepsTriangles(const TriangleMesh& input, const std::vector<Vec3>& points,
  const std::vector<std::int64_t>& around)
{
  for (const auto f : around)
  {
    const Triangle& t = input.triangles[static_cast<std::size_t>(f)];
    auto normal = [&](const std::vector<Vec3>& p) {
      const Vec3& a = p[static_cast<std::size_t>(t[0])];
      return Vec3((p[static_cast<std::size_t>(t[1])] - a).cross(p[static_cast<std::size_t>(t[2])] - a));
    };
    const Vec3 n0 = normal(input.points), n1 = normal(points);
    const double l0 = n0.norm(), l1 = n1.norm();
    if (!(l1 >= kSnapAreaRatio * l0) || n0.dot(n1) < kSnapCosTurn * l0 * l1)
      return false;
  }
  return true;
}

/// Snap: each path vertex moves to the closest point of the projected
/// stroke, as far as it can without folding a triangle around it. A vertex
/// whose full move would turn one of its triangles by more than 60 degrees
/// or flatten it stops at the farthest fraction of the move (bisection)
/// that keeps them; those vertices are retried after the others have moved,
/// and what is left of each move is reported (StrokeResult::snapGaps).
void snapPath(const TriangleMesh& mesh, const std::vector<Vec3>& projected, const std::vector<std::int64_t>& path,
  StrokeResult& result)
{
  std::vector<std::vector<std::int64_t>> facesAt(mesh.points.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (const auto v : mesh.triangles[f])
      facesAt[static_cast<std::size_t>(v)].push_back(static_cast<std::int64_t>(f));
  std::set<std::int64_t> seen;
  for (const auto v : path)
    if (seen.insert(v).second)
      result.movedVertices.push_back(v);
  const std::size_t n = result.movedVertices.size();
  std::vector<Vec3> targets(n);
  std::vector<std::size_t> todo(n); // indices into movedVertices
  for (std::size_t i = 0; i < n; ++i)
  {
    targets[i] = closestOnPolyline(projected, mesh.points[static_cast<std::size_t>(result.movedVertices[i])]);
    todo[i] = i;
  }
  std::vector<Vec3>& points = result.mesh.points;
  for (int pass = 0; pass < 3 && !todo.empty(); ++pass)
  {
    std::vector<std::size_t> shortOnes;
    for (const auto i : todo)
    {
      const auto vi = static_cast<std::size_t>(result.movedVertices[i]);
      const Vec3 from = points[vi], to = targets[i];
      points[vi] = to;
      if (snapKeepsTriangles(mesh, points, facesAt[vi]))
        continue;
      double lo = 0.0, hi = 1.0; // lo keeps the triangles (the vertex's place before this move does)
      for (int k = 0; k < 20; ++k)
      {
        const double mid = 0.5 * (lo + hi);
        points[vi] = from + mid * (to - from);
        (snapKeepsTriangles(mesh, points, facesAt[vi]) ? lo : hi) = mid;
      }
      points[vi] = from + lo * (to - from);
      shortOnes.push_back(i);
    }
    todo = std::move(shortOnes);
  }
  result.snapGaps.assign(n, 0.0);
  for (const auto i : todo)
    result.snapGaps[i] = (targets[i] - points[static_cast<std::size_t>(result.movedVertices[i])]).norm();
}

/// Why a short stroke's loop was taken as closed, and what to draw instead.
std::string closingHint(double closeTolerance)
{
  return " (a stroke whose ends lie within " + std::to_string(closeTolerance) +
    " of each other counts as closed: draw a larger loop, or an open stroke longer than that)";
}

/// The refusal of a closed stroke whose loop covers fewer than three points.
std::invalid_argument loopTooSmall(std::size_t points, const char* what, double closeTolerance)
{
  return std::invalid_argument("a closed line needs at least three vertices: the stroke's loop covers " +
    std::to_string(points) + " " + what + closingHint(closeTolerance));
}
} // namespace

std::vector<std::int64_t> withoutSpurs(const std::vector<std::int64_t>& closedLine)
{
  if (closedLine.size() < 2)
    return closedLine;
  // The loop without its repeated first vertex; a spur's tip (v with the
  // same vertex before and after it) goes, with one of its two neighbours,
  // as a stack does it: the spur's edges cancel in pairs.
  std::vector<std::int64_t> loop;
  for (std::size_t i = 0; i + 1 < closedLine.size(); ++i)
  {
    const std::int64_t v = closedLine[i];
    if (!loop.empty() && loop.back() == v)
      continue;
    if (loop.size() >= 2 && loop[loop.size() - 2] == v)
      loop.pop_back();
    else
      loop.push_back(v);
  }
  // Where the loop closes: a spur whose tip is its last or first vertex.
  for (bool changed = true; changed && loop.size() >= 3;)
  {
    changed = false;
    if (loop.back() == loop.front())
    {
      loop.pop_back();
      changed = true;
    }
    else if (loop[loop.size() - 2] == loop.front())
    {
      loop.pop_back(); // the tip, last: its neighbours are the one before and the first
      loop.pop_back();
      changed = true;
    }
    else if (loop[1] == loop.back())
    {
      loop.erase(loop.begin()); // the tip, first: its neighbours are the last and the second
      loop.pop_back();
      changed = true;
    }
  }
  if (!loop.empty())
    loop.push_back(loop.front());
  return loop;
}

std::vector<std::int64_t> withoutSmallLoops(
  const std::vector<std::int64_t>& closedLine, const std::vector<Vec3>& points, double longest)
{
  if (closedLine.size() < 2)
    return closedLine;
  std::vector<std::int64_t> loop(closedLine.begin(), closedLine.end() - 1);
  const auto length = [&](std::size_t k) {
    return (points[static_cast<std::size_t>(loop[(k + 1) % loop.size()])] -
      points[static_cast<std::size_t>(loop[k])])
      .norm();
  };
  for (bool changed = true; changed;)
  {
    changed = false;
    double total = 0.0;
    for (std::size_t k = 0; k < loop.size(); ++k)
      total += length(k);
    std::map<std::int64_t, std::size_t> first;
    for (std::size_t i = 0; i < loop.size() && !changed; ++i)
    {
      const auto [it, added] = first.emplace(loop[i], i);
      if (added)
        continue;
      // loop[a] == loop[i]: the loop from a to i, and the rest.
      const std::size_t a = it->second;
      double inner = 0.0;
      for (std::size_t k = a; k < i; ++k)
        inner += length(k);
      if (std::min(inner, total - inner) > longest)
        continue; // two loops as drawn
      if (inner <= total - inner)
        loop.erase(loop.begin() + static_cast<std::ptrdiff_t>(a + 1), loop.begin() + static_cast<std::ptrdiff_t>(i + 1));
      else
        loop = std::vector<std::int64_t>(loop.begin() + static_cast<std::ptrdiff_t>(a), loop.begin() + static_cast<std::ptrdiff_t>(i));
      changed = true;
    }
  }
  if (!loop.empty())
    loop.push_back(loop.front());
  return loop;
}

namespace
{
constexpr double kCloseEdges = 2.0; ///< the default closeTolerance, in mean edge lengths
} // namespace

double meanEdgeLength(const TriangleMesh& mesh)
{
  if (mesh.triangles.empty())
    return 0.0;
  double total = 0.0;
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
      total += (mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>(i)])] -
                 mesh.points[static_cast<std::size_t>(t[static_cast<std::size_t>((i + 1) % 3)])])
                 .norm();
  return total / (3.0 * static_cast<double>(mesh.triangles.size()));
}

double defaultCloseTolerance(const TriangleMesh& mesh)
{
  return kCloseEdges * meanEdgeLength(mesh);
}

StrokeResult strokeToFeatureLine(const TriangleMesh& mesh, const std::vector<Vec3>& strokeIn, const StrokeOptions& o)
{
  const std::string problem = validateTriangleMesh(mesh);
  if (!problem.empty())
    throw std::invalid_argument(problem);
  if (strokeIn.size() < 2)
    throw std::invalid_argument("a stroke needs at least two points");
  for (std::size_t i = 0; i < strokeIn.size(); ++i)
    if (!isUsablePoint(strokeIn[i]))
      throw std::invalid_argument("stroke point " + std::to_string(i + 1) + " has " + unusablePointReason(strokeIn[i]));
  const double meanEdge = meanEdgeLength(mesh);
  const double spacing = o.spacing > 0 ? o.spacing : 0.25 * meanEdge;
  const double radius = o.brushRadius > 0 ? o.brushRadius : 0.5 * meanEdge;
  const double closeTol = o.closeTolerance > 0 ? o.closeTolerance : kCloseEdges * meanEdge;
  const double maxDist = o.maxDistance > 0 ? o.maxDistance : 5.0 * meanEdge;

  StrokeResult result;
  result.closed = (strokeIn.front() - strokeIn.back()).norm() <= closeTol;
  // Resample (closing the stroke when its ends meet) and project.
  std::vector<Vec3> stroke = strokeIn;
  if (result.closed)
    stroke.back() = stroke.front();
  if (o.mode == StrokeMode::Split)
  {
    // The stroke's points become line vertices, joined across the faces
    // (StrokeSplitter, the same walk the planner's pen uses point by point).
    StrokeSplitter splitter(mesh, maxDist);
    for (std::size_t i = 0; i + (result.closed ? 1 : 0) < stroke.size(); ++i)
      splitter.addPoint(stroke[i]);
    if (result.closed)
    {
      const std::set<std::int64_t> distinct(splitter.line().begin(), splitter.line().end());
      if (distinct.size() < 3)
        throw loopTooSmall(distinct.size(), "line vertex(es)", closeTol);
      splitter.close();
      // Where the line goes out along edges and straight back (b, c, b: a
      // spur), the spur encloses nothing and is left out of the loop. A
      // line drawn in parts makes one where a drag begins near an end of
      // the line it continues, but not on it, and the join runs back over
      // the line's first edges (a line all round the chin in three drags).
      // A drag that begins beside the line's start (within the closing
      // tolerance) can also make a small loop there, the line touching
      // itself at a vertex (a sliver 0.9 mm round, of ten vertices, in a
      // random trial): the cut refused it as lines that "meet or cross".
      // Loops up to twice the tolerance round are left out too; a larger one
      // is what was drawn, and the cut says where it touches.
      TriangleMesh drawnOn = splitter.mesh();
      std::vector<std::int64_t> line = withoutSmallLoops(withoutSpurs(splitter.line()), drawnOn.points, 2.0 * closeTol);
      // A short stroke can split in a line that goes out and comes back
      // along the same edges (a, b, c, b, a): three vertices, but a loop
      // around nothing, which no cut can take.
      std::set<EdgeKey> taken;
      for (std::size_t i = 0; i + 1 < line.size(); ++i)
        if (!taken.insert(edgeKey(line[i], line[i + 1])).second)
        {
          line.clear();
          break;
        }
      if (line.size() < 4)
      {
        const auto& drawn = splitter.line();
        std::set<EdgeKey> seen;
        for (std::size_t i = 0; i + 1 < drawn.size(); ++i)
          if (!seen.insert(edgeKey(drawn[i], drawn[i + 1])).second)
            throw std::invalid_argument("the closed line runs back along itself (edge " + std::to_string(drawn[i]) +
              "-" + std::to_string(drawn[i + 1]) + " twice), so its loop encloses nothing" + closingHint(closeTol));
        throw loopTooSmall(line.empty() ? 0 : line.size() - 1, "line vertex(es)", closeTol);
      }
      result.mesh = std::move(drawnOn);
      result.line = std::move(line);
    }
    else
    {
      result.mesh = splitter.mesh();
      result.line = splitter.line();
    }
    for (std::size_t i = 0; i + 1 < result.line.size(); ++i)
      result.featureEdges.push_back(edgeKey(result.line[i], result.line[i + 1]));
    sortUnique(result.featureEdges);
    return result;
  }
  // Paint, nearest edges and snap keep the mesh (snap moves line vertices).
  result.mesh = mesh;
  // The stroke sampled at most `spacing` apart, each sample projected as it
  // is made, on a tree over the faces near the stroke (those within
  // `maxDist` of it and a little more; a sample farther than that is refused
  // anyway, on the whole mesh's tree).
  Vec3 lo = stroke.front(), hi = stroke.front();
  for (const Vec3& p : stroke)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec3 margin = Vec3::Constant(1.01 * maxDist + meanEdge);
  const ClosestPointTree tree(mesh, lo - margin, hi + margin);
  std::vector<ClosestPointTree::Hit> hits;
  const auto project = [&](const Vec3& sample, std::size_t segment, bool betweenPoints) {
    hits.push_back(hits.empty() ? tree.closest(sample) : tree.closest(sample, hits.back()));
    if (hits.back().distance <= maxDist)
      return;
    const std::string how = std::to_string(hits.back().distance) + " from it (more than " + std::to_string(maxDist) + ")";
    if (!betweenPoints)
      throw std::invalid_argument("the stroke misses the surface: a stroke point lies " + how);
    // Its points lie on the surface, but the straight line between two of
    // them does not: a drag that jumped a gap (fast, over the bone's edge
    // or from one part of it to another).
    throw std::invalid_argument("the stroke misses the surface between its points " + std::to_string(segment + 1) +
      " and " + std::to_string(segment + 2) + " (" + std::to_string((stroke[segment + 1] - stroke[segment]).norm()) +
      " apart): the line between them runs " + how +
      ", as where a drag jumps across a gap or over the bone's edge; draw there more slowly, or in two strokes");
  };
  for (std::size_t i = 0; i + 1 < stroke.size(); ++i)
  {
    const double len = (stroke[i + 1] - stroke[i]).norm();
    const int n = std::max(1, static_cast<int>(std::ceil(len / spacing)));
    for (int k = 0; k < n; ++k)
      project(stroke[i] + (stroke[i + 1] - stroke[i]) * (double(k) / n), i, k > 0);
  }
  project(stroke.back(), stroke.size() - 1, false);
  std::vector<Vec3> projected;
  for (const auto& h : hits)
    projected.push_back(h.point);

  auto addFaceEdges = [&](std::size_t f) {
    const Triangle& t = mesh.triangles[f];
    for (int i = 0; i < 3; ++i)
      result.featureEdges.push_back(edgeKey(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)]));
  };

  if (o.mode == StrokeMode::Paint)
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
    std::vector<std::int64_t> path = edgePathThrough(mesh, tree, anchors);
    // A closed path's spurs and small loops first, wherever they are, as in
    // split mode: one at its start (the path out to a neighbour of the first
    // vertex and back, where the stroke's first points lie between two
    // vertices) was taken below for the loop coming back to its start, and
    // a stroke round the mandible 54 mm long became a loop of two vertices,
    // refused (a drag begun beside the line's start, in a random trial).
    if (result.closed && path.size() > 1 && path.front() == path.back())
      path = withoutSmallLoops(withoutSpurs(path), mesh.points, 2.0 * closeTol);
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
    // A line must have an edge, and a loop three vertices (as in split
    // mode). A short stroke, a click or a small circle, maps onto one or
    // two mesh points; so would a stroke that only goes back and forth.
    const std::size_t distinct = simple.size() - (result.closed && simple.size() > 1 && simple.back() == simple.front());
    if (result.closed && distinct < 3)
      throw loopTooSmall(distinct, "mesh point(s)", closeTol);
    if (distinct < 2)
      throw std::invalid_argument("the stroke covers no mesh edge: all its points are nearest mesh point " +
        std::to_string(simple.empty() ? -1 : simple.front()) + " (draw it across at least one edge)");
    result.line = simple;
    for (std::size_t i = 0; i + 1 < simple.size(); ++i)
      result.featureEdges.push_back(edgeKey(simple[i], simple[i + 1]));
    if (o.mode == StrokeMode::Snap)
      snapPath(mesh, projected, simple, result);
  }
  sortUnique(result.featureEdges);
  return result;
}

std::vector<std::vector<std::int64_t>> carryLines(
  const TriangleMesh& after, std::size_t verticesBefore, const std::vector<std::vector<std::int64_t>>& lines)
{
  const auto n = static_cast<std::int64_t>(after.points.size());
  // A line changes only where a split put new vertices on its edges.
  if (after.points.size() <= verticesBefore)
    return lines;
  // The neighbours of the vertices a chain can start from or pass (the
  // lines' and the new ones), in the order of the triangles: a skull has
  // 750,000 vertices, a line a few hundred.
  std::vector<char> wanted(after.points.size(), 0);
  for (std::size_t v = verticesBefore; v < after.points.size(); ++v)
    wanted[v] = 1;
  for (const auto& line : lines)
    for (const auto v : line)
      if (v >= 0 && v < n)
        wanted[static_cast<std::size_t>(v)] = 1;
  std::vector<std::vector<std::int64_t>> neighbours(after.points.size());
  for (const Triangle& t : after.triangles)
    for (int i = 0; i < 3; ++i)
    {
      const auto a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
      if (wanted[static_cast<std::size_t>(a)])
        neighbours[static_cast<std::size_t>(a)].push_back(b);
      if (wanted[static_cast<std::size_t>(b)])
        neighbours[static_cast<std::size_t>(b)].push_back(a);
    }
  auto joined = [&](std::int64_t a, std::int64_t b) {
    const auto& na = neighbours[static_cast<std::size_t>(a)];
    return std::find(na.begin(), na.end(), b) != na.end();
  };
  // The new vertices on segment (a, b), from a to b, each joined to the
  // last by an edge; empty when there is no such chain.
  auto chain = [&](std::int64_t a, std::int64_t b) {
    const Vec3 pa = after.points[static_cast<std::size_t>(a)];
    const Vec3 d = after.points[static_cast<std::size_t>(b)] - pa;
    const double len2 = d.squaredNorm();
    std::vector<std::int64_t> out;
    if (!(len2 > 0.0))
      return out;
    const double tolerance = 1e-9 * std::sqrt(len2);
    std::int64_t at = a;
    double tAt = 0.0;
    while (!joined(at, b))
    {
      std::int64_t next = -1;
      double tNext = 1.0;
      for (const auto c : neighbours[static_cast<std::size_t>(at)])
      {
        if (c < static_cast<std::int64_t>(verticesBefore))
          continue;
        const Vec3 q = after.points[static_cast<std::size_t>(c)] - pa;
        const double t = q.dot(d) / len2;
        if (t > tAt && t < tNext && (q - t * d).norm() <= tolerance)
        {
          next = c;
          tNext = t;
        }
      }
      if (next < 0)
        return std::vector<std::int64_t>();
      out.push_back(next);
      at = next;
      tAt = tNext;
    }
    return out;
  };
  std::vector<std::vector<std::int64_t>> carried;
  carried.reserve(lines.size());
  for (const auto& line : lines)
  {
    std::vector<std::int64_t> c;
    for (std::size_t i = 0; i < line.size(); ++i)
    {
      const auto b = line[i];
      if (i > 0)
      {
        const auto a = line[i - 1];
        if (a >= 0 && b >= 0 && a < n && b < n && a != b && !joined(a, b))
        {
          const auto between = chain(a, b);
          c.insert(c.end(), between.begin(), between.end());
        }
      }
      c.push_back(b);
    }
    carried.push_back(std::move(c));
  }
  return carried;
}

} // namespace lk
