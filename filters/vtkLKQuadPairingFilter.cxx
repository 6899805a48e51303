#include "vtkLKQuadPairingFilter.h"
#include "vtkLKFieldValues.h"
#include "vtkLKAbort.h"

#include "latticekit/QuadPairing.h"
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
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkLKQuadPairingFilter);

int vtkLKQuadPairingFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);

  vtkNew<vtkPolyData> faces;
  if (input)
  {
    faces->ShallowCopy(input);
    vtkNew<vtkCellArray> none;
    faces->SetLines(none);
  }
  lk::TriangleMesh mesh;
  const std::string problem = lkvtk::toTriangleMesh(faces, mesh);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot pair triangles: " << problem << ".");
    return 0;
  }
  std::set<lk::EdgeKey> features;
  const vtkIdType lineCount = input->GetNumberOfLines();
  if (lineCount > 0)
  {
    auto it = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k + 1 < n; ++k)
        features.insert(lk::edgeKey(ids[k], ids[k + 1]));
    }
  }
  lk::QuadPairingOptions o;
  o.rightAngleTolerance = this->RightAngleTolerance;
  o.angleSumTolerance = this->AngleSumTolerance;
  o.maxDihedralDegrees = this->MaximumDihedralAngle;
  lk::QuadPairingResult r;
  try
  {
    r = lk::pairTrianglesIntoQuads(mesh, features, o);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot pair triangles: " << e.what() << ".");
    return 0;
  }
  this->UpdateProgress(0.8);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  output->SetPoints(input->GetPoints());
  output->GetPointData()->PassData(input->GetPointData());
  vtkNew<vtkCellArray> polys;
  for (const auto& f : r.lattice.faces)
  {
    std::vector<vtkIdType> ids(f.begin(), f.end());
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  output->SetLines(input->GetLines());
  output->SetPolys(polys);
  // Cell data: the input's line cells keep theirs; faces name their first triangle.
  vtkCellData* inCd = input->GetCellData();
  vtkCellData* outCd = output->GetCellData();
  outCd->CopyAllocate(inCd, lineCount + static_cast<vtkIdType>(r.lattice.faces.size()));
  const vtkIdType firstLine = input->GetNumberOfVerts();
  const vtkIdType firstPoly = firstLine + lineCount;
  for (vtkIdType i = 0; i < lineCount; ++i)
    outCd->CopyData(inCd, firstLine + i, i);
  vtkNew<vtkIdTypeArray> origin;
  origin->SetName("InputCellId");
  for (vtkIdType i = 0; i < lineCount; ++i)
    origin->InsertNextValue(firstLine + i);
  for (std::size_t f = 0; f < r.lattice.faces.size(); ++f)
  {
    const vtkIdType src = firstPoly + static_cast<vtkIdType>(r.faceTriangles[f][0]);
    outCd->CopyData(inCd, src, lineCount + static_cast<vtkIdType>(f));
    origin->InsertNextValue(src);
  }
  outCd->AddArray(origin);
  auto add = [&](const char* name, double v) { lkvtk::addFieldValue(output->GetFieldData(), name, v); };
  add("Quads", static_cast<double>(r.quads));
  add("Triangles", static_cast<double>(r.lattice.faces.size() - r.quads));
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLKQuadPairingFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RightAngleTolerance: " << this->RightAngleTolerance << "\n";
  os << indent << "AngleSumTolerance: " << this->AngleSumTolerance << "\n";
  os << indent << "MaximumDihedralAngle: " << this->MaximumDihedralAngle << "\n";
}
