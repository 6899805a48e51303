#include "common/PlaneSection.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCutter.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPlane.h>
#include <vtkStripper.h>

#include <cmath>

namespace lkapp
{

std::vector<std::vector<Point3>> sectionLoops(vtkPolyData* surface, vtkImplicitFunction* function)
{
  std::vector<std::vector<Point3>> loops;
  if (!surface || !function || surface->GetNumberOfPolys() == 0)
    return loops;
  vtkNew<vtkCutter> cutter;
  cutter->SetInputData(surface);
  cutter->SetCutFunction(function);
  vtkNew<vtkStripper> strip;
  strip->SetInputConnection(cutter->GetOutputPort());
  strip->JoinContiguousSegmentsOn();
  strip->Update();
  vtkPolyData* sections = strip->GetOutput();
  if (!sections->GetLines())
    return loops;
  auto it = vtk::TakeSmartPointer(sections->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    if (n < 8 || ids[0] != ids[n - 1])
      continue; // open sections (at an open surface's border) are not loops
    std::vector<Point3>& loop = loops.emplace_back(static_cast<std::size_t>(n));
    for (vtkIdType k = 0; k < n; ++k)
      sections->GetPoint(ids[k], loop[static_cast<std::size_t>(k)].data());
  }
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
  int best = -1;
  double nearest = VTK_DOUBLE_MAX;
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (const Point3& q : loops[l])
    {
      const double d = vtkMath::Distance2BetweenPoints(p.data(), q.data());
      if (d < nearest)
      {
        nearest = d;
        best = static_cast<int>(l);
      }
    }
  if (distance)
    *distance = best < 0 ? VTK_DOUBLE_MAX : std::sqrt(nearest);
  return best;
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
