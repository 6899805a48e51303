#include "vtkLKMeshRepairFilter.h"
#include "vtkLKAbort.h"

#include "latticekit/ManifoldRepair.h"
#include "vtkLKPolyDataConversion.h"

#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

#include <stdexcept>

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
  if (!input || input->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("The input has no polygons to repair.");
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
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(surfaceOnly);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  this->UpdateProgress(0.1);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  lk::TriangleMesh mesh;
  const std::string problem = lkvtk::toTriangleMesh(triangulate->GetOutput(), mesh);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot repair: " << problem << ".");
    return 0;
  }
  lk::RepairReport report;
  try
  {
    report = lk::repairToManifold(mesh);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Repair failed: " << e.what());
    return 0;
  }
  this->UpdateProgress(0.9);
  if (lkvtk::stopRequested(this, { output }))
    return 1;
  output->ShallowCopy(lkvtk::fromTriangleMesh(mesh));
  vtkFieldData* fd = output->GetFieldData();
  addCount(fd, "MergedPoints", report.mergedPoints);
  addCount(fd, "RemovedDegenerateFaces", report.removedDegenerateFaces + report.removedSoupPolygons);
  addCount(fd, "SplitNonManifoldVertices", report.splitNonManifold);
  addCount(fd, "Components", report.components);
  addCount(fd, "BoundaryEdges", report.boundaryEdges);
  this->UpdateProgress(1.0);
  return 1;
}
