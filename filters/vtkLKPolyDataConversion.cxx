#include "vtkLKPolyDataConversion.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <sstream>

namespace lkvtk
{

std::string toTriangleMesh(vtkPolyData* pd, lk::TriangleMesh& mesh)
{
  mesh = lk::TriangleMesh();
  if (!pd || pd->GetNumberOfPoints() == 0 || pd->GetNumberOfCells() == 0)
  {
    return "the mesh is empty (no points or no cells)";
  }
  std::ostringstream os;
  if (pd->GetNumberOfVerts() > 0 || pd->GetNumberOfLines() > 0 || pd->GetNumberOfStrips() > 0)
  {
    os << "only triangles are accepted, but the mesh has " << pd->GetNumberOfVerts()
       << " vertex, " << pd->GetNumberOfLines() << " line and " << pd->GetNumberOfStrips()
       << " strip cells (use vtkTriangleFilter, and drop lines and vertices)";
    return os.str();
  }
  const vtkIdType np = pd->GetNumberOfPoints();
  mesh.points.resize(static_cast<std::size_t>(np));
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    mesh.points[static_cast<std::size_t>(i)] = lk::Vec3(p[0], p[1], p[2]);
  }
  vtkCellArray* polys = pd->GetPolys();
  mesh.triangles.reserve(static_cast<std::size_t>(polys->GetNumberOfCells()));
  auto it = vtk::TakeSmartPointer(polys->NewIterator());
  vtkIdType cellId = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cellId)
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    if (n != 3)
    {
      os << "only triangles are accepted, but cell " << cellId << " has " << n
         << " points (use vtkTriangleFilter first)";
      mesh = lk::TriangleMesh();
      return os.str();
    }
    mesh.triangles.push_back({ ids[0], ids[1], ids[2] });
  }
  std::string problem = lk::validateTriangleMesh(mesh);
  if (!problem.empty())
  {
    mesh = lk::TriangleMesh();
  }
  return problem;
}

std::string toPolygonMesh(vtkPolyData* pd, lk::PolygonMesh& mesh)
{
  mesh = lk::PolygonMesh();
  if (!pd || pd->GetNumberOfPoints() == 0 || pd->GetNumberOfPolys() == 0)
  {
    return "the lattice is empty (no points or no polygons)";
  }
  if (pd->GetNumberOfVerts() > 0 || pd->GetNumberOfLines() > 0 || pd->GetNumberOfStrips() > 0)
  {
    std::ostringstream os;
    os << "a lattice is made of polygons, but this one has " << pd->GetNumberOfVerts() << " vertex, "
       << pd->GetNumberOfLines() << " line and " << pd->GetNumberOfStrips() << " strip cells";
    return os.str();
  }
  mesh.points.resize(static_cast<std::size_t>(pd->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    mesh.points[static_cast<std::size_t>(i)] = lk::Vec3(p[0], p[1], p[2]);
  }
  auto it = vtk::TakeSmartPointer(pd->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    mesh.faces.emplace_back(ids, ids + n);
  }
  return {};
}

vtkSmartPointer<vtkPolyData> fromTriangleMesh(const lk::TriangleMesh& mesh)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.points.size()));
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), mesh.points[i].data());
  }
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto conn = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(static_cast<vtkIdType>(mesh.triangles.size() + 1));
  conn->SetNumberOfValues(static_cast<vtkIdType>(3 * mesh.triangles.size()));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
  {
    offsets->SetValue(static_cast<vtkIdType>(t), static_cast<vtkIdType>(3 * t));
    for (int k = 0; k < 3; ++k)
    {
      conn->SetValue(static_cast<vtkIdType>(3 * t + k), static_cast<vtkIdType>(mesh.triangles[t][k]));
    }
  }
  offsets->SetValue(static_cast<vtkIdType>(mesh.triangles.size()),
    static_cast<vtkIdType>(3 * mesh.triangles.size()));
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->SetData(offsets, conn);
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetPolys(polys);
  return pd;
}

} // namespace lkvtk
