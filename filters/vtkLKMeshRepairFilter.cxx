#include "vtkLKMeshRepairFilter.h"
#include "vtkLKAbort.h"

#include "latticekit/ManifoldRepair.h"
#include "latticekit/PointHash.h"
#include "vtkLKPolyDataConversion.h"
#include "vtkLKSurfaceAttributes.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <array>
#include <stdexcept>
#include <unordered_map>

vtkStandardNewMacro(vtkLKMeshRepairFilter);

namespace
{
void addCount(vtkFieldData* fd, const char* name, std::size_t value)
{
  vtkNew<vtkIntArray> a;
  a->SetName(name);
  a->InsertNextValue(static_cast<int>(value));
  fd->AddArray(a);
}

constexpr const char* originalCellIdName = "vtkLKMeshRepairFilter_OriginalCellId";

struct PointKeyHash
{
  std::size_t operator()(const std::array<double, 3>& p) const { return lk::hashCoordinates(p[0], p[1], p[2]); }
};

/// Carries the input's point and cell data to the repaired mesh, as
/// vtkCleanPolyData does: an output point takes the data of the input point
/// at its position (the lowest id among duplicates that were merged), an
/// output triangle the data of the input cell with the same three corner
/// positions; a point or face the repair made, from the input triangle
/// nearest it (see vtkLKSurfaceAttributes.h). Normals are left out: the
/// repair may turn faces and whole components over.
void carryAttributes(vtkPolyData* input, vtkPolyData* triangulated, vtkPolyData* output)
{
  if (input->GetPointData()->GetNumberOfArrays() == 0 && input->GetCellData()->GetNumberOfArrays() == 0)
    return; // a bare surface (marching cubes in the bone filter): nothing to look up
  vtkPoints* inPoints = input->GetPoints();
  const vtkIdType nIn = inPoints->GetNumberOfPoints();
  std::unordered_map<std::array<double, 3>, vtkIdType, PointKeyHash> first;
  first.reserve(static_cast<std::size_t>(nIn));
  std::vector<vtkIdType> representative(static_cast<std::size_t>(nIn));
  for (vtkIdType i = 0; i < nIn; ++i)
  {
    std::array<double, 3> p;
    inPoints->GetPoint(i, p.data());
    representative[static_cast<std::size_t>(i)] = first.emplace(p, i).first->second;
  }
  const vtkIdType nOut = output->GetNumberOfPoints();
  std::vector<vtkIdType> source(static_cast<std::size_t>(nOut), -1);
  for (vtkIdType j = 0; j < nOut; ++j)
  {
    std::array<double, 3> p;
    output->GetPoint(j, p.data());
    const auto it = first.find(p);
    if (it != first.end())
      source[static_cast<std::size_t>(j)] = it->second;
  }
  vtkDataArray* originalIds = triangulated->GetCellData()->GetArray(originalCellIdName);
  std::vector<vtkIdType> cellOf(static_cast<std::size_t>(originalIds->GetNumberOfTuples()));
  for (std::size_t t = 0; t < cellOf.size(); ++t)
    cellOf[t] = static_cast<vtkIdType>(originalIds->GetTuple1(static_cast<vtkIdType>(t)));
  lkvtk::carrySurfaceAttributes(input, triangulated, cellOf, source, representative, output);
}
} // namespace

void vtkLKMeshRepairFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

int vtkLKMeshRepairFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("The input has no polygons or triangle strips to repair.");
    return 0;
  }
  if (input->GetNumberOfVerts() > 0 || input->GetNumberOfLines() > 0)
  {
    vtkWarningMacro("Vertex and line cells are dropped; only surfaces are repaired.");
  }
  vtkNew<vtkPolyData> surfaceOnly;
  surfaceOnly->SetPoints(input->GetPoints());
  surfaceOnly->SetPolys(input->GetPolys());
  surfaceOnly->SetStrips(input->GetStrips());
  {
    // Which input cell each triangle comes from (cells count verts, lines, polys, strips).
    vtkNew<vtkIdTypeArray> ids;
    ids->SetName(originalCellIdName);
    const vtkIdType first = input->GetNumberOfVerts() + input->GetNumberOfLines();
    const vtkIdType n = input->GetNumberOfPolys() + input->GetNumberOfStrips();
    ids->SetNumberOfValues(n);
    for (vtkIdType c = 0; c < n; ++c)
      ids->SetValue(c, first + c);
    surfaceOnly->GetCellData()->AddArray(ids);
  }
  // Triangles (marching cubes' output) pass vtkTriangleFilter unchanged:
  // it is skipped for them (0.5 s on 3 million).
  vtkSmartPointer<vtkPolyData> triangles = surfaceOnly.Get();
  if (input->GetNumberOfStrips() > 0 || input->GetPolys()->IsHomogeneous() != 3)
  {
    vtkNew<vtkTriangleFilter> triangulate;
    triangulate->SetInputData(surfaceOnly);
    triangulate->PassVertsOff();
    triangulate->PassLinesOff();
    triangulate->Update();
    triangles = triangulate->GetOutput();
  }
  this->UpdateProgress(0.1);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  lk::TriangleMesh mesh;
  const std::string problem = lkvtk::toTriangleMesh(triangles, mesh);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot repair: " << problem << ".");
    return 0;
  }
  lk::RepairReport report;
  try
  {
    report = lk::repairToManifold(mesh, [this](double f) {
      this->UpdateProgress(0.1 + 0.8 * f);
      return !this->GetAbortExecute();
    });
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Repair failed: " << e.what());
    return 0;
  }
  if (lkvtk::stopRequested(this, { output }))
    return 1;
  this->UpdateProgress(0.9);
  output->ShallowCopy(lkvtk::fromTriangleMesh(mesh));
  carryAttributes(input, triangles, output);
  vtkFieldData* fd = output->GetFieldData();
  fd->PassData(input->GetFieldData());
  addCount(fd, "MergedPoints", report.mergedPoints);
  addCount(fd, "RemovedDegenerateFaces", report.removedDegenerateFaces + report.removedSoupPolygons);
  addCount(fd, "SplitNonManifoldVertices", report.splitNonManifold);
  addCount(fd, "Components", report.components);
  addCount(fd, "BoundaryEdges", report.boundaryEdges);
  this->UpdateProgress(1.0);
  return 1;
}
