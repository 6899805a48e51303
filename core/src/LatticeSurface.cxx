#include "latticekit/LatticeSurface.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <map>
#include <stdexcept>
#include <utility>

namespace lk
{

namespace
{

/// A cubic curve with its Chiyokura-Kimura basis vectors at both ends, in
/// the curve's own direction.
struct Curve
{
  std::array<Vec3, 4> X;
  Vec3 b0, b1;

  Curve reversed() const { return { { X[3], X[2], X[1], X[0] }, b1, b0 }; }
  /// The halves at t = 1/2 (de Casteljau); b is restricted with the curve:
  /// the midpoint's b is the mean of the ends'. The split patches fit their
  /// cross-boundary derivative at the midpoint to that b and C'(1/2), and on
  /// a crumpled lattice the two can be nearly parallel, or the mean nearly
  /// zero (the tangent planes at the ends turned against each other); the
  /// fitted k, h then grow without bound and the patches spike. With
  /// `conditionMid`, b's component along C'(1/2) is cut until b is at least
  /// 10 degrees from it, and b is lengthened to at least half the ends' mean
  /// length. And b is kept on the side of the curve that b0 is on: b0 =
  /// n0 x C'(0) lies on the curve's left about the start's plane normal n0,
  /// and b must lie on its left about `midNormal` (the mean of the ends'
  /// plane normals). Where the ends' planes turn against each other, the
  /// mean of b0 and b1 can cross over to the right; k(t) of both patches
  /// then changes sign between the end and the midpoint, at different t, and
  /// between those the two patches lie on the same side of the curve (a
  /// fold). Each change keeps b in the plane of the mean and C'(1/2), the
  /// midpoint's tangent plane, and both faces of the edge split it alike, so
  /// G1 holds; an edge beside a quad must not use them (the quad's patch
  /// uses the whole curve's linear b).
  std::pair<Curve, Curve> split(bool conditionMid, const Vec3& startNormal, const Vec3& midNormal) const
  {
    const Vec3 a = 0.5 * (X[0] + X[1]), b = 0.5 * (X[1] + X[2]), c = 0.5 * (X[2] + X[3]);
    const Vec3 d = 0.5 * (a + b), e = 0.5 * (b + c), m = 0.5 * (d + e);
    Vec3 bm = 0.5 * (b0 + b1);
    if (conditionMid)
    {
      const Vec3 tangent = e - d; // along C'(1/2)
      if (tangent.norm() > 0.0)
      {
        const Vec3 t = tangent.normalized();
        const double along = bm.dot(t);
        Vec3 across = bm - along * t;
        if (b0.dot(startNormal.cross(X[1] - X[0])) * across.dot(midNormal.cross(t)) < 0.0)
        {
          across = -across;
          bm = along * t + across;
        }
        const double most = across.norm() / std::tan(10.0 * M_PI / 180.0);
        if (std::abs(along) > most)
        {
          bm = across + std::copysign(most, along) * t;
        }
      }
      const double shortest = 0.25 * (b0.norm() + b1.norm());
      if (bm.norm() > 0.0 && bm.norm() < shortest)
      {
        bm *= shortest / bm.norm();
      }
    }
    return { Curve{ { X[0], a, d, m }, b0, bm }, Curve{ { m, e, c, X[3] }, bm, b1 } };
  }
};

Vec3 projectOnPlane(const Vec3& v, const Vec3& n)
{
  return v - v.dot(n) * n;
}

/// The direction of t projected into the plane, with t's own length but at
/// least minLength (direction of the projected chord when t vanishes) and at
/// most maxLength. A plain projection can leave a tangent that points mostly
/// along the normal nearly zero long, and eq. 2.2 itself gives an almost zero
/// tangent where two large faces dominate a vertex (Q is then nearly V').
/// Such tangents distort the patches beside them until they fold. On a
/// crumpled lattice eq. 2.2 can also give tangents longer than the chord; two
/// of them along the chord stop the curve at its midpoint (C'(1/2) =
/// 3/4 (2 chord + t1 - t0) vanishes), and the split patches, whose
/// cross-boundary derivative is fitted to C'(1/2), spike. The edge curves
/// cap their tangents at 3/4 of the chord, which keeps |C'(1/2)| at least
/// 3/8 of it. On a regular grid eq. 2.2 gives a third of the chord, so the
/// floor (a sixth) and the cap leave it alone.
Vec3 tangentInPlane(const Vec3& t, const Vec3& n, const Vec3& chord, double minLength,
  double maxLength = std::numeric_limits<double>::infinity())
{
  Vec3 p = projectOnPlane(t, n);
  double len = p.norm();
  if (!(len > 1e-12 * (t.norm() + chord.norm())))
  {
    p = projectOnPlane(chord, n);
    len = p.norm();
  }
  if (!(len > 0.0))
  {
    return p;
  }
  return p * (std::clamp(t.norm(), minLength, std::max(minLength, maxLength)) / len);
}

Vec3 unit(const Vec3& v, const char* what)
{
  const double len = v.norm();
  if (!(len > 0.0) || !std::isfinite(len))
  {
    throw std::invalid_argument(std::string("the lattice surface degenerates: ") + what);
  }
  return v / len;
}

/// Best k, h with a ~ k b + h c (exact when a lies in the plane of b and c).
void fit(const Vec3& a, const Vec3& b, const Vec3& c, double& k, double& h)
{
  const double bb = b.dot(b), bc = b.dot(c), cc = c.dot(c);
  const double det = bb * cc - bc * bc;
  if (!(std::abs(det) > 1e-300))
  {
    throw std::invalid_argument("the lattice surface degenerates: a curve is tangent to its basis vector");
  }
  k = (a.dot(b) * cc - a.dot(c) * bc) / det;
  h = (a.dot(c) * bb - a.dot(b) * bc) / det;
}

/// Interior control vectors e1, e2 of the cross-boundary derivative
/// D(t) = k(t) b(t) + h(t) C'(t) that starts at a0 and ends at a1.
std::pair<Vec3, Vec3> crossDerivative(const Curve& side, const Vec3& a0, const Vec3& a1)
{
  const Vec3 c0 = 3.0 * (side.X[1] - side.X[0]);
  const Vec3 c1 = 3.0 * (side.X[2] - side.X[1]);
  const Vec3 c2 = 3.0 * (side.X[3] - side.X[2]);
  double k0, h0, k1, h1;
  fit(a0, side.b0, c0, k0, h0);
  fit(a1, side.b1, c2, k1, h1);
  // k(t) b(t): quadratic, raised to cubic.
  const Vec3 q0 = k0 * side.b0, q1 = 0.5 * (k0 * side.b1 + k1 * side.b0), q2 = k1 * side.b1;
  const Vec3 kb1 = (q0 + 2.0 * q1) / 3.0, kb2 = (2.0 * q1 + q2) / 3.0;
  // h(t) C'(t): linear times quadratic.
  const Vec3 hc1 = (h1 * c0 + 2.0 * h0 * c1) / 3.0, hc2 = (2.0 * h1 * c1 + h0 * c2) / 3.0;
  return { kb1 + hc1, kb2 + hc2 };
}

/// Fills a Gregory patch from its four sides, given in the patch's
/// directions: s0 (v = 0, c0 -> c1), s1 (u = 1, c1 -> c2), s2 (v = 1,
/// c3 -> c2), s3 (u = 0, c0 -> c3).
GregoryPatch makePatch(const Curve& s0, const Curve& s1, const Curve& s2, const Curve& s3)
{
  GregoryPatch p;
  for (int i = 0; i < 4; ++i)
  {
    p.P(i, 0) = s0.X[static_cast<std::size_t>(i)];
    p.P(3, i) = s1.X[static_cast<std::size_t>(i)];
    p.P(i, 3) = s2.X[static_cast<std::size_t>(i)];
    p.P(0, i) = s3.X[static_cast<std::size_t>(i)];
  }
  // Each side's cross-boundary derivative, pointing into the patch, starts
  // and ends with the tangents of the neighbouring sides at its corners.
  auto e = crossDerivative(s0, 3.0 * (p.P(0, 1) - p.P(0, 0)), 3.0 * (p.P(3, 1) - p.P(3, 0)));
  p.inner(1, 1, 0) = p.P(1, 0) + e.first / 3.0;
  p.inner(2, 1, 0) = p.P(2, 0) + e.second / 3.0;
  e = crossDerivative(s2, 3.0 * (p.P(0, 2) - p.P(0, 3)), 3.0 * (p.P(3, 2) - p.P(3, 3)));
  p.inner(1, 2, 0) = p.P(1, 3) + e.first / 3.0;
  p.inner(2, 2, 0) = p.P(2, 3) + e.second / 3.0;
  e = crossDerivative(s3, 3.0 * (p.P(1, 0) - p.P(0, 0)), 3.0 * (p.P(1, 3) - p.P(0, 3)));
  p.inner(1, 1, 1) = p.P(0, 1) + e.first / 3.0;
  p.inner(1, 2, 1) = p.P(0, 2) + e.second / 3.0;
  e = crossDerivative(s1, 3.0 * (p.P(2, 0) - p.P(3, 0)), 3.0 * (p.P(2, 3) - p.P(3, 3)));
  p.inner(2, 1, 1) = p.P(3, 1) + e.first / 3.0;
  p.inner(2, 2, 1) = p.P(3, 2) + e.second / 3.0;
  return p;
}

struct FaceGeometry
{
  Vec3 normal;       ///< unit (Newell)
  double area = 0.0;
  std::vector<Vec3> ds; ///< Doo-Sabin point of each corner
};

} // namespace

LatticeSurface buildLatticeSurface(const PolygonMesh& lattice, const LatticeWeights& weights)
{
  const std::string problem = latticeProblem(lattice);
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  const std::size_t nv = lattice.points.size();
  const auto& P = lattice.points;
  if (!weights.vertex.empty() && weights.vertex.size() != nv)
  {
    throw std::invalid_argument("the vertex weights must be one per lattice point");
  }
  for (double w : weights.vertex)
  {
    if (!(w >= 0.0 && w <= 1.0))
    {
      throw std::invalid_argument("a vertex weight is outside [0, 1] (or NaN)");
    }
  }
  for (const auto& [key, w] : weights.edge)
  {
    if (!(w >= 0.0 && w <= 1.0))
    {
      throw std::invalid_argument("an edge weight is outside [0, 1] (or NaN)");
    }
  }

  // Faces: Newell normal and area, Doo-Sabin points.
  std::vector<FaceGeometry> faces(lattice.faces.size());
  for (std::size_t f = 0; f < lattice.faces.size(); ++f)
  {
    const auto& face = lattice.faces[f];
    const std::size_t n = face.size();
    const Vec3 newell = newellVector(lattice, f);
    faces[f].area = 0.5 * newell.norm();
    faces[f].normal = newell.normalized();
    faces[f].ds.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      Vec3 d = Vec3::Zero();
      for (std::size_t j = 0; j < n; ++j)
      {
        const std::size_t k = (j + n - i) % n;
        const double a = k == 0 ? (n + 5.0) / (4.0 * n)
                                : (3.0 + 2.0 * std::cos(2.0 * M_PI * static_cast<double>(k) / n)) / (4.0 * n);
        d += a * P[static_cast<std::size_t>(face[j])];
      }
      faces[f].ds[i] = d;
    }
  }

