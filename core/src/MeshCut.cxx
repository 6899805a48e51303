#include "latticekit/MeshCut.h"

#include "CutCaps.h"
#include "InnerWalls.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <future>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>

namespace lk
{
namespace
{
using cut::Cap;
using cut::LoopOutline;
using cut::LoopPlane;

std::size_t find(std::vector<std::size_t>& parent, std::size_t x)
{
  while (parent[x] != x)
    x = parent[x] = parent[parent[x]];
  return x;
}

/// Directed edges grouped by their source vertex (compressed rows): the
/// face of a -> b in O(valence), without a tree or hash of all edges.
struct DirectedEdges
{
  /// Slots and ids in 32 bits: half the memory to fill and walk (the skull's
  /// 1.7 million directed edges); meshes beyond that are refused.
  using Slot = std::uint32_t;
  static constexpr Slot npos = std::numeric_limits<Slot>::max();
  std::vector<std::size_t> start;    ///< per vertex, into the slots below
  std::vector<Slot> target;          ///< the vertex each edge points to
  std::vector<Slot> face;
  std::vector<Slot> previous;        ///< the slot of the edge before this one in its face
  std::vector<Slot> twin;            ///< the slot of b -> a, or npos at a border
  std::vector<char> cut;             ///< per directed edge: on a loop

