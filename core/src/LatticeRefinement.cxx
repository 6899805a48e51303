#include "latticekit/LatticeRefinement.h"

#include "latticekit/LatticeSurface.h"
#include "latticekit/ClosestPointTree.h"
#include "latticekit/LatticeSimplification.h"

#include <ceres/ceres.h>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

namespace lk
{
namespace
{
/// An affine combination of lattice vertices.
using Combo = std::vector<std::pair<std::int64_t, double>>;

Vec3 evaluate(const Combo& c, const std::vector<Vec3>& x)
{
  Vec3 p = Vec3::Zero();
  for (const auto& [v, w] : c)
    p += w * x[static_cast<std::size_t>(v)];
  return p;
}

/// The points of the lattice surface that are (nearly) affine in the control
/// points: V' per vertex, the edge-curve midpoint per edge, the centre per face.
struct Anchors
{
  std::vector<Combo> vertex;
  std::map<std::pair<std::int64_t, std::int64_t>, Combo> edge; ///< by ordered pair
  std::vector<Combo> face;
};

/// Doo-Sabin point of corner i of face f.
Combo dooSabin(const std::vector<std::int64_t>& face, std::size_t i)
{
  const std::size_t n = face.size();
  Combo c;
  for (std::size_t j = 0; j < n; ++j)
  {
    const std::size_t k = (j + n - i) % n;
    const double a = k == 0 ? (n + 5.0) / (4.0 * n) : (3.0 + 2.0 * std::cos(2.0 * kPi * k / n)) / (4.0 * n);
    c.emplace_back(face[j], a);
  }
  return c;
}

void add(Combo& to, const Combo& c, double s)
{
  for (const auto& [v, w] : c)
    to.emplace_back(v, s * w);
}

/// The anchors follow the lattice surface's rules (LatticeSurface.h): a
/// crease is an edge of weight 0 or a border edge; a vertex on two creases
/// has V' = (p + 4 V + q) / 6 along the crease polygon, on three or more
/// V' = V; a vertex weight w moves V' to V + w (V'_1 - V), still affine. A
/// crease edge's midpoint is its cubic's, affine unless an end is a dart
/// (the tangent is projected there; no anchor). Smooth edges' midpoints are
/// (Q + R) / 2; their weights in (0, 1) are not modelled.
Anchors buildAnchors(const PolygonMesh& m, const LatticeWeights& weights)
{
  using Key = std::pair<std::int64_t, std::int64_t>;
  const std::size_t nv = m.points.size();
  Anchors a;
  a.vertex.assign(nv, {});
  std::vector<double> areaSum(nv, 0.0);
  std::vector<Combo> weighted(nv);
  // Directed edge -> (face, corner index of its start).
  std::map<Key, std::pair<std::size_t, std::size_t>> half;
  for (std::size_t f = 0; f < m.faces.size(); ++f)
  {
    const auto& face = m.faces[f];
    const double area = 0.5 * newellVector(m, f).norm();
    Combo centre;
    for (std::size_t i = 0; i < face.size(); ++i)
    {
      const auto v = static_cast<std::size_t>(face[i]);
      add(weighted[v], dooSabin(face, i), area);
      areaSum[v] += area;
      half[{ face[i], face[(i + 1) % face.size()] }] = { f, i };
      centre.emplace_back(face[i], 1.0 / static_cast<double>(face.size()));
    }
    a.face.push_back(centre);
  }
  auto isCrease = [&](const Key& e) {
    return !half.count({ e.second, e.first }) || weights.edgeWeight(e.first, e.second) == 0.0;
  };
  // Each vertex's crease neighbours, every undirected crease once.
  std::vector<std::vector<std::int64_t>> creaseNeighbours(nv);
  for (const auto& [e, fi] : half)
  {
    const bool border = !half.count({ e.second, e.first });
    if (isCrease(e) && (border || e.first < e.second))
    {
      creaseNeighbours[static_cast<std::size_t>(e.first)].push_back(e.second);
      creaseNeighbours[static_cast<std::size_t>(e.second)].push_back(e.first);
    }
  }
  for (std::size_t v = 0; v < nv; ++v)
  {
    const auto& cn = creaseNeighbours[v];
    const auto vi = static_cast<std::int64_t>(v);
    if (cn.size() >= 3)
    {
      a.vertex[v] = { { vi, 1.0 } };
      continue;
    }
    if (cn.size() == 2)
      a.vertex[v] = { { cn[0], 1.0 / 6.0 }, { vi, 4.0 / 6.0 }, { cn[1], 1.0 / 6.0 } };
    else if (areaSum[v] > 0.0)
    {
      for (auto& [u, w] : weighted[v])
        a.vertex[v].emplace_back(u, w / areaSum[v]);
    }
    const double w = weights.vertex.empty() ? 1.0 : weights.vertex[v];
    if (w != 1.0 && !a.vertex[v].empty())
    {
      for (auto& uw : a.vertex[v])
        uw.second *= w;
      a.vertex[v].emplace_back(vi, 1.0 - w);
    }
  }
  // A crease curve's inner point leaves its end along the crease polygon's
  // B-spline tangent (two creases) or the lattice edge (a corner).
  auto creaseTangent = [&](std::int64_t from, std::int64_t to, Combo& c, double s) {
    const auto& cn = creaseNeighbours[static_cast<std::size_t>(from)];
    if (cn.size() == 2)
    {
      c.emplace_back(to, s / 6.0);
      c.emplace_back(cn[0] == to ? cn[1] : cn[0], -s / 6.0);
    }
    else
    {
      c.emplace_back(to, s / 3.0);
      c.emplace_back(from, -s / 3.0);
    }
  };
  for (const auto& [e, fi] : half)
  {
    const auto back = half.find({ e.second, e.first });
    Combo c;
    if (isCrease(e))
    {
      // The cubic's midpoint (P0 + 3 P1 + 3 P2 + P3) / 8 with P1 = P0 + t0,
      // P2 = P3 + t3: (V'_a + V'_b) / 2 + 3 (t0 + t3) / 8.
      if (creaseNeighbours[static_cast<std::size_t>(e.first)].size() < 2 ||
        creaseNeighbours[static_cast<std::size_t>(e.second)].size() < 2)
        continue;
      add(c, a.vertex[static_cast<std::size_t>(e.first)], 0.5);
      add(c, a.vertex[static_cast<std::size_t>(e.second)], 0.5);
      creaseTangent(e.first, e.second, c, 3.0 / 8.0);
      creaseTangent(e.second, e.first, c, 3.0 / 8.0);
    }
    else
    {
      // (Q + R) / 2: the mean of the four Doo-Sabin points beside the edge.
      for (const auto& side : { fi, back->second })
      {
        const auto& face = m.faces[side.first];
        const std::size_t n = face.size();
        add(c, dooSabin(face, side.second), 0.25);
        add(c, dooSabin(face, (side.second + 1) % n), 0.25);
      }
    }
    a.edge[e] = c;
  }
  return a;
}

/// Quadratic Lagrange basis on nodes 0, 1/2, 1.
double lagrange(int node, double t)
{
  switch (node)
  {
    case 0:
      return 2.0 * (t - 0.5) * (t - 1.0);
    case 1:
      return 4.0 * t * (1.0 - t);
    default:
      return 2.0 * t * (t - 0.5);
  }
}

/// Every patch's nodes and the anchor combination each node follows.
struct PatchModel
{
  bool quad = false;
  std::array<const Combo*, 9> node{}; ///< quad: 3x3 at (a/2, b/2), index 3a+b; split: corners 0..3
};

std::vector<PatchModel> buildPatchModels(
  const PolygonMesh& m, const LatticeSurface& s, const Anchors& anchors)
{
  std::vector<PatchModel> out(s.patches.size());
  for (std::size_t p = 0; p < s.patches.size(); ++p)
  {
    const auto f = static_cast<std::size_t>(s.patchFace[p]);
    const auto& face = m.faces[f];
    std::vector<const Combo*> candidates;
    for (std::size_t i = 0; i < face.size(); ++i)
    {
      candidates.push_back(&anchors.vertex[static_cast<std::size_t>(face[i])]);
      const auto it = anchors.edge.find({ face[i], face[(i + 1) % face.size()] });
      if (it != anchors.edge.end())
        candidates.push_back(&it->second);
    }
    candidates.push_back(&anchors.face[f]);
    auto nearest = [&](const Vec3& x) {
      const Combo* best = nullptr;
      double bd = 0.0;
      for (const Combo* c : candidates)
      {
        if (c->empty())
          continue;
        const double d = (evaluate(*c, m.points) - x).squaredNorm();
        if (!best || d < bd)
        {
          best = c;
          bd = d;
        }
      }
      return best;
    };
    PatchModel& pm = out[p];
    pm.quad = !isSplitPatch(s, p);
    if (pm.quad)
    {
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          pm.node[static_cast<std::size_t>(3 * a + b)] = nearest(s.patches[p].evaluate(a / 2.0, b / 2.0));
    }
    else
    {
      const double corner[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
      for (int k = 0; k < 4; ++k)
        pm.node[static_cast<std::size_t>(k)] = nearest(s.patches[p].evaluate(corner[k][0], corner[k][1]));
    }
  }
  return out;
}

/// The sample's point as a combination of lattice vertices (merged by vertex).
Combo sampleCombo(const PatchModel& pm, double u, double v)
{
  std::map<std::int64_t, double> acc;
  auto take = [&](const Combo* c, double w) {
    if (!c || w == 0.0)
      return;
    for (const auto& [vi, cw] : *c)
      acc[vi] += w * cw;
  };
  if (pm.quad)
  {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        take(pm.node[static_cast<std::size_t>(3 * a + b)], lagrange(a, u) * lagrange(b, v));
  }
  else
  {
    take(pm.node[0], (1 - u) * (1 - v));
    take(pm.node[1], u * (1 - v));
    take(pm.node[2], u * v);
    take(pm.node[3], (1 - u) * v);
  }
  return { acc.begin(), acc.end() };
}

/// The worker threads for a requested count (0: every hardware thread).
unsigned workerThreads(int requested)
{
  return requested > 0 ? static_cast<unsigned>(requested) : std::max(1u, std::thread::hardware_concurrency());
}

/// work(begin, end) over [0, count) in one chunk per thread (at most 8).
template <class Work>
void inChunks(std::size_t count, int requestedThreads, const Work& work)
{
  const std::size_t threads = std::min(8u, workerThreads(requestedThreads));
  std::vector<std::thread> pool;
  const std::size_t chunk = (count + threads - 1) / threads;
  for (std::size_t t = 0; t < threads; ++t)
    pool.emplace_back(work, std::min(count, t * chunk), std::min(count, (t + 1) * chunk));
  for (auto& th : pool)
    th.join();
}

struct Foot
{
  std::size_t patch;
  double u, v;
  Vec3 point, normal;
  double distance;
};

/// Foot points: the closest point on a tessellation (CGAL AABB tree), its
/// (u, v) by barycentric interpolation, then Gauss-Newton steps on that patch
/// (clamped to the parameter square). Cheaper than LatticeSurfaceLocator's
/// exhaustive search, and enough for samples that lie close to the surface.
/// `previous`: the samples' foot points on a surface of the same lattice
/// before a step; each one's tessellation triangle starts its own search,
/// which bounds it nearly at the answer (half the search time on the
/// mandible; the answer is the same up to ties between triangles).
std::vector<Foot> footPoints(const LatticeSurface& s, const std::vector<Vec3>& samples, int resolution, int threads,
  const std::vector<Foot>* previous = nullptr)
{
  const int r = std::max(2, resolution);
  TriangleMesh tess;
  std::vector<std::array<double, 2>> uv;
  std::vector<std::size_t> patchOf;
  for (std::size_t p = 0; p < s.patches.size(); ++p)
  {
    const auto base = static_cast<std::int64_t>(tess.points.size());
    for (int i = 0; i <= r; ++i)
      for (int j = 0; j <= r; ++j)
      {
        tess.points.push_back(s.patches[p].evaluate(double(i) / r, double(j) / r));
        uv.push_back({ double(i) / r, double(j) / r });
      }
    auto id = [&](int i, int j) { return base + i * (r + 1) + j; };
    for (int i = 0; i < r; ++i)
      for (int j = 0; j < r; ++j)
      {
        tess.triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
        tess.triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
        patchOf.push_back(p);
        patchOf.push_back(p);
      }
  }
  const ClosestPointTree tree(tess);
  const bool usePrevious = previous && previous->size() == samples.size() &&
    std::all_of(previous->begin(), previous->end(), [&](const Foot& f) { return f.patch < s.patches.size(); });
  std::vector<Foot> out(samples.size());
  auto work = [&](std::size_t begin, std::size_t end) {
    ClosestPointTree::Hit hint;
    bool haveHint = false;
    for (std::size_t i = begin; i < end; ++i)
    {
      const Vec3& q = samples[i];
      if (usePrevious)
      {
        // The triangle of cell (ci, cj) that holds the previous (u, v):
        // the first of the pair below its diagonal, the second above.
        const Foot& f = (*previous)[i];
        const double fu = f.u * r, fv = f.v * r;
        const int ci = std::clamp(static_cast<int>(fu), 0, r - 1), cj = std::clamp(static_cast<int>(fv), 0, r - 1);
        const std::size_t cell = f.patch * static_cast<std::size_t>(r * r) + static_cast<std::size_t>(ci * r + cj);
        hint.face = static_cast<std::int64_t>(2 * cell + (fu - ci >= fv - cj ? 0 : 1));
        haveHint = true;
      }
      hint = haveHint ? tree.closest(q, hint) : tree.closest(q);
      haveHint = true;
      const Triangle& t = tess.triangles[static_cast<std::size_t>(hint.face)];
      const Vec3 a = tess.points[static_cast<std::size_t>(t[0])], b = tess.points[static_cast<std::size_t>(t[1])],
                 c = tess.points[static_cast<std::size_t>(t[2])];
      // Barycentric coordinates of the hit.
      const Vec3 v0 = b - a, v1 = c - a, v2 = hint.point - a;
      const double d00 = v0.dot(v0), d01 = v0.dot(v1), d11 = v1.dot(v1), d20 = v2.dot(v0), d21 = v2.dot(v1);
      const double den = d00 * d11 - d01 * d01;
      const double bb = den > 0 ? (d11 * d20 - d01 * d21) / den : 0.0, bc = den > 0 ? (d00 * d21 - d01 * d20) / den : 0.0;
      const double ba = 1.0 - bb - bc;
      double u = 0.0, v = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        const double w = k == 0 ? ba : (k == 1 ? bb : bc);
        u += w * uv[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])][0];
        v += w * uv[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])][1];
      }
      const std::size_t p = patchOf[static_cast<std::size_t>(hint.face)];
      const GregoryPatch& patch = s.patches[p];
      Vec3 du, dv;
      Vec3 x = patch.evaluate(u, v, &du, &dv);
      for (int it = 0; it < 4; ++it)
      {
        const Vec3 e = q - x;
        Eigen::Matrix2d J;
        J << du.dot(du), du.dot(dv), du.dot(dv), dv.dot(dv);
        const Eigen::Vector2d g(du.dot(e), dv.dot(e));
        const double det = J.determinant();
        if (!(std::abs(det) > 1e-30))
          break;
        const Eigen::Vector2d step = J.inverse() * g;
        const double nu = std::clamp(u + step[0], 0.0, 1.0), nv = std::clamp(v + step[1], 0.0, 1.0);
        Vec3 ndu, ndv;
        const Vec3 nx = patch.evaluate(nu, nv, &ndu, &ndv);
        if ((q - nx).squaredNorm() >= e.squaredNorm())
          break;
        u = nu;
        v = nv;
        x = nx;
        du = ndu;
        dv = ndv;
      }
      out[i] = { p, u, v, x, patch.normalFrom(du, dv, u, v), (q - x).norm() };
    }
  };
  inChunks(samples.size(), threads, work);
  return out;
}

