#include "vtkLKRaisedLabel.h"
#include "vtkLKRayCast.h"

#include <vtkAdaptiveSubdivisionFilter.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkContourFilter.h>
#include <vtkContourTriangulator.h>
#include <vtkDecimatePolylineFilter.h>
#include <vtkGenericCell.h>
#include <vtkImageData.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStaticCellLocator.h>
#include <vtkStripper.h>
#include <vtkTriangle.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVectorText.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace lkvtk
{

vtkSmartPointer<vtkPolyData> textOutline(const std::string& text, double height, double stroke, double edge)
{
  if (!(height > 0.0) || !(edge > 0.0) || !(stroke >= 0.0))
    return nullptr;
  vtkNew<vtkVectorText> source;
  source->SetText(text.c_str());
  source->Update();
  vtkPolyData* glyphs = source->GetOutput();
  if (glyphs->GetNumberOfPolys() == 0)
    return nullptr;
  double bounds[6];
  glyphs->GetBounds(bounds);
  if (!(bounds[3] > bounds[2]))
    return nullptr;
  // vtkVectorText's strokes are about 0.135 units wide (its digits and
  // capitals 1.1 units tall); thickened to `stroke` by growing the outline
  // by half the difference, within `height` all told.
  const double tall = bounds[3] - bounds[2];
  double scale = height / tall;
  if (0.135 * scale < stroke)
    scale = (height - stroke) / (tall - 0.135);
  if (!(scale > 0.0))
    return nullptr;
  const double grow = std::max(0.0, 0.5 * (stroke - 0.135 * scale));
  // The raster: pixels of a 25th of the stroke (0.04 mm at most), a margin
  // of the growth and two pixels all round.
  const double pixel = std::min(0.04, std::max(stroke, 0.135 * scale) / 25.0);
  const double margin = grow + 2.0 * pixel;
  const double x0 = bounds[0] * scale - margin, y0 = bounds[2] * scale - margin;
  const int nx = static_cast<int>(std::ceil(((bounds[1] - bounds[0]) * scale + 2.0 * margin) / pixel)) + 1;
  const int ny = static_cast<int>(std::ceil(((bounds[3] - bounds[2]) * scale + 2.0 * margin) / pixel)) + 1;
  std::vector<unsigned char> inside(static_cast<std::size_t>(nx) * ny, 0);
  // Each triangle's pixels (those whose centres it holds).
  auto it = vtk::TakeSmartPointer(glyphs->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 1; k + 1 < n; ++k) // a fan, for a polygon
    {
      double p[3][2];
      for (int c = 0; c < 3; ++c)
      {
        double x[3];
        glyphs->GetPoint(ids[c == 0 ? 0 : k + c - 1], x);
        p[c][0] = x[0] * scale;
        p[c][1] = x[1] * scale;
      }
      const double area = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
      if (std::abs(area) < 1e-18)
        continue;
      const int i0 = std::max(0, static_cast<int>(std::floor((std::min({ p[0][0], p[1][0], p[2][0] }) - x0) / pixel)));
      const int i1 = std::min(nx - 1, static_cast<int>(std::ceil((std::max({ p[0][0], p[1][0], p[2][0] }) - x0) / pixel)));
      const int j0 = std::max(0, static_cast<int>(std::floor((std::min({ p[0][1], p[1][1], p[2][1] }) - y0) / pixel)));
      const int j1 = std::min(ny - 1, static_cast<int>(std::ceil((std::max({ p[0][1], p[1][1], p[2][1] }) - y0) / pixel)));
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i)
        {
          const double x = x0 + i * pixel, y = y0 + j * pixel;
          double w[3];
          for (int c = 0; c < 3; ++c)
          {
            const double* a = p[(c + 1) % 3];
            const double* b = p[(c + 2) % 3];
            w[c] = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / area;
          }
          if (w[0] >= 0.0 && w[1] >= 0.0 && w[2] >= 0.0)
            inside[static_cast<std::size_t>(j) * nx + i] = 1;
        }
    }
  }
  // Thickened: every pixel within `grow` of one inside.
  if (grow > 0.0)
  {
    const int r = static_cast<int>(std::ceil(grow / pixel));
    std::vector<unsigned char> grown(inside.size(), 0);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        if (!inside[static_cast<std::size_t>(j) * nx + i])
          continue;
        for (int dj = -r; dj <= r; ++dj)
          for (int di = -r; di <= r; ++di)
          {
            const int a = i + di, b = j + dj;
            if (a >= 0 && b >= 0 && a < nx && b < ny && (di * di + dj * dj) * pixel * pixel <= grow * grow)
              grown[static_cast<std::size_t>(b) * nx + a] = 1;
          }
      }
    inside.swap(grown);
  }
  // Traced (marching squares halfway), and the outlines filled.
  vtkNew<vtkImageData> image;
  image->SetDimensions(nx, ny, 1);
  image->SetOrigin(x0, y0, 0.0);
  image->SetSpacing(pixel, pixel, 1.0);
  vtkNew<vtkUnsignedCharArray> values;
  values->SetName("inside");
  values->SetNumberOfValues(static_cast<vtkIdType>(inside.size()));
  for (std::size_t k = 0; k < inside.size(); ++k)
    values->SetValue(static_cast<vtkIdType>(k), inside[k]);
  image->GetPointData()->SetScalars(values);
  vtkNew<vtkContourFilter> trace;
  trace->SetInputData(image);
  trace->SetValue(0, 0.5);
  // The traced loops thinned where they run straight (within a quarter of
  // a pixel), then filled.
  vtkNew<vtkStripper> loops;
  loops->SetInputConnection(trace->GetOutputPort());
  loops->SetMaximumLength(std::numeric_limits<int>::max() / 2);
  loops->JoinContiguousSegmentsOn();
  vtkNew<vtkDecimatePolylineFilter> thin;
  thin->SetInputConnection(loops->GetOutputPort());
  thin->SetTargetReduction(1.0);
  loops->Update();
  thin->SetMaximumError(0.25 * pixel / std::max(pixel, loops->GetOutput()->GetLength())); // of the bounds' diagonal
  thin->Update();
  // Each loop wound as vtkContourTriangulator reads holes: counter-clockwise
  // inside an even number of others (an outline), clockwise inside an odd
  // number (a hole; the stripper keeps no winding).
  vtkPolyData* thinned = thin->GetOutput();
  std::vector<std::vector<std::array<double, 2>>> rings;
  auto line = vtk::TakeSmartPointer(thinned->GetLines()->NewIterator());
  for (line->GoToFirstCell(); !line->IsDoneWithTraversal(); line->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    line->GetCurrentCell(n, ids);
    if (n > 1 && ids[0] == ids[n - 1])
      --n; // the closing point once
    if (n < 3)
      continue;
    rings.emplace_back();
    for (vtkIdType k = 0; k < n; ++k)
    {
      double x[3];
      thinned->GetPoint(ids[k], x);
      rings.back().push_back({ x[0], x[1] });
    }
  }
  auto contains = [](const std::vector<std::array<double, 2>>& ring, const std::array<double, 2>& p) {
    bool in = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
      if ((ring[i][1] > p[1]) != (ring[j][1] > p[1]) &&
        p[0] < (ring[j][0] - ring[i][0]) * (p[1] - ring[i][1]) / (ring[j][1] - ring[i][1]) + ring[i][0])
        in = !in;
    return in;
  };
  vtkNew<vtkPoints> ringPoints;
  ringPoints->SetDataTypeToDouble();
  vtkNew<vtkCellArray> ringLines;
  for (std::size_t r = 0; r < rings.size(); ++r)
  {
    int depth = 0;
    for (std::size_t q = 0; q < rings.size(); ++q)
      depth += q != r && contains(rings[q], rings[r][0]);
    double area = 0.0;
    for (std::size_t i = 0, j = rings[r].size() - 1; i < rings[r].size(); j = i++)
      area += rings[r][j][0] * rings[r][i][1] - rings[r][i][0] * rings[r][j][1];
    if ((area > 0.0) != (depth % 2 == 0))
      std::reverse(rings[r].begin(), rings[r].end());
    const auto first = ringPoints->GetNumberOfPoints();
    for (const auto& x : rings[r])
      ringPoints->InsertNextPoint(x[0], x[1], 0.0);
    ringLines->InsertNextCell(static_cast<vtkIdType>(rings[r].size()) + 1);
    for (vtkIdType k = 0; k < static_cast<vtkIdType>(rings[r].size()); ++k)
      ringLines->InsertCellPoint(first + k);
    ringLines->InsertCellPoint(first);
  }
  vtkNew<vtkPolyData> wound;
  wound->SetPoints(ringPoints);
  wound->SetLines(ringLines);
  vtkNew<vtkContourTriangulator> fill;
  fill->SetInputData(wound);
  vtkNew<vtkAdaptiveSubdivisionFilter> split;
  split->SetInputConnection(fill->GetOutputPort());
  split->SetMaximumEdgeLength(edge);
  split->Update();
  vtkPolyData* filled = split->GetOutput();
  if (filled->GetNumberOfPolys() == 0)
    return nullptr;
  // Counter-clockwise from +z, the text's corner at (0, 0).
  double b[6];
  filled->GetBounds(b);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (vtkIdType i = 0; i < filled->GetNumberOfPoints(); ++i)
  {
    double x[3];
    filled->GetPoint(i, x);
    points->InsertNextPoint(x[0] - b[0], x[1] - b[2], 0.0);
  }
  vtkNew<vtkCellArray> triangles;
  auto t = vtk::TakeSmartPointer(filled->GetPolys()->NewIterator());
  for (t->GoToFirstCell(); !t->IsDoneWithTraversal(); t->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    t->GetCurrentCell(n, ids);
    if (n != 3)
      continue;
    double p[3][3];
    for (int c = 0; c < 3; ++c)
      points->GetPoint(ids[c], p[c]);
    const double area = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
    if (area == 0.0)
      continue;
    const vtkIdType ccw[3] = { ids[0], area > 0.0 ? ids[1] : ids[2], area > 0.0 ? ids[2] : ids[1] };
    triangles->InsertNextCell(3, ccw);
  }
  auto outline = vtkSmartPointer<vtkPolyData>::New();
  outline->SetPoints(points);
  outline->SetPolys(triangles);
  return outline;
}

