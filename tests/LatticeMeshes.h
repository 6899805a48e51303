#pragma once
/// \file LatticeMeshes.h
/// Small closed and open lattices for the lattice-surface tests.

#include "TestMeshes.h"
#include "latticekit/PolygonMesh.h"

#include <cmath>
#include <cstddef>
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

/// A lattice of triangles from point and face arrays.
template <std::size_t P, std::size_t F>
inline lk::PolygonMesh triangleLattice(const double (&points)[P][3], const int (&faces)[F][3])
{
  lk::PolygonMesh m;
  for (const auto& p : points)
  {
    m.points.emplace_back(p[0], p[1], p[2]);
  }
  for (const auto& f : faces)
  {
    m.faces.push_back({ f[0], f[1], f[2] });
  }
  return m;
}

/// Three vertex stars of the 1,000-vertex lattice fitted to the bundled CT
/// head's -400 HU surface (genus 253, crumpled at that size) or of a refined
/// lattice of its outer skin (bench_fit's models), coordinates in
/// mm around one face's centre, rounded to 0.01. The stars of a face's three
/// vertices hold every lattice face its patches depend on, so those patches
/// are the full lattice's. Where the stars pinch, the pinched vertex has a
/// copy (same coordinates) to keep them a manifold.
/// Face { 3, 14, 35 }: the centre lies almost along an edge-curve midpoint's
/// normal, and the plain projection left the inner curve a start tangent 2 %
/// of its length: the cross-boundary derivative fitted to it put a Gregory
/// interior point 663 mm out, and the surface 42 mm outside the stars'
/// bounding box (diagonal 108 mm). Vertices 9 and 41 coincide.
inline lk::PolygonMesh crumpledStarsShortInnerTangent()
{
  const double points[][3] = {
    { 2.93, -6.6, 31.06 }, { 2.25, -35.39, 51.27 }, { -0.82, -1.15, 28.48 }, { -7.48, -8.53, 6.4 },
    { 0.33, -4.07, 31.19 }, { 1.23, -2.55, 34.54 }, { -2.13, -2.16, 27.35 }, { -12.85, -11.35, 14.72 },
    { -8.08, -12.71, 7.96 }, { -13.21, -9.5, 2.26 }, { 6.08, -8.21, 36.54 }, { -6.67, -4.6, 34.86 },
    { -7, -14.02, 33.89 }, { -13.79, 0.44, 15.57 }, { -11.7, 5.37, 19.38 }, { -11.32, -1.34, 31.66 },
    { -10.28, 4.33, 11.88 }, { -15.51, 3.44, 26 }, { -10.49, -6.13, 2.67 }, { -2.63, 6.16, 24.77 },
    { -7.2, 10.45, 28.85 }, { -3.05, 5.45, 33.54 }, { -13.36, -2.03, 6.93 }, { -0.98, 5.42, 29.24 },
    { 4.45, 3.37, 32.92 }, { -13.8, 13.22, 16.64 }, { -6.56, 6.5, 38.41 }, { 3.84, 2.09, 39.53 },
    { -11.85, 11.79, 20.04 }, { -8.44, 5.26, 17.81 }, { -9.68, 10.8, 23.02 }, { -14.5, 6.79, 10.43 },
    { -19.14, -1.7, -6.76 }, { -12.9, 8.62, 19.96 }, { -20.41, 2.46, -30.52 }, { 19.18, 3.17, -25.78 },
    { -20.71, -12.79, -8.51 }, { -6.84, -2.51, -1.3 }, { -16.59, 0.08, -13.51 }, { -9.66, -3.2, -13.15 },
    { -8.72, 23.31, 14.22 }, { -13.21, -9.5, 2.26 }
  };
  const int faces[][3] = {
    { 35, 34, 36 }, { 34, 35, 39 }, { 35, 38, 39 }, { 35, 32, 38 }, { 40, 32, 35 }, { 9, 35, 36 },
    { 35, 37, 40 }, { 35, 18, 37 }, { 22, 18, 35 }, { 13, 3, 41 }, { 9, 12, 35 }, { 3, 35, 12 },
    { 3, 14, 35 }, { 14, 22, 35 }, { 41, 3, 0 }, { 13, 16, 3 }, { 7, 3, 17 }, { 17, 3, 16 },
    { 22, 14, 33 }, { 14, 30, 31 }, { 31, 33, 14 }, { 8, 3, 15 }, { 3, 8, 1 }, { 3, 7, 15 },
    { 30, 14, 29 }, { 25, 29, 14 }, { 0, 3, 2 }, { 12, 2, 3 }, { 14, 3, 1 }, { 25, 14, 28 },
    { 14, 19, 28 }, { 14, 23, 19 }, { 20, 14, 1 }, { 14, 20, 21 }, { 6, 14, 5 }, { 14, 4, 5 },
    { 23, 14, 27 }, { 11, 4, 14 }, { 14, 26, 11 }, { 10, 26, 14 }, { 14, 21, 10 }, { 14, 6, 24 },
    { 14, 24, 27 }
  };
  return triangleLattice(points, faces);
}

