#include "vtkLKMeshPointIds.h"

#include <vtkDataArray.h>
#include <vtkMath.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <cstdio>

namespace lkvtk
{

vtkIdType meshPointIdOf(vtkDataArray* ids, vtkIdType i, vtkIdType meshPoints)
{
  const double v = ids->GetComponent(i, 0);
  return v >= 0.0 && v < static_cast<double>(meshPoints) && v == std::floor(v) ? static_cast<vtkIdType>(v) : -1;
}

std::string linesOffTheirMeshPoints(vtkPolyData* lines, vtkPolyData* mesh)
{
  vtkDataArray* ids = lines && mesh ? lines->GetPointData()->GetArray("MeshPointId") : nullptr;
  if (!ids)
    return {};
  const double tolerance = 1e-4 * mesh->GetLength();
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints() && i < ids->GetNumberOfTuples(); ++i)
  {
    const vtkIdType v = meshPointIdOf(ids, i, mesh->GetNumberOfPoints());
    if (v < 0)
      continue;
    double p[3], q[3];
    lines->GetPoint(i, p);
    mesh->GetPoint(v, q);
    const double d = std::sqrt(vtkMath::Distance2BetweenPoints(p, q));
    if (!(d <= tolerance))
    {
      char text[300];
      std::snprintf(text, sizeof text,
        "line point %lld, which names mesh point %lld by MeshPointId, lies %.4g from it",
        static_cast<long long>(i), static_cast<long long>(v), d);
      return text;
    }
  }
  return {};
}

} // namespace lkvtk
