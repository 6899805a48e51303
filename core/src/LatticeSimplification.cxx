#include "latticekit/LatticeSimplification.h"

#include "latticekit/FeatureChains.h"
#include "latticekit/ManifoldRepair.h"
#include "SurfaceMeshConversion.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <Eigen/Eigenvalues>
#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <queue>
#include <tuple>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lk
{
namespace
{
using Point = cgal::Point;
using Mesh = cgal::SurfaceMesh;
using VD = Mesh::Vertex_index;
using HD = Mesh::Halfedge_index;
using ED = Mesh::Edge_index;

Vec3 toVec(const Point& p)
{
  return { p.x(), p.y(), p.z() };
}

/// (n.x + d)^2 summed with weights: x^T A x + 2 b.x + c.
struct Quadric
{
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Vec3 b = Vec3::Zero();
  double c = 0.0;

  static Quadric plane(const Vec3& n, double d, double w)
  {
    Quadric q;
    q.A = w * n * n.transpose();
    q.b = w * d * n;
    q.c = w * d * d;
    return q;
  }
  Quadric& operator+=(const Quadric& o)
  {
    A += o.A;
    b += o.b;
    c += o.c;
    return *this;
  }
  Quadric& operator*=(double s)
  {
    A *= s;
    b *= s;
    c *= s;
    return *this;
  }
  double operator()(const Vec3& x) const { return x.dot(A * x) + 2.0 * b.dot(x) + c; }
  /// This quadric evaluated at alpha V + k, as a quadric in V.
  Quadric composed(double alpha, const Vec3& k) const
  {
    Quadric q;
    q.A = alpha * alpha * A;
    q.b = alpha * (A * k + b);
    q.c = k.dot(A * k) + 2.0 * b.dot(k) + c;
    return q;
  }
};

/// The lattice around the vertex V that a collapse of (v0, v1) would create.
struct Star
{
  struct Face
  {
    VD a, b;      ///< the face is (V, a, b), counter-clockwise
    VD from;      ///< v0 or v1: the vertex V replaces in it
  };
  struct Link
  {
    VD x;
    Quadric q; ///< sum of the quadrics of (v0, x) and (v1, x)
  };
  boost::container::small_vector<Face, 16> faces;
  boost::container::small_vector<Link, 12> links;
  Quadric vertex;
  bool border = false;
  VD p, q; ///< boundary neighbours of V when on the border
};

struct State
{
  Mesh& mesh;
  const SimplificationOptions& options;
  Mesh::Property_map<VD, Quadric> vq;
  Mesh::Property_map<ED, Quadric> eq;
  Mesh::Property_map<ED, bool> feature;
  Mesh::Property_map<VD, bool> featureVertex;
  /// Locked line vertices that featureTolerance lets go: each may collapse
  /// along its line into a neighbour that is kept (FeatureChains.h).
  Mesh::Property_map<VD, bool> droppable;
  /// The input vertex whose point each vertex holds (a collapse onto a kept
  /// point may keep the other vertex's index).
  Mesh::Property_map<VD, std::int64_t> origin;
  std::vector<std::int64_t> parent;
  std::size_t vertices = 0;
  std::size_t collapses = 0;
  std::size_t toRemove = 0;
  std::size_t reportEvery = 1;
  bool aborted = false;



  Vec3 pos(VD v) const { return toVec(mesh.point(v)); }

  /// A locked feature edge that may collapse all the same: a droppable
  /// vertex into its neighbour along the line, which is kept.
  bool alongLine(ED e) const
  {
    const HD h = mesh.halfedge(e);
    return feature[e] && droppable[mesh.source(h)] != droppable[mesh.target(h)];
  }
  /// Whether e may collapse at all: not a locked feature edge, or one along
  /// its line.
  bool collapsible(ED e) const { return !options.lockFeatures || !feature[e] || alongLine(e); }

  Star star(VD v0, VD v1) const
  {
    Star s;
    for (VD v : { v0, v1 })
    {
      const VD other = v == v0 ? v1 : v0;
      for (HD h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh))
      {
        const VD x = mesh.source(h);
        if (!mesh.is_border(h))
        {
          const VD w = mesh.target(mesh.next(h));
          if (x != other && w != other)
            s.faces.push_back({ w, x, v });
        }
        if (x == other)
          continue;
        auto it = std::find_if(s.links.begin(), s.links.end(), [x](const Star::Link& l) { return l.x == x; });
        if (it == s.links.end())
          s.links.push_back({ x, eq[mesh.edge(h)] });
        else
          it->q += eq[mesh.edge(h)];
      }
    }
    s.vertex = vq[v0];
    s.vertex += vq[v1];
    s.vertex += eq[mesh.edge(CGAL::halfedge(v0, v1, mesh).first)];
    if (mesh.is_border(v0) || mesh.is_border(v1))
    {
      // Ends of the face fan: an 'a' that is no face's 'b', and the reverse.
      // One of each on a plain border. Where v0 and v1 share a neighbour
      // through no common face (two sheets of the surface touch; the link
      // condition refuses that collapse) the union of their fans has other
      // ends, or two of one kind: the star is then costed as interior (a finite
      // cost; the edge is not collapsed while the link condition fails).
      int starts = 0, ends = 0;
      for (const Star::Face& f : s.faces)
      {
        if (std::none_of(s.faces.begin(), s.faces.end(), [&](const Star::Face& g) { return g.b == f.a; }))
        {
          s.q = f.a;
          ++starts;
        }
        if (std::none_of(s.faces.begin(), s.faces.end(), [&](const Star::Face& g) { return g.a == f.b; }))
        {
          s.p = f.b;
          ++ends;
        }
      }
      s.border = starts == 1 && ends == 1;
    }
    return s;
  }

  /// F of eq. 2.7 as one quadric in V.
  Quadric total(const Star& s, const Vec3& mid) const
  {
    if (!options.roundedSurfaceQuadrics)
    {
      Quadric t = s.vertex;
      for (const Star::Link& l : s.links)
        t += l.q;
      return t;
    }
    Vec3 k = Vec3::Zero();
    if (s.border)
      k = (pos(s.p) + pos(s.q)) / 6.0;
    else
    {
      double areaSum = 0.0;
      for (const Star::Face& f : s.faces)
      {
        const Vec3 a = pos(f.a), b = pos(f.b);
        const double area = (a - mid).cross(b - mid).norm();
        k += area * (a + b) / 6.0;
        areaSum += area;
      }
      k = areaSum > 0.0 ? Vec3(k / areaSum) : Vec3(mid / 3.0);
    }
    Quadric t = s.vertex.composed(2.0 / 3.0, k);
    for (const Star::Link& l : s.links)
    {
      const Vec3 x = pos(l.x);
      Vec3 others = Vec3::Zero();
      int n = 0;
      for (const Star::Face& f : s.faces)
      {
        if (f.a == l.x)
        {
          others += pos(f.b);
          ++n;
        }
        else if (f.b == l.x)
        {
          others += pos(f.a);
          ++n;
        }
      }
      if (n == 0)
        continue;
      t += l.q.composed(5.0 / 12.0, 5.0 / 12.0 * x + others / (6.0 * n));
    }
    return t;
  }
};

/// Minimum of the quadric, solved about `mid` with small eigenvalues dropped.
Vec3 minimum(const Quadric& q, const Vec3& mid)
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
  es.computeDirect(q.A);
  const Eigen::Vector3d lambda = es.eigenvalues();
  const double lmax = lambda.maxCoeff();
  Vec3 x = mid;
  if (!(lmax > 0.0))
    return x;
  const Vec3 g = q.A * mid + q.b;
  for (int i = 0; i < 3; ++i)
  {
    if (lambda[i] > 1e-3 * lmax)
    {
      const Vec3 u = es.eigenvectors().col(i);
      x -= u * (u.dot(g) / lambda[i]);
    }
  }
  return x;
}

