#include "vtkLKSectionLoops.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCutter.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkStripper.h>

#include <cmath>

namespace lkvtk
{

std::vector<std::vector<Point3>> sectionPolylines(vtkPolyData* surface, vtkImplicitFunction* function)
{
  std::vector<std::vector<Point3>> lines;
  if (!surface || !function || surface->GetNumberOfPolys() == 0)
    return lines;
  vtkNew<vtkCutter> cutter;
  cutter->SetInputData(surface);
  cutter->SetCutFunction(function);
  vtkNew<vtkStripper> strip;
  strip->SetInputConnection(cutter->GetOutputPort());
  strip->JoinContiguousSegmentsOn();
  strip->SetMaximumLength(100000); // its largest
  strip->Update();
  vtkPolyData* sections = strip->GetOutput();
  if (!sections->GetLines())
    return lines;
  auto it = vtk::TakeSmartPointer(sections->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    if (n == 0)
      continue;
    std::vector<Point3>& line = lines.emplace_back(static_cast<std::size_t>(n));
    for (vtkIdType k = 0; k < n; ++k)
      sections->GetPoint(ids[k], line[static_cast<std::size_t>(k)].data());
  }
  return lines;
}

int nearestPolyline(const std::vector<std::vector<Point3>>& lines, const Point3& p, double* distance)
{
  int best = -1;
  double nearest = VTK_DOUBLE_MAX;
  for (std::size_t l = 0; l < lines.size(); ++l)
    for (const Point3& q : lines[l])
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

} // namespace lkvtk
