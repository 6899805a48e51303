#include "latticekit/LatticeSurfaceLocator.h"

#include <algorithm>
#include <cmath>
#include <limits>
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
        mesh_.triangles.push_back({ a, b, c });
        mesh_.triangles.push_back({ a, c, d });
      }
    }
  }
  tree_ = std::make_unique<ClosestPointTree>(mesh_);
  boxes_.resize(surface.patches.size());
  for (std::size_t p = 0; p < surface.patches.size(); ++p)
  {
    for (const Vec3& c : surface.patches[p].grid)
    {
      boxes_[p].extend(c);
    }
    for (const Vec3& c : surface.patches[p].interior)
    {
      boxes_[p].extend(c);
    }
  }
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
  // The nearest tessellation vertex is a point of the surface: its distance
  // bounds the answer. A Gregory patch lies in the convex hull of its control
  // points, so only patches whose control-point box is within that bound can
  // hold the closest point. Each is refined from its nearest grid sample.
  const ClosestPointTree::Hit hit = tree_->closest(query);
  const auto& tri = mesh_.triangles[static_cast<std::size_t>(hit.face)];
  double bound = std::numeric_limits<double>::max();
  for (const auto id : tri)
  {
    bound = std::min(bound, (mesh_.points[static_cast<std::size_t>(id)] - query).norm());
  }
  const int m = resolution_;
  const auto perPatch = static_cast<std::size_t>((m + 1) * (m + 1));
  Result best;
  best.distance = std::numeric_limits<double>::max();
  for (std::size_t p = 0; p < surface_.patches.size(); ++p)
  {
    const Box3& box = boxes_[p];
    const Vec3 outside = (box.min - query).cwiseMax(query - box.max).cwiseMax(0.0);
    if (outside.norm() > bound)
    {
      continue;
    }
    Result r;
    r.patch = p;
    double nearest = std::numeric_limits<double>::max();
    for (std::size_t k = 0; k < perPatch; ++k)
    {
      const double d = (mesh_.points[p * perPatch + k] - query).squaredNorm();
      if (d < nearest)
      {
        nearest = d;
        r.u = static_cast<double>(k % static_cast<std::size_t>(m + 1)) / m;
        r.v = static_cast<double>(k / static_cast<std::size_t>(m + 1)) / m;
      }
    }
    refine(query, r);
    if (r.distance < best.distance)
    {
      best = r;
    }
  }
  return best;
}

} // namespace lk
