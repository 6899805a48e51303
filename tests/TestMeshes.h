#pragma once
/// \file TestMeshes.h
/// Small exact meshes for the core tests.

#include "latticekit/LatticeSimplification.h"
#include "latticekit/PolygonMesh.h"
#include "latticekit/TriangleMesh.h"

#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace lktest
{

/// Every edge of a triangle mesh, once, as (smaller id, larger id).
inline std::set<lk::EdgeKey> edgesOf(const lk::TriangleMesh& m)
{
  std::set<lk::EdgeKey> e;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i)
      e.insert(lk::edgeKey(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)]));
  return e;
}

/// An n x n grid of unit-square cells in the plane z = height, each cell two triangles.
inline lk::TriangleMesh grid(int n, double size, double height)
{
  lk::TriangleMesh m;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      m.points.emplace_back(size * i / n, size * j / n, height);
    }
  }
  auto id = [n](int i, int j) { return static_cast<std::int64_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      m.triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      m.triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return m;
}

/// An icosphere of the given radius after `levels` 1-to-4 subdivisions, outward.
inline lk::TriangleMesh icosphere(int levels, double radius)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  lk::TriangleMesh m;
  const double v[12][3] = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t },
    { 0, 1, t }, { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 },
    { -t, 0, 1 } };
  for (auto& p : v)
  {
    m.points.push_back(lk::Vec3(p[0], p[1], p[2]).normalized());
  }
  m.triangles = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 }, { 1, 5, 9 },
    { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 },
    { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
  for (int l = 0; l < levels; ++l)
  {
    std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> mid;
    auto midpoint = [&](std::int64_t a, std::int64_t b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end())
      {
        return it->second;
      }
      m.points.push_back(
        (m.points[static_cast<std::size_t>(a)] + m.points[static_cast<std::size_t>(b)]).normalized());
      const auto id = static_cast<std::int64_t>(m.points.size() - 1);
      mid[key] = id;
      return id;
    };
    std::vector<lk::Triangle> next;
    for (const auto& tri : m.triangles)
    {
      const auto a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]), c = midpoint(tri[2], tri[0]);
      next.push_back({ tri[0], a, c });
      next.push_back({ tri[1], b, a });
      next.push_back({ tri[2], c, b });
      next.push_back({ a, b, c });
    }
    m.triangles = next;
  }
  for (auto& p : m.points)
  {
    p *= radius;
  }
  return m;
}

/// A torus about the z axis (radii R and r), nu x nv quads split into
/// triangles; point i * nv + j at angles 2 pi i / nu around the axis and
/// 2 pi j / nv around the tube (tests/data/torus.obj is (16, 8, 3, 1)).
inline lk::TriangleMesh torus(int nu, int nv, double R, double r)
{
  lk::TriangleMesh m;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
    {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      m.points.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
    {
      const std::int64_t a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv,
                         d = i * nv + (j + 1) % nv;
      m.triangles.push_back({ a, b, c });
      m.triangles.push_back({ a, c, d });
    }
  return m;
}

/// Closed unit cube [0,1]^3 as 12 outward triangles.
inline lk::TriangleMesh cube()
{
  lk::TriangleMesh m;
  for (int i = 0; i < 8; ++i)
  {
    m.points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  }
  m.triangles = { { 0, 2, 3 }, { 0, 3, 1 }, { 4, 5, 7 }, { 4, 7, 6 }, { 0, 1, 5 }, { 0, 5, 4 },
    { 2, 6, 7 }, { 2, 7, 3 }, { 0, 4, 6 }, { 0, 6, 2 }, { 1, 3, 7 }, { 1, 7, 5 } };
  return m;
}

} // namespace lktest
