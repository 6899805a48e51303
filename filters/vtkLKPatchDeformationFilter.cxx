#include "vtkLKPatchDeformationFilter.h"

#include "latticekit/AdaptivePatchMesh.h"
#include "vtkLKPolyDataConversion.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cmath>

vtkStandardNewMacro(vtkLKPatchDeformationFilter);

void vtkLKPatchDeformationFilter::AddFunctionalDeformation(double x, double y, double z, double k, double a, double D)
{
  this->Deformations.push_back({ 0, { { x, y, z, k, a, D, 0, 0, 0 } } });
  this->Modified();
}

void vtkLKPatchDeformationFilter::AddRangeDeformation(double xmin, double xmax, double ymin, double ymax,
  double zmin, double zmax, double dx, double dy, double dz)
{
  this->Deformations.push_back({ 1, { { xmin, xmax, ymin, ymax, zmin, zmax, dx, dy, dz } } });
  this->Modified();
}

void vtkLKPatchDeformationFilter::AddSmoothingDeformation(double x, double y, double z, double D, int iterations)
{
  this->Deformations.push_back({ 2, { { x, y, z, D, static_cast<double>(iterations), 0, 0, 0, 0 } } });
  this->Modified();
}

void vtkLKPatchDeformationFilter::RemoveAllDeformations()
{
  this->Deformations.clear();
  this->Modified();
}

int vtkLKPatchDeformationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  lk::TriangleMesh base;
  const std::string problem = lkvtk::toTriangleMesh(input, base);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot deform: " << problem << ".");
    return 0;
  }
  if (!(this->Tolerance >= 0.0) || !std::isfinite(this->Tolerance))
  {
    vtkErrorMacro("Tolerance must be 0 (automatic) or a positive length, not " << this->Tolerance << ".");
    return 0;
  }
  double tolerance = this->Tolerance;
  if (tolerance == 0.0)
    tolerance = 1e-3 * input->GetLength();
  try
  {
    lk::AdaptivePatchMesh mesh(base, this->MaxLevel);
    const std::size_t n = this->Deformations.size();
    for (std::size_t i = 0; i < n; ++i)
    {
      const auto& d = this->Deformations[i];
      const auto& p = d.p;
      if (d.kind == 0)
        mesh.functionalDeformation(lk::Vec3(p[0], p[1], p[2]), p[3], p[4], p[5], tolerance);
      else if (d.kind == 1)
        mesh.rangeDeformation(lk::Vec3(p[0], p[2], p[4]), lk::Vec3(p[1], p[3], p[5]), lk::Vec3(p[6], p[7], p[8]));
      else
        mesh.smoothingDeformation(lk::Vec3(p[0], p[1], p[2]), p[3], static_cast<int>(p[4]));
      this->UpdateProgress(0.9 * static_cast<double>(i + 1) / static_cast<double>(n));
      if (this->GetAbortExecute())
        return 1;
    }
    const auto tris = mesh.triangles();
    const auto levels = mesh.triangleLevels();
    const auto np = static_cast<vtkIdType>(mesh.vertexCount());
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(np);
    vtkNew<vtkDoubleArray> displacement, normals;
    displacement->SetName("Displacement");
    displacement->SetNumberOfComponents(3);
    displacement->SetNumberOfTuples(np);
    normals->SetName("BaseNormals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(np);
    for (vtkIdType v = 0; v < np; ++v)
    {
      const lk::Vec3 q = mesh.position(static_cast<int>(v));
      points->SetPoint(v, q.data());
      displacement->SetTuple(v, mesh.displacement(static_cast<int>(v)).data());
      normals->SetTuple(v, mesh.baseNormal(static_cast<int>(v)).data());
    }
    vtkNew<vtkCellArray> cells;
    vtkNew<vtkIntArray> level;
    level->SetName("Level");
    for (std::size_t t = 0; t < tris.size(); ++t)
    {
      const vtkIdType ids[3] = { tris[t][0], tris[t][1], tris[t][2] };
      cells->InsertNextCell(3, ids);
      level->InsertNextValue(levels[t]);
    }
    output->SetPoints(points);
    output->SetPolys(cells);
    output->GetPointData()->AddArray(displacement);
    output->GetPointData()->AddArray(normals);
    output->GetCellData()->AddArray(level);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot deform: " << e.what() << ".");
    return 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLKPatchDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Deformations: " << this->Deformations.size() << "\n";
  os << indent << "MaxLevel: " << this->MaxLevel << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
}