/// Sum of squared distances (feet or reverse points).
template <class T>
double energy(const std::vector<T>& points)
{
  double e = 0.0;
  for (const T& p : points)
    e += p.distance * p.distance;
  return e;
}

/// Sum of squared excesses max(0, d - tau)^2 (the tail penalty, unweighted).
template <class T>
double tailEnergy(const std::vector<T>& points, double tau)
{
  double e = 0.0;
  for (const T& p : points)
    if (p.distance > tau)
      e += (p.distance - tau) * (p.distance - tau);
  return e;
}

/// A fixed parameter point of the surface and its closest point on the
/// original mesh (the reverse direction of Metro).
struct ReversePoint
{
  std::size_t patch;
  double u, v;
  Vec3 point, closest, normal; ///< normal of the original's triangle at the closest point
  double distance;
};

std::vector<ReversePoint> reversePoints(
  const LatticeSurface& s, const TriangleMesh& original, const ClosestPointTree& tree, int threads)
{
  const double at[3] = { 1.0 / 6.0, 0.5, 5.0 / 6.0 };
  std::vector<ReversePoint> out(9 * s.patches.size());
  auto work = [&](std::size_t begin, std::size_t end) {
    ClosestPointTree::Hit hint;
    bool haveHint = false;
    for (std::size_t p = begin; p < end; ++p)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
        {
          ReversePoint& r = out[9 * p + static_cast<std::size_t>(3 * i + j)];
          r.patch = p;
          r.u = at[i];
          r.v = at[j];
          r.point = s.patches[p].evaluate(r.u, r.v);
          hint = haveHint ? tree.closest(r.point, hint) : tree.closest(r.point);
          haveHint = true;
          const Triangle& t = original.triangles[static_cast<std::size_t>(hint.face)];
          const Vec3& a = original.points[static_cast<std::size_t>(t[0])];
          const Vec3 n = (original.points[static_cast<std::size_t>(t[1])] - a)
                           .cross(original.points[static_cast<std::size_t>(t[2])] - a);
          r.closest = hint.point;
          r.normal = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3(0, 0, 1);
          r.distance = hint.distance;
        }
  };
  inChunks(s.patches.size(), threads, work);
  return out;
}

