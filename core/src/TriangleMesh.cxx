#include "latticekit/TriangleMesh.h"

#include <cmath>
#include <sstream>

namespace lk
{

Box3 boundingBox(const TriangleMesh& mesh)
{
  Box3 box;
  for (const Triangle& t : mesh.triangles)
  {
    for (auto id : t)
    {
      box.extend(mesh.points[static_cast<std::size_t>(id)]);
    }
  }
  return box;
}

double triangleArea(const TriangleMesh& mesh, std::size_t t)
{
  const Triangle& tri = mesh.triangles[t];
  const Vec3& a = mesh.points[static_cast<std::size_t>(tri[0])];
  const Vec3& b = mesh.points[static_cast<std::size_t>(tri[1])];
  const Vec3& c = mesh.points[static_cast<std::size_t>(tri[2])];
  return 0.5 * (b - a).cross(c - a).norm();
}

double surfaceArea(const TriangleMesh& mesh)
{
  double area = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
  {
    area += triangleArea(mesh, t);
  }
  return area;
}

std::string validateTriangleMesh(const TriangleMesh& mesh)
{
  if (mesh.triangles.empty())
  {
    return "the mesh has no triangles";
  }
  const auto n = static_cast<std::int64_t>(mesh.points.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
  {
    for (auto id : mesh.triangles[t])
    {
      if (id < 0 || id >= n)
      {
        std::ostringstream os;
        os << "triangle " << t << " refers to point " << id << ", but the mesh has " << n
           << " points";
        return os.str();
      }
      const Vec3& p = mesh.points[static_cast<std::size_t>(id)];
      if (!isUsablePoint(p))
      {
        std::ostringstream os;
        os << "point " << id << " (used by triangle " << t << ") has " << unusablePointReason(p);
        return os.str();
      }
    }
  }
  return {};
}

} // namespace lk