  explicit DirectedEdges(const PolygonMesh& mesh)
    : start(mesh.points.size() + 1, 0)
  {
    // The ids are checked here too: the index check runs beside this.
    const auto n = static_cast<std::int64_t>(mesh.points.size());
    for (const auto& f : mesh.faces)
      for (auto v : f)
      {
        if (v < 0 || v >= n)
          throw std::invalid_argument("a face refers to a point outside the mesh");
        ++start[static_cast<std::size_t>(v) + 1];
      }
    for (std::size_t i = 1; i < start.size(); ++i)
      start[i] += start[i - 1];
    if (start.back() >= npos || mesh.points.size() >= npos || mesh.faces.size() >= npos)
      throw std::invalid_argument("the mesh is too large to cut (4 billion edges or more)");
    target.resize(start.back());
    face.resize(start.back());
    previous.resize(start.back());
    cut.assign(start.back(), 0);
    std::vector<std::size_t> next(start.begin(), start.end() - 1), slots;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    {
      const auto& fv = mesh.faces[f];
      slots.clear();
      for (std::size_t i = 0; i < fv.size(); ++i)
      {
        const std::size_t k = next[static_cast<std::size_t>(fv[i])]++;
        target[k] = static_cast<Slot>(fv[(i + 1) % fv.size()]);
        face[k] = static_cast<Slot>(f);
        slots.push_back(k);
      }
      for (std::size_t i = 0; i < fv.size(); ++i)
        previous[slots[i]] = static_cast<Slot>(slots[(i + fv.size() - 1) % fv.size()]);
    }
    twin.assign(start.back(), npos);
    for (std::size_t a = 0; a + 1 < start.size(); ++a)
      for (std::size_t k = start[a]; k < start[a + 1]; ++k)
        if (target[k] > a) // each pair once, from its smaller end
        {
          const Slot back = find(target[k], static_cast<std::int64_t>(a));
          twin[k] = back;
          if (back != npos)
            twin[back] = static_cast<Slot>(k);
        }
  }
  /// The slot of a -> b, or npos.
  Slot find(std::int64_t a, std::int64_t b) const
  {
    for (std::size_t k = start[static_cast<std::size_t>(a)]; k < start[static_cast<std::size_t>(a) + 1]; ++k)
      if (target[k] == b)
        return static_cast<Slot>(k);
    return npos;
  }
  /// Empty, or why the faces do not form a manifold, consistently oriented
  /// surface (what CGAL's polygon-soup test refuses, in linear time): a
  /// directed edge used twice (an edge with more than two faces, or faces
  /// oriented against each other), or a vertex whose faces form more than
  /// one fan (a pinched vertex).
  std::string problem() const
  {
    const std::string surface = "the mesh is not a manifold, consistently oriented surface: ";
    for (std::size_t a = 0; a + 1 < start.size(); ++a)
      for (std::size_t k = start[a]; k < start[a + 1]; ++k)
        for (std::size_t j = k + 1; j < start[a + 1]; ++j)
          if (target[j] == target[k])
            return surface + "the edge " + std::to_string(a) + "-" + std::to_string(target[k]) +
              " has more than two faces or faces oriented against each other";
    // Fans: around vertex a, the face of a -> b is followed by the face of
    // a -> c, where c -> a is the edge before a -> b in its face. The faces
    // around a must form one orbit of this map (a cycle inside, a chain at a
    // border): walked from the chain's start, or from any slot, it must
    // visit every slot of a.
    std::vector<char> reached;
    for (std::size_t a = 0; a + 1 < start.size(); ++a)
    {
      const std::size_t valence = start[a + 1] - start[a];
      if (valence == 0)
        continue;
      // The chain's start is the slot no other slot's map reaches (the
      // twin of the edge before a -> c is a -> c, in a's row).
      reached.assign(valence, 0);
      for (std::size_t j = start[a]; j < start[a + 1]; ++j)
      {
        const Slot r = twin[previous[j]];
        if (r != npos && r >= start[a] && r < start[a + 1])
          reached[r - start[a]] = 1;
      }
      const std::size_t first =
        start[a] + static_cast<std::size_t>(std::find(reached.begin(), reached.end(), 0) - reached.begin()) % valence;
      std::size_t visited = 0;
      for (std::size_t k = first; k != npos && visited <= valence; k = twin[previous[k]])
      {
        ++visited;
        if (twin[previous[k]] == first)
          break;
      }
      if (visited != valence)
        return surface + "its faces meet at vertex " + std::to_string(a) + " in more than one fan (a pinched vertex)";
    }
    return {};
  }
};

/// Which vertices of a piece are loop vertices: `vertexOrigin` (the input
/// vertex of each, -1 for cap points) into `onLoop` (per input vertex).
struct LoopVertices
{
  const std::vector<std::int64_t>& vertexOrigin;
  const std::vector<char>& onLoop;
  bool operator()(std::int64_t v) const
  {
    const auto o = vertexOrigin[static_cast<std::size_t>(v)];
    return o >= 0 && onLoop[static_cast<std::size_t>(o)];
  }
};

/// Closed pockets at a cap: a loop along mesh edges can detour around a
/// stretch of bone whose faces are all spanned by loop vertices; the cap
/// covers the same stretch with its own triangles, and the two enclose
/// nothing (a sliver between two triangulations of the same loop vertices;
/// two coinciding triangles are the smallest, taken out as the cap is
/// inserted). Such faces share edges that other faces of the piece use too,
/// so the piece is not a manifold there. Marks in `drop` each connected set
/// of bone and cap faces spanned by loop vertices only, holding both kinds,
/// whose every edge has exactly two faces of that kind: without them the
/// piece is closed and manifold there. `near`: the faces to look at (all
/// faces at a loop vertex).
void markCapPockets(const PolygonMesh& piece, const std::vector<std::int64_t>& faceOrigin, const LoopVertices& onLoop,
  const std::vector<std::size_t>& near, std::vector<char>& drop)
{
  std::vector<std::size_t> spanned; // faces spanned by loop vertices only
  for (const auto f : near)
  {
    const auto& face = piece.faces[f];
    if (!drop[f] && face.size() == 3 && onLoop(face[0]) && onLoop(face[1]) && onLoop(face[2]))
      spanned.push_back(f);
  }
  if (spanned.empty())
    return;
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::size_t>> facesOf; // edge -> index into spanned
  for (std::size_t i = 0; i < spanned.size(); ++i)
  {
    const auto& face = piece.faces[spanned[i]];
    for (std::size_t k = 0; k < 3; ++k)
      facesOf[{ std::min(face[k], face[(k + 1) % 3]), std::max(face[k], face[(k + 1) % 3]) }].push_back(i);
  }
  std::vector<std::size_t> parent(spanned.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [edge, fs] : facesOf)
    if (fs.size() == 2)
      parent[find(parent, fs[0])] = find(parent, fs[1]);
  std::map<std::size_t, std::array<bool, 3>> kinds; // root -> (bone, cap, open)
  for (const auto& [edge, fs] : facesOf)
    for (const auto i : fs)
      kinds[find(parent, i)][2] = kinds[find(parent, i)][2] || fs.size() != 2;
  for (std::size_t i = 0; i < spanned.size(); ++i)
    kinds[find(parent, i)][faceOrigin[spanned[i]] < 0 ? 1 : 0] = true;
  for (std::size_t i = 0; i < spanned.size(); ++i)
  {
    const auto& k = kinds[find(parent, i)];
    if (k[0] && k[1] && !k[2])
      drop[spanned[i]] = 1;
  }
}

/// An edge between two loop vertices with more than two faces of a capped
/// piece, of which some are cap faces (a cap edge across a stretch of bone
/// the loop detours around, which markCapPockets could not take out: the
/// stretch has vertices off the loop): the cap faces on it are split at its
/// midpoint, a new vertex of the piece, so the edge keeps the bone's two
/// faces and the cap runs beside it. New faces are added to `near`.
void splitOverfullCapEdges(PolygonMesh& piece, std::vector<std::int64_t>& faceOrigin,
  std::vector<std::int64_t>& vertexOrigin, const std::vector<char>& inputOnLoop, std::vector<std::size_t>& near)
{
  // Where face f runs along the edge {a, b} (either way): the k with
  // {face[k], face[k + 1]} = {a, b}; the face's size when it does not.
  auto edgeAt = [&](std::size_t f, std::int64_t a, std::int64_t b) {
    const auto& face = piece.faces[f];
    std::size_t k = 0;
    for (; k < face.size(); ++k)
    {
      const auto u = face[k], v = face[(k + 1) % face.size()];
      if ((u == a && v == b) || (u == b && v == a))
        break;
    }
    return k;
  };
  // A cap triangle can lie on two such edges: split for the first, it no
  // longer holds the second, whose faces are then found again in the next
  // round (the new vertex is on no loop, so each round has fewer edges).
  for (bool again = true; again;)
  {
    again = false;
    std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::size_t>> facesOf;
    {
      const LoopVertices onLoop{ vertexOrigin, inputOnLoop };
      for (const auto f : near)
      {
        const auto& face = piece.faces[f];
        for (std::size_t k = 0; k < face.size(); ++k)
        {
          const auto a = face[k], b = face[(k + 1) % face.size()];
          if (onLoop(a) && onLoop(b))
            facesOf[{ std::min(a, b), std::max(a, b) }].push_back(f);
        }
      }
    }
    for (const auto& [edge, fs] : facesOf)
    {
      if (fs.size() <= 2)
        continue;
      if (!std::all_of(fs.begin(), fs.end(),
            [&](std::size_t f) { return edgeAt(f, edge.first, edge.second) < piece.faces[f].size(); }))
      {
        again = true; // a face here was split this round
        continue;
      }
      std::vector<std::size_t> capFaces;
      for (const auto f : fs)
        if (faceOrigin[f] < 0 && piece.faces[f].size() == 3)
          capFaces.push_back(f);
      if (capFaces.empty() || capFaces.size() == fs.size())
        continue;
      const auto m = static_cast<std::int64_t>(piece.points.size());
      piece.points.push_back(0.5 * (piece.points[static_cast<std::size_t>(edge.first)] +
                                piece.points[static_cast<std::size_t>(edge.second)]));
      vertexOrigin.push_back(-1);
      for (const auto f : capFaces)
      {
        const auto t = piece.faces[f];
        const std::size_t k = edgeAt(f, edge.first, edge.second); // < 3: checked above
        const auto u = t[k], v = t[(k + 1) % 3], w = t[(k + 2) % 3];
        piece.faces[f] = { u, m, w };
        near.push_back(piece.faces.size());
        piece.faces.push_back({ m, v, w });
        faceOrigin.push_back(-1);
      }
    }
  }
}

/// Edges of a capped piece near its loops (`near`: the faces at loop
/// vertices and the caps' faces) used by more than two faces, or twice in
/// one direction: where the piece is not a manifold, consistently oriented
/// solid (0 when it is).
std::size_t nonManifoldCapEdges(const PolygonMesh& piece, const std::vector<std::size_t>& near)
{
  std::map<std::pair<std::int64_t, std::int64_t>, std::pair<int, int>> uses; // (low, high) -> (low->high, high->low)
  for (const auto f : near)
  {
    const auto& face = piece.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i)
    {
      const auto a = face[i], b = face[(i + 1) % face.size()];
      auto& u = uses[{ std::min(a, b), std::max(a, b) }];
      ++(a < b ? u.first : u.second);
    }
  }
  // An edge of a near face whose other faces are not near (away from the
  // loops) shows fewer uses here; only too many count.
  std::size_t bad = 0;
  for (const auto& [edge, u] : uses)
    bad += u.first > 1 || u.second > 1;
  return bad;
}

/// Why loops that do not separate a mesh could not, where it can be told:
/// the component of vertex `a0` has handles (on a bone, a canal or a marrow
/// cavity open to the outside), and a path around a handle joins the two
/// sides of a loop. The genus counts the component's border loops (a CT
/// surface is open where the scan's border cuts the bone): an open surface
/// without handles is cut in two by any closed loop. Empty otherwise.
std::string handlesNote(const PolygonMesh& mesh, const DirectedEdges& directed,
  const std::vector<std::size_t>& faceRegion, std::vector<std::size_t>& regionComponent, std::size_t a0)
{
  if (directed.start[a0] == directed.start[a0 + 1])
    return "";
  auto component = [&](std::size_t f) { return find(regionComponent, faceRegion[f]); };
  const std::size_t comp = component(directed.face[directed.start[a0]]);
  std::int64_t faces = 0, edges = 0, vertices = 0;
  std::vector<char> seen(mesh.points.size(), 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    if (component(f) != comp)
      continue;
    ++faces;
    for (const auto v : mesh.faces[f])
      if (!seen[static_cast<std::size_t>(v)])
      {
        seen[static_cast<std::size_t>(v)] = 1;
        ++vertices;
      }
  }
  // Edges, and the border loops: the border edges' vertices joined along them.
  std::vector<std::size_t> borderRoot(mesh.points.size());
  std::iota(borderRoot.begin(), borderRoot.end(), 0);
  std::vector<std::size_t> borderVertices;
  for (std::size_t a = 0; a + 1 < directed.start.size(); ++a)
    for (std::size_t k = directed.start[a]; k < directed.start[a + 1]; ++k)
    {
      if (component(directed.face[k]) != comp)
        continue;
      if (directed.twin[k] == DirectedEdges::npos)
      {
        ++edges;
        borderRoot[find(borderRoot, a)] = find(borderRoot, static_cast<std::size_t>(directed.target[k]));
        borderVertices.push_back(a);
      }
      else if (directed.target[k] > static_cast<std::int64_t>(a))
        ++edges;
    }
  std::vector<std::size_t> roots;
  for (const auto v : borderVertices)
    roots.push_back(find(borderRoot, v));
  std::sort(roots.begin(), roots.end());
  const auto borderLoops = static_cast<std::int64_t>(std::unique(roots.begin(), roots.end()) - roots.begin());
  const std::int64_t genus = (2 - borderLoops - (vertices - edges + faces)) / 2;
  if (genus <= 0)
    return "";
  return ": the surface has " + std::to_string(genus) + (genus == 1 ? " handle" : " handles") +
    " (on a bone: a canal, or a marrow cavity open to the outside), and a path around a handle joins the two "
    "sides. Draw the line where the bone is solid";
}

/// Loops that share a cap, the outermost first: a flat loop lies inside
/// another (its first point within the other's projection) when both are
/// flat, their planes are within 10 degrees, and it is within the other's
/// flatness tolerance of the other's plane. Every other loop is a group of one.
std::vector<std::vector<std::size_t>> nestedLoopGroups(
  const std::vector<std::vector<Vec3>>& loops, const std::vector<LoopPlane>& planes)
{
  const std::size_t n = loops.size();
  std::vector<std::size_t> root(n);
  std::iota(root.begin(), root.end(), 0);
  const double parallel = std::cos(10.0 * kPi / 180.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
    {
      const LoopPlane& pi = planes[i];
      const LoopPlane& pj = planes[j];
      if (i == j || !pi.flat || !pj.flat || pj.tolerance <= pi.tolerance ||
        std::abs(pi.normal.dot(pj.normal)) < parallel)
        continue;
      if (!std::all_of(loops[i].begin(), loops[i].end(),
            [&](const Vec3& p) { return std::abs(pj.normal.dot(p - pj.centre)) <= pj.tolerance; }))
        continue;
      if (LoopOutline(loops[j], pj).side(loops[i].front()) != LoopOutline::Side::Inside)
        continue;
      if (root[i] == i || pj.tolerance > planes[root[i]].tolerance)
        root[i] = j; // the largest loop around it
    }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < n && root[root[i]] != root[i]; ++k)
      root[i] = root[root[i]];
  std::vector<std::vector<std::size_t>> groups;
  std::vector<std::size_t> groupOf(n, n);
  for (std::size_t i = 0; i < n; ++i)
    if (root[i] == i)
    {
      groupOf[i] = groups.size();
      groups.push_back({ i });
    }
  for (std::size_t i = 0; i < n; ++i)
    if (root[i] != i)
      groups[groupOf[root[i]]].push_back(i);
  return groups;
}

/// The pieces on the two sides of a cap for the loops of `group` (ids loop
/// after loop, as makeNestedCap numbers them), sorted, or nothing when the
/// cap does not fit: the cap must run along or against every loop, and no
/// piece may lie on both sides. For a hollow bone each side is one piece,
/// holding its part of the outer and of the inner wall; where a canal open at
/// one end only, or a dip inside the line, crosses the plane, the part
/// beyond the plane is a piece of its own on the far side, to be joined with
/// the piece there. Turns the cap so that it runs along the first loop's
/// first edge.
using CapSides = std::pair<std::vector<std::size_t>, std::vector<std::size_t>>;
std::optional<CapSides> nestedCapSides(Cap& cap, const std::vector<std::size_t>& group,
  const std::vector<std::vector<std::int64_t>>& loops, const DirectedEdges& directed,
  const std::vector<std::size_t>& faceRegion)
{
  if (cap.triangles.empty())
    return std::nullopt;
  // Whether the cap runs k -> k + 1 (its loop vertices' ids), against it, or neither.
  auto runs = [&](std::int64_t k) {
    const std::int64_t a = -k - 1, b = -k - 2;
    for (const auto& t : cap.triangles)
      for (int i = 0; i < 3; ++i)
      {
        if (t[static_cast<std::size_t>(i)] == a && t[static_cast<std::size_t>((i + 1) % 3)] == b)
          return 1;
        if (t[static_cast<std::size_t>(i)] == b && t[static_cast<std::size_t>((i + 1) % 3)] == a)
          return -1;
      }
    return 0;
  };
  const int first = runs(0);
  if (first == 0)
    return std::nullopt;
  if (first < 0)
    for (auto& t : cap.triangles)
      std::swap(t[1], t[2]);
  std::int64_t offset = 0;
  std::set<std::size_t> along, against; // the pieces of each side
  for (auto l : group)
  {
    const auto& loop = loops[l];
    const int dir = runs(offset);
    if (dir == 0)
      return std::nullopt;
    const auto a = dir > 0 ? loop[0] : loop[1], b = dir > 0 ? loop[1] : loop[0];
    const std::size_t ab = directed.find(a, b), ba = directed.find(b, a);
    if (ab == DirectedEdges::npos || ba == DirectedEdges::npos)
      return std::nullopt;
    along.insert(faceRegion[directed.face[ab]]);
    against.insert(faceRegion[directed.face[ba]]);
    offset += static_cast<std::int64_t>(loop.size());
  }
  for (auto p : along)
    if (against.count(p))
      return std::nullopt;
  return CapSides{ { along.begin(), along.end() }, { against.begin(), against.end() } };
}

} // namespace

