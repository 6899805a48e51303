#include "CutReport.h"
#include "ScanOnPlane.h"
#include "vtkLKOpenEdges.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkFieldData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkMassProperties.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPlane.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace lkapp
{

PieceFacts pieceFacts(vtkPolyData* piece)
{
  PieceFacts facts;
  facts.faces = piece->GetNumberOfPolys();
  facts.openEdges = lkvtk::countOpenEdges(piece); // ids below 2^32: the cut refuses larger meshes
  if (vtkDataArray* cap = piece->GetCellData()->GetArray("Cap"))
  {
    const vtkIdType first = piece->GetNumberOfVerts() + piece->GetNumberOfLines();
    for (vtkIdType cell = first; cell < first + facts.faces; ++cell)
      facts.capFaces += cap->GetTuple1(cell) > 0.5;
  }
  if (facts.openEdges == 0 && facts.faces > 0)
  {
    vtkNew<vtkTriangleFilter> triangles; // a lattice's quads and n-gons
    triangles->SetInputData(piece);
    vtkNew<vtkMassProperties> mass;
    mass->SetInputConnection(triangles->GetOutputPort());
    mass->Update();
    facts.volume = mass->GetVolume();
  }
  return facts;
}

std::string pieceFactsText(const PieceFacts& facts)
{
  char text[128];
  if (facts.openEdges == 0)
    std::snprintf(text, sizeof text, ", closed, volume %.4g ml", facts.volume / 1000.0);
  else
    std::snprintf(text, sizeof text, ", open: %lld border edges", static_cast<long long>(facts.openEdges));
  return text;
}

std::vector<LineFacts> lineFacts(vtkPolyData* lines)
{
  std::vector<LineFacts> out;
  if (!lines || !lines->GetLines())
    return out;
  auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    LineFacts f;
    // Closed: it ends where it starts (the same point, or a copy of it).
    double first[3], last[3];
    if (n > 0)
    {
      lines->GetPoint(ids[0], first);
      lines->GetPoint(ids[n - 1], last);
    }
    f.closed = n > 3 && (ids[0] == ids[n - 1] || vtkMath::Distance2BetweenPoints(first, last) == 0.0);
    const vtkIdType m = f.closed ? n - 1 : n; // the closing repeat once
    f.vertices = m;
    vtkNew<vtkPoints> pts;
    for (vtkIdType k = 0; k < m; ++k)
      pts->InsertNextPoint(lines->GetPoint(ids[k]));
    double weighted[3] = { 0, 0, 0 };
    for (vtkIdType k = 0; k + 1 < n; ++k)
    {
      double a[3], b[3];
      lines->GetPoint(ids[k], a);
      lines->GetPoint(ids[k + 1], b);
      const double l = std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
      f.length += l;
      for (int i = 0; i < 3; ++i)
        weighted[i] += 0.5 * l * (a[i] + b[i]);
    }
    double origin[3];
    vtkPlane::ComputeBestFittingPlane(pts, origin, f.normal);
    for (int i = 0; i < 3; ++i)
      f.centre[i] = f.length > 0.0 ? weighted[i] / f.length : origin[i];
    for (vtkIdType k = 0; k < m; ++k)
    {
      double p[3];
      pts->GetPoint(k, p);
      f.flatness = std::max(f.flatness,
        std::abs(vtkMath::Dot(f.normal, p) - vtkMath::Dot(f.normal, f.centre)));
    }
    if (f.closed)
    {
      // The vector area of the loop along the normal, and its extent in the
      // plane as the CT picture of it shows the plane.
      const ViewFrame frame = viewFrame({ f.centre[0], f.centre[1], f.centre[2] }, { f.normal[0], f.normal[1], f.normal[2] });
      double lowest[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX }, highest[2] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
      double twice = 0.0;
      for (vtkIdType k = 0; k < m; ++k)
      {
        double p[3], q[3];
        pts->GetPoint(k, p);
        pts->GetPoint((k + 1) % m, q);
        const auto a = inFrame(frame, { p[0], p[1], p[2] }), b = inFrame(frame, { q[0], q[1], q[2] });
        twice += a[0] * b[1] - b[0] * a[1];
        for (int i = 0; i < 2; ++i)
        {
          lowest[i] = std::min(lowest[i], a[static_cast<std::size_t>(i)]);
          highest[i] = std::max(highest[i], a[static_cast<std::size_t>(i)]);
        }
      }
      f.area = 0.5 * std::abs(twice);
      f.extentRight = highest[0] - lowest[0];
      f.extentUp = highest[1] - lowest[1];
      const std::array<double, 3> down{ -frame.up[0], -frame.up[1], -frame.up[2] },
        left{ -frame.right[0], -frame.right[1], -frame.right[2] };
      f.upAxis = std::string(directionLetter(frame.up)) + "-" + directionLetter(down);
      f.rightAxis = std::string(directionLetter(left)) + "-" + directionLetter(frame.right);
    }
    out.push_back(f);
  }
  return out;
}

LinesApart linesApart(const LineFacts& a, const LineFacts& b)
{
  LinesApart apart;
  apart.distance = std::sqrt(vtkMath::Distance2BetweenPoints(a.centre, b.centre));
  apart.degrees =
    vtkMath::DegreesFromRadians(std::acos(std::min(1.0, std::abs(vtkMath::Dot(a.normal, b.normal)))));
  return apart;
}

std::string lineFactsText(const std::vector<LineFacts>& facts, bool patientAxes)
{
  std::string text;
  char line[400];
  for (std::size_t k = 0; k < facts.size(); ++k)
  {
    const LineFacts& f = facts[k];
    if (!f.closed)
      continue;
    std::snprintf(line, sizeof line,
      "cut line %zu: %lld vertices, %.2f mm long, centre (%.2f, %.2f, %.2f), plane normal (%.3f, %.3f, %.3f), "
      "every vertex within %.2f mm of that plane",
      k + 1, static_cast<long long>(f.vertices), f.length, f.centre[0], f.centre[1], f.centre[2], f.normal[0],
      f.normal[1], f.normal[2], f.flatness);
    text += line;
    if (patientAxes)
      std::snprintf(line, sizeof line, "; it encloses %.1f mm^2 and spans %.2f mm (%s) by %.2f mm (%s) in that plane\n", f.area,
        f.extentUp, f.upAxis.c_str(), f.extentRight, f.rightAxis.c_str());
    else
      std::snprintf(line, sizeof line, "; it encloses %.1f mm^2 and spans %.2f by %.2f mm in that plane\n", f.area, f.extentUp,
        f.extentRight);
    text += line;
  }
  for (std::size_t j = 0; j < facts.size(); ++j)
    for (std::size_t k = j + 1; k < facts.size(); ++k)
    {
      if (!facts[j].closed || !facts[k].closed)
        continue;
      const LinesApart apart = linesApart(facts[j], facts[k]);
      std::snprintf(line, sizeof line, "cut lines %zu and %zu: centres %.2f mm apart, planes %.2f deg apart\n", j + 1,
        k + 1, apart.distance, apart.degrees);
      text += line;
    }
  return text;
}

} // namespace lkapp
