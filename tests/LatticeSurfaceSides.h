#pragma once
/// \file LatticeSurfaceSides.h
/// Samples along the sides of a lattice surface's patches, matched with the
/// samples of the neighbouring patches at the same points: the tests of
/// watertightness, G1 and folds compare them.

#include "latticekit/LatticeSurface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace lktest
{

struct SideSample
{
  lk::Vec3 p, n;
  std::size_t patch;
};

/// Samples every patch side: quad patches at 65 points a side (t = k/64),
/// split patches at 33 (s = k/32, which is t = k/64 on a split edge), so
/// that each sample has its partners on the neighbouring patches.
inline std::vector<SideSample> sideSamples(const lk::LatticeSurface& s)
{
  std::vector<SideSample> out;
  for (std::size_t p = 0; p < s.patches.size(); ++p)
  {
    const int m = lk::isSplitPatch(s, p) ? 32 : 64;
    for (int k = 0; k <= m; ++k)
    {
      const double t = static_cast<double>(k) / m;
      for (auto uv : { std::pair<double, double>{ t, 0.0 }, { 1.0, t }, { t, 1.0 }, { 0.0, t } })
      {
        out.push_back({ s.patches[p].evaluate(uv.first, uv.second), s.patches[p].normal(uv.first, uv.second), p });
      }
    }
  }
  return out;
}

/// Calls fn(x, y) for every two samples of different patches at one point
/// (within 1e-7 of `size`); returns how many points have no such partner.
template <typename Fn>
std::size_t forEachCoincidentPair(const std::vector<SideSample>& samples, double size, Fn fn)
{
  std::map<std::array<long long, 3>, std::vector<std::size_t>> buckets;
  const double q = 1e-7 * size;
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    const auto& p = samples[i].p;
    buckets[{ std::llround(p.x() / q), std::llround(p.y() / q), std::llround(p.z() / q) }].push_back(i);
  }
  std::size_t unmatched = 0;
  for (const auto& [key, ids] : buckets)
  {
    bool partner = false;
    for (std::size_t a = 0; a < ids.size(); ++a)
    {
      for (std::size_t b = a + 1; b < ids.size(); ++b)
      {
        if (samples[ids[a]].patch != samples[ids[b]].patch)
        {
          partner = true;
          fn(samples[ids[a]], samples[ids[b]]);
        }
      }
    }
    unmatched += partner ? 0 : 1;
  }
  return unmatched;
}

/// The angle between two samples' normals (rad), orientation included.
inline double normalAngle(const SideSample& x, const SideSample& y)
{
  return std::atan2(x.n.cross(y.n).norm(), x.n.dot(y.n));
}

/// How many pairs of patches' side samples at one point have normals more
/// than 90 degrees apart: there the two patches lie on the same side of
/// their common curve (they fold over each other), though their tangent
/// planes agree. Creases (no G1 asked) can do this too: use it on lattices
/// without them. `pairs`, if given, gets the number of pairs compared.
inline std::size_t foldedSidePairs(const lk::LatticeSurface& s, double size, std::size_t* pairs = nullptr)
{
  std::size_t folded = 0, compared = 0;
  forEachCoincidentPair(sideSamples(s), size, [&](const SideSample& x, const SideSample& y) {
    ++compared;
    folded += normalAngle(x, y) > 0.5 * M_PI ? 1 : 0;
  });
  if (pairs)
    *pairs = compared;
  return folded;
}

} // namespace lktest