namespace
{
/// Loops that leave the mesh in one piece (the message says why, where it can).
struct LoopsDoNotSeparate : std::invalid_argument
{
  using std::invalid_argument::invalid_argument;
};

/// The loops without a repeated closing vertex (a loop may end where it
/// starts).
std::vector<std::vector<std::int64_t>> openLoops(std::vector<std::vector<std::int64_t>> loops)
{
  for (auto& loop : loops)
    if (loop.size() > 1 && loop.front() == loop.back())
      loop.pop_back();
  return loops;
}

/// Checks the loops (without closing vertices, openLoops): closed along mesh
/// edges, not crossing themselves. Marks the cut's directed edges.
void checkLoops(
  const PolygonMesh& mesh, const std::vector<std::vector<std::int64_t>>& loops, DirectedEdges& directed)
{
  for (std::size_t l = 0; l < loops.size(); ++l)
  {
    const std::vector<std::int64_t>& loop = loops[l];
    const std::string which = "loop " + std::to_string(l);
    if (loop.size() < 3)
      throw std::invalid_argument(which + " has fewer than 3 vertices: it is not a closed line");
    std::set<std::int64_t> seen;
    for (std::size_t i = 0; i < loop.size(); ++i)
    {
      const auto a = loop[i], b = loop[(i + 1) % loop.size()];
      if (a < 0 || a >= static_cast<std::int64_t>(mesh.points.size()) || b < 0 ||
        b >= static_cast<std::int64_t>(mesh.points.size()))
        throw std::invalid_argument(which + " has a vertex id outside the mesh");
      if (!seen.insert(a).second)
        throw std::invalid_argument(which + " crosses itself (vertex " + std::to_string(a) + " twice)");
      const std::size_t ab = directed.find(a, b), ba = directed.find(b, a);
      if (ab == DirectedEdges::npos && ba == DirectedEdges::npos)
        throw std::invalid_argument(which + " is not closed along mesh edges: " + std::to_string(a) + " and " +
          std::to_string(b) + " are not joined by an edge");
      if (ab != DirectedEdges::npos)
        directed.cut[ab] = 1;
      if (ba != DirectedEdges::npos)
        directed.cut[ba] = 1;
    }
  }
}

/// One cut along the loops (without closing vertices, openLoops).
CutResult cutOnce(const PolygonMesh& mesh, const std::vector<std::vector<std::int64_t>>& loops, bool cap)
{
  if (loops.empty())
    throw std::invalid_argument("no loop to cut along");
  // The two checks of the input run on a second thread, each beside the step
  // that comes before its answer is needed (on the skull: the index check,
  // 14 ms, beside the directed edges, 45 ms; the manifold check, 16 ms,
  // beside the loop check and the regions). Their messages come first, as if
  // they had run before.
  std::future<std::string> indexProblem = std::async(std::launch::async, [&]() { return polygonIndexProblem(mesh); });
  std::optional<DirectedEdges> built;
  try
  {
    built.emplace(mesh);
  }
  catch (const std::invalid_argument&)
  {
    const std::string problem = indexProblem.get();
    if (!problem.empty())
      throw std::invalid_argument(problem);
    throw;
  }
  std::string problem = indexProblem.get();
  if (!problem.empty())
    throw std::invalid_argument(problem);
  DirectedEdges& directed = *built;
  std::future<std::string> manifoldProblem = std::async(std::launch::async, [&]() { return directed.problem(); });
  try
  {
    checkLoops(mesh, loops, directed);
  }
  catch (const std::invalid_argument&)
  {
    problem = manifoldProblem.get();
    if (!problem.empty())
      throw std::invalid_argument(problem);
    throw;
  }
  std::vector<char> onLoop(mesh.points.size(), 0);
  for (const auto& loop : loops)
    for (auto v : loop)
      onLoop[static_cast<std::size_t>(v)] = 1;
  // Regions: faces joined across edges that are not cut. Components: regions
  // joined across the cut edges (loops only separate within a component).
  std::vector<std::size_t> parent(mesh.faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t a = 0; a + 1 < directed.start.size(); ++a)
    for (std::size_t k = directed.start[a]; k < directed.start[a + 1]; ++k)
    {
      if (directed.target[k] < static_cast<std::int64_t>(a) || directed.cut[k])
        continue; // each edge once, from its smaller end; cut edges below
      const std::size_t back = directed.twin[k];
      if (back == DirectedEdges::npos)
        continue;
      const std::size_t f = find(parent, directed.face[k]), g = find(parent, directed.face[back]);
      parent[std::max(f, g)] = std::min(f, g); // a region's root is its first face
    }
  problem = manifoldProblem.get();
  if (!problem.empty())
    throw std::invalid_argument(problem);
  std::vector<std::size_t> faceRegion(mesh.faces.size());
  std::size_t pieces = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    const std::size_t r = find(parent, f);
    faceRegion[f] = r == f ? pieces++ : faceRegion[r]; // r <= f: numbered before f
  }
  parent.clear();
  parent.shrink_to_fit();
  std::vector<std::size_t> regionComponent(pieces);
  std::iota(regionComponent.begin(), regionComponent.end(), 0);
  for (std::size_t k = 0; k < directed.cut.size(); ++k)
    if (directed.cut[k] && directed.twin[k] != DirectedEdges::npos)
      regionComponent[find(regionComponent, faceRegion[directed.face[k]])] =
        find(regionComponent, faceRegion[directed.face[directed.twin[k]]]);
  std::size_t components = 0;
  for (std::size_t r = 0; r < pieces; ++r)
    components += find(regionComponent, r) == r;
  if (pieces <= components)
  {
    const std::string why =
      handlesNote(mesh, directed, faceRegion, regionComponent, static_cast<std::size_t>(loops.front().front()));
    throw LoopsDoNotSeparate("the loops do not separate the mesh (it stays in one piece)" + why);
  }