/// Optimal position and cost of collapsing (v0, v1); false when no
/// position exists.
bool placeAndCost(const State& s, VD v0, VD v1, Vec3& x, double& cost)
{
  const Vec3 p0 = s.pos(v0), p1 = s.pos(v1);
  const Vec3 mid = 0.5 * (p0 + p1);
  const Quadric total = s.total(s.star(v0, v1), mid);
  // Locked: a feature vertex stays where it is; along a line the droppable
  // vertex goes into its kept neighbour.
  const bool stays0 = s.featureVertex[v0] && !s.droppable[v0], stays1 = s.featureVertex[v1] && !s.droppable[v1];
  if (s.options.lockFeatures && (stays0 || (s.featureVertex[v0] && !s.featureVertex[v1])))
    x = p0;
  else if (s.options.lockFeatures && (stays1 || s.featureVertex[v1]))
    x = p1;
  else
    x = minimum(total, mid);
  if (!x.allFinite())
    return false;
  cost = std::max(0.0, total(x));
  return std::isfinite(cost);
}

double minAngle(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return std::min({ angleAt(a, b, c), angleAt(b, c, a), angleAt(c, a, b) });
}

/// Refuses collapses that turn a triangle too far (or flip it) or create a
/// sliver. `slivers`: a sliver is allowed (a line vertex let go along its
/// line: the split lines that have them come with slivers beside them, and
/// refusing would keep vertices the tolerance lets go).
bool geometricallyValid(const State& s, VD v0, VD v1, const Vec3& x, bool slivers = false)
{
  const double cosMax = std::cos(s.options.maxNormalChangeDegrees * kPi / 180.0);
  const double angleMin = s.options.minAngleDegrees * kPi / 180.0;
  double oldMin = kPi, newMin = kPi;
  for (VD v : { v0, v1 })
  {
    const VD other = v == v0 ? v1 : v0;
    for (HD h : CGAL::halfedges_around_target(s.mesh.halfedge(v), s.mesh))
    {
      if (s.mesh.is_border(h))
        continue;
      const VD b = s.mesh.source(h), a = s.mesh.target(s.mesh.next(h));
      const Vec3 pv = s.pos(v), pa = s.pos(a), pb = s.pos(b);
      oldMin = std::min(oldMin, minAngle(pv, pa, pb));
      if (a == other || b == other)
        continue;
      const Vec3 nOld = (pa - pv).cross(pb - pv);
      const Vec3 nNew = (pa - x).cross(pb - x);
      const double len = nOld.norm() * nNew.norm();
      if (!(len > 0.0) || nOld.dot(nNew) < cosMax * len)
        return false;
      newMin = std::min(newMin, minAngle(x, pa, pb));
    }
  }
  return slivers || !(newMin < angleMin && newMin < oldMin);
}