/// One distance of the energy, linearised: e = S - p is the surface point
/// minus its partner (sample, or the original's closest point), n the normal
/// at the point measured against, combo the surface point as lattice
/// vertices, scale the square root of the distance's weight. Point-to-plane
/// where e is along n: one residual scale n . (S + J dX - p). Point-to-point
/// where it is not (a foot point on a border with the partner beyond it: the
/// plane would not see the border's shrinkage): three, scale (S + J dX - p).
struct Term
{
  const Combo* combo;
  Vec3 e, n;
  double scale;

  bool point() const { return e.norm() > 1e-12 && std::abs(n.dot(e)) < 0.866 * e.norm(); }
};

/// The terms of one face's patches, compressed: sum_t |r_t + J_t dX|^2 =
/// |c + R dX|^2 + const, [R c] the triangular factor of the QR decomposition
/// of the stacked rows [J_t r_t] over the face's vertices. Exact for the
/// linear step; Ceres then forms its normal equations from one block per
/// face instead of one per sample (ten times faster on the mandible).
struct FaceBlock
{
  std::vector<std::int64_t> vertices; ///< the parameter blocks, in column order
  Eigen::MatrixXd rc;                 ///< rows x (3 vertices + 1): R, then c
};

std::vector<FaceBlock> compress(const std::vector<std::vector<Term>>& termsOfFace, int threads)
{
  std::vector<FaceBlock> out(termsOfFace.size());
  inChunks(termsOfFace.size(), threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f)
    {
      const auto& terms = termsOfFace[f];
      FaceBlock& fb = out[f];
      Eigen::Index rows = 0;
      for (const Term& t : terms)
      {
        for (const auto& vw : *t.combo)
          fb.vertices.push_back(vw.first);
        rows += t.point() ? 3 : 1;
      }
      std::sort(fb.vertices.begin(), fb.vertices.end());
      fb.vertices.erase(std::unique(fb.vertices.begin(), fb.vertices.end()), fb.vertices.end());
      if (rows == 0 || fb.vertices.empty())
        continue;
      const auto cols = static_cast<Eigen::Index>(3 * fb.vertices.size());
      Eigen::MatrixXd a = Eigen::MatrixXd::Zero(rows, cols + 1);
      Eigen::Index row = 0;
      for (const Term& t : terms)
      {
        const bool point = t.point();
        for (const auto& [v, w] : *t.combo)
        {
          const auto j = 3 * static_cast<Eigen::Index>(
            std::lower_bound(fb.vertices.begin(), fb.vertices.end(), v) - fb.vertices.begin());
          for (int k = 0; k < 3; ++k)
          {
            if (point)
              a(row + k, j + k) += t.scale * w;
            else
              a(row, j + k) += t.scale * w * t.n[k];
          }
        }
        if (point)
          a.block(row, cols, 3, 1) = t.scale * t.e;
        else
          a(row, cols) = t.scale * t.n.dot(t.e);
        row += point ? 3 : 1;
      }
      const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a);
      fb.rc = qr.matrixQR().topRows(std::min(rows, cols + 1)).triangularView<Eigen::Upper>();
    }
  });
  return out;
}