/// Face { 20, 1, 0 } (vertex 20 has 30 neighbours): the tangent planes at the
/// ends of one of its edges are turned against each other, so the mean of the
/// ends' basis vectors b, the edge midpoint's, is nearly zero, and a patch
/// reached 3.2 times its corners' extent. Vertices 25 and 32 coincide.
inline lk::PolygonMesh crumpledStarsTwistedEdge()
{
  const double points[][3] = {
    { 0.58, 9.85, 3.3 }, { 2.96, -0.17, 7.59 }, { -1.52, 3.28, -2.66 }, { 2.36, -40.04, -1.36 },
    { -36.12, -38.82, 8.9 }, { 0.74, -20.29, -20.77 }, { 3.36, -35.84, -0.09 }, { 5.88, -23.63, 5.2 },
    { 10.51, -28.3, -12.15 }, { -0.54, -35.51, 0.25 }, { 3.88, -23.46, 0.26 }, { -5.25, -10.84, 19.33 },
    { 7.36, -23.95, -11.31 }, { 0.59, -22.29, 6.5 }, { 1.37, -19.68, 3.69 }, { 4.32, -9.36, 7.44 },
    { 7.96, -14.87, -11.92 }, { 0.48, -17.44, 4.36 }, { 0.67, -25.62, 8.98 }, { 8.06, -15.26, 4.4 },
    { -3.54, -9.68, -10.89 }, { 0.96, -22.45, 3.85 }, { 6.08, -14.84, -14.1 }, { 6.64, 0.06, 16.49 },
    { 9.54, -11.5, -10.44 }, { -22.12, -6.92, 20.38 }, { -0.02, -9.93, -10.25 }, { 2.74, -11.19, -6.31 },
    { 7.46, -8.99, 9.81 }, { 21.07, 22.46, 6.11 }, { 3.44, -5.05, -4.56 }, { -1.04, -8.16, -12.05 },
    { -22.12, -6.92, 20.38 }
  };
  const int faces[][3] = {
    { 20, 5, 12 }, { 22, 20, 8 }, { 20, 12, 8 }, { 20, 24, 31 }, { 20, 31, 26 }, { 20, 9, 5 },
    { 20, 16, 24 }, { 27, 20, 30 }, { 26, 30, 20 }, { 20, 22, 16 }, { 29, 20, 27 }, { 20, 29, 2 },
    { 29, 0, 2 }, { 4, 9, 20 }, { 6, 20, 7 }, { 20, 10, 7 }, { 4, 20, 11 }, { 20, 13, 10 }, { 20, 14, 13 },
    { 20, 25, 17 }, { 20, 6, 3 }, { 20, 17, 21 }, { 21, 19, 20 }, { 14, 20, 19 }, { 20, 2, 1 },
    { 23, 2, 0 }, { 20, 1, 0 }, { 18, 20, 3 }, { 20, 18, 11 }, { 25, 20, 0 }, { 1, 23, 0 }, { 32, 1, 15 },
    { 1, 28, 15 }, { 1, 2, 28 }, { 1, 32, 23 }, { 0, 29, 25 }
  };
  return triangleLattice(points, faces);
}