  // The caps depend on the loops alone: they are made on a second thread
  // while the pieces are built (on the skull's craniotomy, about 20 of the
  // cut's 130 ms). A group of nested loops gets its shared cap; a loop alone
  // its own.
  std::vector<std::vector<Vec3>> loopPoints(loops.size());
  std::vector<LoopPlane> planes(loops.size());
  std::vector<std::vector<std::size_t>> groups;
  auto capOfLoop = [&](std::size_t l) {
    Cap c = cut::makeCap(loopPoints[l], planes[l]);
    if (c.triangles.empty())
      throw std::invalid_argument("a loop could not be capped (CGAL's hole filling failed)");
    return c;
  };
  std::future<std::vector<Cap>> capsMade;
  if (cap)
  {
    for (std::size_t l = 0; l < loops.size(); ++l)
    {
      for (auto v : loops[l])
        loopPoints[l].push_back(mesh.points[static_cast<std::size_t>(v)]);
      planes[l] = cut::fitLoopPlane(loopPoints[l]);
    }
    groups = nestedLoopGroups(loopPoints, planes);
    capsMade = std::async(std::launch::async, [&]() {
      std::vector<Cap> made;
      for (const auto& group : groups)
      {
        if (group.size() == 1)
        {
          made.push_back(capOfLoop(group.front()));
          continue;
        }
        std::vector<std::vector<Vec3>> points;
        for (auto l : group)
          points.push_back(loopPoints[l]);
        made.push_back(cut::makeNestedCap(points, planes[group.front()]));
      }
      return made;
    });
  }
  // Nested caps need their pieces: which ones each side holds, and those of
  // one side joined into one piece, before the pieces are built.
  std::vector<Cap> caps;
  std::vector<char> nestedFits(groups.size(), 0);
  if (std::any_of(groups.begin(), groups.end(), [](const auto& g) { return g.size() > 1; }))
  {
    caps = capsMade.get();
    std::vector<std::optional<CapSides>> sides(groups.size());
    for (std::size_t g = 0; g < groups.size(); ++g)
      if (groups[g].size() > 1)
        sides[g] = nestedCapSides(caps[g], groups[g], loops, directed, faceRegion);
    std::vector<std::size_t> joined(pieces);
    std::iota(joined.begin(), joined.end(), 0);
    for (const auto& side : sides)
      if (side)
        for (const auto* pieceSet : { &side->first, &side->second })
          for (auto p : *pieceSet)
          {
            const std::size_t a = find(joined, p), b = find(joined, pieceSet->front());
            joined[std::max(a, b)] = std::min(a, b); // the smallest piece's number leads
          }
    // Joined, a cap's two sides must still be different pieces (caps of
    // several groups could join them); otherwise only caps with one piece on
    // each side are kept, as they are.
    bool consistent = true;
    for (const auto& side : sides)
      if (side && find(joined, side->first.front()) == find(joined, side->second.front()))
        consistent = false;
    for (std::size_t g = 0; g < groups.size(); ++g)
      nestedFits[g] = sides[g] && (consistent || (sides[g]->first.size() == 1 && sides[g]->second.size() == 1));
    if (consistent)
    {
      std::vector<std::size_t> number(pieces, static_cast<std::size_t>(-1));
      std::size_t joinedPieces = 0;
      for (std::size_t p = 0; p < pieces; ++p)
        if (find(joined, p) == p)
          number[p] = joinedPieces++;
      for (auto& r : faceRegion)
        r = number[find(joined, r)];
      pieces = joinedPieces;
    }
  }

