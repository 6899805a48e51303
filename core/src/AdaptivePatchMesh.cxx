#include "latticekit/AdaptivePatchMesh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lk
{

AdaptivePatchMesh::Key AdaptivePatchMesh::key(int a, int b)
{
  if (a > b)
    std::swap(a, b);
  return (static_cast<Key>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

AdaptivePatchMesh::AdaptivePatchMesh(const TriangleMesh& mesh, int maxLevel)
  : maxLevel_(maxLevel)
{
  if (maxLevel < 0 || maxLevel > 12)
    throw std::invalid_argument("the refinement depth must be 0 to 12, not " + std::to_string(maxLevel));
  if (mesh.triangles.empty())
    throw std::invalid_argument("the mesh has no triangles");
  const int np = static_cast<int>(mesh.points.size());
  for (const Vec3& p : mesh.points)
    if (!p.allFinite())
      throw std::invalid_argument("the mesh has a point that is not finite (NaN or infinite)");
  base_ = mesh.points;
  inputVertexCount_ = mesh.points.size();
  normal_.assign(np, Vec3::Zero());
  displacement_.assign(np, Vec3::Zero());
  tris_.reserve(mesh.triangles.size() * 2);
  edgeTris_.reserve(mesh.triangles.size() * 4);
  midpoints_.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
  {
    const auto& tri = mesh.triangles[t];
    for (int c = 0; c < 3; ++c)
      if (tri[c] < 0 || tri[c] >= np)
        throw std::invalid_argument("triangle " + std::to_string(t) + " names a point that does not exist");
    const Vec3 n = (base_[tri[1]] - base_[tri[0]]).cross(base_[tri[2]] - base_[tri[0]]);
    if (!(n.norm() > 0.0))
      throw std::invalid_argument("triangle " + std::to_string(t) + " has zero area");
    for (int c = 0; c < 3; ++c)
      normal_[tri[c]] += n;
    Tri node;
    node.v = { { static_cast<int>(tri[0]), static_cast<int>(tri[1]), static_cast<int>(tri[2]) } }; // < np, checked above
    tris_.push_back(node);
    addEdges(static_cast<int>(t));
  }
  leafCount_ = tris_.size();
  for (int v = 0; v < np; ++v)
    if (normal_[v].norm() > 0.0)
      normal_[v].normalize();
}

void AdaptivePatchMesh::addEdges(int t)
{
  const auto& v = tris_[t].v;
  for (int e = 0; e < 3; ++e)
  {
    auto [it, fresh] = edgeTris_.emplace(key(v[e], v[(e + 1) % 3]), std::array<int, 2>{ { t, -1 } });
    if (!fresh)
    {
      if (it->second[1] >= 0)
        throw std::invalid_argument("the mesh is not manifold: edge (" + std::to_string(v[e]) + ", " +
          std::to_string(v[(e + 1) % 3]) + ") has more than two triangles");
      it->second[1] = t;
    }
  }
}

int AdaptivePatchMesh::midpoint(int a, int b) const
{
  const auto it = midpoints_.find(key(a, b));
  return it == midpoints_.end() ? -1 : it->second;
}

int AdaptivePatchMesh::makeMidpoint(int a, int b)
{
  const int existing = midpoint(a, b);
  if (existing >= 0)
    return existing;
  const int m = static_cast<int>(base_.size());
  base_.push_back(0.5 * (base_[a] + base_[b]));
  Vec3 n = normal_[a] + normal_[b];
  normal_.push_back(n.norm() > 0.0 ? n.normalized() : normal_[a]);
  displacement_.push_back(0.5 * (displacement_[a] + displacement_[b]));
  midpointEnds_.push_back({ { a, b } });
  midpoints_.emplace(key(a, b), m);
  // Record it in the triangles on the edge (no hashing when drawing).
  const auto it = edgeTris_.find(key(a, b));
  if (it != edgeTris_.end())
    for (int t : it->second)
      if (t >= 0)
        for (int e = 0; e < 3; ++e)
          if (key(tris_[t].v[e], tris_[t].v[(e + 1) % 3]) == key(a, b))
            tris_[t].mid[e] = m;
  return m;
}

int AdaptivePatchMesh::neighbour(int t, int a, int b) const
{
  const auto it = edgeTris_.find(key(a, b));
  if (it == edgeTris_.end())
    return -1;
  return it->second[0] == t ? it->second[1] : it->second[0];
}

int AdaptivePatchMesh::hanging(int t) const
{
  const auto& mid = tris_[t].mid;
  return (mid[0] >= 0 ? 1 : 0) + (mid[1] >= 0 ? 1 : 0) + (mid[2] >= 0 ? 1 : 0);
}

bool AdaptivePatchMesh::split(int t)
{
  if (t < 0 || t >= static_cast<int>(tris_.size()))
    return false;
  return splitNow(t);
}

bool AdaptivePatchMesh::splitNow(int t)
{
  if (tris_[t].firstChild >= 0 || tris_[t].level >= maxLevel_)
    return false;
  // A coarser neighbour across one of our edges is split first, so that our
  // midpoints never fall inside its longer edge.
  if (tris_[t].parent >= 0)
  {
    const auto v = tris_[t].v;
    const int parentId = tris_[t].parent;
    const auto parentV = tris_[parentId].v; // copies: splitting below grows tris_
    for (int e = 0; e < 3; ++e)
    {
      const int a = v[e], b = v[(e + 1) % 3];
      if (neighbour(t, a, b) >= 0)
        continue;
      for (int pe = 0; pe < 3; ++pe)
      {
        const int x = parentV[pe], y = parentV[(pe + 1) % 3];
        const int m = midpoint(x, y);
        const Key k = key(a, b);
        if (m >= 0 && (k == key(x, m) || k == key(m, y)))
        {
          const int coarse = neighbour(parentId, x, y);
          if (coarse >= 0)
            splitNow(coarse);
        }
      }
    }
  }
  if (tris_[t].firstChild >= 0)
    return false;
  const auto v = tris_[t].v;
  const int mab = makeMidpoint(v[0], v[1]);
  const int mbc = makeMidpoint(v[1], v[2]);
  const int mca = makeMidpoint(v[2], v[0]);
  const int first = static_cast<int>(tris_.size());
  const std::array<std::array<int, 3>, 4> children{ { { { v[0], mab, mca } }, { { mab, v[1], mbc } },
    { { mca, mbc, v[2] } }, { { mab, mbc, mca } } } };
  for (const auto& c : children)
  {
    Tri node;
    node.v = c;
    node.parent = t;
    node.level = tris_[t].level + 1;
    for (int e = 0; e < 3; ++e) // normally none exist yet; kept exact regardless
      node.mid[e] = midpoint(c[e], c[(e + 1) % 3]);
    tris_.push_back(node);
    addEdges(static_cast<int>(tris_.size()) - 1);
  }
  tris_[t].firstChild = first;
  leafCount_ += 3;
  ++splits_;
  // Neighbours with two hanging midpoints are split too (figure 2 e, f).
  for (int e = 0; e < 3; ++e)
  {
    const int n = neighbour(t, v[e], v[(e + 1) % 3]);
    if (n >= 0 && tris_[n].firstChild < 0 && hanging(n) >= 2)
      splitNow(n);
  }
  return true;
}

std::vector<int> AdaptivePatchMesh::leaves() const
{
  std::vector<int> out;
  out.reserve(leafCount_);
  for (int t = 0; t < static_cast<int>(tris_.size()); ++t)
    if (tris_[t].firstChild < 0)
      out.push_back(t);
  return out;
}

std::vector<std::array<int, 3>> AdaptivePatchMesh::triangles() const
{
  std::vector<std::array<int, 3>> out;
  out.reserve(leafCount_ + leafCount_ / 4);
  for (const Tri& t : tris_)
  {
    if (t.firstChild >= 0)
      continue;
    int e = 0, m = -1;
    for (; e < 3; ++e)
      if ((m = t.mid[e]) >= 0)
        break;
    if (m < 0)
    {
      out.push_back(t.v);
      continue;
    }
    // Transition triangle: two triangles through the hanging midpoint.
    const int a = t.v[e], b = t.v[(e + 1) % 3], c = t.v[(e + 2) % 3];
    out.push_back({ { a, m, c } });
    out.push_back({ { m, b, c } });
  }
  return out;
}

std::vector<int> AdaptivePatchMesh::triangleLevels() const
{
  std::vector<int> out;
  out.reserve(leafCount_ + leafCount_ / 4);
  for (const Tri& t : tris_)
  {
    if (t.firstChild >= 0)
      continue;
    out.push_back(t.level);
    if (t.mid[0] >= 0 || t.mid[1] >= 0 || t.mid[2] >= 0) // a transition triangle is output twice
      out.push_back(t.level);
  }
  return out;
}

std::vector<int> AdaptivePatchMesh::triangleOrigins() const
{
  std::vector<int> out;
  out.reserve(leafCount_ + leafCount_ / 4);
  for (int t = 0; t < static_cast<int>(tris_.size()); ++t)
  {
    const Tri& tri = tris_[t];
    if (tri.firstChild >= 0)
      continue;
    int root = t;
    while (tris_[root].parent >= 0)
      root = tris_[root].parent;
    out.push_back(root);
    if (tri.mid[0] >= 0 || tri.mid[1] >= 0 || tri.mid[2] >= 0) // a transition triangle is output twice
      out.push_back(root);
  }
  return out;
}

std::array<int, 2> AdaptivePatchMesh::midpointEnds(int v) const
{
  if (v < static_cast<int>(inputVertexCount_))
    return { { -1, -1 } };
  return midpointEnds_[static_cast<std::size_t>(v) - inputVertexCount_];
}

std::vector<int> AdaptivePatchMesh::leavesNear(const Vec3& lo, const Vec3& hi) const
{
  std::vector<int> out;
  for (int t = 0; t < static_cast<int>(tris_.size()); ++t)
  {
    const Tri& tri = tris_[t];
    if (tri.firstChild >= 0)
      continue;
    const Vec3 p0 = position(tri.v[0]), p1 = position(tri.v[1]), p2 = position(tri.v[2]);
    const Vec3 a = p0.cwiseMin(p1).cwiseMin(p2), b = p0.cwiseMax(p1).cwiseMax(p2);
    if ((a.array() <= hi.array()).all() && (b.array() >= lo.array()).all())
      out.push_back(t);
  }
  return out;
}

void AdaptivePatchMesh::refine(std::vector<int> stack, const std::function<bool(int)>& needsSplit)
{
  while (!stack.empty())
  {
    const int t = stack.back();
    stack.pop_back();
    if (tris_[t].firstChild >= 0)
    {
      for (int c = 0; c < 4; ++c)
        stack.push_back(tris_[t].firstChild + c);
      continue;
    }
    if (tris_[t].level >= maxLevel_ || !needsSplit(t))
      continue;
    const std::size_t before = tris_.size();
    splitNow(t);
    // Children of t, and of anything the conformity rules split with it.
    for (std::size_t c = before; c < tris_.size(); ++c)
      stack.push_back(static_cast<int>(c));
  }
}

int AdaptivePatchMesh::functionalDeformation(const Vec3& c, double k, double a, double D, double tolerance)
{
  if (!c.allFinite() || !std::isfinite(k) || !(a >= 0.0) || !std::isfinite(a) || !(D > 0.0) || !std::isfinite(D))
    throw std::invalid_argument("functional deformation needs a finite centre and k, a >= 0 and D > 0");
  auto f = [&](const Vec3& p) {
    const double d2 = (p - c).squaredNorm();
    return d2 <= D * D ? k * std::exp(-a * d2) : 0.0;
  };
  if (tolerance > 0.0)
  {
    const Vec3 r = Vec3::Constant(D);
    refine(leavesNear(c - r, c + r), [&](int t) {
      const auto& v = tris_[t].v;
      const Vec3 p[3] = { position(v[0]), position(v[1]), position(v[2]) };
      const double fv[3] = { f(p[0]), f(p[1]), f(p[2]) };
      for (int e = 0; e < 3; ++e)
      {
        const int e2 = (e + 1) % 3;
        if (std::abs(f(0.5 * (p[e] + p[e2])) - 0.5 * (fv[e] + fv[e2])) > tolerance)
          return true;
      }
      return std::abs(f((p[0] + p[1] + p[2]) / 3.0) - (fv[0] + fv[1] + fv[2]) / 3.0) > tolerance;
    });
  }
  // Displacements from positions before any vertex moves.
  std::vector<std::pair<int, double>> moves;
  for (int v = 0; v < static_cast<int>(base_.size()); ++v)
  {
    const double d2 = (position(v) - c).squaredNorm();
    if (d2 <= D * D)
      moves.emplace_back(v, k * std::exp(-a * d2));
  }
  for (const auto& [v, amount] : moves)
    displacement_[v] += amount * normal_[v];
  return static_cast<int>(moves.size());
}

int AdaptivePatchMesh::rangeDeformation(const Vec3& lo, const Vec3& hi, const Vec3& move, bool refineBorder)
{
  if (!lo.allFinite() || !hi.allFinite() || !move.allFinite() || (lo.array() > hi.array()).any())
    throw std::invalid_argument("range deformation needs a finite box (min <= max) and a finite vector");
  auto inside = [&](int v) {
    const Vec3 p = position(v);
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  };
  if (refineBorder)
    refine(leavesNear(lo, hi), [&](int t) {
      const auto& v = tris_[t].v;
      const int n = (inside(v[0]) ? 1 : 0) + (inside(v[1]) ? 1 : 0) + (inside(v[2]) ? 1 : 0);
      return n == 1 || n == 2;
    });
  std::vector<int> moving;
  for (int v = 0; v < static_cast<int>(base_.size()); ++v)
    if (inside(v))
      moving.push_back(v);
  for (int v : moving)
    displacement_[v] += move;
  return static_cast<int>(moving.size());
}

int AdaptivePatchMesh::smoothingDeformation(const Vec3& c, double D, int iterations, double selfWeight)
{
  // More iterations than kMaximumSmoothingIterations only ran on (2^31 - 1
  // would take about 18 minutes on 81 vertices) towards the ball's harmonic fill.
  if (!c.allFinite() || !(D > 0.0) || !std::isfinite(D) || iterations < 0 || iterations > kMaximumSmoothingIterations ||
    !(selfWeight >= 0.0) || !std::isfinite(selfWeight))
    throw std::invalid_argument("smoothing needs a finite centre, D > 0, iterations from 0 to " +
      std::to_string(kMaximumSmoothingIterations) + " (not " + std::to_string(iterations) +
      ") and a finite selfWeight >= 0");
  const auto tris = triangles();
  std::vector<std::vector<int>> ring(base_.size());
  std::vector<char> region(base_.size(), 0);
  int count = 0;
  for (int v = 0; v < static_cast<int>(base_.size()); ++v)
    if ((position(v) - c).squaredNorm() <= D * D)
    {
      region[v] = 1;
      ++count;
    }
  for (const auto& t : tris)
    for (int e = 0; e < 3; ++e)
    {
      const int a = t[e], b = t[(e + 1) % 3];
      if (region[a])
        ring[a].push_back(b);
      if (region[b])
        ring[b].push_back(a);
    }
  for (int it = 0; it < iterations; ++it)
  {
    std::vector<Vec3> next = displacement_;
    for (int v = 0; v < static_cast<int>(base_.size()); ++v)
    {
      if (!region[v] || ring[v].empty())
        continue;
      auto& r = ring[v];
      std::sort(r.begin(), r.end());
      r.erase(std::unique(r.begin(), r.end()), r.end());
      Vec3 sum = selfWeight * displacement_[v];
      for (int j : r)
        sum += displacement_[j];
      next[v] = sum / (selfWeight + static_cast<double>(r.size()));
    }
    displacement_.swap(next);
  }
  return count;
}

} // namespace lk
