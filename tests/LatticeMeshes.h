#pragma once
/// \file LatticeMeshes.h
/// Small closed and open lattices for the lattice-surface tests.

#include "latticekit/PolygonMesh.h"

#include <cmath>
#include <map>

namespace lktest
{

inline lk::PolygonMesh cubeLattice()
{
  lk::PolygonMesh m;
  for (int i = 0; i < 8; ++i)
  {
    m.points.emplace_back((i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5);
  }
  m.faces = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  return m;
}

inline lk::PolygonMesh octahedronLattice()
{
  lk::PolygonMesh m;
  m.points = { lk::Vec3(1, 0, 0), lk::Vec3(-1, 0, 0), lk::Vec3(0, 1, 0), lk::Vec3(0, -1, 0), lk::Vec3(0, 0, 1),
    lk::Vec3(0, 0, -1) };
  m.faces = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } };
  return m;
}

/// The cube with each face cut into k x k quads (a regularly refined cube).
inline lk::PolygonMesh refinedCubeLattice(int k)
{
  lk::PolygonMesh m;
  std::map<std::array<long, 3>, std::int64_t> ids;
  auto id = [&](const lk::Vec3& p) {
    const std::array<long, 3> key = { std::lround(p.x() * 2 * k), std::lround(p.y() * 2 * k), std::lround(p.z() * 2 * k) };
    auto it = ids.find(key);
    if (it != ids.end())
    {
      return it->second;
    }
    m.points.push_back(p);
    return ids[key] = static_cast<std::int64_t>(m.points.size() - 1);
  };
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side : { -1, 1 })
    {
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      for (int i = 0; i < k; ++i)
      {
        for (int j = 0; j < k; ++j)
        {
          auto corner = [&](int di, int dj) {
            lk::Vec3 p;
            p[axis] = 0.5 * side;
            p[a] = -0.5 + static_cast<double>(i + di) / k;
            p[b] = -0.5 + static_cast<double>(j + dj) / k;
            return id(p);
          };
          std::vector<std::int64_t> f = { corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1) };
          if (side < 0)
          {
            std::swap(f[1], f[3]);
          }
          m.faces.push_back(f);
        }
      }
    }
  }
  return m;
}

/// An n-gonal bipyramid: two apexes of valence n, 2n triangles.
inline lk::PolygonMesh bipyramidLattice(int n)
{
  lk::PolygonMesh m;
  for (int i = 0; i < n; ++i)
  {
    const double a = 2.0 * M_PI * i / n;
    m.points.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  m.points.emplace_back(0, 0, 1.2);
  m.points.emplace_back(0, 0, -0.9);
  const auto top = static_cast<std::int64_t>(n), bottom = static_cast<std::int64_t>(n + 1);
  for (int i = 0; i < n; ++i)
  {
    const std::int64_t a = i, b = (i + 1) % n;
    m.faces.push_back({ a, b, top });
    m.faces.push_back({ b, a, bottom });
  }
  return m;
}

/// A pentagonal prism: two pentagons and five quads, valence-3 vertices.
inline lk::PolygonMesh pentagonalPrismLattice()
{
  lk::PolygonMesh m;
  for (int z : { 0, 1 })
  {
    for (int i = 0; i < 5; ++i)
    {
      const double a = 2.0 * M_PI * i / 5;
      m.points.emplace_back(std::cos(a), std::sin(a), 1.3 * z);
    }
  }
  m.faces.push_back({ 4, 3, 2, 1, 0 });
  m.faces.push_back({ 5, 6, 7, 8, 9 });
  for (std::int64_t i = 0; i < 5; ++i)
  {
    const std::int64_t j = (i + 1) % 5;
    m.faces.push_back({ i, j, j + 5, i + 5 });
  }
  return m;
}

/// A cube with one corner cut off: one triangle, three pentagons, three quads.
inline lk::PolygonMesh truncatedCornerCubeLattice()
{
  lk::PolygonMesh m;
  // Cube [0,1]^3 without corner (1,1,1); the cut passes through t = 0.6 on its edges.
  m.points = { lk::Vec3(0, 0, 0), lk::Vec3(1, 0, 0), lk::Vec3(0, 1, 0), lk::Vec3(1, 1, 0), lk::Vec3(0, 0, 1),
    lk::Vec3(1, 0, 1), lk::Vec3(0, 1, 1), lk::Vec3(0.6, 1, 1), lk::Vec3(1, 0.6, 1), lk::Vec3(1, 1, 0.6) };
  m.faces = {
    { 0, 2, 3, 1 },          // z = 0
    { 0, 1, 5, 4 },          // y = 0
    { 0, 4, 6, 2 },          // x = 0
    { 4, 5, 8, 7, 6 },       // z = 1 (pentagon)
    { 1, 3, 9, 8, 5 },       // x = 1 (pentagon)
    { 2, 6, 7, 9, 3 },       // y = 1 (pentagon)
    { 7, 8, 9 },             // the cut
  };
  return m;
}

/// An open, planar lattice in z = 0 mixing quads, triangles and a pentagon.
inline lk::PolygonMesh planarMixedLattice()
{
  lk::PolygonMesh m;
  m.points = { lk::Vec3(0, 0, 0), lk::Vec3(1, 0, 0), lk::Vec3(2, 0, 0), lk::Vec3(0, 1, 0), lk::Vec3(1, 1.1, 0),
    lk::Vec3(2, 1, 0), lk::Vec3(0, 2, 0), lk::Vec3(1, 2, 0), lk::Vec3(2.2, 2, 0), lk::Vec3(3, 1.5, 0),
    lk::Vec3(3, 0.3, 0) };
  m.faces = { { 0, 1, 4, 3 }, { 1, 2, 5, 4 }, { 3, 4, 7, 6 }, { 4, 5, 8 }, { 4, 8, 7 }, { 2, 10, 9, 8, 5 } };
  return m;
}

} // namespace lktest