/// The same from the outer skin's refined 2,000-vertex lattice, face
/// { 3, 6, 5 }: eq. 2.2 gave an edge curve end tangents longer than its
/// chord, the curve all but stopped at its midpoint (C'(1/2) nearly zero),
/// and a split patch fitted to it reached 4.6 times its corners'
/// extent.
inline lk::PolygonMesh crumpledStarsLongTangents()
{
  const double points[][3] = {
    { -15.91, 15.84, -9.96 }, { -16.37, 19.24, -5.96 }, { -6.11, 4.56, -10.2 }, { -2.6, 2.21, -0.65 },
    { -4.58, 10.68, 2.77 }, { -4.48, 3.99, -2.41 }, { 7.08, -6.2, 3.07 }, { 6.41, -6.93, -3.8 },
    { -1.56, 8.19, 2.56 }, { 4.51, 0.14, 6.17 }, { 15.76, -12.44, -0.83 }, { 8.25, -3.72, 7.73 },
    { 16.63, -10.14, 8.27 }
  };
  const int faces[][3] = {
    { 2, 3, 0 }, { 2, 7, 3 }, { 1, 0, 3 }, { 6, 7, 10 }, { 4, 1, 3 }, { 6, 3, 7 }, { 3, 6, 5 },
    { 3, 5, 4 }, { 5, 8, 4 }, { 10, 12, 6 }, { 8, 5, 9 }, { 12, 11, 6 }, { 6, 11, 5 }, { 11, 9, 5 }
  };
  return triangleLattice(points, faces);
}

/// The 1,000-vertex head lattice again, refined with the bounds above, face
/// { 19, 5, 6 }: at one edge's midpoint the mean of the ends' b was nearly
/// along C'(1/2) (the fit's basis almost degenerate, k = 2,820), and a patch
/// reached 9.2 times its corners' extent. Vertices 21, 22 and 23 are copies of
/// 0, 11 and 18.
inline lk::PolygonMesh crumpledStarsMidpointBasisAlongTheCurve()
{
  const double points[][3] = {
    { -7.19, -2.53, -2.75 }, { -3.28, -4.89, -3.36 }, { -1.71, -2.48, -4.25 }, { 1.13, -2.15, -6.33 },
    { 0.14, -2.91, -6.52 }, { -1.31, -0.73, -1.64 }, { -2.48, -2.35, 1.02 }, { 0.29, -2.57, -3.96 },
    { -2.05, 2.49, -1.33 }, { -3.93, 0.34, 0.79 }, { -0.42, -3.53, 0.58 }, { -3.14, -2.58, -2.67 },
    { -19.93, 36.5, -0.57 }, { -4.29, 0.72, 1.7 }, { -1.31, 1.99, -3.64 }, { 0.55, -1.46, -1.22 },
    { -1.79, -0.58, -0.41 }, { -2.66, -3.09, -2.18 }, { -4.88, 0.62, 1.02 }, { 3.78, 3.08, 0.62 },
    { 11.12, 6.14, -7.83 }, { -7.19, -2.53, -2.75 }, { -3.14, -2.58, -2.67 }, { -4.88, 0.62, 1.02 }
  };
  const int faces[][3] = {
    { 1, 5, 2 }, { 5, 15, 2 }, { 12, 20, 19 }, { 5, 4, 0 }, { 5, 1, 4 }, { 10, 17, 5 }, { 11, 21, 6 },
    { 12, 6, 21 }, { 8, 5, 0 }, { 5, 9, 3 }, { 7, 5, 3 }, { 5, 7, 16 }, { 16, 10, 5 }, { 8, 11, 6 },
    { 19, 20, 18 }, { 17, 15, 5 }, { 5, 8, 6 }, { 5, 13, 14 }, { 23, 5, 14 }, { 9, 5, 23 }, { 19, 22, 13 },
    { 19, 13, 5 }, { 19, 18, 22 }, { 12, 19, 6 }, { 19, 5, 6 }
  };
  return triangleLattice(points, faces);
}

/// The icosphere of radius 1 after two subdivisions (162 vertices, 320
/// triangles), crumpled: each vertex moved in or out by up to half the
/// radius and across by up to 0.15, by a fixed hash of its index (no random
/// generator, so the lattice is the same everywhere). Many of its edges fold
/// sharply, as on decimated or refined lattices of noisy skin.
inline lk::PolygonMesh crumpledIcosphereLattice()
{
  lk::PolygonMesh m = lk::asPolygonMesh(icosphere(2, 1.0));
  for (std::size_t i = 0; i < m.points.size(); ++i)
  {
    auto hash = [i](double k) {
      const double x = std::sin(12.9898 * static_cast<double>(i) + 78.233 * k) * 43758.5453;
      return 2.0 * (x - std::floor(x)) - 1.0;
    };
    m.points[i] = m.points[i] * (1.0 + 0.5 * hash(1)) + 0.15 * lk::Vec3(hash(2), hash(3), hash(4));
  }
  return m;
}

} // namespace lktest