/// c + R dX: a face's compressed residuals, linear in its vertices' moves.
class FaceResidual : public ceres::CostFunction
{
public:
  explicit FaceResidual(const Eigen::MatrixXd& rc) : rc_(rc)
  {
    set_num_residuals(static_cast<int>(rc.rows()));
    for (Eigen::Index j = 0; j < (rc.cols() - 1) / 3; ++j)
      mutable_parameter_block_sizes()->push_back(3);
  }
  bool Evaluate(double const* const* params, double* residuals, double** jacobians) const override
  {
    const Eigen::Index rows = rc_.rows(), blocks = (rc_.cols() - 1) / 3;
    Eigen::Map<Eigen::VectorXd> r(residuals, rows);
    r = rc_.col(rc_.cols() - 1);
    for (Eigen::Index j = 0; j < blocks; ++j)
    {
      r += rc_.middleCols(3 * j, 3) * Eigen::Map<const Eigen::Vector3d>(params[j]);
      if (jacobians && jacobians[j])
        Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(jacobians[j], rows, 3) =
          rc_.middleCols(3 * j, 3);
    }
    return true;
  }

private:
  const Eigen::MatrixXd& rc_; ///< owned by the outer iteration's FaceBlock
};

/// sqrt(lambda) dX.
class Damping : public ceres::SizedCostFunction<3, 3>
{
public:
  explicit Damping(double w) : w_(w) {}
  bool Evaluate(double const* const* params, double* residuals, double** jacobians) const override
  {
    for (int k = 0; k < 3; ++k)
      residuals[k] = w_ * params[0][k];
    if (jacobians && jacobians[0])
    {
      for (int i = 0; i < 9; ++i)
        jacobians[0][i] = (i % 4 == 0) ? w_ : 0.0;
    }
    return true;
  }

private:
  double w_;
};

