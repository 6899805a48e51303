#pragma once
/// \file TriangleMesh.h
/// The plain triangle mesh the algorithm cores work on: shared points and
/// index triples. No topology is implied; see ManifoldRepair.h for that.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace lk
{

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<std::int64_t, 3>;

struct TriangleMesh
{
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;

  bool empty() const { return triangles.empty(); }
};

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

/// Checks that every index is in range and every used coordinate is finite.
/// Returns an empty string when the mesh is usable, else a sentence saying why not.
std::string validateTriangleMesh(const TriangleMesh& mesh);

} // namespace lk
