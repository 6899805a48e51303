#include "vtkLKHomogenizedLoopFilter.h"
#include "vtkLKAbort.h"
#include "vtkLKMemory.h"

#include "latticekit/HomogenizedLoop.h"
#include "vtkLKPolyDataConversion.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
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
#include <vtkSmartPointer.h>

#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkLKHomogenizedLoopFilter);

int vtkLKHomogenizedLoopFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);

  vtkNew<vtkPolyData> triangles;
  if (input)
  {
    triangles->ShallowCopy(input);
    vtkNew<vtkCellArray> none;
    triangles->SetLines(none);
  }
  lk::HomogenizedLoopInput in;
  const std::string problem = lkvtk::toTriangleMesh(triangles, in.mesh);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot subdivide: " << problem << ".");
    return 0;
  }
  const char* name = this->WeightArrayName.c_str();
  if (vtkDataArray* vw = input->GetPointData()->GetArray(name))
  {
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
      in.vertexWeights.push_back(vw->GetComponent(i, 0));
  }
  const vtkIdType firstLine = input->GetNumberOfVerts();
  const vtkIdType firstPoly = firstLine + input->GetNumberOfLines();
  vtkDataArray* cw = input->GetCellData()->GetArray(name);
  if (cw)
  {
    for (vtkIdType c = 0; c < input->GetNumberOfPolys(); ++c)
      in.faceWeights.push_back(cw->GetComponent(firstPoly + c, 0));
    auto it = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
    vtkIdType cell = firstLine;
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k + 1 < n; ++k)
        in.edgeWeights.push_back({ lk::edgeKey(ids[k], ids[k + 1]), cw->GetComponent(cell, 0) });
    }
  }
  // Point data rides along as extra homogeneous coordinates.
  std::vector<vtkDataArray*> arrays;
  vtkPointData* inPd = input->GetPointData();
  for (int a = 0; a < inPd->GetNumberOfArrays(); ++a)
  {
    if (vtkDataArray* arr = inPd->GetArray(a))
    {
      arrays.push_back(arr);
      in.attributeComponents += arr->GetNumberOfComponents();
    }
  }
  const auto np = static_cast<std::size_t>(input->GetNumberOfPoints());
  const auto comps = static_cast<std::size_t>(in.attributeComponents);
  in.attributes.resize(np * comps);
  {
    std::size_t offset = 0;
    for (vtkDataArray* arr : arrays)
    {
      const int nc = arr->GetNumberOfComponents();
      for (std::size_t p = 0; p < np; ++p)
        for (int c = 0; c < nc; ++c)
          in.attributes[p * comps + offset + static_cast<std::size_t>(c)] =
            arr->GetComponent(static_cast<vtkIdType>(p), c);
      offset += static_cast<std::size_t>(nc);
    }
  }
  {
    // Each step makes four triangles of one: refuse what cannot fit before
    // working towards it for minutes. Measured: about 130 bytes per output
    // triangle at the peak (the core's levels and the VTK copy), and two
    // copies of each attribute value per point (half a point per triangle).
    const double out = static_cast<double>(in.mesh.triangles.size()) * std::pow(4.0, this->NumberOfSubdivisions);
    std::string tooLarge;
    if (lkvtk::exceedsMemory(out * (130.0 + 8.0 * static_cast<double>(in.attributeComponents)), tooLarge))
    {
      vtkErrorMacro("Subdividing " << in.mesh.triangles.size() << " triangles " << this->NumberOfSubdivisions
                                   << " times would make " << static_cast<long long>(out) << " triangles ("
                                   << tooLarge << "): ask for fewer subdivisions.");
      return 0;
    }
  }
  this->UpdateProgress(0.1);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  lk::HomogenizedLoopOutput out;
  try
  {
    out = lk::homogenizedLoop(in, this->NumberOfSubdivisions, [this](double done) {
      this->UpdateProgress(0.1 + 0.7 * done);
      return !this->GetAbortExecute();
    });
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot subdivide: " << e.what() << ".");
    return 0;
  }
  if (lkvtk::stopRequested(this, { output }))
    return 1;
  this->UpdateProgress(0.8);

  vtkSmartPointer<vtkPolyData> result = lkvtk::fromTriangleMesh(out.mesh);
  output->ShallowCopy(result);
  output->GetFieldData()->PassData(input->GetFieldData());
  std::size_t offset = 0;
  const std::size_t n = out.mesh.points.size();
  for (vtkDataArray* arr : arrays)
  {
    const int nc = arr->GetNumberOfComponents();
    auto copy = vtk::TakeSmartPointer(arr->NewInstance());
    copy->SetName(arr->GetName());
    copy->SetNumberOfComponents(nc);
    copy->SetNumberOfTuples(static_cast<vtkIdType>(n));
    for (std::size_t p = 0; p < n; ++p)
      for (int c = 0; c < nc; ++c)
        copy->SetComponent(
          static_cast<vtkIdType>(p), c, out.attributes[p * comps + offset + static_cast<std::size_t>(c)]);
    offset += static_cast<std::size_t>(nc);
    output->GetPointData()->AddArray(copy);
  }
  vtkNew<vtkDoubleArray> w;
  w->SetName("HomogeneousWeight");
  w->SetNumberOfTuples(static_cast<vtkIdType>(n));
  for (std::size_t p = 0; p < n; ++p)
    w->SetValue(static_cast<vtkIdType>(p), out.weights[p]);
  output->GetPointData()->AddArray(w);

  vtkCellData* inCd = input->GetCellData();
  vtkCellData* outCd = output->GetCellData();
  const auto nt = static_cast<vtkIdType>(out.mesh.triangles.size());
  outCd->CopyAllocate(inCd, nt);
  vtkNew<vtkIdTypeArray> origin;
  origin->SetName("InputCellId");
  origin->SetNumberOfTuples(nt);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    const vtkIdType src = firstPoly + static_cast<vtkIdType>(out.parentFace[static_cast<std::size_t>(t)]);
    outCd->CopyData(inCd, src, t);
    origin->SetValue(t, src);
  }
  outCd->AddArray(origin);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLKHomogenizedLoopFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSubdivisions: " << this->NumberOfSubdivisions << "\n";
  os << indent << "WeightArrayName: " << this->WeightArrayName << "\n";
}