/// The fold guard (beyond the paper). The linear model sees the surface
/// through points of it (V', face centres, curve midpoints), not through the
/// shape of the lattice, and a step that brings those points closer to the
/// samples can fold the surface: a small lattice face turns over between its
/// neighbours, or a patch folds into a thin fin. Metro hardly sees a fin
/// that lies along the original, but the surface then passes through itself
/// (dark specks in a rendering; no valid solid to print). The guard shortens
/// the step of the vertices that fold (halves it, the fifth time zeroes it):
/// - before the step is measured, an edge whose faces' normals end more than
///   150 degrees apart, and further apart than before the step (a face
///   turned over onto its neighbour; creases are left out: no G1 is asked
///   across them), shortens both faces' vertices' steps;
/// - after the surface is built, a face more of whose patches' normals (a
///   5 x 5 grid inside each) point away from the face's normal at the start
///   of the refinement than before the step shortens its vertices' steps;
///   where it still folds, those of every face at its vertices too (its
///   patches depend on no others); the surface is rebuilt, until no face
///   folds more.
/// Both loops end: each round shortens at least one step that is not zero
/// yet, and a face whose vertices and neighbours all stay folds as before.
/// Where the original is folded itself (a thin process's tip, a wedge
/// where a cut meets the bone at a glancing angle: triangles bent by more
/// than 120 degrees at a common edge), the surface must fold to follow it;
/// the faces there are left to the refinement. (At 90 degrees the main
/// job's refined row keeps more of its accuracy, max 0.52 % against 0.76 %,
/// but six triangles of the second TCIA mandible count and its surface
/// crosses itself a little more than before the refinement.)
class FoldGuard
{
public:
  FoldGuard(const PolygonMesh& lattice, const LatticeSurface& surface, const LatticeWeights& weights,
    const TriangleMesh* original, int resolution, int threads)
    : facesAt_(lattice.points.size()), exempt_(lattice.faces.size(), 0)
  {
    std::map<EdgeKey, std::size_t> faceOf; // directed edge -> its face
    for (std::size_t f = 0; f < lattice.faces.size(); ++f)
    {
      const auto& face = lattice.faces[f];
      for (std::size_t i = 0; i < face.size(); ++i)
      {
        faceOf[{ face[i], face[(i + 1) % face.size()] }] = f;
        facesAt_[static_cast<std::size_t>(face[i])].push_back(f);
      }
    }
    for (const auto& [edge, f] : faceOf)
    {
      const auto twin = faceOf.find({ edge.second, edge.first });
      if (edge.first < edge.second && twin != faceOf.end() && weights.edgeWeight(edge.first, edge.second) > 0.0)
        edges_.emplace_back(f, twin->second);
    }
    startNormals_ = faceNormals(lattice);
    reversed_ = reversedNormals(surface);
    if (original)
      exemptSharpPlaces(lattice, surface, *original, resolution, threads);
  }

  /// Shortens the step of the vertices of faces it would turn over;
  /// `lattice` is at the points before the step.
  void holdBackTurnedFaces(const PolygonMesh& lattice, std::vector<std::array<double, 3>>& delta) const
  {
    const std::vector<Vec3> before = faceNormals(lattice);
    PolygonMesh after = lattice;
    std::vector<int> cuts(lattice.points.size(), 0);
    for (bool more = true; more;)
    {
      more = false;
      for (std::size_t v = 0; v < after.points.size(); ++v)
        after.points[v] = lattice.points[v] + Vec3(delta[v][0], delta[v][1], delta[v][2]);
      const std::vector<Vec3> now = faceNormals(after);
      for (const auto& [f, g] : edges_)
      {
        // A face of zero area after the step (normal zero) is not turned:
        // the surface build refuses it.
        const double c = now[f].dot(now[g]);
        if (exempt_[f] || exempt_[g] || c >= kTurnedCosine || c >= before[f].dot(before[g]))
          continue;
        for (const std::size_t face : { f, g })
          for (const auto v : lattice.faces[face])
            more = shorten(static_cast<std::size_t>(v), cuts, delta) || more;
      }
    }
  }

  /// After the step (`lattice` at x0 + delta, `trial` its surface): shortens
  /// the steps of the vertices of faces whose patches fold more than before
  /// it, moves them in `lattice` and rebuilds `trial`, until none does.
  /// Returns the final trial's counts of turned normals, for accept().
  std::vector<int> holdBackFoldedPatches(PolygonMesh& lattice, const std::vector<Vec3>& x0, LatticeSurface& trial,
    const LatticeWeights& weights, std::vector<std::array<double, 3>>& delta) const
  {
    std::vector<int> cuts(lattice.points.size(), 0);
    std::vector<char> again(lattice.faces.size(), 0);
    for (;;)
    {
      std::vector<int> now = reversedNormals(trial);
      bool more = false;
      for (std::size_t f = 0; f < now.size(); ++f)
      {
        if (exempt_[f] || now[f] <= reversed_[f])
          continue;
        for (const auto v : lattice.faces[f])
        {
          if (!again[f])
          {
            more = shorten(static_cast<std::size_t>(v), cuts, delta) || more;
            continue;
          }
          for (const std::size_t g : facesAt_[static_cast<std::size_t>(v)])
            for (const auto w : lattice.faces[g])
              more = shorten(static_cast<std::size_t>(w), cuts, delta) || more;
        }
        again[f] = 1;
      }
      if (!more)
        return now;
      for (std::size_t v = 0; v < lattice.points.size(); ++v)
        if (cuts[v] > 0)
          lattice.points[v] = x0[v] + Vec3(delta[v][0], delta[v][1], delta[v][2]);
      trial = buildLatticeSurface(lattice, weights);
    }
  }

  /// A step was kept: its surface (its counts, from holdBackFoldedPatches)
  /// is the one the next step is measured against.
  void accept(std::vector<int> reversed) { reversed_ = std::move(reversed); }

private:
  static constexpr double kTurnedCosine = -0.8660254037844386; // cos 150 degrees
  static constexpr double kSharpCosine = -0.5;                 // cos 120 degrees