  // Edges: the faces beside each (face, corner index of the edge's first vertex),
  // and whether the edge is a crease (weight below 1/2, or a boundary).
  using Key = std::pair<std::int64_t, std::int64_t>;
  std::map<Key, std::vector<std::pair<std::size_t, std::size_t>>> edgeFaces;
  for (std::size_t f = 0; f < lattice.faces.size(); ++f)
  {
    const auto& face = lattice.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i)
    {
      const auto a = face[i], b = face[(i + 1) % face.size()];
      edgeFaces[{ std::min(a, b), std::max(a, b) }].push_back({ f, i });
    }
  }
  for (const auto& [key, w] : weights.edge)
  {
    if (!edgeFaces.count({ std::min(key.first, key.second), std::max(key.first, key.second) }))
    {
      std::ostringstream os;
      os << "a weight is given to (" << key.first << ", " << key.second << "), which is not a lattice edge";
      throw std::invalid_argument(os.str());
    }
  }
  auto isCrease = [&](const Key& key, std::size_t besides) {
    return besides == 1 || weights.edgeWeight(key.first, key.second) == 0.0;
  };
  std::map<Key, bool> crease;
  std::vector<std::vector<std::int64_t>> creaseNeighbours(nv);
  std::vector<std::vector<Key>> vertexEdges(nv);
  for (const auto& [key, besides] : edgeFaces)
  {
    vertexEdges[static_cast<std::size_t>(key.first)].push_back(key);
    vertexEdges[static_cast<std::size_t>(key.second)].push_back(key);
    crease[key] = isCrease(key, besides.size());
    if (crease[key])
    {
      creaseNeighbours[static_cast<std::size_t>(key.first)].push_back(key.second);
      creaseNeighbours[static_cast<std::size_t>(key.second)].push_back(key.first);
    }
  }

  // Sectors: the faces around a vertex, split by its creases. A union-find
  // per vertex over the faces, joined across the vertex's smooth edges.
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> sectorOf; // (vertex, face) -> sector
  std::vector<std::vector<std::vector<std::size_t>>> sectors(nv);      // vertex -> sector -> faces
  {
    std::vector<std::vector<std::size_t>> vertexFaces(nv);
    for (std::size_t f = 0; f < lattice.faces.size(); ++f)
    {
      for (const auto id : lattice.faces[f])
      {
        vertexFaces[static_cast<std::size_t>(id)].push_back(f);
      }
    }
    for (std::size_t v = 0; v < nv; ++v)
    {
      const auto& fs = vertexFaces[v];
      std::vector<std::size_t> parent(fs.size());
      for (std::size_t i = 0; i < fs.size(); ++i)
      {
        parent[i] = i;
      }
      std::function<std::size_t(std::size_t)> root = [&](std::size_t i) {
        return parent[i] == i ? i : parent[i] = root(parent[i]);
      };
      auto local = [&](std::size_t f) {
        return static_cast<std::size_t>(std::find(fs.begin(), fs.end(), f) - fs.begin());
      };
      for (const Key& key : vertexEdges[v])
      {
        const auto& besides = edgeFaces[key];
        if (besides.size() == 2 && !crease[key])
        {
          parent[root(local(besides[0].first))] = root(local(besides[1].first));
        }
      }
      std::map<std::size_t, std::size_t> index;
      for (std::size_t i = 0; i < fs.size(); ++i)
      {
        const std::size_t r = root(i);
        if (!index.count(r))
        {
          index[r] = sectors[v].size();
          sectors[v].emplace_back();
        }
        sectors[v][index[r]].push_back(fs[i]);
        sectorOf[{ v, fs[i] }] = index[r];
      }
    }
  }

  // Vertices: rounded point (eq. 2.1, or the crease rules) and a tangent
  // plane per sector.
  LatticeSurface s;
  s.roundedPoints.assign(nv, Vec3::Zero());
  std::vector<int> kind(nv, 0); // 0 smooth (or dart), 2 crease, 3 corner
  std::vector<double> areaSum(nv, 0.0);
  for (std::size_t f = 0; f < lattice.faces.size(); ++f)
  {
    for (std::size_t i = 0; i < lattice.faces[f].size(); ++i)
    {
      const auto v = static_cast<std::size_t>(lattice.faces[f][i]);
      s.roundedPoints[v] += faces[f].area * faces[f].ds[i];
      areaSum[v] += faces[f].area;
    }
  }
  for (std::size_t v = 0; v < nv; ++v)
  {
    const double w = weights.vertex.empty() ? 1.0 : weights.vertex[v];
    const auto& cn = creaseNeighbours[v];
    if (cn.size() >= 3)
    {
      kind[v] = 3;
      s.roundedPoints[v] = P[v];
    }
    else if (cn.size() == 2)
    {
      // On a crease (or a boundary) the curve is the uniform cubic B-spline
      // of the crease polygon: V' = (p + 4 V + q) / 6.
      kind[v] = 2;
      s.roundedPoints[v] = P[v] + w * ((P[static_cast<std::size_t>(cn[0])] + P[static_cast<std::size_t>(cn[1])]) / 6.0 - P[v] / 3.0);
    }
    else
    {
      s.roundedPoints[v] = P[v] + w * (s.roundedPoints[v] / areaSum[v] - P[v]);
    }
  }

  // Crease curves do not depend on tangent planes: build them first.
  auto creaseTangent = [&](std::int64_t a, std::int64_t b) -> Vec3 {
    const auto ia = static_cast<std::size_t>(a);
    if (kind[ia] == 2)
    {
      const auto& cn = creaseNeighbours[ia];
      const std::int64_t other = cn[0] == b ? cn[1] : cn[0];
      return (P[static_cast<std::size_t>(b)] - P[static_cast<std::size_t>(other)]) / 6.0;
    }
    return (P[static_cast<std::size_t>(b)] - P[ia]) / 3.0; // corner, or a dart end (projected below)
  };

  std::vector<std::vector<Vec3>> sectorNormal(nv);
  for (std::size_t v = 0; v < nv; ++v)
  {
    for (const auto& fs : sectors[v])
    {
      Vec3 n = Vec3::Zero();
      for (const std::size_t f : fs)
      {
        n += faces[f].area * faces[f].normal;
      }
      n = unit(n, "opposite faces cancel at a vertex");
      const auto& cn = creaseNeighbours[v];
      if (kind[v] == 2)
      {
        // Both sectors contain the crease tangent.
        const Vec3 t = unit(creaseTangent(static_cast<std::int64_t>(v), cn[0]), "a crease has coincident points");
        n = unit(n - n.dot(t) * t, "a crease runs along the surface normal");
      }
      else if (kind[v] == 3)
      {
        // A corner's sector is spanned by its two bounding crease tangents.
        std::vector<Vec3> bounding;
        for (const auto x : cn)
        {
          const Key key{ std::min<std::int64_t>(static_cast<std::int64_t>(v), x), std::max<std::int64_t>(static_cast<std::int64_t>(v), x) };
          for (const auto& [f, i] : edgeFaces[key])
          {
            if (std::find(fs.begin(), fs.end(), f) != fs.end())
            {
              bounding.push_back(creaseTangent(static_cast<std::int64_t>(v), x));
              break;
            }
          }
        }
        if (bounding.size() == 2)
        {
          Vec3 m = bounding[0].cross(bounding[1]);
          if (m.norm() > 1e-12 * bounding[0].norm() * bounding[1].norm())
          {
            n = m.dot(n) < 0.0 ? Vec3(-m.normalized()) : Vec3(m.normalized());
          }
          else
          {
            n = unit(n - n.dot(bounding[0].normalized()) * bounding[0].normalized(), "a corner's creases are collinear");
          }
        }
      }
      sectorNormal[v].push_back(n);
    }
  }
  auto normalAt = [&](std::int64_t v, std::size_t f) -> const Vec3& {
    const auto iv = static_cast<std::size_t>(v);
    return sectorNormal[iv][sectorOf.at({ iv, f })];
  };

  // Eq. 2.2's tangent of every smooth edge at each end, in the end's plane.
  std::map<std::pair<std::int64_t, std::int64_t>, Vec3> tangentAt; // (vertex, other end) -> tangent
  for (const auto& [key, besides] : edgeFaces)
  {
    if (crease[key])
    {
      continue;
    }
    for (const bool first : { true, false })
    {
      const auto v = first ? key.first : key.second;
      const auto x = first ? key.second : key.first;
      const Vec3& V = s.roundedPoints[static_cast<std::size_t>(v)];
      Vec3 Q = Vec3::Zero();
      for (const auto& [f, i] : besides)
      {
        const auto& face = lattice.faces[f];
        Q += faces[f].ds[face[i] == v ? i : (i + 1) % face.size()];
      }
      Q /= static_cast<double>(besides.size());
      // An edge weight w in (0, 1) tightens the rounding along the edge: Q
      // moves towards the lattice edge's third point, (2 V + X) / 3, so the
      // curve leans towards the lattice edge; the tangent plane is unchanged,
      // so G1 holds for every w > 0 (w = 0 is the crease).
      const double w = weights.edgeWeight(key.first, key.second);
      Q = w * Q + (1.0 - w) * (2.0 * P[static_cast<std::size_t>(v)] + P[static_cast<std::size_t>(x)]) / 3.0;
      const Vec3 chord = s.roundedPoints[static_cast<std::size_t>(x)] - V;
      tangentAt[{ v, x }] = tangentInPlane((4.0 * Q - V) / 3.0 - V, normalAt(v, besides[0].first), chord, chord.norm() / 6.0,
        0.75 * chord.norm());
    }
  }
  // At a smooth interior vertex of a folded-back fan (decimated lattices have
  // them), projected tangents can swap order in the plane; a face corner is
  // then inverted and its patch folds. There, keep every tangent's length but
  // spread the directions in the fan's cyclic order: at the projected lattice
  // edges' angles when those are in order, else at equal angles.
  for (std::size_t v = 0; v < nv; ++v)
  {
    if (kind[v] != 0 || !creaseNeighbours[v].empty() || sectors[v].size() != 1)
    {
      continue;
    }
    const auto vi = static_cast<std::int64_t>(v);
    const Vec3& n = sectorNormal[v][0];
    // Cyclic order: each face turns from its next edge to its previous one.
    std::map<std::int64_t, std::int64_t> turn; // next -> prev, per face at v
    for (const std::size_t f : sectors[v][0])
    {
      const auto& face = lattice.faces[f];
      const auto i = static_cast<std::size_t>(std::find(face.begin(), face.end(), vi) - face.begin());
      turn[face[(i + 1) % face.size()]] = face[(i + face.size() - 1) % face.size()];
    }
    bool inverted = false;
    for (const auto& [next, prev] : turn)
    {
      inverted = inverted || tangentAt.at({ vi, next }).cross(tangentAt.at({ vi, prev })).dot(n) <= 0.0;
    }
    if (!inverted)
    {
      continue;
    }
    std::vector<std::int64_t> ring = { turn.begin()->first };
    while (ring.size() < turn.size() && turn.count(ring.back()))
    {
      ring.push_back(turn.at(ring.back()));
    }
    if (ring.size() != turn.size() || turn.at(ring.back()) != ring.front())
    {
      continue; // not a single closed fan; leave it
    }
    const Vec3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    auto angle = [&](const Vec3& t) { return std::atan2(t.dot(e2), t.dot(e1)); };
    std::vector<double> theta(ring.size());
    bool ordered = true;
    double total = 0.0;
    for (std::size_t k = 0; k < ring.size(); ++k)
    {
      theta[k] = angle(P[static_cast<std::size_t>(ring[k])] - P[v]);
      if (k > 0)
      {
        double step = theta[k] - theta[k - 1];
        while (step <= 0.0)
        {
          step += 2.0 * M_PI;
        }
        ordered = ordered && step < M_PI;
        total += step;
      }
    }
    double closing = theta[0] - theta.back();
    while (closing <= 0.0)
    {
      closing += 2.0 * M_PI;
    }
    ordered = ordered && closing < M_PI && std::abs(total + closing - 2.0 * M_PI) < 1e-9;
    for (std::size_t k = 0; k < ring.size(); ++k)
    {
      const double a = ordered ? theta[k] : theta[0] + 2.0 * M_PI * static_cast<double>(k) / ring.size();
      Vec3& t = tangentAt.at({ vi, ring[k] });
      t = t.norm() * (std::cos(a) * e1 + std::sin(a) * e2);
    }
  }

  // Edge curves; a smooth edge's b is shared by its two faces, a crease's b is
  // made per face (see sideCurve).
  std::map<Key, std::size_t> edgeIndex;
  std::vector<Curve> curves;
  for (const auto& [key, besides] : edgeFaces)
  {
    const auto a = key.first, b = key.second;
    const auto ia = static_cast<std::size_t>(a), ib = static_cast<std::size_t>(b);
    const Vec3& A = s.roundedPoints[ia];
    const Vec3& B = s.roundedPoints[ib];
    const std::size_t f0 = besides[0].first;
    const Vec3& na = normalAt(a, f0);
    const Vec3& nb = normalAt(b, f0);
    Curve c;
    if (crease[key])
    {
      Vec3 ta = creaseTangent(a, b), tb = creaseTangent(b, a);
      if (kind[ia] == 0)
      {
        ta = projectOnPlane(ta, na); // a dart: the crease fades into a smooth vertex
      }
      if (kind[ib] == 0)
      {
        tb = projectOnPlane(tb, nb);
      }
      c.X = { A, A + ta, B + tb, B };
    }
    else
    {
      // Eq. 2.2, affine: P1' = (4Q - P0') / 3, in the sector's plane (above).
      c.X = { A, A + tangentAt.at({ a, b }), B + tangentAt.at({ b, a }), B };
    }
    c.b0 = na.cross(unit(c.X[1] - c.X[0], "an edge curve has no tangent at its start"));
    c.b1 = nb.cross(unit(c.X[3] - c.X[2], "an edge curve has no tangent at its end"));
    edgeIndex[key] = curves.size();
    curves.push_back(c);
    s.edgeCurves.push_back(c.X);
    s.edgeVertices.push_back({ a, b });
    s.edgeCrease.push_back(crease[key] ? 1 : 0);
  }
  // The curve of edge (from, to) as face f sees it, oriented from `from`.
  auto sideCurve = [&](std::int64_t from, std::int64_t to, std::size_t f) {
    const Key key{ std::min(from, to), std::max(from, to) };
    Curve c = curves[edgeIndex.at(key)];
    if (crease.at(key))
    {
      c.b0 = normalAt(key.first, f).cross(unit(c.X[1] - c.X[0], "a crease curve has no tangent"));
      c.b1 = normalAt(key.second, f).cross(unit(c.X[3] - c.X[2], "a crease curve has no tangent"));
    }
    return from < to ? c : c.reversed();
  };

  for (std::size_t f = 0; f < lattice.faces.size(); ++f)
  {
    const auto& face = lattice.faces[f];
    const std::size_t n = face.size();
    if (n == 4)
    {
      s.patches.push_back(makePatch(sideCurve(face[0], face[1], f), sideCurve(face[1], face[2], f),
        sideCurve(face[3], face[2], f), sideCurve(face[0], face[3], f)));
      s.patchFace.push_back(static_cast<std::int64_t>(f));
      s.patchCorner.push_back(-1);
      continue;
    }
    // Centre and the inner curves from each edge midpoint to it.
    Vec3 centre = Vec3::Zero();
    for (const Vec3& d : faces[f].ds)
    {
      centre += d / static_cast<double>(n);
    }
    std::vector<Curve> inner(n), firstHalf(n), secondHalf(n);
    std::vector<Vec3> endsNormal(n); // the sum of edge i's ends' plane normals (outward at its midpoint)
    for (std::size_t i = 0; i < n; ++i)
    {
      // The edge's own direction decides the midpoint data, so both faces agree.
      const Key key{ std::min(face[i], face[(i + 1) % n]), std::max(face[i], face[(i + 1) % n]) };
      bool quadBeside = false;
      for (const auto& [g, corner] : edgeFaces.at(key))
      {
        quadBeside = quadBeside || lattice.faces[g].size() == 4;
      }
      const Vec3& startNormal = normalAt(face[i], f);
      endsNormal[i] = startNormal + normalAt(face[(i + 1) % n], f);
      const auto halves = sideCurve(face[i], face[(i + 1) % n], f).split(!quadBeside, startNormal, endsNormal[i]);
      firstHalf[i] = halves.first;   // V_i -> M_i
      secondHalf[i] = halves.second; // M_i -> V_{i+1}
    }
    // The centre's tangent plane is the plane the edge-curve midpoints span
    // (Newell normal of their polygon), not the flat face's: on a strongly
    // curved face the midpoints lie far off the face plane, and projecting
    // them onto it can leave short tangents in the wrong angular order (a
    // fold at the centre). On a planar lattice the two planes coincide.
    Vec3 newell = Vec3::Zero();
    for (std::size_t i = 0; i < n; ++i)
    {
      newell += firstHalf[i].X[3].cross(firstHalf[(i + 1) % n].X[3]);
    }
    Vec3 nc = newell.norm() > 0.0 ? Vec3(newell.normalized()) : faces[f].normal;
    if (nc.dot(faces[f].normal) < 0.0)
    {
      nc = -nc;
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      const Vec3& M = firstHalf[i].X[3];
      const Vec3 tangentM = firstHalf[i].X[3] - firstHalf[i].X[2];
      // The midpoint's plane normal, turned outward like the edge's ends'
      // planes, so that both faces beside the edge agree on it (turned like
      // each face's centre plane, the two faces of a sharply folded edge could
      // take opposite normals, and their inner curves then left the midpoint
      // to the same side: the patches folded along the edge).
      Vec3 nm = unit(firstHalf[i].b1.cross(tangentM), "an edge midpoint has no tangent plane");
      if (nm.dot(endsNormal[i]) < 0.0)
      {
        nm = -nm;
      }
      // The inner curve's end tangents get the edge curves' floor (a sixth of
      // the chord): on a crumpled lattice the centre can lie almost along the
      // midpoint's normal, and a plain projection then leaves a start tangent
      // a few % of the chord long. The cross-boundary derivative fitted to
      // such a short tangent (crossDerivative) grows without bound, and the
      // patches beside it spike far out of the lattice.
      Curve c;
      const Vec3 toCentre = centre - M;
      const double shortest = toCentre.norm() / 6.0;
      c.X = { M, M + tangentInPlane(toCentre / 3.0, nm, toCentre, shortest),
        centre + tangentInPlane(-toCentre / 3.0, nc, -toCentre, shortest), centre };
      // The inner curve leaves the midpoint into the face: on the edge's left
      // about nm (the face runs counter-clockwise), at least 10 degrees from
      // the edge, with its length kept. Where the lattice folds sharply at the
      // edge, the centre can project behind the edge; the patches beside the
      // inner curve and beside the edge then fold.
      const Vec3 left = nm.cross(tangentM).normalized();
      const Vec3 start = c.X[1] - c.X[0];
      const double leastIn = start.norm() * std::sin(10.0 * M_PI / 180.0);
      if (start.dot(left) < leastIn)
      {
        const Vec3 along = tangentM.normalized();
        const double alongLength = std::sqrt(std::max(0.0, start.squaredNorm() - leastIn * leastIn));
        c.X[1] = c.X[0] + leastIn * left + std::copysign(alongLength, start.dot(along)) * along;
      }
      c.b0 = nm.cross(unit(c.X[1] - c.X[0], "an inner curve has no tangent at its midpoint end"));
      inner[i] = c;
    }
    // The inner curves leave the centre towards the midpoints in the face's
    // order (counter-clockwise about nc). Where the lattice is irregular (a
    // vertex nearly in its neighbours' plane between slivers) the projected
    // directions can swap, and the patch between them is inverted at the
    // centre: there, as at a vertex of a folded-back fan, every tangent
    // keeps its length and the directions are spread at equal angles.
    bool inverted = false;
    for (std::size_t i = 0; i < n; ++i)
    {
      const Vec3 a = inner[i].X[2] - centre, b = inner[(i + 1) % n].X[2] - centre;
      inverted = inverted || a.cross(b).dot(nc) <= 0.0;
    }
    if (inverted)
    {
      const Vec3 e1 = unit(inner[0].X[2] - centre, "an inner curve has no tangent at the face centre"),
                 e2 = nc.cross(e1);
      for (std::size_t i = 0; i < n; ++i)
      {
        const double angle = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n);
        inner[i].X[2] = centre + (inner[i].X[2] - centre).norm() * (std::cos(angle) * e1 + std::sin(angle) * e2);
      }
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      inner[i].b1 = nc.cross(unit(inner[i].X[3] - inner[i].X[2], "an inner curve has no tangent at the face centre"));
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      const std::size_t prev = (i + n - 1) % n;
      // Corners: V_i, M_i, centre, M_{i-1}.
      s.patches.push_back(makePatch(firstHalf[i], inner[i], inner[prev], secondHalf[prev].reversed()));
      s.patchFace.push_back(static_cast<std::int64_t>(f));
      s.patchCorner.push_back(static_cast<int>(i));
    }
  }
  s.sectorOf = std::move(sectorOf);
  return s;
}

} // namespace lk
