#include "latticekit/HomogenizedLoop.h"

#include "latticekit/ManifoldRepair.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace lk
{
namespace
{
std::uint64_t key(std::int64_t a, std::int64_t b)
{
  if (a > b)
    std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
}

double loopBeta(int k)
{
  if (k == 3)
    return 3.0 / 16.0;
  const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * kPi / k);
  return (5.0 / 8.0 - c * c) / k;
}

void checkWeights(const std::vector<double>& w, std::size_t count, const char* what)
{
  if (w.empty())
    return;
  if (w.size() != count)
    throw std::invalid_argument(std::string("the ") + what + " weights must be one per " + what + " (" +
      std::to_string(count) + "), not " + std::to_string(w.size()));
  for (std::size_t i = 0; i < w.size(); ++i)
    if (!(std::isfinite(w[i]) && w[i] > 0.0))
      throw std::invalid_argument(std::string("the weight of ") + what + " " + std::to_string(i) + " is " +
        std::to_string(w[i]) + "; weights must be finite and above 0");
}
} // namespace

HomogenizedLoopOutput homogenizedLoop(
  const HomogenizedLoopInput& in, int levels, const std::function<bool(double)>& progress)
{
  if (levels < 0 || levels > 6)
    throw std::invalid_argument("the number of subdivisions must lie in 0..6 (each level has 4 times the triangles)");
  const std::string problem = cgalSurfaceMeshProblem(in.mesh);
  if (!problem.empty())
    throw std::invalid_argument(problem);
  const std::size_t n0 = in.mesh.points.size();
  checkWeights(in.vertexWeights, n0, "vertex");
  checkWeights(in.faceWeights, in.mesh.triangles.size(), "face");
  if (in.attributeComponents < 0 ||
    in.attributes.size() != n0 * static_cast<std::size_t>(in.attributeComponents))
    throw std::invalid_argument("the point attributes must hold the given components for every point");

  const std::size_t C = 3 + static_cast<std::size_t>(in.attributeComponents);
  const std::size_t S = C + 1; // stride: C weighted components, then w
  std::vector<double> H(n0 * S);
  for (std::size_t v = 0; v < n0; ++v)
  {
    const double w = in.vertexWeights.empty() ? 1.0 : in.vertexWeights[v];
    double* h = &H[v * S];
    for (int k = 0; k < 3; ++k)
      h[k] = w * in.mesh.points[v][k];
    for (std::size_t k = 3; k < C; ++k)
      h[k] = w * in.attributes[v * (C - 3) + (k - 3)];
    h[C] = w;
  }
  std::vector<Triangle> tris = in.mesh.triangles;
  std::vector<double> faceW = in.faceWeights.empty() ? std::vector<double>(tris.size(), 1.0) : in.faceWeights;
  std::vector<std::int64_t> parent(tris.size());
  for (std::size_t f = 0; f < tris.size(); ++f)
    parent[f] = static_cast<std::int64_t>(f);

  // Edge weights, sparse (only those != 1).
  std::unordered_map<std::uint64_t, double> edgeW;
  {
    std::unordered_map<std::uint64_t, int> edges;
    for (const Triangle& t : tris)
      for (int i = 0; i < 3; ++i)
        edges[key(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)])] = 1;
    for (const auto& [e, w] : in.edgeWeights)
    {
      if (!(std::isfinite(w) && w > 0.0))
        throw std::invalid_argument("the weight of edge (" + std::to_string(e.first) + ", " +
          std::to_string(e.second) + ") is " + std::to_string(w) + "; weights must be finite and above 0");
      if (e.first < 0 || e.second < 0 || !edges.count(key(e.first, e.second)))
        throw std::invalid_argument("(" + std::to_string(e.first) + ", " + std::to_string(e.second) +
          ") is not an edge of the mesh");
      if (w != 1.0)
        edgeW[key(e.first, e.second)] = w;
    }
  }

  for (int level = 0; level < levels; ++level)
  {
    const std::size_t n = H.size() / S, F = tris.size();
    if (n + 3 * F >= (std::size_t(1) << 32))
      throw std::invalid_argument("the subdivided mesh would have too many points");
    // Edges: sorted (key, face, local) records.
    struct Rec
    {
      std::uint64_t key;
      std::uint32_t face;
      std::uint8_t local;
    };
    std::vector<Rec> recs(3 * F);
    for (std::size_t f = 0; f < F; ++f)
      for (int i = 0; i < 3; ++i)
        recs[3 * f + static_cast<std::size_t>(i)] = { key(tris[f][static_cast<std::size_t>(i)],
                                                        tris[f][static_cast<std::size_t>((i + 1) % 3)]),
          static_cast<std::uint32_t>(f), static_cast<std::uint8_t>(i) };
    std::sort(recs.begin(), recs.end(),
      [](const Rec& a, const Rec& b) { return a.key != b.key ? a.key < b.key : a.face < b.face; });
    std::vector<std::uint32_t> faceEdge(3 * F);
    struct Edge
    {
      std::int64_t a, b;
      std::int64_t f[2];
      std::int64_t opp[2];
      double c;
    };
    std::vector<Edge> edges;
    edges.reserve(3 * F / 2 + 1);
    for (std::size_t i = 0; i < recs.size();)
    {
      std::size_t j = i;
      while (j < recs.size() && recs[j].key == recs[i].key)
        ++j;
      if (j - i > 2)
        throw std::invalid_argument("an edge has more than two faces (not a manifold)");
      Edge e;
      e.a = static_cast<std::int64_t>(recs[i].key >> 32);
      e.b = static_cast<std::int64_t>(recs[i].key & 0xffffffffu);
      e.f[1] = e.opp[1] = -1;
      for (std::size_t r = i; r < j; ++r)
      {
        const Triangle& t = tris[recs[r].face];
        e.f[r - i] = recs[r].face;
        e.opp[r - i] = t[static_cast<std::size_t>((recs[r].local + 2) % 3)];
        faceEdge[3 * recs[r].face + recs[r].local] = static_cast<std::uint32_t>(edges.size());
      }
      const auto it = edgeW.find(recs[i].key);
      e.c = it == edgeW.end() ? 1.0 : it->second;
      edges.push_back(e);
      i = j;
    }
    const std::size_t E = edges.size();
    std::vector<double> out((n + E) * S, 0.0);
    auto addScaled = [&](double* dst, std::size_t src, double s) {
      const double* h = &H[src * S];
      for (std::size_t k = 0; k < S; ++k)
        dst[k] += s * h[k];
    };
    // Edge points (eqs. 2.4, 4.1).
    std::vector<int> boundaryCount(n, 0);
    std::vector<std::int64_t> boundaryNb(2 * n, -1);
    std::vector<double> boundaryC(2 * n, 1.0);
    for (std::size_t e = 0; e < E; ++e)
    {
      const Edge& ed = edges[e];
      double* dst = &out[(n + e) * S];
      if (ed.f[1] < 0)
      {
        addScaled(dst, static_cast<std::size_t>(ed.a), 0.5 * ed.c);
        addScaled(dst, static_cast<std::size_t>(ed.b), 0.5 * ed.c);
        for (auto [v, o] : { std::pair(ed.a, ed.b), std::pair(ed.b, ed.a) })
        {
          const auto vi = static_cast<std::size_t>(v);
          if (boundaryCount[vi] >= 2)
            throw std::invalid_argument("a vertex has more than two boundary edges (not a manifold)");
          boundaryNb[2 * vi + static_cast<std::size_t>(boundaryCount[vi])] = o;
          boundaryC[2 * vi + static_cast<std::size_t>(boundaryCount[vi])] = ed.c;
          ++boundaryCount[vi];
        }
      }
      else
      {
        for (int s = 0; s < 2; ++s)
        {
          const double wf = faceW[static_cast<std::size_t>(ed.f[s])];
          addScaled(dst, static_cast<std::size_t>(ed.a), wf * ed.c * 3.0 / 16.0);
          addScaled(dst, static_cast<std::size_t>(ed.b), wf * ed.c * 3.0 / 16.0);
          addScaled(dst, static_cast<std::size_t>(ed.opp[s]), wf / 8.0);
        }
      }
    }
    // Vertex points (eqs. 2.1 to 2.3, 4.2), accumulated per face.
    std::vector<double> acc(n * S, 0.0), wsum(n, 0.0);
    std::vector<int> k(n, 0);
    for (std::size_t f = 0; f < F; ++f)
    {
      for (std::size_t i = 0; i < 3; ++i)
      {
        const auto v = static_cast<std::size_t>(tris[f][i]);
        const auto a = static_cast<std::size_t>(tris[f][(i + 1) % 3]);
        const auto b = static_cast<std::size_t>(tris[f][(i + 2) % 3]);
        const double cva = edges[faceEdge[3 * f + i]].c, cvb = edges[faceEdge[3 * f + (i + 2) % 3]].c;
        addScaled(&acc[v * S], a, faceW[f] * cva);
        addScaled(&acc[v * S], b, faceW[f] * cvb);
        wsum[v] += faceW[f];
        ++k[v];
      }
    }
    for (std::size_t v = 0; v < n; ++v)
    {
      double* dst = &out[v * S];
      if (boundaryCount[v] == 2)
      {
        addScaled(dst, v, 0.75);
        addScaled(dst, static_cast<std::size_t>(boundaryNb[2 * v]), boundaryC[2 * v] / 8.0);
        addScaled(dst, static_cast<std::size_t>(boundaryNb[2 * v + 1]), boundaryC[2 * v + 1] / 8.0);
      }
      else if (k[v] > 0)
      {
        const double beta = loopBeta(k[v]);
        addScaled(dst, v, (1.0 - k[v] * beta) * wsum[v] / k[v]);
        for (std::size_t c = 0; c < S; ++c)
          dst[c] += 0.5 * beta * acc[v * S + c];
      }
      else
        addScaled(dst, v, 1.0);
    }
    // Topology: four children per face, weights inherited.
    std::vector<Triangle> next(4 * F);
    std::vector<double> nextW(4 * F);
    std::vector<std::int64_t> nextParent(4 * F);
    for (std::size_t f = 0; f < F; ++f)
    {
      const auto a = tris[f][0], b = tris[f][1], c = tris[f][2];
      const auto ab = static_cast<std::int64_t>(n + faceEdge[3 * f]);
      const auto bc = static_cast<std::int64_t>(n + faceEdge[3 * f + 1]);
      const auto ca = static_cast<std::int64_t>(n + faceEdge[3 * f + 2]);
      next[4 * f] = { a, ab, ca };
      next[4 * f + 1] = { ab, b, bc };
      next[4 * f + 2] = { ca, bc, c };
      next[4 * f + 3] = { ab, bc, ca };
      for (int i = 0; i < 4; ++i)
      {
        nextW[4 * f + static_cast<std::size_t>(i)] = faceW[f];
        nextParent[4 * f + static_cast<std::size_t>(i)] = parent[f];
      }
    }
    std::unordered_map<std::uint64_t, double> nextEdgeW;
    for (std::size_t e = 0; e < E; ++e)
    {
      if (edges[e].c != 1.0)
      {
        const auto m = static_cast<std::int64_t>(n + e);
        nextEdgeW[key(edges[e].a, m)] = edges[e].c;
        nextEdgeW[key(m, edges[e].b)] = edges[e].c;
      }
    }
    H.swap(out);
    tris.swap(next);
    faceW.swap(nextW);
    parent.swap(nextParent);
    edgeW.swap(nextEdgeW);
    // Level k costs 4^k of the first level's work.
    if (progress && !progress((std::pow(4.0, level + 1) - 1.0) / (std::pow(4.0, levels) - 1.0)))
      return {};
  }

  HomogenizedLoopOutput result;
  const std::size_t n = H.size() / S;
  result.mesh.points.resize(n);
  result.weights.resize(n);
  result.attributes.resize(n * (C - 3));
  for (std::size_t v = 0; v < n; ++v)
  {
    const double* h = &H[v * S];
    const double w = h[C];
    result.mesh.points[v] = Vec3(h[0] / w, h[1] / w, h[2] / w);
    result.weights[v] = w;
    for (std::size_t k = 3; k < C; ++k)
      result.attributes[v * (C - 3) + (k - 3)] = h[k] / w;
  }
  result.mesh.triangles = std::move(tris);
  result.parentFace = std::move(parent);
  return result;
}

} // namespace lk
