#pragma once
/// \file TriangleMesh.h
/// The plain triangle mesh the algorithm cores work on: shared points and
/// index triples. No topology is implied; see ManifoldRepair.h for that.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace lk
{

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<std::int64_t, 3>;

/// pi, for the cores' angles.
inline constexpr double kPi = 3.14159265358979323846;

struct TriangleMesh
{
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;

  bool empty() const { return triangles.empty(); }
};

/// The closest point of segment [a, b] to p (a when the segment is a point).
inline Vec3 closestPointOnSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  if (!(length2 > 0.0))
    return a;
  return a + ab * std::clamp(ab.dot(p - a) / length2, 0.0, 1.0);
}

/// The closest point of triangle (a, b, c) to p by Voronoi-region tests
/// (Ericson, "Real-Time Collision Detection", 5.1.5): a handful of dot
/// products. Inline: it sits in the closest-point tree's hot loop. A
/// degenerate triangle (two corners in one place, or all three on a line) is
/// the segment it spans: the region tests stay right for it, and where one
/// would divide by a zero edge length the closest of its edges is taken
/// (it returned NaN, and Metro's mean with it).
inline Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  auto onEdges = [&]() {
    const Vec3 x = closestPointOnSegment(p, a, b), y = closestPointOnSegment(p, b, c),
               z = closestPointOnSegment(p, c, a);
    const double dx = (x - p).squaredNorm(), dy = (y - p).squaredNorm(), dz = (z - p).squaredNorm();
    return dx <= dy && dx <= dz ? x : (dy <= dz ? y : z);
  };
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0)
    return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3)
    return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
    return d1 - d3 > 0.0 ? Vec3(a + ab * (d1 / (d1 - d3))) : onEdges(); // d1 - d3 = |ab|^2
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6)
    return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
    return d2 - d6 > 0.0 ? Vec3(a + ac * (d2 / (d2 - d6))) : onEdges(); // |ac|^2
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    const double bc2 = (d4 - d3) + (d5 - d6); // |bc|^2
    return bc2 > 0.0 ? Vec3(b + (c - b) * ((d4 - d3) / bc2)) : onEdges();
  }
  const double sum = va + vb + vc; // |ab x ac|^2
  if (!(sum > 0.0))
    return onEdges();
  const double denom = 1.0 / sum;
  return a + ab * (vb * denom) + ac * (vc * denom);
}

/// The angle at p between the directions to q and to r, in [0, pi]
/// (atan2 of |u x v| and u . v: accurate near 0 and pi, unlike acos).
inline double angleAt(const Vec3& p, const Vec3& q, const Vec3& r)
{
  const Vec3 u = q - p, v = r - p;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

/// Axis-aligned box.
struct Box3
{
  Vec3 min{ Vec3::Constant(std::numeric_limits<double>::infinity()) };
  Vec3 max{ Vec3::Constant(-std::numeric_limits<double>::infinity()) };
  void extend(const Vec3& p)
  {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void extend(const Box3& b)
  {
    min = min.cwiseMin(b.min);
    max = max.cwiseMax(b.max);
  }
  bool valid() const { return (min.array() <= max.array()).all(); }
  double diagonal() const { return valid() ? (max - min).norm() : 0.0; }
};

/// Bounding box of the points that triangles use (isolated points are ignored).
Box3 boundingBox(const TriangleMesh& mesh);

/// Area of triangle t.
double triangleArea(const TriangleMesh& mesh, std::size_t t);

/// Total area.
double surfaceArea(const TriangleMesh& mesh);

/// The largest coordinate magnitude a mesh may have (1e15, a million km in
/// mm). Larger ones come from corrupt files or overflow (VTK's OBJ reader
/// stores 1e309 as 3.4e38), and distance queries lose all precision there:
/// Metro's tree search could not prune and ran for hours.
constexpr double kLargestCoordinate = 1e15;

/// A finite point whose coordinates are at most kLargestCoordinate in magnitude.
inline bool isUsablePoint(const Vec3& p)
{
  return p.allFinite() && p.cwiseAbs().maxCoeff() <= kLargestCoordinate;
}

/// Why a point that is not usable is not: "a NaN or infinite coordinate" or
/// "a coordinate beyond 1e15 (a corrupt file or an overflow)".
inline const char* unusablePointReason(const Vec3& p)
{
  return p.allFinite() ? "a coordinate beyond 1e15 (a corrupt file or an overflow)" : "a NaN or infinite coordinate";
}

/// Checks that every index is in range and every used point is usable
/// (isUsablePoint). Returns an empty string when the mesh is usable, else a
/// sentence saying why not.
std::string validateTriangleMesh(const TriangleMesh& mesh);

} // namespace lk