  CutResult result;
  // A loop whose two sides are in one piece separates nothing: a slit.
  for (std::size_t l = 0; l < loops.size(); ++l)
  {
    const auto& loop = loops[l];
    const std::size_t ab = directed.find(loop[0], loop[1]), ba = directed.find(loop[1], loop[0]);
    if (ab != DirectedEdges::npos && ba != DirectedEdges::npos &&
      faceRegion[directed.face[ab]] == faceRegion[directed.face[ba]])
      result.loopsInOnePiece.push_back(l);
  }
  result.pieces.resize(pieces);
  result.vertexOrigin.resize(pieces);
  result.faceOrigin.resize(pieces);
  // The piece's id of each input vertex: most vertices are in one piece
  // (firstPiece, firstId); loop vertices are in more, kept in `other`.
  std::vector<std::int64_t> firstPiece(mesh.points.size(), -1), firstId(mesh.points.size(), -1);
  std::map<std::pair<std::size_t, std::int64_t>, std::int64_t> other;
  auto localId = [&](std::size_t p, std::int64_t v) {
    const auto i = static_cast<std::size_t>(v);
    std::int64_t* id = nullptr;
    if (firstPiece[i] < 0)
    {
      firstPiece[i] = static_cast<std::int64_t>(p);
      id = &firstId[i];
    }
    else if (firstPiece[i] == static_cast<std::int64_t>(p))
      id = &firstId[i];
    else
    {
      const auto it = other.emplace(std::make_pair(p, v), -1).first;
      id = &it->second;
    }
    if (*id < 0)
    {
      *id = static_cast<std::int64_t>(result.pieces[p].points.size());
      result.pieces[p].points.push_back(mesh.points[i]);
      result.vertexOrigin[p].push_back(v);
    }
    return *id;
  };
  {
    std::vector<std::size_t> facesIn(pieces, 0);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
      ++facesIn[faceRegion[f]];
    for (std::size_t p = 0; p < pieces; ++p)
    {
      result.pieces[p].faces.reserve(facesIn[p]);
      result.faceOrigin[p].reserve(facesIn[p]);
    }
  }
  // Each input face's place in its piece, and how many bone faces each
  // piece has before its caps: the faces at the loops are found from the
  // loops' vertices, without a pass over the whole piece (the skull's).
  std::vector<std::uint32_t> faceLocal(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    const std::size_t p = faceRegion[f];
    faceLocal[f] = static_cast<std::uint32_t>(result.pieces[p].faces.size());
    const auto& input = mesh.faces[f];
    auto& face = result.pieces[p].faces.emplace_back(input.size());
    for (std::size_t i = 0; i < input.size(); ++i)
      face[i] = localId(p, input[i]);
    result.faceOrigin[p].push_back(static_cast<std::int64_t>(f));
  }
  if (!cap)
    return result;
  std::vector<std::size_t> boneFaces(pieces);
  for (std::size_t p = 0; p < pieces; ++p)
    boneFaces[p] = result.pieces[p].faces.size();
  std::vector<char> renumbered(pieces, 0); // by a compaction: faceLocal and boneFaces no longer hold
  // Drops the marked faces of piece p, then the points no face uses (the
  // ids of the input's vertices in the piece follow).
  auto compact = [&](std::size_t p, const std::vector<char>& dropFace) {
    if (std::find(dropFace.begin(), dropFace.end(), 1) == dropFace.end())
      return;
    renumbered[p] = 1;
    PolygonMesh& piece = result.pieces[p];
    std::vector<std::vector<std::int64_t>> faces;
    std::vector<std::int64_t> origin;
    for (std::size_t f = 0; f < piece.faces.size(); ++f)
    {
      if (f < dropFace.size() && dropFace[f])
        continue;
      faces.push_back(std::move(piece.faces[f]));
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
    for (std::size_t v = 0; v < firstPiece.size(); ++v)
      if (firstPiece[v] == static_cast<std::int64_t>(p) && firstId[v] >= 0)
        firstId[v] = newId[static_cast<std::size_t>(firstId[v])];
    for (auto& [key, id] : other)
      if (key.first == p && id >= 0)
        id = newId[static_cast<std::size_t>(id)];
    piece.faces = std::move(faces);
    piece.points = std::move(points);
    result.faceOrigin[p] = std::move(origin);
    result.vertexOrigin[p] = std::move(vorigin);
  };
  // One cap per loop, except for loops nested in one plane (the outer and
  // the inner wall of a hollow bone), which share one flat cap with holes.
  // `ids` are the cap's loop vertices (mesh ids, loop after loop); the cap's
  // triangles run along the first loop (ids[0] -> ids[1]); a piece whose
  // faces run ids[0] -> ids[1] takes the cap reversed, the other as it is.
  auto insertCap = [&](const std::vector<std::int64_t>& ids, const Cap& c) {
    for (int side = 0; side < 2; ++side)
    {
      const auto a = ids[0], b = ids[1];
      const std::size_t slot = side == 0 ? directed.find(a, b) : directed.find(b, a);
      if (slot == DirectedEdges::npos)
        continue;
      const std::size_t p = faceRegion[directed.face[slot]];
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
      std::map<std::array<std::int64_t, 3>, std::size_t> loopFaces;
      for (std::size_t f = 0; f < result.pieces[p].faces.size(); ++f)
      {
        const auto& face = result.pieces[p].faces[f];
        if (face.size() != 3 || result.faceOrigin[p][f] < 0)
          continue;
        const auto& input = mesh.faces[static_cast<std::size_t>(result.faceOrigin[p][f])];
        if (!onLoop[static_cast<std::size_t>(input[0])] || !onLoop[static_cast<std::size_t>(input[1])] ||
          !onLoop[static_cast<std::size_t>(input[2])])
          continue;
        std::array<std::int64_t, 3> key{ face[0], face[1], face[2] };
        std::sort(key.begin(), key.end());
        loopFaces[key] = f;
      }
      std::vector<char> dropFace(result.pieces[p].faces.size(), 0);
      for (const auto& t : c.triangles)
      {
        std::vector<std::int64_t> face;
        for (auto i : t)
          face.push_back(i < 0 ? localId(p, ids[static_cast<std::size_t>(-i - 1)]) : capIds[static_cast<std::size_t>(i)]);
        if (reverse)
          std::reverse(face.begin(), face.end());
        std::array<std::int64_t, 3> key{ face[0], face[1], face[2] };
        std::sort(key.begin(), key.end());
        const auto twin = loopFaces.find(key);
        if (twin != loopFaces.end() && twin->second < dropFace.size())
        {
          dropFace[twin->second] = 1;
          continue;
        }
        result.pieces[p].faces.push_back(face);
        result.faceOrigin[p].push_back(-1);
      }
      compact(p, dropFace);
    }
  };
  if (capsMade.valid())
    caps = capsMade.get();

  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    const auto& group = groups[g];
    if (group.size() > 1)
    {
      std::vector<std::int64_t> ids;
      for (auto l : group)
        ids.insert(ids.end(), loops[l].begin(), loops[l].end());
      if (nestedFits[g])
      {
        insertCap(ids, caps[g]);
        continue;
      }
      for (auto l : group)
        insertCap(loops[l], capOfLoop(l));
    }
    else
      insertCap(loops[group.front()], caps[g]);
  }
  // Each piece's faces at its loops: those around the loops' vertices, and
  // its caps' (after its bone faces); after a compaction, by a pass over it.
  auto nearFaces = [&](std::size_t p) {
    std::vector<std::size_t> near;
    const PolygonMesh& piece = result.pieces[p];
    if (renumbered[p])
    {
      const LoopVertices onLoopHere{ result.vertexOrigin[p], onLoop };
      for (std::size_t f = 0; f < piece.faces.size(); ++f)
        if (std::any_of(piece.faces[f].begin(), piece.faces[f].end(),
              [&](std::int64_t v) { return result.vertexOrigin[p][static_cast<std::size_t>(v)] < 0 || onLoopHere(v); }))
          near.push_back(f);
      return near;
    }
    for (const auto& loop : loops)
      for (const auto v : loop)
        for (std::size_t k = directed.start[static_cast<std::size_t>(v)]; k < directed.start[static_cast<std::size_t>(v) + 1]; ++k)
          if (faceRegion[directed.face[k]] == p)
            near.push_back(faceLocal[directed.face[k]]);
    for (std::size_t f = boneFaces[p]; f < piece.faces.size(); ++f)
      near.push_back(f);
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    return near;
  };
  result.capCrossings.resize(result.pieces.size());
  result.capCrossingDepths.resize(result.pieces.size());
  result.capNonManifoldEdges.resize(result.pieces.size());
  for (std::size_t p = 0; p < result.pieces.size(); ++p)
  {
    // Pockets between the bone and a cap, then cap edges that still lie on
    // a bone edge (a loop along mesh edges that detours around it).
    std::vector<std::size_t> near = nearFaces(p);
    std::vector<char> drop(result.pieces[p].faces.size(), 0);
    markCapPockets(result.pieces[p], result.faceOrigin[p], LoopVertices{ result.vertexOrigin[p], onLoop }, near, drop);
    if (std::find(drop.begin(), drop.end(), 1) != drop.end())
    {
      compact(p, drop);
      near = nearFaces(p);
    }
    splitOverfullCapEdges(result.pieces[p], result.faceOrigin[p], result.vertexOrigin[p], onLoop, near);
    result.capNonManifoldEdges[p] = nonManifoldCapEdges(result.pieces[p], near);
    std::tie(result.capCrossings[p], result.capCrossingDepths[p]) =
      cut::capCrossings(result.pieces[p], result.faceOrigin[p]);
  }
  // A piece whose faces all coincided with its cap's triangles (a loop
  // around one or two triangles) has none left: it is no piece.
  std::size_t kept = 0;
  for (std::size_t p = 0; p < result.pieces.size(); ++p)
  {
    if (result.pieces[p].faces.empty())
    {
      ++result.emptyPieces;
      continue;
    }
    if (kept != p)
    {
      result.pieces[kept] = std::move(result.pieces[p]);
      result.vertexOrigin[kept] = std::move(result.vertexOrigin[p]);
      result.faceOrigin[kept] = std::move(result.faceOrigin[p]);
      result.capCrossings[kept] = result.capCrossings[p];
      result.capCrossingDepths[kept] = result.capCrossingDepths[p];
      result.capNonManifoldEdges[kept] = result.capNonManifoldEdges[p];
    }
    ++kept;
  }
  result.capCrossings.resize(kept);
  result.capNonManifoldEdges.resize(kept);
  result.pieces.resize(kept);
  result.vertexOrigin.resize(kept);
  result.faceOrigin.resize(kept);
  result.capCrossingDepths.resize(kept);
  return result;
}

