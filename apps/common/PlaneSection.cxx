#include "common/PlaneSection.h"
#include "vtkLKSectionLoops.h"

#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPlane.h>

#include <cmath>

namespace lkapp
{

std::vector<std::vector<Point3>> sectionLoops(vtkPolyData* surface, vtkImplicitFunction* function)
{
  std::vector<std::vector<Point3>> loops;
  for (std::vector<Point3>& line : lkvtk::sectionPolylines(surface, function))
    if (line.size() >= 8 && line.front() == line.back()) // open sections (at an open surface's border) are not loops
      loops.push_back(std::move(line));
  return loops;
}

std::vector<std::vector<Point3>> planeSectionLoops(
  vtkPolyData* surface, const Point3& origin, const Point3& normal, double beside)
{
  // A plane through a face's corners (a piece's cap, in its cut's plane)
  // has no defined section there: vtkCutter gives the face's edges, or
  // nothing. The plane can be moved along its normal, off such faces.
  double n[3] = { normal[0], normal[1], normal[2] };
  const double shift = vtkMath::Normalize(n) > 0.0 ? beside : 0.0;
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(origin[0] + shift * n[0], origin[1] + shift * n[1], origin[2] + shift * n[2]);
  plane->SetNormal(normal.data());
  return sectionLoops(surface, plane);
}

int nearestLoop(const std::vector<std::vector<Point3>>& loops, const Point3& p, double* distance)
{
  return lkvtk::nearestPolyline(loops, p, distance);
}

bool loopEncloses(const std::vector<Point3>& loop, const Point3& p, const Point3& normal)
{
  double n[3] = { normal[0], normal[1], normal[2] }, u[3], v[3];
  if (vtkMath::Normalize(n) == 0.0 || loop.size() < 4)
    return false;
  vtkMath::Perpendiculars(n, u, v, 0.0);
  // Coordinates in the plane, p at the origin; a ray along +u crosses the
  // edges that straddle v = 0 right of p.
  auto at = [&](const Point3& q) {
    const double d[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
    return std::array<double, 2>{ vtkMath::Dot(d, u), vtkMath::Dot(d, v) };
  };
  bool inside = false;
  std::array<double, 2> a = at(loop.back());
  for (const Point3& q : loop)
  {
    const std::array<double, 2> b = at(q);
    if ((a[1] > 0.0) != (b[1] > 0.0) && a[0] + (b[0] - a[0]) * (0.0 - a[1]) / (b[1] - a[1]) > 0.0)
      inside = !inside;
    a = b;
  }
  return inside;
}

std::vector<Point3> strokeAlongLoop(const std::vector<Point3>& loop, double step, double offset)
{
  std::vector<Point3> stroke;
  if (loop.size() < 2)
    return stroke;
  Point3 centre{ 0, 0, 0 };
  for (const Point3& p : loop)
    for (int c = 0; c < 3; ++c)
      centre[c] += p[c] / static_cast<double>(loop.size());
  double run = VTK_DOUBLE_MAX;
  for (std::size_t i = 0; i + 1 < loop.size(); ++i)
  {
    run += std::sqrt(vtkMath::Distance2BetweenPoints(loop[i + 1].data(), loop[i].data()));
    if (run < step)
      continue;
    run = 0;
    Point3 out{ 0, 0, 0 };
    for (int c = 0; c < 3; ++c)
      out[c] = loop[i][c] - centre[c];
    const double length = vtkMath::Norm(out.data());
    Point3 p = loop[i];
    for (int c = 0; c < 3; ++c)
      p[c] += length > 0 ? offset * out[c] / length : 0.0;
    stroke.push_back(p);
  }
  if (!stroke.empty())
    stroke.push_back(stroke.front()); // the pen comes back to where it started
  return stroke;
}

} // namespace lkapp
