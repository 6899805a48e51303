#include "vtkLKMeshRepairFilter.h"
#include "vtkLKAbort.h"

#include "latticekit/ManifoldRepair.h"
#include "vtkLKPolyDataConversion.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>
#include <vtkStaticPointLocator.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <array>
#include <functional>
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
  std::size_t operator()(const std::array<double, 3>& p) const
  {
    const std::hash<double> h;
    return h(p[0]) ^ (h(p[1]) * 0x9E3779B97F4A7C15ULL) ^ (h(p[2]) * 0xC2B2AE3D27D4EB4FULL);
  }
};

/// Carries the input's point and cell data to the repaired mesh, as
/// vtkCleanPolyData does. An output point takes the data of the input point
/// at its position (the lowest id among duplicates that were merged; the
/// nearest input point if the repair moved it). An output triangle takes the
/// data of the input cell with the same three positions (either orientation),
/// or else of the input triangle nearest its centre (a face the repair made).
/// Normals are left out: the repair may turn faces and whole components over.
void carryAttributes(vtkPolyData* input, vtkPolyData* triangulated, vtkPolyData* output)
{
  vtkPointData* inPD = input->GetPointData();
  vtkCellData* inCD = input->GetCellData();
  if (inPD->GetNumberOfArrays() == 0 && inCD->GetNumberOfArrays() == 0)
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
  std::vector<vtkIdType> source(static_cast<std::size_t>(nOut));
  vtkSmartPointer<vtkStaticPointLocator> nearest;
  for (vtkIdType j = 0; j < nOut; ++j)
  {
    std::array<double, 3> p;
    output->GetPoint(j, p.data());
    const auto it = first.find(p);
    if (it != first.end())
    {
      source[static_cast<std::size_t>(j)] = it->second;
      continue;
    }
    if (!nearest)
    {
      nearest = vtkSmartPointer<vtkStaticPointLocator>::New();
      nearest->SetDataSet(input);
      nearest->BuildLocator();
    }
    source[static_cast<std::size_t>(j)] = nearest->FindClosestPoint(p.data());
  }
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyNormalsOff();
  outPD->CopyAllocate(inPD, nOut);
  for (vtkIdType j = 0; j < nOut; ++j)
    outPD->CopyData(inPD, source[static_cast<std::size_t>(j)], j);

  // Input triangles by their three point positions.
  using Triple = std::array<vtkIdType, 3>;
  // A triangle's key: its corners' positions, as input point ids, sorted.
  auto key = [](const std::vector<vtkIdType>& idOf, const vtkIdType* ids) {
    Triple t{ { idOf[static_cast<std::size_t>(ids[0])], idOf[static_cast<std::size_t>(ids[1])],
      idOf[static_cast<std::size_t>(ids[2])] } };
    std::sort(t.begin(), t.end());
    return t;
  };
  auto forEachTriangle = [](vtkCellArray* cells, auto&& f) {
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    vtkIdType t = 0;
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++t)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      if (n == 3)
        f(t, ids);
    }
  };
  vtkDataArray* originalIds = triangulated->GetCellData()->GetArray(originalCellIdName);
  struct TripleHash
  {
    std::size_t operator()(const Triple& t) const
    {
      return std::hash<vtkIdType>()(t[0]) ^ (std::hash<vtkIdType>()(t[1]) * 0x9E3779B97F4A7C15ULL) ^
        (std::hash<vtkIdType>()(t[2]) * 0xC2B2AE3D27D4EB4FULL);
    }
  };
  std::unordered_map<Triple, vtkIdType, TripleHash> cellOf;
  cellOf.reserve(static_cast<std::size_t>(triangulated->GetNumberOfPolys()));
  forEachTriangle(triangulated->GetPolys(), [&](vtkIdType t, const vtkIdType* ids) {
    cellOf.emplace(key(representative, ids), static_cast<vtkIdType>(originalIds->GetTuple1(t)));
  });
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyNormalsOff();
  outCD->CopyAllocate(inCD, output->GetNumberOfPolys());
  vtkSmartPointer<vtkStaticCellLocator> nearestCell;
  forEachTriangle(output->GetPolys(), [&](vtkIdType t, const vtkIdType* ids) {
    const auto found = cellOf.find(key(source, ids));
    vtkIdType from;
    if (found != cellOf.end())
      from = found->second;
    else
    {
      if (!nearestCell)
      {
        nearestCell = vtkSmartPointer<vtkStaticCellLocator>::New();
        nearestCell->SetDataSet(triangulated);
        nearestCell->BuildLocator();
      }
      double c[3] = { 0, 0, 0 }, x[3], closest[3], d2;
      for (int k = 0; k < 3; ++k)
      {
        output->GetPoint(ids[k], x);
        for (int d = 0; d < 3; ++d)
          c[d] += x[d] / 3.0;
      }
      vtkIdType cell;
      int subId;
      nearestCell->FindClosestPoint(c, closest, cell, subId, d2);
      from = static_cast<vtkIdType>(originalIds->GetTuple1(cell));
    }
    outCD->CopyData(inCD, from, t);
  });
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
  carryAttributes(input, triangulate->GetOutput(), output);
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