std::size_t totalCrossings(const CutResult& cut)
{
  return std::accumulate(cut.capCrossings.begin(), cut.capCrossings.end(), std::size_t(0));
}

/// The cut through the inner walls: the mesh split where each flat loop's
/// plane meets walls inside it and away from it, and cut along all loops.
/// Nothing when no loop's plane meets such a wall. The loops are checked
/// (cutOnce) and without closing vertices.
std::optional<CutResult> cutThroughInnerWalls(
  const PolygonMesh& mesh, const std::vector<std::vector<std::int64_t>>& loops, bool cap)
{
  std::vector<char> marked(mesh.points.size(), 0);
  for (const auto& loop : loops)
    for (auto v : loop)
      marked[static_cast<std::size_t>(v)] = 1;
  // The mesh as split so far: the input itself until a wall is found (no
  // copy of a large mesh whose loops meet none).
  PolygonMesh split;
  const PolygonMesh* current = &mesh;
  std::vector<std::int64_t> faceParent(mesh.faces.size());
  std::iota(faceParent.begin(), faceParent.end(), 0);
  std::vector<std::vector<std::int64_t>> all = loops;
  for (const auto& loop : loops)
  {
    cut::InnerWalls walls = cut::splitAlongInnerWalls(*current, loop, marked);
    if (walls.loops.empty())
      continue;
    for (auto& f : walls.faceParent)
      f = faceParent[static_cast<std::size_t>(f)];
    faceParent = std::move(walls.faceParent);
    split = std::move(walls.mesh);
    current = &split;
    marked.resize(current->points.size(), 0);
    for (auto& inner : walls.loops)
    {
      for (auto v : inner)
        marked[static_cast<std::size_t>(v)] = 1;
      all.push_back(std::move(inner));
    }
  }
  if (all.size() == loops.size())
    return std::nullopt;
  CutResult result = cutOnce(*current, all, cap);
  for (auto& origins : result.vertexOrigin)
    for (auto& v : origins)
      if (v >= static_cast<std::int64_t>(mesh.points.size()))
        v = -1;
  for (auto& origins : result.faceOrigin)
    for (auto& f : origins)
      if (f >= 0)
        f = faceParent[static_cast<std::size_t>(f)];
  result.innerWallLoops = all.size() - loops.size();
  return result;
}
} // namespace