/// Topology: CGAL's link condition, no edge joining two border vertices
/// through the interior, no collapse that would leave fewer than four
/// vertices on a closed piece.
bool topologicallyValid(const Mesh& m, ED e)
{
  const HD h = m.halfedge(e);
  const VD v0 = m.source(h), v1 = m.target(h);
  if (m.is_border(v0) && m.is_border(v1) && !m.is_border(e))
    return false;
  return CGAL::Euler::does_satisfy_link_condition(e, m);
}

struct HeapEntry
{
  double cost;
  std::uint32_t edge;
  std::uint32_t stamp;
  bool operator>(const HeapEntry& o) const { return std::tie(cost, edge) > std::tie(o.cost, o.edge); }
};

/// Collapses e into x: the quadrics of its ends and of the edge merge into
/// the kept vertex, those of the two edges of each side triangle into the one
/// left, and so do the feature flags. `constrained`: CGAL's constrained
/// collapse, which keeps a feature edge where two edges merge (e itself must
/// not be a feature edge then).
VD collapseEdge(State& state, ED e, const Vec3& x, bool constrained)
{
  Mesh& mesh = state.mesh;
  const HD h = mesh.halfedge(e);
  const VD v0 = mesh.source(h), v1 = mesh.target(h);
  Quadric qv = state.vq[v0];
  qv += state.vq[v1];
  qv += state.eq[e];
  const bool fv = state.featureVertex[v0] || state.featureVertex[v1];
  // A droppable vertex merged with a vertex off the line stays droppable; one
  // merged into its kept neighbour along the line is gone.
  const bool dropped = state.alongLine(e);
  const bool droppable = !dropped && (state.droppable[v0] || state.droppable[v1]);
  const Vec3 p0 = state.pos(v0), p1 = state.pos(v1);
  const std::int64_t o0 = state.origin[v0], o1 = state.origin[v1];
  struct Side
  {
    bool exists = false;
    VD apex;
    Quadric q;
    bool feature = false;
  } sides[2];
  for (int k = 0; k < 2; ++k)
  {
    const HD side = k == 0 ? h : mesh.opposite(h);
    if (mesh.is_border(side))
      continue;
    // side: a -> b, next: b -> apex, prev: apex -> a.
    const HD n = mesh.next(side), p = mesh.prev(side);
    sides[k].exists = true;
    sides[k].apex = mesh.target(n);
    sides[k].q = state.eq[mesh.edge(n)];
    sides[k].q += state.eq[mesh.edge(p)];
    sides[k].feature = state.feature[mesh.edge(n)] || state.feature[mesh.edge(p)];
  }
  const VD kept = constrained ? CGAL::Euler::collapse_edge(e, mesh, state.feature) : CGAL::Euler::collapse_edge(e, mesh);
  mesh.point(kept) = Point(x.x(), x.y(), x.z());
  state.vq[kept] = qv;
  state.featureVertex[kept] = fv;
  state.droppable[kept] = droppable;
  if (x == p0)
    state.origin[kept] = o0;
  else if (x == p1)
    state.origin[kept] = o1;
  for (const Side& sd : sides)
  {
    if (!sd.exists)
      continue;
    const auto hk = CGAL::halfedge(kept, sd.apex, mesh);
    if (hk.second)
    {
      state.eq[mesh.edge(hk.first)] = sd.q;
      state.feature[mesh.edge(hk.first)] = sd.feature;
    }
  }
  const VD removed = kept == v0 ? v1 : v0;
  state.parent[static_cast<std::size_t>(removed)] = static_cast<std::int64_t>(kept);
  --state.vertices;
  ++state.collapses;
  return kept;
}

