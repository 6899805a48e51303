#include "latticekit/StrokeSplitter.h"

#include "latticekit/ClosestPointTree.h"

#include "SurfaceMeshConversion.h"

#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace lk
{
namespace
{
using SMesh = cgal::SurfaceMesh;
using VI = SMesh::Vertex_index;
using HI = SMesh::Halfedge_index;
using FI = SMesh::Face_index;

/// One step of a planned walk: the plane crosses an edge (split it at x) or
/// passes through a vertex.
struct Event
{
  bool atVertex = false;
  HI edge;   ///< a halfedge of the crossed edge
  VI vertex; ///< the vertex passed
  Vec3 x;
};

struct Plan
{
  std::vector<Event> events;
  bool endInFace = false; ///< the end is a new vertex inside `endFace` at `end`
  FI endFace;
  Vec3 end;
};
} // namespace

struct StrokeSplitter::Impl
{
  /// How many ways round a segment whose walk fails may take in a row
  /// (walkInParts: halves, or a step along an edge).
  static constexpr int kWaysRound = 6;
  /// How many ways round one segment may try in all (each halving is
  /// journalled, to go back to when its halves fail), so that a segment
  /// that cannot be followed is refused in bounded time.
  static constexpr int kTries = 24;
  int triesLeft = 0;

  SMesh m;
  ClosestPointTree tree;
  std::vector<Vec3> faceNormals; ///< of the input faces (splitting keeps the surface)
  std::vector<std::int64_t> line;
  bool closed = false;
  double maxDistance = 0.0;
  double meanEdge = 0.0;

  explicit Impl(const TriangleMesh& mesh)
    : tree(mesh)
  {
  }

  Vec3 p(VI v) const
  {
    const auto& q = m.point(v);
    return Vec3(q.x(), q.y(), q.z());
  }

  Vec3 vertexNormal(VI v) const
  {
    Vec3 n = Vec3::Zero();
    for (HI h : CGAL::halfedges_around_target(m.halfedge(v), m))
    {
      if (m.is_border(h))
        continue;
      const Vec3 a = p(m.source(h)), b = p(v), c = p(m.target(m.next(h)));
      n += (b - a).cross(c - b);
    }
    return n.norm() > 0 ? Vec3(n.normalized()) : n;
  }

  /// Where a point of triangle f goes: onto a corner, onto an edge (a
  /// point closer than 1e-3 mean edge lengths to it: a vertex inside the
  /// face there would make needle triangles), or inside.
  struct Placement
  {
    VI vertex = SMesh::null_vertex();
    HI edge = SMesh::null_halfedge();
    Vec3 point;
  };
  Placement place(FI f, const Vec3& x) const
  {
    Placement at;
    const double snap = 1e-3 * meanEdge;
    double bestVertex = snap, bestEdge = snap;
    for (HI h : CGAL::halfedges_around_face(m.halfedge(f), m))
    {
      const Vec3 a = p(m.source(h)), b = p(m.target(h));
      if ((b - x).norm() <= bestVertex)
      {
        bestVertex = (b - x).norm();
        at.vertex = m.target(h);
      }
      const Vec3 e = b - a;
      const double t = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
      const Vec3 q = a + t * e;
      if ((q - x).norm() <= bestEdge && t > 0.0 && t < 1.0)
      {
        bestEdge = (q - x).norm();
        at.edge = h;
        at.point = q;
      }
    }
    if (at.vertex != SMesh::null_vertex())
      at.edge = SMesh::null_halfedge();
    return at;
  }

  /// The walk from vertex `a` to the point `x` (or to the vertex `target`
  /// when it is valid), in the plane through a and x that holds the mean
  /// normal `normal`. Does not change the mesh.
  Plan plan(VI a, Vec3 x, VI target, const Vec3& normal) const
  {
    // What a user can do when a segment cannot be followed across the faces
    // (it spans a fold or a sharp turn of the surface between two points).
    static const std::string retry = ": draw it again with its points closer together, or in nearest-edges mode";
    const Vec3 pa = p(a);
    if (target != SMesh::null_vertex())
      x = p(target);
    const Vec3 d = x - pa;
    const double dd = d.squaredNorm();
    Vec3 planeNormal = d.cross(normal);
    if (dd <= 0.0 || planeNormal.norm() <= 1e-12 * std::sqrt(dd))
      throw std::invalid_argument("the stroke segment runs along the surface normal (no plane to follow)");
    planeNormal.normalize();
    const double snapLength = 1e-6 * meanEdge; // closer than this to a vertex: through the vertex
    auto side = [&](const Vec3& y) { return planeNormal.dot(y - pa); };
    auto along = [&](const Vec3& y) { return (y - pa).dot(d) / dd; };
    const double endTolerance = 1e-3 * meanEdge / std::sqrt(dd); // in t
    Plan plan;
    // Where the plane's section passes the end's place along the segment,
    // the end must be there too: on a curved surface the section can pass
    // it at a distance (the far side of a ridge or a thin plate), and a
    // vertex put there would be joined to faces it is not on (a spike).
    static const std::string missed = "the stroke could not be followed (the walk passed the point without meeting it)";
    const double onFace = 1e-3 * meanEdge;
    // The end is on the crossing the walk meets at t = 1.
    auto endOnCrossing = [&](const Event& e) {
      if ((e.x - x).norm() > onFace)
        throw std::invalid_argument(missed + retry);
      plan.events.push_back(e);
    };
    auto endHere = [&](FI f) {
      // The end lies in f: on one of its vertices or edges, or inside.
      const HI h0 = m.halfedge(f);
      if ((closestPointOnTriangle(x, p(m.source(h0)), p(m.target(h0)), p(m.target(m.next(h0)))) - x).norm() > onFace)
        throw std::invalid_argument(missed + retry);
      const Placement at = place(f, x);
      if (at.vertex != SMesh::null_vertex())
        plan.events.push_back({ true, HI(), at.vertex, p(at.vertex) });
      else if (at.edge != SMesh::null_halfedge())
        plan.events.push_back({ false, at.edge, VI(), at.point });
      else
      {
        plan.endInFace = true;
        plan.endFace = f;
        plan.end = x;
      }
    };
    // Crossing of edge (u, w) by the plane: the parameter along u -> w.
    auto crossing = [&](VI u, VI w, double& lambda) {
      const double su = side(p(u)), sw = side(p(w));
      if ((su > 0) == (sw > 0) && su != 0 && sw != 0)
        return false;
      lambda = su / (su - sw);
      return true;
    };
    const std::size_t maxSteps = 4 * m.number_of_faces() + 16;
    bool atVertex = true;
    VI v = a;
    HI entering; // edge state: the halfedge of the crossed edge in the face being entered
    double tPrevious = 0.0;
    for (std::size_t step = 0; step < maxSteps; ++step)
    {
      if (atVertex)
      {
        if (v == target)
          return plan;
        const double tv = along(p(v));
        struct Candidate
        {
          double score = -2.0;
          Event event;
          double t = 0.0;
          FI face;
          bool isEnd = false;
        } best;
        for (HI h : CGAL::halfedges_around_target(m.halfedge(v), m))
        {
          if (m.is_border(h))
            continue;
          const FI f = m.face(h);
          const HI opposite = m.next(m.next(h)); // w1 -> w2, the edge facing v
          const VI w1 = m.source(opposite), w2 = m.target(opposite);
          if (target != SMesh::null_vertex() && (w1 == target || w2 == target))
          {
            plan.events.push_back({ true, HI(), target, x });
            return plan;
          }
          double lambda = 0.0;
          if (!crossing(w1, w2, lambda))
            continue;
          const double length = (p(w2) - p(w1)).norm();
          Event e;
          if (lambda * length <= snapLength)
            e = { true, HI(), w1, p(w1) };
          else if ((1.0 - lambda) * length <= snapLength)
            e = { true, HI(), w2, p(w2) };
          else
            e = { false, opposite, VI(), p(w1) + lambda * (p(w2) - p(w1)) };
          const double t = along(e.x);
          if (t <= tv)
            continue;
          const Vec3 dir = e.x - p(v);
          const double score = dir.norm() > 0 ? dir.normalized().dot(d) / std::sqrt(dd) : -1.0;
          if (score > best.score)
            best = { score, e, t, f, t >= 1.0 - endTolerance };
        }
        if (best.score <= -2.0)
          throw std::invalid_argument("the stroke could not be followed from a line vertex (no face ahead)" + retry);
        if (best.isEnd && target == SMesh::null_vertex())
        {
          if (std::abs(best.t - 1.0) <= endTolerance)
            endOnCrossing(best.event);
          else
            endHere(best.face);
          return plan;
        }
        plan.events.push_back(best.event);
        tPrevious = best.t;
        if (best.event.atVertex)
          v = best.event.vertex;
        else
        {
          atVertex = false;
          entering = m.opposite(best.event.edge);
        }
        continue;
      }
      // Edge state: entering the face of `entering` across its edge.
      if (m.is_border(entering))
        throw std::invalid_argument("the stroke leaves the surface at a border");
      const FI g = m.face(entering);
      const VI z = m.target(m.next(entering));
      if (target != SMesh::null_vertex() && z == target)
      {
        plan.events.push_back({ true, HI(), z, x });
        return plan;
      }
      Event e;
      if (std::abs(side(p(z))) <= snapLength)
        e = { true, HI(), z, p(z) };
      else
      {
        const HI e1 = m.next(entering), e2 = m.next(e1); // w -> z, z -> u
        double lambda = 0.0;
        HI exit = e1;
        if (!crossing(m.source(e1), m.target(e1), lambda))
        {
          exit = e2;
          if (!crossing(m.source(e2), m.target(e2), lambda))
            throw std::invalid_argument("internal: the stroke plane left a face without crossing an edge");
        }
        const Vec3 pu = p(m.source(exit)), pw = p(m.target(exit));
        const double length = (pw - pu).norm();
        if (lambda * length <= snapLength)
          e = { true, HI(), m.source(exit), pu };
        else if ((1.0 - lambda) * length <= snapLength)
          e = { true, HI(), m.target(exit), pw };
        else
          e = { false, exit, VI(), pu + lambda * (pw - pu) };
      }
      const double t = along(e.x);
      if (target == SMesh::null_vertex() && t >= 1.0 - endTolerance)
      {
        if (std::abs(t - 1.0) <= endTolerance)
          endOnCrossing(e);
        else
          endHere(g);
        return plan;
      }
      if (t < tPrevious - 1e-9)
        throw std::invalid_argument("the stroke could not be followed (the walk turned back)" + retry);
      tPrevious = t;
      plan.events.push_back(e);
      if (e.atVertex)
      {
        atVertex = true;
        v = e.vertex;
      }
      else
        entering = m.opposite(e.edge);
    }
    throw std::invalid_argument("the stroke could not be followed (the walk did not reach the point)" + retry);
  }

  /// Triangulates a convex planar face (a triangle cut by straight line
  /// edges, with the vertices inserted on its sides) so that its smallest
  /// angle is largest: dynamic programming over the polygon's diagonals
  /// (O(n^3); n is a handful). The vertices inserted on one side are
  /// collinear, and a triangle of three of them has zero area: the fan from
  /// the widest corner used before made one as soon as a side held two
  /// inserted vertices (a stroke that crosses one edge twice, as along a
  /// ring of edges on a torus). Triangles facing against the face are never
  /// taken while another choice exists.
  void triangulateConvex(FI f)
  {
    std::vector<HI> around; // halfedges whose targets are the polygon's corners, in order
    for (HI h : CGAL::halfedges_around_face(m.halfedge(f), m))
      around.push_back(h);
    const std::size_t n = around.size();
    if (n <= 3)
      return;
    std::vector<Vec3> q(n);
    for (std::size_t i = 0; i < n; ++i)
      q[i] = p(m.target(around[i]));
    Vec3 normal = Vec3::Zero(); // Newell's
    for (std::size_t i = 0; i < n; ++i)
      normal += q[i].cross(q[(i + 1) % n]);
    // The smallest angle of triangle (a, b, c); 0 for a flat one and -1 for
    // one facing against the polygon.
    auto quality = [&](std::size_t a, std::size_t b, std::size_t c) {
      const Vec3 ab = q[b] - q[a], bc = q[c] - q[b], ca = q[a] - q[c];
      const Vec3 cross = ab.cross(bc);
      if (!(cross.dot(normal) > 0.0))
        return cross.norm() > 0.0 ? -1.0 : 0.0;
      auto angle = [](const Vec3& u, const Vec3& v) { return std::atan2(u.cross(v).norm(), u.dot(v)); };
      return std::min({ angle(ab, -ca), angle(bc, -ab), angle(ca, -bc) });
    };
    // best[i][j]: the best smallest angle over the triangulations of corners
    // i..j (j > i + 1; 4 for a side, j = i + 1); apex[i][j]: the corner that
    // makes a triangle with side (i, j) there.
    std::vector<std::vector<double>> best(n, std::vector<double>(n, 4.0));
    std::vector<std::vector<std::size_t>> apex(n, std::vector<std::size_t>(n, 0));
    for (std::size_t length = 2; length < n; ++length)
      for (std::size_t i = 0; i + length < n; ++i)
      {
        const std::size_t j = i + length;
        best[i][j] = -2.0;
        for (std::size_t k = i + 1; k < j; ++k)
        {
          const double value = std::min({ best[i][k], best[k][j], quality(i, k, j) });
          if (value > best[i][j])
          {
            best[i][j] = value;
            apex[i][j] = k;
          }
        }
      }
    // The diagonals, outermost first, each splitting the sub-face that holds
    // both its ends (diagonals do not cross, so exactly one does).
    std::vector<std::pair<std::size_t, std::size_t>> diagonals, pending{ { 0, n - 1 } };
    while (!pending.empty())
    {
      const auto [i, j] = pending.back();
      pending.pop_back();
      if (j < i + 2)
        continue;
      const std::size_t k = apex[i][j];
      if (k > i + 1)
        diagonals.emplace_back(i, k);
      if (j > k + 1)
        diagonals.emplace_back(k, j);
      pending.emplace_back(i, k);
      pending.emplace_back(k, j);
    }
    std::vector<FI> parts{ f };
    for (const auto& [i, j] : diagonals)
    {
      const VI a = m.target(around[i]), b = m.target(around[j]);
      bool done = false;
      for (std::size_t part = 0; part < parts.size() && !done; ++part)
      {
        HI ha = SMesh::null_halfedge(), hb = SMesh::null_halfedge();
        for (HI h : CGAL::halfedges_around_face(m.halfedge(parts[part]), m))
        {
          if (m.target(h) == a)
            ha = h;
          if (m.target(h) == b)
            hb = h;
        }
        if (ha == SMesh::null_halfedge() || hb == SMesh::null_halfedge())
          continue;
        record(ha);
        const HI h = CGAL::Euler::split_face(ha, hb, m);
        parts.push_back(m.face(m.opposite(h)));
        done = true;
      }
      if (!done)
        throw std::logic_error("internal: a diagonal of a split face has no sub-face");
    }
  }

  void triangulateAround(VI v)
  {
    std::vector<FI> polygons;
    for (FI f : CGAL::faces_around_target(m.halfedge(v), m))
      if (f != SMesh::null_face() && CGAL::degree(f, m) > 3)
        polygons.push_back(f);
    for (FI f : polygons)
      triangulateConvex(f);
  }

  /// Splits the face shared by a and b (when they are not joined yet).
  void connect(VI a, VI b)
  {
    if (a == b || CGAL::halfedge(a, b, m).second)
      return;
    for (HI h : CGAL::halfedges_around_target(m.halfedge(a), m))
    {
      if (m.is_border(h))
        continue;
      for (HI g : CGAL::halfedges_around_face(h, m))
        if (m.target(g) == b && g != m.next(h) && h != m.next(g))
        {
          record(h);
          CGAL::Euler::split_face(h, g, m);
          return;
        }
    }
    throw std::invalid_argument("internal: consecutive line vertices share no face");
  }

  void appendToLine(VI v)
  {
    const auto id = static_cast<std::int64_t>(static_cast<std::size_t>(v));
    if (line.empty() || line.back() != id)
      line.push_back(id);
  }

  /// When the split edge (u, w) was an edge of the line, the new vertex goes
  /// between them.
  void insertIntoLine(VI u, VI w, VI c)
  {
    const auto iu = static_cast<std::int64_t>(static_cast<std::size_t>(u));
    const auto iw = static_cast<std::int64_t>(static_cast<std::size_t>(w));
    for (std::size_t i = 0; i + 1 < line.size(); ++i)
      if ((line[i] == iu && line[i + 1] == iw) || (line[i] == iw && line[i + 1] == iu))
      {
        line.insert(line.begin() + static_cast<std::ptrdiff_t>(i + 1), static_cast<std::int64_t>(static_cast<std::size_t>(c)));
        ++i;
      }
  }

  std::size_t apply(VI a, const Plan& plan)
  {
    const std::size_t before = line.size();
    std::vector<VI> touched{ a };
    VI previous = a;
    // The vertices along each edge the walk splits, in order from one end,
    // keyed by the edge's ends on the unchanged mesh. A walk can cross (or
    // end on) one edge twice when the stroke runs along it; the second
    // split must go to the piece of the edge that holds its point (the
    // event's halfedge spans only the first piece by then, and a vertex put
    // outside its segment folded the faces beside it).
    std::map<std::pair<VI, VI>, std::vector<VI>> pieces;
    std::vector<std::pair<VI, VI>> ends;
    for (const Event& e : plan.events)
      ends.emplace_back(e.atVertex ? VI() : m.source(e.edge), e.atVertex ? VI() : m.target(e.edge));
    for (std::size_t i = 0; i < plan.events.size(); ++i)
    {
      const Event& e = plan.events[i];
      VI next = e.vertex;
      if (!e.atVertex)
      {
        const auto key = std::minmax(ends[i].first, ends[i].second);
        std::vector<VI>& chain = pieces[key];
        if (chain.empty())
          chain = { key.first, key.second };
        const Vec3 p0 = p(chain.front()), d = p(chain.back()) - p0;
        auto along = [&](const Vec3& y) { return (y - p0).dot(d) / d.squaredNorm(); };
        const double t = along(e.x);
        std::size_t k = 0;
        while (k + 2 < chain.size() && along(p(chain[k + 1])) < t)
          ++k;
        const VI u = chain[k], w = chain[k + 1];
        const double snap = 1e-6 * meanEdge;
        if ((p(u) - e.x).norm() <= snap)
          next = u;
        else if ((p(w) - e.x).norm() <= snap)
          next = w;
        else
        {
          const auto [piece, found] = CGAL::halfedge(u, w, m);
          if (!found)
            throw std::logic_error("internal: a split edge lost a piece");
          record(piece);
          const HI h = CGAL::Euler::split_edge(piece, m);
          next = m.target(h);
          m.point(next) = cgal::Point(e.x.x(), e.x.y(), e.x.z());
          insertIntoLine(u, w, next);
          chain.insert(chain.begin() + static_cast<std::ptrdiff_t>(k + 1), next);
        }
      }
      connect(previous, next);
      appendToLine(next);
      touched.push_back(next);
      previous = next;
    }
    if (plan.endInFace)
    {
      record(m.halfedge(plan.endFace));
      const HI h = CGAL::Euler::add_center_vertex(m.halfedge(plan.endFace), m);
      const VI c = m.target(h);
      m.point(c) = cgal::Point(plan.end.x(), plan.end.y(), plan.end.z());
      appendToLine(c);
      touched.push_back(c);
    }
    // Faces left with more than three corners (an edge split on their side)
    // are convex and planar: triangulate them.
    for (VI v : touched)
      triangulateAround(v);
    return line.size() - before;
  }

  /// The walk from the line's last vertex `a` to `x` (or to `target`) in
  /// one plane, applied when it succeeds: the plane that holds the mean of
  /// the normals at the ends, then the one of either end's normal alone
  /// (the mean can make the plane graze a vertex's star). `normalAtX` is
  /// the surface normal at the end; `added` counts the line vertices added.
  bool walkInOnePlane(VI a, const Vec3& x, const Vec3& normalAtX, VI target, std::size_t& added)
  {
    const Vec3 normalAtA = vertexNormal(a);
    for (const Vec3& normal : { Vec3(normalAtA + normalAtX), normalAtA, normalAtX })
    {
      Plan planned;
      try
      {
        planned = plan(a, x, target, normal);
      }
      catch (const std::invalid_argument&)
      {
        continue;
      }
      added += apply(a, planned);
      return true;
    }
    return false;
  }

  /// What a way round changes, to go back to when it fails: the mesh's
  /// element counts (a split only adds elements) and, in a journal, the
  /// links of the elements it had before that each Euler operation may
  /// rewire (a copy of the mesh cost a skull of 1.5 million faces 0.3 s a
  /// try).
  struct Saved
  {
    std::size_t journal = 0;
    SMesh::size_type vertices = 0, edges = 0, faces = 0;
    std::vector<std::int64_t> line;
    std::size_t added = 0;
  };
  struct HalfedgeLinks
  {
    HI h, next, prev;
    VI target;
    FI face;
  };
  struct Journal
  {
    std::vector<HalfedgeLinks> halfedges;
    std::vector<std::pair<VI, HI>> vertices; ///< each vertex's halfedge
    std::vector<std::pair<FI, HI>> faces;    ///< each face's halfedge
    std::vector<std::array<std::size_t, 3>> marks; ///< sizes of the three at each save
  };
  Journal journal;
  bool journaling = false; ///< ways round in progress (nothing is recorded outside them)

  Saved save(std::size_t added)
  {
    journal.marks.push_back({ journal.halfedges.size(), journal.vertices.size(), journal.faces.size() });
    return { journal.marks.size() - 1, m.num_vertices(), m.num_edges(), m.num_faces(), line, added };
  }
  void restore(const Saved& saved, std::size_t& added)
  {
    const auto mark = journal.marks[saved.journal];
    // Latest first, so each element ends with the value it had first.
    for (std::size_t i = journal.halfedges.size(); i-- > mark[0];)
    {
      const HalfedgeLinks& l = journal.halfedges[i];
      m.set_next_only(l.h, l.next);
      m.set_prev_only(l.h, l.prev);
      m.set_target(l.h, l.target);
      m.set_face(l.h, l.face);
    }
    for (std::size_t i = journal.vertices.size(); i-- > mark[1];)
      m.set_halfedge(journal.vertices[i].first, journal.vertices[i].second);
    for (std::size_t i = journal.faces.size(); i-- > mark[2];)
      m.set_halfedge(journal.faces[i].first, journal.faces[i].second);
    journal.halfedges.resize(mark[0]);
    journal.vertices.resize(mark[1]);
    journal.faces.resize(mark[2]);
    journal.marks.resize(saved.journal);
    m.resize(saved.vertices, saved.edges, saved.faces);
    line = saved.line;
    added = saved.added;
  }

  /// Before an Euler operation on `h` (split_edge(h), split_face(h, g) with
  /// g in h's face, add_center_vertex(h)): the links it may change. CGAL's
  /// split_face and add_center_vertex rewire the halfedges of h's face and
  /// set the face's halfedge; split_edge rewires h, its opposite and their
  /// neighbours in their loops and sets the halfedge of h's source.
  void record(HI h)
  {
    if (!journaling)
      return;
    auto halfedge = [&](HI g) {
      journal.halfedges.push_back({ g, m.next(g), m.prev(g), m.target(g), m.face(g) });
      journal.vertices.emplace_back(m.target(g), m.halfedge(m.target(g)));
      if (!m.is_border(g))
        journal.faces.emplace_back(m.face(g), m.halfedge(m.face(g)));
    };
    for (HI g : { h, m.opposite(h) })
    {
      halfedge(m.prev(g));
      halfedge(g);
      halfedge(m.next(g));
      if (!m.is_border(g))
        for (HI k : CGAL::halfedges_around_face(g, m))
          halfedge(k);
    }
  }

  /// walkInOnePlane, and when no plane works, two ways round, nested at most
  /// `depth` deep (the halves journalled, and put back when they fail):
  /// - halves: the segment is cut at the surface point nearest its
  ///   midpoint and each half is walked in its own plane (a segment over a
  ///   fold, or one whose plane's section of the faces turns back near a
  ///   vertex);
  /// - an edge: the line goes on along the edge of `a` that points most
  ///   nearly at the end and walks on from there (a vertex at a convex
  ///   corner, where no plane through the segment crosses the faces around
  ///   it ahead: their corners all lie behind it).
  /// False when every way fails; the mesh and the line may then hold parts
  /// already walked, and walk() puts them back.
  bool walkInParts(VI a, const Vec3& x, const Vec3& normalAtX, VI target, int depth, std::size_t& added)
  {
    if (walkInOnePlane(a, x, normalAtX, target, added))
      return true;
    if (depth <= 0 || triesLeft <= 0)
      return false;
    --triesLeft;
    const Vec3 pa = p(a);
    const double snap = 1e-3 * meanEdge;
    auto reached = [&](VI b) { return b == target || (target == SMesh::null_vertex() && (p(b) - x).norm() <= snap); };
    // Halves. The midpoint must split the segment, on the side of the
    // surface its ends face (across a thin plate of bone the nearest
    // surface point can lie on the far side).
    const auto middle = tree.closest(0.5 * (pa + x));
    const Vec3& normalAtMiddle = faceNormals[static_cast<std::size_t>(middle.face)];
    if ((middle.point - pa).norm() > snap && (middle.point - x).norm() > snap &&
      normalAtMiddle.dot(vertexNormal(a) + normalAtX) > 0.0)
    {
      const Saved saved = save(added);
      if (walkInParts(a, middle.point, normalAtMiddle, SMesh::null_vertex(), depth - 1, added))
      {
        const VI b(static_cast<SMesh::size_type>(line.back()));
        if (reached(b) || walkInParts(b, x, normalAtX, target, depth - 1, added))
          return true;
      }
      restore(saved, added);
    }
    // An edge of a, toward the end (its other vertex nearer the end).
    VI next = SMesh::null_vertex();
    double bestScore = -2.0;
    const Vec3 d = (x - pa).normalized();
    for (HI h : CGAL::halfedges_around_target(m.halfedge(a), m))
    {
      const VI w = m.source(h);
      const Vec3 e = p(w) - pa;
      if (!((p(w) - x).norm() < (pa - x).norm()) || e.norm() <= 0.0)
        continue;
      // Not back onto the line (it would touch itself there), but for the
      // first vertex that closes it.
      const auto id = static_cast<std::int64_t>(static_cast<std::size_t>(w));
      if (w != target && std::find(line.begin(), line.end(), id) != line.end())
        continue;
      const double score = e.normalized().dot(d);
      if (score > bestScore)
      {
        bestScore = score;
        next = w;
      }
    }
    if (next == SMesh::null_vertex())
      return false;
    appendToLine(next);
    ++added;
    return reached(next) || walkInParts(next, x, normalAtX, target, depth - 1, added);
  }

  /// walkInParts as a transaction: on failure the mesh and the line are put
  /// back and the segment's own error (of the walk in one plane) is thrown.
  std::size_t walk(VI a, const Vec3& x, const Vec3& normalAtX, VI target)
  {
    try
    {
      const Plan planned = plan(a, x, target, vertexNormal(a) + normalAtX);
      return apply(a, planned);
    }
    catch (const std::invalid_argument&)
    {
      // The ways round are journalled while they are tried, and the journal
      // goes with them however they end.
      journaling = true;
      struct Done
      {
        Impl& s;
        ~Done()
        {
          s.journaling = false;
          s.journal = Journal();
        }
      } done{ *this };
      std::size_t added = 0;
      const Saved saved = save(added);
      triesLeft = kTries;
      try
      {
        if (walkInParts(a, x, normalAtX, target, kWaysRound, added))
          return added;
      }
      catch (...)
      {
        restore(saved, added);
        throw;
      }
      restore(saved, added);
      throw;
    }
  }
};

StrokeSplitter::StrokeSplitter(const TriangleMesh& mesh, double maxDistance)
{
  const std::string problem = validateTriangleMesh(mesh);
  if (!problem.empty())
    throw std::invalid_argument(problem);
  // The half-edge mesh and the closest-point tree, each a pass over the
  // whole surface (a second each on a skull of 1.5 million faces), side by
  // side.
  auto halfEdges = std::async(std::launch::async, [&mesh] {
    std::pair<bool, SMesh> built;
    built.first = cgal::toSurfaceMesh(mesh, built.second);
    return built;
  });
  impl_ = std::make_unique<Impl>(mesh);
  std::pair<bool, SMesh> built = halfEdges.get();
  if (!built.first)
    throw std::invalid_argument("split mode needs a manifold, consistently oriented triangle mesh");
  impl_->m = std::move(built.second);
  double total = 0.0;
  impl_->faceNormals.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
  {
    const Vec3 &a = mesh.points[static_cast<std::size_t>(t[0])], &b = mesh.points[static_cast<std::size_t>(t[1])],
               &c = mesh.points[static_cast<std::size_t>(t[2])];
    total += (b - a).norm() + (c - b).norm() + (a - c).norm();
    const Vec3 n = (b - a).cross(c - a);
    impl_->faceNormals.push_back(n.norm() > 0 ? Vec3(n.normalized()) : n);
  }
  impl_->meanEdge = total / (3.0 * static_cast<double>(mesh.triangles.size()));
  impl_->maxDistance = maxDistance > 0 ? maxDistance : 5.0 * impl_->meanEdge;
}

StrokeSplitter::~StrokeSplitter() = default;

std::size_t StrokeSplitter::addPoint(const Vec3& point)
{
  Impl& s = *impl_;
  if (!isUsablePoint(point))
    throw std::invalid_argument(std::string("a stroke point has ") + unusablePointReason(point));
  if (s.closed)
    throw std::invalid_argument("the line is closed; start a new splitter for another stroke");
  const auto hit = s.tree.closest(point);
  if (hit.distance > s.maxDistance)
    throw std::invalid_argument("the stroke misses the surface: a stroke point lies " + std::to_string(hit.distance) +
      " from it (more than " + std::to_string(s.maxDistance) + ")");
  if (s.line.empty())
  {
    // The input's faces keep their ids until the first split.
    const FI f(static_cast<SMesh::size_type>(hit.face));
    const Impl::Placement at = s.place(f, hit.point);
    VI v = at.vertex;
    if (v == SMesh::null_vertex() && at.edge != SMesh::null_halfedge())
    {
      const HI h = CGAL::Euler::split_edge(at.edge, s.m);
      v = s.m.target(h);
      s.m.point(v) = cgal::Point(at.point.x(), at.point.y(), at.point.z());
      s.triangulateAround(v);
    }
    else if (v == SMesh::null_vertex())
    {
      const HI h = CGAL::Euler::add_center_vertex(s.m.halfedge(f), s.m);
      v = s.m.target(h);
      s.m.point(v) = cgal::Point(hit.point.x(), hit.point.y(), hit.point.z());
    }
    s.appendToLine(v);
    return 1;
  }
  const VI a(static_cast<SMesh::size_type>(s.line.back()));
  if ((s.p(a) - hit.point).norm() <= 1e-3 * s.meanEdge)
    return 0;
  return s.walk(a, hit.point, s.faceNormals[static_cast<std::size_t>(hit.face)], SMesh::null_vertex());
}

void StrokeSplitter::close()
{
  Impl& s = *impl_;
  if (s.closed)
    return;
  if (s.line.size() < 3)
    throw std::invalid_argument("a closed line needs at least three vertices");
  if (s.line.back() == s.line.front())
  {
    // The stroke came back onto its first vertex: closed already (there is
    // no walk from a vertex to itself).
    if (std::set<std::int64_t>(s.line.begin(), s.line.end()).size() < 3)
      throw std::invalid_argument("a closed line needs at least three vertices");
    s.closed = true;
    return;
  }
  const VI a(static_cast<SMesh::size_type>(s.line.back()));
  const VI first(static_cast<SMesh::size_type>(s.line.front()));
  s.walk(a, s.p(first), s.vertexNormal(first), first);
  if (s.line.back() != s.line.front())
    s.line.push_back(s.line.front());
  s.closed = true;
}

const std::vector<std::int64_t>& StrokeSplitter::line() const
{
  return impl_->line;
}

bool StrokeSplitter::closed() const
{
  return impl_->closed;
}

TriangleMesh StrokeSplitter::mesh() const
{
  const SMesh& m = impl_->m;
  TriangleMesh out;
  out.points.reserve(m.number_of_vertices());
  for (VI v : m.vertices())
    out.points.push_back(impl_->p(v));
  out.triangles.reserve(m.number_of_faces());
  for (FI f : m.faces())
  {
    Triangle t{};
    int k = 0;
    for (VI v : CGAL::vertices_around_face(m.halfedge(f), m))
      if (k < 3)
        t[static_cast<std::size_t>(k++)] = static_cast<std::int64_t>(static_cast<std::size_t>(v));
      else
        ++k;
    if (k == 3) // every face is a triangle after each step
      out.triangles.push_back(t);
  }
  return out;
}

std::size_t StrokeSplitter::numberOfTriangles() const
{
  return impl_->m.number_of_faces();
}

double StrokeSplitter::meanEdgeLength() const
{
  return impl_->meanEdge;
}

} // namespace lk
