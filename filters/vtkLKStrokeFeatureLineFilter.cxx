#include "vtkLKStrokeFeatureLineFilter.h"

#include "latticekit/StrokeFeatureLine.h"
#include "vtkLKPolyDataConversion.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

vtkStandardNewMacro(vtkLKStrokeFeatureLineFilter);

vtkLKStrokeFeatureLineFilter::vtkLKStrokeFeatureLineFilter()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

void vtkLKStrokeFeatureLineFilter::SetStrokeConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkLKStrokeFeatureLineFilter::SetStrokeData(vtkPolyData* stroke)
{
  this->SetInputData(1, stroke);
}

vtkPolyData* vtkLKStrokeFeatureLineFilter::GetFeatureLineOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkLKStrokeFeatureLineFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkLKStrokeFeatureLineFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* strokePd = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* lineOut = vtkPolyData::GetData(outputVector, 1);

  lk::TriangleMesh mesh;
  std::string problem = lkvtk::toTriangleMesh(input, mesh);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot make a feature line: " << problem << ".");
    return 0;
  }
  std::vector<lk::Vec3> stroke;
  if (strokePd && strokePd->GetNumberOfLines() > 0)
  {
    auto it = vtk::TakeSmartPointer(strokePd->GetLines()->NewIterator());
    it->GoToFirstCell();
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k)
    {
      double p[3];
      strokePd->GetPoint(ids[k], p);
      stroke.emplace_back(p[0], p[1], p[2]);
    }
  }
  else if (strokePd)
  {
    for (vtkIdType i = 0; i < strokePd->GetNumberOfPoints(); ++i)
    {
      double p[3];
      strokePd->GetPoint(i, p);
      stroke.emplace_back(p[0], p[1], p[2]);
    }
  }
  lk::StrokeOptions o;
  o.mode = this->Mode == PAINT ? lk::StrokeMode::Paint
    : this->Mode == SNAP       ? lk::StrokeMode::Snap
    : this->Mode == SPLIT      ? lk::StrokeMode::Split
                               : lk::StrokeMode::NearestEdges;
  o.brushRadius = this->BrushRadius;
  o.closeTolerance = this->CloseTolerance;
  lk::StrokeResult r;
  try
  {
    r = lk::strokeToFeatureLine(mesh, stroke, o);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot make a feature line: " << e.what() << ".");
    return 0;
  }

  vtkSmartPointer<vtkPolyData> result = lkvtk::fromTriangleMesh(r.mesh);
  output->SetPoints(result->GetPoints());
  if (r.mesh.points.size() == mesh.points.size())
    output->GetPointData()->PassData(input->GetPointData());
  vtkNew<vtkCellArray> lines;
  for (const auto& e : r.featureEdges)
  {
    const vtkIdType ids[2] = { e.first, e.second };
    lines->InsertNextCell(2, ids);
  }
  output->SetLines(lines);
  output->SetPolys(result->GetPolys());
  vtkNew<vtkUnsignedCharArray> flag;
  flag->SetName("FeatureEdge");
  for (std::size_t i = 0; i < r.featureEdges.size(); ++i)
    flag->InsertNextValue(1);
  for (std::size_t i = 0; i < r.mesh.triangles.size(); ++i)
    flag->InsertNextValue(0);
  output->GetCellData()->AddArray(flag);

  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkIdTypeArray> meshIds;
  meshIds->SetName("MeshPointId");
  vtkNew<vtkCellArray> cells;
  auto add = [&](std::int64_t v) {
    meshIds->InsertNextValue(static_cast<vtkIdType>(v));
    return pts->InsertNextPoint(r.mesh.points[static_cast<std::size_t>(v)].data());
  };
  if (!r.line.empty())
  {
    cells->InsertNextCell(static_cast<vtkIdType>(r.line.size()));
    for (auto v : r.line)
      cells->InsertCellPoint(add(v));
  }
  else
  {
    for (const auto& e : r.featureEdges)
    {
      const vtkIdType ids[2] = { add(e.first), add(e.second) };
      cells->InsertNextCell(2, ids);
    }
  }
  lineOut->SetPoints(pts);
  lineOut->SetLines(cells);
  lineOut->GetPointData()->AddArray(meshIds);
  vtkNew<vtkDoubleArray> closed;
  closed->SetName("Closed");
  closed->InsertNextValue(r.closed ? 1.0 : 0.0);
  lineOut->GetFieldData()->AddArray(closed);
  output->GetFieldData()->AddArray(closed);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLKStrokeFeatureLineFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "BrushRadius: " << this->BrushRadius << "\n";
  os << indent << "CloseTolerance: " << this->CloseTolerance << "\n";
}