  /// Marks the faces nearest to the original's sharply bent triangles (more
  /// than 120 degrees at a common edge), and the faces around them.
  void exemptSharpPlaces(const PolygonMesh& lattice, const LatticeSurface& surface, const TriangleMesh& original,
    int resolution, int threads)
  {
    std::vector<std::pair<EdgeKey, std::size_t>> edges;
    edges.reserve(3 * original.triangles.size());
    for (std::size_t t = 0; t < original.triangles.size(); ++t)
      for (int i = 0; i < 3; ++i)
        edges.emplace_back(edgeKey(original.triangles[t][i], original.triangles[t][(i + 1) % 3]), t);
    std::sort(edges.begin(), edges.end());
    auto normal = [&](std::size_t t) {
      const auto& tri = original.triangles[t];
      const Vec3& a = original.points[static_cast<std::size_t>(tri[0])];
      const Vec3 n = (original.points[static_cast<std::size_t>(tri[1])] - a).cross(original.points[static_cast<std::size_t>(tri[2])] - a);
      return n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
    };
    std::vector<Vec3> centres;
    for (std::size_t i = 0; i + 1 < edges.size(); ++i)
    {
      if (edges[i].first != edges[i + 1].first || normal(edges[i].second).dot(normal(edges[i + 1].second)) >= kSharpCosine)
        continue;
      for (const std::size_t t : { edges[i].second, edges[i + 1].second })
      {
        const auto& tri = original.triangles[t];
        centres.push_back((original.points[static_cast<std::size_t>(tri[0])] + original.points[static_cast<std::size_t>(tri[1])] +
                            original.points[static_cast<std::size_t>(tri[2])]) / 3.0);
      }
    }
    if (centres.empty())
      return;
    for (const Foot& foot : footPoints(surface, centres, resolution, threads))
      for (const auto v : lattice.faces[static_cast<std::size_t>(surface.patchFace[foot.patch])])
        for (const std::size_t g : facesAt_[static_cast<std::size_t>(v)])
          exempt_[g] = 1;
  }

  static std::vector<Vec3> faceNormals(const PolygonMesh& m)
  {
    std::vector<Vec3> n(m.faces.size());
    for (std::size_t f = 0; f < m.faces.size(); ++f)
    {
      const Vec3 v = newellVector(m, f);
      n[f] = v.norm() > 0.0 ? Vec3(v.normalized()) : Vec3::Zero();
    }
    return n;
  }

  /// Per lattice face: its patches' normals on a 5 x 5 grid inside each that
  /// point away from the face's normal at the start.
  std::vector<int> reversedNormals(const LatticeSurface& s) const
  {
    std::vector<int> out(startNormals_.size(), 0);
    for (std::size_t p = 0; p < s.patches.size(); ++p)
    {
      const auto f = static_cast<std::size_t>(s.patchFace[p]);
      for (int i = 1; i <= 5; ++i)
        for (int j = 1; j <= 5; ++j)
          out[f] += s.patches[p].normal(i / 6.0, j / 6.0).dot(startNormals_[f]) < 0.0 ? 1 : 0;
    }
    return out;
  }

  /// Halves vertex v's step, the fifth time zeroes it; false when it is
  /// zero already (held back, or a fixed vertex).
  static bool shorten(std::size_t v, std::vector<int>& cuts, std::vector<std::array<double, 3>>& delta)
  {
    if (delta[v][0] == 0.0 && delta[v][1] == 0.0 && delta[v][2] == 0.0)
      return false;
    const double scale = ++cuts[v] < 5 ? 0.5 : 0.0;
    for (double& c : delta[v])
      c *= scale;
    return true;
  }

  std::vector<std::pair<std::size_t, std::size_t>> edges_; ///< interior non-crease edges, as their faces
  std::vector<std::vector<std::size_t>> facesAt_;          ///< per vertex
  std::vector<Vec3> startNormals_;                         ///< per face, at the start
  std::vector<int> reversed_;                              ///< per face, on the surface the step starts from
  std::vector<char> exempt_;                               ///< per face: the original is folded there
};

} // namespace

std::string refinementOptionsProblem(const RefinementOptions& options)
{
  if (options.iterations < 1)
    return "the refinement needs at least one iteration";
  if (!(options.reverseWeight >= 0.0))
    return "the reverse weight must be 0 or more";
  if (!(options.tailWeight >= 0.0) || !(options.tailThreshold > 0.0))
    return "the tail weight must be 0 or more and its threshold above 0";
  if (options.threads < 0)
    return "the thread count must be 0 (every hardware thread) or more";
  return {};
}