vtkSmartPointer<vtkPolyData> raisedLabel(vtkPolyData* surface, vtkPolyData* outline, const double origin[3],
  const double xAxis[3], const double yAxis[3], double relief, double depth, std::string& why)
{
  why.clear();
  if (!surface || surface->GetNumberOfCells() == 0 || !outline || outline->GetNumberOfPolys() == 0)
  {
    why = "nothing to put the text on, or no text";
    return nullptr;
  }
  double up[3];
  vtkMath::Cross(xAxis, yAxis, up);
  vtkMath::Normalize(up);
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(surface);
  locator->BuildLocator();
  double centre[3];
  surface->GetCenter(centre);
  const vtkIdType count = outline->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(2 * count); // 0..count-1 on top, then beneath
  vtkNew<vtkGenericCell> cell;
  const double facing = 0.5; // cos 60 degrees
  for (vtkIdType i = 0; i < count; ++i)
  {
    double p[3];
    outline->GetPoint(i, p);
    double base[3];
    for (int c = 0; c < 3; ++c)
      base[c] = origin[c] + p[0] * xAxis[c] + p[1] * yAxis[c];
    const double reach = surface->GetLength() + std::sqrt(vtkMath::Distance2BetweenPoints(base, centre)) + 1.0;
    double from[3], to[3];
    for (int c = 0; c < 3; ++c)
    {
      from[c] = base[c] + reach * up[c];
      to[c] = base[c] - reach * up[c];
    }
    double hit[3];
    if (!lkvtk::firstHit(locator, from, to, cell, hit))
    {
      why = "the text would reach beyond the surface";
      return nullptr;
    }
    double normal[3] = { 0, 0, 0 };
    vtkPoints* corners = cell->GetPoints();
    if (corners->GetNumberOfPoints() >= 3)
    {
      double a[3], b[3], c[3];
      corners->GetPoint(0, a);
      corners->GetPoint(1, b);
      corners->GetPoint(2, c);
      vtkTriangle::ComputeNormal(a, b, c, normal);
    }
    if (vtkMath::Dot(normal, up) < facing)
    {
      why = "the text would lie over a face turned away from it (an edge, a slot or a hole)";
      return nullptr;
    }
    double top[3], beneath[3];
    for (int c = 0; c < 3; ++c)
    {
      top[c] = hit[c] + relief * up[c];
      beneath[c] = hit[c] - depth * up[c];
    }
    points->SetPoint(i, top);
    points->SetPoint(count + i, beneath);
  }
  // The top as the outline (counter-clockwise, facing up), the bottom
  // reversed, and a wall under each border edge (used by one triangle),
  // facing out of it.
  vtkNew<vtkCellArray> faces;
  std::map<std::pair<vtkIdType, vtkIdType>, int> uses;
  std::vector<std::pair<vtkIdType, vtkIdType>> directed;
  auto it = vtk::TakeSmartPointer(outline->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    if (n != 3)
      continue;
    faces->InsertNextCell({ ids[0], ids[1], ids[2] });
    faces->InsertNextCell({ count + ids[0], count + ids[2], count + ids[1] });
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType a = ids[k], b = ids[(k + 1) % 3];
      ++uses[{ std::min(a, b), std::max(a, b) }];
      directed.emplace_back(a, b);
    }
  }
  for (const auto& [a, b] : directed)
    if (uses[{ std::min(a, b), std::max(a, b) }] == 1)
    {
      faces->InsertNextCell({ count + a, count + b, b });
      faces->InsertNextCell({ count + a, b, a });
    }
  auto solid = vtkSmartPointer<vtkPolyData>::New();
  solid->SetPoints(points);
  solid->SetPolys(faces);
  return solid;
}

} // namespace lkvtk