/// Marks the locked line vertices that featureTolerance lets go
/// (chainVerticesToKeep on each chain of feature edges).
void markDroppableVertices(State& state, const TriangleMesh& input, const std::vector<EdgeKey>& featureEdges)
{
  for (const std::vector<std::int64_t>& chain : featureChains(featureEdges))
  {
    const std::vector<char> keep = chainVerticesToKeep(input.points, chain, state.options.featureTolerance);
    // A closed chain's first vertex (repeated last) is one of its own.
    const std::size_t first = chain.front() == chain.back() ? 0 : 1;
    for (std::size_t k = first; k + 1 < chain.size(); ++k)
      if (!keep[k])
        state.droppable[VD(static_cast<Mesh::size_type>(chain[k]))] = true;
  }
}

void checkOptions(const TriangleMesh& mesh, const SimplificationOptions& o)
{
  auto positive = [](double w) { return std::isfinite(w) && w > 0.0; };
  if (!positive(o.featureWeight))
    throw std::invalid_argument("the feature weight k must be a finite number above 0");
  if (!positive(o.featureNeighbourWeight))
    throw std::invalid_argument("the weight of edges next to a feature must be a finite number above 0");
  if (!(std::isfinite(o.boundaryWeight) && o.boundaryWeight >= 0.0))
    throw std::invalid_argument("the boundary weight must be a finite number >= 0");
  if (!(std::isfinite(o.featureTolerance) && o.featureTolerance >= 0.0))
    throw std::invalid_argument("the feature tolerance must be a finite distance >= 0");
  if (o.targetVertices < 4)
    throw std::invalid_argument("the target vertex count must be at least 4");
  if (o.targetVertices >= mesh.points.size())
    throw std::invalid_argument("the target of " + std::to_string(o.targetVertices) +
      " vertices is not below the input's " + std::to_string(mesh.points.size()) + " vertices");
}

} // namespace