RefinementReport refineLatticeFit(PolygonMesh& lattice, const std::vector<Vec3>& samples,
  const RefinementOptions& options)
{
  if (samples.empty())
    throw std::invalid_argument("the refinement needs samples of the original surface");
  if (!options.fixed.empty() && options.fixed.size() != lattice.points.size())
    throw std::invalid_argument("the fixed-vertex flags must be one per lattice vertex");
  const std::string problem = refinementOptionsProblem(options);
  if (!problem.empty())
    throw std::invalid_argument(problem);
  for (const Vec3& p : samples)
    if (!p.allFinite())
      throw std::invalid_argument("a sample of the original surface is not finite");

  // Progress: the set-up (the surface, the foot points, the original's
  // tree; several seconds on a 600,000-triangle input) counts as half an
  // iteration, reported at its two halves; then each iteration twice.
  const double units = static_cast<double>(options.iterations) + 0.5;
  auto goOn = [&](double done) { return !options.progress || options.progress(done / units); };
  RefinementReport report;
  LatticeSurface surface = buildLatticeSurface(lattice, options.weights); // throws for a bad lattice
  std::vector<Foot> feet = footPoints(surface, samples, options.locatorResolution, options.threads);
  report.initialRms = std::sqrt(energy(feet) / static_cast<double>(samples.size()));
  const bool twoWay = options.original && options.reverseWeight > 0.0;
  bool stopped = !goOn(twoWay ? 0.25 : 0.5);
  std::unique_ptr<ClosestPointTree> originalTree;
  std::vector<ReversePoint> reverse;
  double reverseWeight = 0.0;
  if (twoWay && !stopped)
  {
    originalTree = std::make_unique<ClosestPointTree>(*options.original);
    reverse = reversePoints(surface, *options.original, *originalTree, options.threads);
    stopped = !goOn(0.5);
    reverseWeight = options.reverseWeight * static_cast<double>(samples.size()) / static_cast<double>(reverse.size());
  }
  // The tail penalty: mu sum max(0, d - tau)^2, over both directions' points.
  const double mu = options.tailWeight;
  const double tau = options.tailThreshold * std::sqrt(energy(feet) / static_cast<double>(samples.size()));
  auto objective = [&](const std::vector<Foot>& fs, const std::vector<ReversePoint>& rs) {
    return energy(fs) + reverseWeight * energy(rs) + mu * (tailEnergy(fs, tau) + reverseWeight * tailEnergy(rs, tau));
  };
  double e0 = objective(feet, reverse);
  const std::size_t nv = lattice.points.size();
  FoldGuard guard(lattice, surface, options.weights, options.original, options.locatorResolution, options.threads);

  // Levenberg-Marquardt on the outer loop: the damping falls after a step
  // that lowered the exact energy and rises (the step is retried) after one
  // that did not.
  double damping = options.damping;
  for (int it = 0; it < options.iterations && !stopped; ++it)
  {
    // The patch models and the samples' combinations and terms live only
    // until they are compressed: on a 20,000-vertex skull they are
    // gigabytes, and the solve needs only the face blocks.
    double weight = 0.0;
    std::vector<FaceBlock> faceBlocks;
    {
      const Anchors anchors = buildAnchors(lattice, options.weights);
      const std::vector<PatchModel> models = buildPatchModels(lattice, surface, anchors);
      std::vector<Combo> combos(samples.size());
      inChunks(samples.size(), options.threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t s = begin; s < end; ++s)
          combos[s] = sampleCombo(models[feet[s].patch], feet[s].u, feet[s].v);
      });
      for (const Combo& combo : combos)
        for (const auto& vw : combo)
          weight += vw.second * vw.second;
      std::vector<Combo> reverseCombos(reverse.size());
      inChunks(reverse.size(), options.threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t r = begin; r < end; ++r)
          reverseCombos[r] = sampleCombo(models[reverse[r].patch], reverse[r].u, reverse[r].v);
      });
      // Each distance d = |e| with its weight, and its tail residual where d > tau.
      std::vector<std::vector<Term>> termsOfFace(lattice.faces.size());
      auto addDistance = [&](std::size_t patch, const Combo& combo, const Vec3& e, const Vec3& n, double d, double w) {
        auto& terms = termsOfFace[static_cast<std::size_t>(surface.patchFace[patch])];
        terms.push_back({ &combo, e, n, std::sqrt(w) });
        if (mu > 0.0 && d > tau)
          terms.push_back({ &combo, e * ((d - tau) / d), n, std::sqrt(mu * w) });
      };
      for (std::size_t s = 0; s < samples.size(); ++s)
        addDistance(feet[s].patch, combos[s], feet[s].point - samples[s], feet[s].normal, feet[s].distance, 1.0);
      for (std::size_t r = 0; r < reverse.size(); ++r)
        addDistance(reverse[r].patch, reverseCombos[r], reverse[r].point - reverse[r].closest, reverse[r].normal,
          reverse[r].distance, reverseWeight);
      faceBlocks = compress(termsOfFace, options.threads);
    }

    const std::vector<Vec3> x0 = lattice.points;
    bool accepted = false;
    for (int attempt = 0; attempt < 4 && !accepted; ++attempt)
    {
      std::vector<std::array<double, 3>> delta(nv, { 0.0, 0.0, 0.0 });
      ceres::Problem::Options po;
      po.cost_function_ownership = ceres::TAKE_OWNERSHIP;
      ceres::Problem problem(po);
      std::vector<double*> blocks;
      for (const FaceBlock& fb : faceBlocks)
      {
        if (fb.rc.rows() == 0)
          continue;
        blocks.clear();
        for (const auto v : fb.vertices)
          blocks.push_back(delta[static_cast<std::size_t>(v)].data());
        problem.AddResidualBlock(new FaceResidual(fb.rc), nullptr, blocks);
      }
      const double lambda = damping * weight / static_cast<double>(nv);
      for (std::size_t v = 0; v < nv; ++v)
      {
        if (!problem.HasParameterBlock(delta[v].data()))
          continue;
        problem.AddResidualBlock(new Damping(std::sqrt(lambda)), nullptr, delta[v].data());
        if (!options.fixed.empty() && options.fixed[v])
          problem.SetParameterBlockConstant(delta[v].data());
      }
      ceres::Solver::Options so;
      so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
      // The step is linear (FaceResidual, Damping): one Gauss-Newton step
      // with this trust region solves it. A second iteration only confirmed
      // convergence, at the cost of another factorisation (same result).
      so.max_num_iterations = 1;
      so.initial_trust_region_radius = 1e8;
      so.logging_type = ceres::SILENT;
      so.minimizer_progress_to_stdout = false;
      so.num_threads = static_cast<int>(workerThreads(options.threads));
      ceres::Solver::Summary summary;
      ceres::Solve(so, &problem, &summary);
      if (!summary.IsSolutionUsable())
        break;
      // Half the iteration is done; measuring the step is the other half
      // (on a 20,000-vertex skull an iteration takes half a minute).
      // A stop here leaves the step unaccepted, so it is undone below.
      if (!goOn(it + 1.0))
        break;
      lattice.points = x0; // a refused attempt left its trial here
      guard.holdBackTurnedFaces(lattice, delta);
      for (std::size_t v = 0; v < nv; ++v)
        lattice.points[v] = x0[v] + Vec3(delta[v][0], delta[v][1], delta[v][2]);
      try
      {
        LatticeSurface trial = buildLatticeSurface(lattice, options.weights);
        std::vector<int> trialReversed = guard.holdBackFoldedPatches(lattice, x0, trial, options.weights, delta);
        std::vector<Foot> trialFeet = footPoints(trial, samples, options.locatorResolution, options.threads, &feet);
        std::vector<ReversePoint> trialReverse;
        if (twoWay)
          trialReverse = reversePoints(trial, *options.original, *originalTree, options.threads);
        const double e = objective(trialFeet, trialReverse);
        if (e < e0)
        {
          guard.accept(std::move(trialReversed));
          surface = std::move(trial);
          feet = std::move(trialFeet);
          reverse = std::move(trialReverse);
          e0 = e;
          accepted = true;
        }
      }
      catch (const std::invalid_argument&)
      {
        // A degenerate trial lattice: damp more.
      }
      damping = accepted ? std::max(1e-4, 0.5 * damping) : 4.0 * damping;
    }
    if (!accepted)
    {
      lattice.points = x0;
      break;
    }
    ++report.iterations;
    if (!goOn(it + 1.5))
      break;
  }
  report.finalRms = std::sqrt(energy(feet) / static_cast<double>(samples.size()));
  auto meanAndMax = [](const auto& points) {
    double sum = 0.0, largest = 0.0;
    for (const auto& p : points)
    {
      sum += p.distance;
      largest = std::max(largest, p.distance);
    }
    return std::make_pair(points.empty() ? 0.0 : sum / static_cast<double>(points.size()), largest);
  };
  const auto forward = meanAndMax(feet), backward = meanAndMax(reverse);
  report.finalMean = reverse.empty() ? forward.first : 0.5 * (forward.first + backward.first);
  report.finalMax = std::max(forward.second, backward.second);
  return report;
}

