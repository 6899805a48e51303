#include "vtkLKPolyDataConversion.h"
#include "vtkLKMeshPointIds.h"


#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkMath.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticPointLocator.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lkvtk
{

std::string surfaceProblem(vtkPolyData* pd)
{
  if (!pd || pd->GetNumberOfPoints() < 3 || pd->GetNumberOfPolys() + pd->GetNumberOfStrips() == 0)
    return "the input has no surface (no polygons or strips)";
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    double x[3];
    pd->GetPoint(i, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      return "point " + std::to_string(i) + " is not finite";
  }
  double b[6];
  pd->GetBounds(b);
  const double low[3] = { b[0], b[2], b[4] }, high[3] = { b[1], b[3], b[5] };
  const double diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(low, high)); // infinite, not NaN, on overflow
  if (diagonal == 0.0)
    return "every point is in one place";
  if (!std::isfinite(diagonal))
    return "the surface is too large to measure (its bounding box's diagonal overflows)";
  return std::string();
}

vtkSmartPointer<vtkPolyData> facesAsTriangles(vtkPolyData* pd)
{
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(pd->GetPoints());
  surface->SetPolys(pd->GetPolys());
  surface->SetStrips(pd->GetStrips());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(surface);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(triangles->GetOutput());
  return out;
}

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

std::string otherThanPolygons(vtkPolyData* pd)
{
  if (!pd || (pd->GetNumberOfVerts() == 0 && pd->GetNumberOfLines() == 0 && pd->GetNumberOfStrips() == 0))
    return std::string();
  std::ostringstream os;
  os << pd->GetNumberOfVerts() << " vertex, " << pd->GetNumberOfLines() << " line and " << pd->GetNumberOfStrips()
     << " strip cells" << (pd->GetNumberOfStrips() > 0 ? " (vtkTriangleFilter turns strips into triangles)" : "");
  return os.str();
}

std::string toPolygonMesh(vtkPolyData* pd, lk::PolygonMesh& mesh)
{
  mesh = lk::PolygonMesh();
  // Other cells first: a lattice of triangle strips only is not "empty".
  if (pd && pd->GetNumberOfPoints() > 0)
    if (const std::string other = otherThanPolygons(pd); !other.empty())
      return "a lattice is made of polygons, but this one has " + other;
  if (!pd || pd->GetNumberOfPoints() == 0 || pd->GetNumberOfPolys() == 0)
  {
    return "the lattice is empty (no points or no polygons)";
  }
  mesh.points.resize(static_cast<std::size_t>(pd->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    mesh.points[static_cast<std::size_t>(i)] = lk::Vec3(p[0], p[1], p[2]);
  }
  mesh.faces.reserve(static_cast<std::size_t>(pd->GetNumberOfPolys()));
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

std::string lineEdges(vtkPolyData* lines, vtkPolyData* mesh, std::vector<lk::EdgeKey>& out)
{
  if (!lines || lines->GetNumberOfPoints() == 0)
    return {};
  if (lines->GetNumberOfPolys() > 0 || lines->GetNumberOfStrips() > 0)
    return "the lines input holds polygons; it takes polylines";
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<vtkIdType> meshId(static_cast<std::size_t>(lines->GetNumberOfPoints()), -1);
  vtkDataArray* ids = lines->GetPointData()->GetArray("MeshPointId");
  if (ids)
  {
    for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i)
    {
      const vtkIdType v = lkvtk::meshPointIdOf(ids, i, n);
      if (v < 0)
      {
        std::ostringstream text; // as the user wrote it: 1000000, not 1000000.000000
        text << "line point " << i << " has MeshPointId " << ids->GetComponent(i, 0)
             << ", outside the mesh's point ids 0.." << n - 1;
        return text.str();
      }
      meshId[static_cast<std::size_t>(i)] = v;
    }
  }
  else
  {
    vtkNew<vtkStaticPointLocator> locator;
    locator->SetDataSet(mesh);
    locator->BuildLocator();
    const double tol = 1e-9 * std::sqrt(mesh->GetLength() * mesh->GetLength());
    for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i)
    {
      double p[3], q[3];
      lines->GetPoint(i, p);
      const vtkIdType id = locator->FindClosestPoint(p);
      mesh->GetPoint(id, q);
      if (id < 0 || std::sqrt(vtkMath::Distance2BetweenPoints(p, q)) > tol)
        return "line point " + std::to_string(i) +
          " is not a point of the mesh (give point data MeshPointId, or points equal to mesh points)";
      meshId[static_cast<std::size_t>(i)] = id;
    }
  }
  auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType np;
    const vtkIdType* pts;
    it->GetCurrentCell(np, pts);
    for (vtkIdType k = 0; k + 1 < np; ++k)
    {
      const vtkIdType a = meshId[static_cast<std::size_t>(pts[k])], b = meshId[static_cast<std::size_t>(pts[k + 1])];
      if (a != b)
        out.push_back(lk::edgeKey(a, b));
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return {};
}

} // namespace lkvtk
