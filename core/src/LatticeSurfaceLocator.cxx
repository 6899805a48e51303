#include "latticekit/LatticeSurfaceLocator.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace lk
{

LatticeSurfaceLocator::LatticeSurfaceLocator(const LatticeSurface& surface, int resolution)
  : surface_(surface)
  , resolution_(std::max(2, resolution))
{
  const int m = resolution_;
  for (std::size_t p = 0; p < surface.patches.size(); ++p)
  {
    const auto base = static_cast<std::int64_t>(mesh_.points.size());
    for (int j = 0; j <= m; ++j)
    {
      for (int i = 0; i <= m; ++i)
      {
        mesh_.points.push_back(surface.patches[p].evaluate(static_cast<double>(i) / m, static_cast<double>(j) / m));
      }
    }
    for (int j = 0; j < m; ++j)
    {
      for (int i = 0; i < m; ++i)
      {
        const std::int64_t a = base + j * (m + 1) + i, b = a + 1, c = a + m + 2, d = a + m + 1;
        const double u0 = static_cast<double>(i) / m, u1 = static_cast<double>(i + 1) / m;
        const double v0 = static_cast<double>(j) / m, v1 = static_cast<double>(j + 1) / m;
        mesh_.triangles.push_back({ a, b, c });
        uv_.push_back({ u0, v0, u1, v0, u1, v1 });
        patchOf_.push_back(p);
        mesh_.triangles.push_back({ a, c, d });
        uv_.push_back({ u0, v0, u1, v1, u0, v1 });
        patchOf_.push_back(p);
      }
    }
  }
  tree_ = std::make_unique<ClosestPointTree>(mesh_);
}

LatticeSurfaceLocator::Result LatticeSurfaceLocator::start(const Vec3& probe) const
{
  const ClosestPointTree::Hit hit = tree_->closest(probe);
  const auto t = static_cast<std::size_t>(hit.face);
  // Barycentric coordinates of the hit in its triangle give the starting (u, v).
  const auto& tri = mesh_.triangles[t];
  const Vec3& a = mesh_.points[static_cast<std::size_t>(tri[0])];
  const Vec3& b = mesh_.points[static_cast<std::size_t>(tri[1])];
  const Vec3& c = mesh_.points[static_cast<std::size_t>(tri[2])];
  const Vec3 n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  double wb = n2 > 0.0 ? (hit.point - a).cross(c - a).dot(n) / n2 : 0.0;
  double wc = n2 > 0.0 ? (b - a).cross(hit.point - a).dot(n) / n2 : 0.0;
  wb = std::clamp(wb, 0.0, 1.0);
  wc = std::clamp(wc, 0.0, 1.0 - wb);
  const double wa = 1.0 - wb - wc;
  const auto& uv = uv_[t];
  Result r;
  r.patch = patchOf_[t];
  r.u = wa * uv[0] + wb * uv[2] + wc * uv[4];
  r.v = wa * uv[1] + wb * uv[3] + wc * uv[5];
  return r;
}

void LatticeSurfaceLocator::refine(const Vec3& query, Result& r) const
{
  // Gauss-Newton on |S(u, v) - q|^2, clamped to the parameter square.
  const GregoryPatch& patch = surface_.patches[r.patch];
  for (int iteration = 0; iteration < 30; ++iteration)
  {
    Vec3 su, sv;
    const Vec3 d = patch.evaluate(r.u, r.v, &su, &sv) - query;
    const double a11 = su.dot(su), a12 = su.dot(sv), a22 = sv.dot(sv);
    const double g1 = su.dot(d), g2 = sv.dot(d);
    const double det = a11 * a22 - a12 * a12;
    if (!(det > 1e-300))
    {
      break;
    }
    const double du = -(a22 * g1 - a12 * g2) / det;
    const double dv = -(a11 * g2 - a12 * g1) / det;
    // Halve the step until the distance does not grow (a clamped or
    // overshooting step may not be a descent at full length).
    double scale = 1.0, nu = r.u, nv = r.v;
    bool improved = false;
    for (int halving = 0; halving < 30 && !improved; ++halving, scale *= 0.5)
    {
      nu = std::clamp(r.u + scale * du, 0.0, 1.0);
      nv = std::clamp(r.v + scale * dv, 0.0, 1.0);
      improved = (patch.evaluate(nu, nv) - query).squaredNorm() <= d.squaredNorm();
    }
    if (!improved)
    {
      break;
    }
    const double step = std::abs(nu - r.u) + std::abs(nv - r.v);
    r.u = nu;
    r.v = nv;
    if (step < 1e-15)
    {
      break;
    }
  }
  // Near a patch corner the rational interior blend makes the derivatives a
  // poor guide and Gauss-Newton can stall short of the minimum: finish with
  // a pattern search (steps of +-h in u and v, h halved when none helps).
  double best = (patch.evaluate(r.u, r.v) - query).squaredNorm();
  for (double h = 1.0 / 64.0; h > 1e-14;)
  {
    bool moved = false;
    for (const auto& [su, sv] : { std::pair<double, double>{ h, 0 }, { -h, 0 }, { 0, h }, { 0, -h } })
    {
      const double nu = std::clamp(r.u + su, 0.0, 1.0), nv = std::clamp(r.v + sv, 0.0, 1.0);
      const double d2 = (patch.evaluate(nu, nv) - query).squaredNorm();
      if (d2 < best)
      {
        best = d2;
        r.u = nu;
        r.v = nv;
        moved = true;
      }
    }
    if (!moved)
    {
      h *= 0.5;
    }
  }
  r.point = patch.evaluate(r.u, r.v);
  r.distance = (r.point - query).norm();
}

LatticeSurfaceLocator::Result LatticeSurfaceLocator::closest(const Vec3& query) const
{
  Result best = start(query);
  refine(query, best);
  // A solution on a patch border may be a false minimum: the true one can lie
  // on the neighbouring patch. Probe a quarter of a tessellation step beyond
  // the border, find the patch there, and continue on it.
  Result current = best;
  for (int hop = 0; hop < 4; ++hop)
  {
    const bool onBorder = current.u <= 0.0 || current.u >= 1.0 || current.v <= 0.0 || current.v >= 1.0;
    if (!onBorder)
    {
      break;
    }
    Vec3 su, sv;
    surface_.patches[current.patch].evaluate(current.u, current.v, &su, &sv);
    Vec3 out = Vec3::Zero();
    out += current.u <= 0.0 ? Vec3(-su) : (current.u >= 1.0 ? su : Vec3::Zero());
    out += current.v <= 0.0 ? Vec3(-sv) : (current.v >= 1.0 ? sv : Vec3::Zero());
    if (!(out.norm() > 0.0))
    {
      break;
    }
    const double h = 0.25 * std::max(su.norm(), sv.norm()) / resolution_;
    Result next = start(current.point + h * out.normalized());
    if (next.patch == current.patch)
    {
      break; // the surface ends here
    }
    refine(query, next);
    if (next.distance < best.distance)
    {
      best = next;
    }
    current = next;
  }
  return best;
}
} // namespace lk