int insertVerticesAtLargestDistances(PolygonMesh& lattice, const std::vector<Vec3>& samples, int count,
  const std::vector<std::pair<std::int64_t, std::int64_t>>& keep, LatticeWeights& weights,
  std::vector<char>& fixed, int locatorResolution, int threads)
{
  if (count <= 0)
    return 0;
  if (samples.empty())
    throw std::invalid_argument("the insertions need samples of the original surface");
  if (!fixed.empty() && fixed.size() != lattice.points.size())
    throw std::invalid_argument("the fixed-vertex flags must be one per lattice vertex");
  const LatticeSurface surface = buildLatticeSurface(lattice, weights); // throws for a bad lattice
  const std::vector<Foot> feet = footPoints(surface, samples, locatorResolution, threads);

  std::set<EdgeKey> kept;
  for (const auto& e : keep)
    kept.insert(edgeKey(e.first, e.second));
  for (const auto& ew : weights.edge)
    kept.insert(edgeKey(ew.first.first, ew.first.second));
  // Directed edge -> its face; and the mean edge length.
  std::map<EdgeKey, std::size_t> faceOf;
  auto index = [&](std::size_t f) {
    const auto& face = lattice.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i)
      faceOf[{ face[i], face[(i + 1) % face.size()] }] = f;
  };
  double length = 0.0;
  std::size_t edges = 0;
  for (std::size_t f = 0; f < lattice.faces.size(); ++f)
  {
    index(f);
    const auto& face = lattice.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i)
      length += (lattice.points[static_cast<std::size_t>(face[i])] -
        lattice.points[static_cast<std::size_t>(face[(i + 1) % face.size()])]).norm();
    edges += face.size();
  }
  const double spacing = 2.0 * length / static_cast<double>(std::max<std::size_t>(1, edges));

  std::vector<std::size_t> order(samples.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return feet[x].distance > feet[y].distance || (feet[x].distance == feet[y].distance && x < y);
  });
  std::vector<Vec3> chosen;
  std::set<std::size_t> used; // faces split already (their foot points are stale)
  int inserted = 0;
  for (const std::size_t s : order)
  {
    if (inserted == count)
      break;
    const auto f = static_cast<std::size_t>(surface.patchFace[feet[s].patch]);
    if (used.count(f) || lattice.faces[f].size() != 3)
      continue;
    bool apart = true;
    for (const Vec3& c : chosen)
      apart = apart && (c - samples[s]).norm() >= spacing;
    if (!apart)
      continue;
    // The splittable edge of f whose midpoint is nearest to the sample.
    const std::vector<std::int64_t> face = lattice.faces[f];
    std::size_t best = 3, g = 0;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < 3; ++i)
    {
      const auto a = face[i], b = face[(i + 1) % 3];
      const auto twin = faceOf.find({ b, a });
      if (kept.count(edgeKey(a, b)) || twin == faceOf.end() || used.count(twin->second) ||
        lattice.faces[twin->second].size() != 3)
        continue;
      const Vec3 mid = 0.5 * (lattice.points[static_cast<std::size_t>(a)] + lattice.points[static_cast<std::size_t>(b)]);
      const double d = (mid - samples[s]).squaredNorm();
      if (d < bestDistance)
      {
        bestDistance = d;
        best = i;
        g = twin->second;
      }
    }
    if (best == 3)
      continue;
    const std::int64_t a = face[best], b = face[(best + 1) % 3], c = face[(best + 2) % 3];
    const auto& other = lattice.faces[g];
    std::int64_t d = -1;
    for (std::size_t j = 0; j < 3; ++j)
      if (other[j] != a && other[j] != b)
        d = other[j];
    // (a, b, c) and (b, a, d) become (a, m, c), (m, b, c), (b, m, d), (m, a, d).
    const auto m = static_cast<std::int64_t>(lattice.points.size());
    lattice.points.push_back(0.5 * (lattice.points[static_cast<std::size_t>(a)] + lattice.points[static_cast<std::size_t>(b)]));
    if (!weights.vertex.empty())
      weights.vertex.push_back(1.0);
    if (!fixed.empty())
      fixed.push_back(0);
    const std::size_t f2 = lattice.faces.size(), g2 = f2 + 1;
    lattice.faces[f] = { a, m, c };
    lattice.faces[g] = { b, m, d };
    lattice.faces.push_back({ m, b, c });
    lattice.faces.push_back({ m, a, d });
    faceOf.erase({ a, b });
    faceOf.erase({ b, a });
    for (const std::size_t changed : { f, g, f2, g2 })
      index(changed);
    used.insert({ f, g, f2, g2 });
    chosen.push_back(samples[s]);
    ++inserted;
  }
  return inserted;
}

} // namespace lk