CutResult cutAlongLoops(
  const PolygonMesh& mesh, const std::vector<std::vector<std::int64_t>>& loopsIn, bool cap, bool throughInnerWalls)
{
  const std::vector<std::vector<std::int64_t>> loops = openLoops(loopsIn);
  if (!throughInnerWalls)
    return cutOnce(mesh, loops, cap);
  // A hollow bone: where the loops do not separate the mesh (a marrow cavity
  // or canal joins their sides), or where a cap crosses the surface (a canal
  // open at one end only, or a dip inside the line, crossing the plane) or a
  // piece has no cap (a closed cavity), the inner walls are cut too. The
  // second is kept only if its caps cross less, or as much with fewer pieces.
  std::optional<CutResult> plain;
  std::string whyNot;
  try
  {
    plain = cutOnce(mesh, loops, cap);
  }
  catch (const LoopsDoNotSeparate& e)
  {
    whyNot = e.what();
  }
  // A piece without a cap face lies beside no loop: an inner surface of its
  // own (a closed cavity), which the caps may run through.
  auto uncapped = [](const CutResult& cut) {
    return std::any_of(cut.faceOrigin.begin(), cut.faceOrigin.end(),
      [](const auto& origin) { return std::none_of(origin.rbegin(), origin.rend(), [](auto f) { return f < 0; }); });
  };
  if (plain && (!cap || (totalCrossings(*plain) == 0 && !uncapped(*plain))))
    return std::move(*plain);
  if (!plain)
  {
    std::optional<CutResult> walls = cutThroughInnerWalls(mesh, loops, cap);
    if (!walls)
      throw std::invalid_argument(whyNot);
    return std::move(*walls);
  }
  try
  {
    std::optional<CutResult> walls = cutThroughInnerWalls(mesh, loops, cap);
    if (walls &&
      (totalCrossings(*walls) < totalCrossings(*plain) ||
        (totalCrossings(*walls) == totalCrossings(*plain) && walls->pieces.size() < plain->pieces.size())))
      return std::move(*walls);
  }
  catch (const std::invalid_argument&)
  {
    // The cut through the walls failed (a cap could not be made): the plain
    // cut stands, with its crossings reported.
  }
  return std::move(*plain);
}

} // namespace lk