SimplificationResult simplifyLattice(const TriangleMesh& input, const std::vector<EdgeKey>& featureEdges,
  const SimplificationOptions& options)
{
  Mesh mesh;
  const std::string problem = cgal::checkedSurfaceMesh(input, mesh);
  if (!problem.empty())
    throw std::invalid_argument(problem);
  checkOptions(input, options);

  State state{ mesh, options, mesh.add_property_map<VD, Quadric>("v:q").first,
    mesh.add_property_map<ED, Quadric>("e:q").first, mesh.add_property_map<ED, bool>("e:feature", false).first,
    mesh.add_property_map<VD, bool>("v:feature", false).first, mesh.add_property_map<VD, bool>("v:droppable", false).first,
    mesh.add_property_map<VD, std::int64_t>("v:origin", -1).first, {} };
  for (VD v : mesh.vertices())
    state.origin[v] = static_cast<std::int64_t>(static_cast<std::size_t>(v));

  for (const EdgeKey& e : featureEdges)
  {
    const auto n = static_cast<std::int64_t>(input.points.size());
    if (e.first < 0 || e.second < 0 || e.first >= n || e.second >= n)
      throw std::invalid_argument("feature edge (" + std::to_string(e.first) + ", " + std::to_string(e.second) +
        ") has a vertex id outside 0.." + std::to_string(n - 1));
    const auto h = CGAL::halfedge(VD(static_cast<Mesh::size_type>(e.first)),
      VD(static_cast<Mesh::size_type>(e.second)), mesh);
    if (!h.second)
      throw std::invalid_argument("feature edge (" + std::to_string(e.first) + ", " + std::to_string(e.second) +
        ") is not an edge of the mesh");
    state.feature[mesh.edge(h.first)] = true;
    state.featureVertex[mesh.source(h.first)] = true;
    state.featureVertex[mesh.target(h.first)] = true;
  }

  // Face quadrics, a third of the area to each vertex and edge (Kanai).
  for (auto f : mesh.faces())
  {
    const HD h = mesh.halfedge(f);
    const VD a = mesh.source(h), b = mesh.target(h), c = mesh.target(mesh.next(h));
    const Vec3 pa = state.pos(a), pb = state.pos(b), pc = state.pos(c);
    Vec3 n = (pb - pa).cross(pc - pa);
    const double twiceArea = n.norm();
    if (!(twiceArea > 0.0))
      continue;
    n /= twiceArea;
    const Quadric q = Quadric::plane(n, -n.dot(pa), twiceArea / 6.0);
    for (VD v : { a, b, c })
      state.vq[v] += q;
    for (HD e : CGAL::halfedges_around_face(h, mesh))
      state.eq[mesh.edge(e)] += q;
  }
  // Boundary quadrics: the plane through a border edge, perpendicular to its face.
  if (options.boundaryWeight > 0.0)
  {
    for (HD h : mesh.halfedges())
    {
      if (!mesh.is_border(h))
        continue;
      const HD o = mesh.opposite(h);
      const VD u = mesh.source(o), x = mesh.target(o);
      const Vec3 pu = state.pos(u), px = state.pos(x), pw = state.pos(mesh.target(mesh.next(o)));
      const Vec3 nf = (px - pu).cross(pw - pu);
      Vec3 nb = (px - pu).cross(nf);
      if (!(nb.norm() > 0.0))
        continue;
      nb.normalize();
      const Quadric q = Quadric::plane(nb, -nb.dot(pu), options.boundaryWeight * (px - pu).squaredNorm());
      state.vq[u] += q;
      state.vq[x] += q;
      state.eq[mesh.edge(h)] += q;
    }
  }
  // Eq. 3.14 and the neighbour weight.
  for (ED e : mesh.edges())
  {
    const HD h = mesh.halfedge(e);
    if (state.feature[e])
      state.eq[e] *= options.featureWeight;
    else if (state.featureVertex[mesh.source(h)] || state.featureVertex[mesh.target(h)])
      state.eq[e] *= options.featureNeighbourWeight;
  }
  for (VD v : mesh.vertices())
  {
    if (state.featureVertex[v])
      state.vq[v] *= options.featureWeight;
  }

  state.parent.assign(input.points.size(), -1);
  state.vertices = input.points.size();
  state.toRemove = state.vertices - options.targetVertices;
  state.reportEvery = std::max<std::size_t>(1, state.toRemove / 200);
  if (options.lockFeatures && options.featureTolerance > 0.0)
    markDroppableVertices(state, input, featureEdges);

  // Lazy queue: a collapse marks the edges around its new vertex's ring
  // dirty (their old cost stays in the heap); a dirty edge that reaches the
  // top is re-costed and pushed back. Far fewer cost evaluations than
  // re-costing every neighbour at once, the same greedy order up to ties.
  const std::size_t edgeCount = mesh.number_of_edges();
  std::vector<std::uint32_t> stamp(edgeCount, 0);
  std::vector<char> dirty(edgeCount, 0);
  std::vector<double> lastCost(edgeCount, 0.0);
  std::priority_queue<HeapEntry, std::vector<HeapEntry>, std::greater<HeapEntry>> heap;
  auto push = [&](ED e) {
    const auto i = static_cast<std::size_t>(e);
    if (!state.collapsible(e))
      return;
    Vec3 x;
    double c;
    const HD h = mesh.halfedge(e);
    if (!placeAndCost(state, mesh.source(h), mesh.target(h), x, c))
      return;
    // A vertex the line lets go goes first, while its neighbourhood is
    // fine (its quadrics carry the feature weight k, which would otherwise
    // keep it to the end).
    if (state.alongLine(e))
      c = 0.0;
    lastCost[i] = c;
    dirty[i] = 0;
    heap.push({ c, static_cast<std::uint32_t>(i), ++stamp[i] });
  };
  for (ED e : mesh.edges())
    push(e);

  while (state.vertices > options.targetVertices && !heap.empty() && !state.aborted)
  {
    const HeapEntry top = heap.top();
    heap.pop();
    const ED e(top.edge);
    if (mesh.is_removed(e) || top.stamp != stamp[top.edge])
      continue;
    if (dirty[top.edge])
    {
      push(e);
      continue;
    }
    const HD h = mesh.halfedge(e);
    const VD v0 = mesh.source(h), v1 = mesh.target(h);
    if (options.lockFeatures && state.featureVertex[v0] && state.featureVertex[v1] && !state.alongLine(e))
      continue;
    if (!topologicallyValid(mesh, e))
      continue;
    Vec3 x;
    double c;
    if (!placeAndCost(state, v0, v1, x, c) || !geometricallyValid(state, v0, v1, x, state.alongLine(e)))
      continue; // comes back when its neighbourhood changes

    const VD kept = collapseEdge(state, e, x, options.lockFeatures && !state.feature[e]);
    // Everything whose cost reads the moved vertex: the edges at its ring.
    for (HD r : CGAL::halfedges_around_target(mesh.halfedge(kept), mesh))
    {
      for (HD g : CGAL::halfedges_around_target(r, mesh))
      {
        const ED ge = mesh.edge(g);
        const auto i = static_cast<std::size_t>(ge);
        if (!state.collapsible(ge))
          continue;
        if (!dirty[i])
        {
          dirty[i] = 1;
          heap.push({ lastCost[i], static_cast<std::uint32_t>(i), ++stamp[i] });
        }
      }
    }
    if (options.progress && state.collapses % state.reportEvery == 0 &&
      !options.progress(std::min(1.0, double(state.collapses) / double(state.toRemove))))
      state.aborted = true;
  }

  if (!state.aborted && options.progress)
    options.progress(1.0);

  SimplificationResult result;
  result.collapses = state.collapses;
  result.aborted = state.aborted;
  std::vector<std::int64_t> newId(input.points.size(), -1);
  for (VD v : mesh.vertices())
  {
    newId[static_cast<std::size_t>(v)] = static_cast<std::int64_t>(result.mesh.points.size());
    result.mesh.points.push_back(state.pos(v));
    result.inputVertex.push_back(state.origin[v]);
  }
  for (auto f : mesh.faces())
  {
    Triangle t{};
    int i = 0;
    for (VD v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      t[static_cast<std::size_t>(i++)] = newId[static_cast<std::size_t>(v)];
    result.mesh.triangles.push_back(t);
  }
  result.collapsedInto.resize(input.points.size());
  for (std::size_t v = 0; v < input.points.size(); ++v)
  {
    std::size_t r = v;
    while (state.parent[r] >= 0)
      r = static_cast<std::size_t>(state.parent[r]);
    result.collapsedInto[v] = newId[r];
  }
  for (ED e : mesh.edges())
  {
    const HD h = mesh.halfedge(e);
    const VD u = mesh.source(h), x = mesh.target(h);
    const EdgeKey key = edgeKey(newId[static_cast<std::size_t>(u)], newId[static_cast<std::size_t>(x)]);
    if (state.feature[e])
      result.featureEdges.push_back(key);
    Vec3 q = 0.5 * (state.pos(u) + state.pos(x));
    if (options.roundedSurfaceQuadrics)
    {
      Vec3 others = Vec3::Zero();
      int n = 0;
      for (HD side : { h, mesh.opposite(h) })
      {
        if (!mesh.is_border(side))
        {
          others += state.pos(mesh.target(mesh.next(side)));
          ++n;
        }
      }
      q = 5.0 / 6.0 * q + others / (6.0 * n);
    }
    result.edgeCost[key] = std::max(0.0, state.eq[e](q));
  }
  std::sort(result.featureEdges.begin(), result.featureEdges.end());
  return result;
}

} // namespace lk
