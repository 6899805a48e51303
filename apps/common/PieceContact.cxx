#include "common/PieceContact.h"

#include "common/CutReport.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkKdTreePointLocator.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyDataNormals.h>
#include <vtkSelectEnclosedPoints.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace lkapp
{

struct ContactSurface::Tools
{
  /// The surface's triangles with outward cell normals (a closed surface),
  /// and a locator on them.
  vtkSmartPointer<vtkPolyData> oriented;
  vtkDataArray* normals = nullptr;
  vtkNew<vtkStaticCellLocator> locator;
  vtkNew<vtkKdTreePointLocator> vertices;
  // IsInsideSurface is not const (it keeps its ray's work): the tools are
  // this surface's own.
  vtkNew<vtkSelectEnclosedPoints> enclosed;
};

ContactSurface::ContactSurface(vtkPolyData* surface)
  : Surface(surface)
  , tools(new Tools)
{
  surface->GetBounds(Bounds);
  if (surface->GetNumberOfCells() == 0)
    return;
  Closed = pieceFacts(surface).openEdges == 0;
  tools->oriented = surface;
  if (Closed)
  {
    // Outward normals whatever the input's order: the side of a point off a
    // face then tells inside from outside without a ray.
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(surface);
    normals->ComputePointNormalsOff();
    normals->ComputeCellNormalsOn();
    normals->SplittingOff();
    normals->ConsistencyOn();
    normals->AutoOrientNormalsOn();
    normals->Update();
    tools->oriented = normals->GetOutput();
    tools->normals = tools->oriented->GetCellData()->GetNormals();
    tools->enclosed->Initialize(surface);
  }
  tools->locator->SetDataSet(tools->oriented);
  tools->locator->BuildLocator();
  tools->vertices->SetDataSet(surface);
  tools->vertices->BuildLocator();
}

double ContactSurface::vertexDistance(const double x[3]) const
{
  if (Surface->GetNumberOfCells() == 0) // no locator: a surface of no faces is nowhere
    return std::numeric_limits<double>::infinity();
  double y[3];
  Surface->GetPoint(tools->vertices->FindClosestPoint(x), y);
  return std::sqrt(vtkMath::Distance2BetweenPoints(x, y));
}

ContactSurface::~ContactSurface()
{
  if (Closed)
    tools->enclosed->Complete();
}

double ContactSurface::distance(const double x[3], bool* inside) const
{
  if (inside)
    *inside = false;
  if (Surface->GetNumberOfCells() == 0)
    return std::numeric_limits<double>::infinity();
  double closest[3], d2 = 0.0;
  vtkIdType cell = -1;
  int sub = 0;
  tools->locator->FindClosestPoint(x, closest, cell, sub, d2);
  const double d = std::sqrt(d2);
  if (!inside || !Closed || d == 0.0)
    return d;
  // Off the inside of a face (the way to it along the face's normal) the
  // normal's side decides; nearest an edge or a corner, where the faces
  // around disagree, a ray does.
  double n[3];
  tools->normals->GetTuple(cell, n);
  const double along = (x[0] - closest[0]) * n[0] + (x[1] - closest[1]) * n[1] + (x[2] - closest[2]) * n[2];
  if (std::abs(along) >= 0.99 * d)
    *inside = along < 0.0;
  else
    *inside = tools->enclosed->IsInsideSurface(x[0], x[1], x[2]) != 0;
  return d;
}

bool ContactSurface::nearBounds(const double x[3], double margin) const
{
  for (int i = 0; i < 3; ++i)
    if (x[i] < Bounds[2 * i] - margin || x[i] > Bounds[2 * i + 1] + margin)
      return false;
  return true;
}

std::array<double, 3> placedPoint(const std::array<double, 16>& m, const std::array<double, 3>& x)
{
  std::array<double, 3> y;
  for (std::size_t i = 0; i < 3; ++i)
    y[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
  return y;
}

namespace
{

/// The inverse of a rigid transform: the rotation's transpose, and the
/// translation turned back.
std::array<double, 16> rigidInverse(const std::array<double, 16>& m)
{
  std::array<double, 16> inv{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      inv[4 * i + j] = m[4 * j + i];
  for (std::size_t i = 0; i < 3; ++i)
    inv[4 * i + 3] = -(inv[4 * i] * m[3] + inv[4 * i + 1] * m[7] + inv[4 * i + 2] * m[11]);
  inv[15] = 1.0;
  return inv;
}

/// Every vertex of `from` (placed by `place`) against `to`: the nearest
/// distance of those outside, and the deepest of those inside.
void vertexPass(const ContactSurface& from, const std::array<double, 16>& place, const ContactSurface& to, double touch,
  bool insideKnown, Contact& c, double& nearest, vtkPoints* insidePoints, const std::array<double, 16>* show)
{
  vtkPolyData* surface = from.surface();
  vtkPoints* points = surface->GetPoints();
  if (!points || to.surface()->GetNumberOfCells() == 0)
    return;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> x;
    points->GetPoint(i, x.data());
    const std::array<double, 3> y = placedPoint(place, x);
    // Beyond `nearest` from the other's bounds a vertex is neither inside
    // it nor nearer it than a vertex already measured.
    if (!to.nearBounds(y.data(), nearest))
      continue;
    // A vertex outside the other's bounds, or within `touch` of its
    // surface, is not inside it.
    bool inside = false;
    const double d = to.distance(y.data(), insideKnown && to.nearBounds(y.data(), 0.0) ? &inside : nullptr);
    if (inside && d > touch)
    {
      c.overlap = true;
      c.depth = std::max(c.depth, d);
      ++c.inside;
      if (insidePoints)
        insidePoints->InsertNextPoint(placedPoint(*show, x).data());
    }
    else
      nearest = std::min(nearest, d);
  }
}
} // namespace

Contact contactOf(const ContactSurface& moved, const std::array<double, 16>& matrix, const ContactSurface& fixed,
  double touch, vtkPoints* insidePoints)
{
  Contact c;
  c.known = moved.closed() && fixed.closed();
  // A first bound on the gap, cheaply: the nearest pair of vertices.
  double nearest = std::numeric_limits<double>::infinity();
  if (moved.surface()->GetNumberOfPoints() > 0 && fixed.surface()->GetNumberOfPoints() > 0)
  {
    vtkPoints* points = moved.surface()->GetPoints();
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      std::array<double, 3> x;
      points->GetPoint(i, x.data());
      const std::array<double, 3> y = placedPoint(matrix, x);
      if (fixed.nearBounds(y.data(), nearest))
        nearest = std::min(nearest, fixed.vertexDistance(y.data()));
    }
  }
  // The moved piece's vertices are shown where the matrix puts them, the
  // fixed piece's where they are.
  const std::array<double, 16> identity{ 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  vertexPass(moved, matrix, fixed, touch, c.known, c, nearest, insidePoints, &matrix);
  vertexPass(fixed, rigidInverse(matrix), moved, touch, c.known, c, nearest, insidePoints, &identity);
  c.gap = c.overlap ? 0.0 : nearest;
  return c;
}

std::string contactText(const Contact& c)
{
  char text[200];
  if (c.overlap)
    std::snprintf(text, sizeof text, "overlapping %.2f mm deep (%lld vertices inside)", c.depth, c.inside);
  else if (!std::isfinite(c.gap))
    std::snprintf(text, sizeof text, "nothing to measure (an empty piece)");
  else
    std::snprintf(text, sizeof text, "%.2f mm apart%s", c.gap,
      c.known ? "" : " at the nearest vertex (an open piece: an overlap cannot be told)");
  return text;
}

} // namespace lkapp
