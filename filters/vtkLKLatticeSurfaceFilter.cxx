#include "vtkLKLatticeSurfaceFilter.h"

#include "latticekit/LatticeSurface.h"
#include "vtkLKPolyDataConversion.h"

#include <vtkCellArray.h>
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
#include <vtkStaticCleanPolyData.h>

#include <algorithm>
#include <stdexcept>

vtkStandardNewMacro(vtkLKLatticeSurfaceFilter);

struct vtkLKLatticeSurfaceFilter::Internals
{
  lk::LatticeSurface surface;
};

vtkLKLatticeSurfaceFilter::vtkLKLatticeSurfaceFilter()
  : Internal(new Internals)
{
  this->SetNumberOfOutputPorts(2);
}

vtkLKLatticeSurfaceFilter::~vtkLKLatticeSurfaceFilter() = default;

void vtkLKLatticeSurfaceFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
}

vtkPolyData* vtkLKLatticeSurfaceFilter::GetControlNetOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

vtkIdType vtkLKLatticeSurfaceFilter::GetNumberOfPatches() const
{
  return static_cast<vtkIdType>(this->Internal->surface.patches.size());
}

bool vtkLKLatticeSurfaceFilter::EvaluatePatch(
  vtkIdType patch, double u, double v, double position[3], double normal[3], double du[3], double dv[3])
{
  const auto& patches = this->Internal->surface.patches;
  if (patch < 0 || patch >= static_cast<vtkIdType>(patches.size()))
  {
    vtkErrorMacro("Patch " << patch << " is out of range (the surface has " << patches.size() << " patches).");
    return false;
  }
  u = std::min(1.0, std::max(0.0, u));
  v = std::min(1.0, std::max(0.0, v));
  const lk::GregoryPatch& p = patches[static_cast<std::size_t>(patch)];
  lk::Vec3 a, b;
  const lk::Vec3 x = p.evaluate(u, v, &a, &b);
  const lk::Vec3 n = p.normal(u, v);
  for (int k = 0; k < 3; ++k)
  {
    position[k] = x[k];
    normal[k] = n[k];
    if (du)
    {
      du[k] = a[k];
    }
    if (dv)
    {
      dv[k] = b[k];
    }
  }
  return true;
}

bool vtkLKLatticeSurfaceFilter::EvaluatePatch(vtkIdType patch, double u, double v, double position[3], double normal[3])
{
  return this->EvaluatePatch(patch, u, v, position, normal, nullptr, nullptr);
}

int vtkLKLatticeSurfaceFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* net = vtkPolyData::GetData(outputVector, 1);
  this->Internal->surface = lk::LatticeSurface();

  lk::PolygonMesh lattice;
  std::string problem = lkvtk::toPolygonMesh(input, lattice);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot build the lattice surface: " << problem << ".");
    return 0;
  }
  try
  {
    this->Internal->surface = lk::buildLatticeSurface(lattice);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot build the lattice surface: " << e.what() << ".");
    return 0;
  }
  this->UpdateProgress(0.2);
  const lk::LatticeSurface& s = this->Internal->surface;

  const int full = this->Resolution + (this->Resolution % 2);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkIdTypeArray> faceIds, patchIds;
  faceIds->SetName("LatticeFaceId");
  patchIds->SetName("PatchId");
  for (std::size_t p = 0; p < s.patches.size(); ++p)
  {
    const int m = lk::isSplitPatch(s, p) ? full / 2 : full;
    const vtkIdType base = points->GetNumberOfPoints();
    for (int j = 0; j <= m; ++j)
    {
      for (int i = 0; i <= m; ++i)
      {
        const double u = static_cast<double>(i) / m, v = static_cast<double>(j) / m;
        lk::Vec3 du, dv;
        const lk::Vec3 x = s.patches[p].evaluate(u, v, &du, &dv);
        lk::Vec3 n = du.cross(dv);
        const double len = n.norm();
        n = len > 1e-14 * du.norm() * dv.norm() && len > 0.0 ? lk::Vec3(n / len) : s.patches[p].normal(u, v);
        points->InsertNextPoint(x.data());
        normals->InsertNextTuple(n.data());
      }
    }
    for (int j = 0; j < m; ++j)
    {
      for (int i = 0; i < m; ++i)
      {
        const vtkIdType a = base + j * (m + 1) + i, b = a + 1, c = a + m + 2, d = a + m + 1;
        const vtkIdType t0[3] = { a, b, c }, t1[3] = { a, c, d };
        triangles->InsertNextCell(3, t0);
        triangles->InsertNextCell(3, t1);
        for (int k = 0; k < 2; ++k)
        {
          faceIds->InsertNextValue(s.patchFace[p]);
          patchIds->InsertNextValue(static_cast<vtkIdType>(p));
        }
      }
    }
    if (p % 64 == 0)
    {
      this->UpdateProgress(0.2 + 0.6 * static_cast<double>(p) / static_cast<double>(s.patches.size()));
      if (this->GetAbortExecute())
      {
        return 1;
      }
    }
  }
  vtkNew<vtkPolyData> raw;
  raw->SetPoints(points);
  raw->SetPolys(triangles);
  raw->GetPointData()->SetNormals(normals);
  raw->GetCellData()->AddArray(faceIds);
  raw->GetCellData()->AddArray(patchIds);

  // Shared curves are sampled at the same parameters on both sides; merge
  // their points (they agree to rounding) so that the mesh is watertight.
  double bounds[6];
  raw->GetBounds(bounds);
  const double diagonal =
    std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) + (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
      (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  vtkNew<vtkStaticCleanPolyData> merge;
  merge->SetInputData(raw);
  merge->ToleranceIsAbsoluteOn();
  merge->SetAbsoluteTolerance(1e-10 * diagonal);
  merge->ConvertPolysToLinesOff();
  merge->ConvertLinesToPointsOff();
  merge->ConvertStripsToPolysOff();
  merge->Update();
  output->ShallowCopy(merge->GetOutput());
  vtkNew<vtkIdTypeArray> displayPolygons;
  displayPolygons->SetName("DisplayPolygons");
  displayPolygons->InsertNextValue(output->GetNumberOfPolys());
  output->GetFieldData()->AddArray(displayPolygons);
  vtkNew<vtkIdTypeArray> patchCount;
  patchCount->SetName("Patches");
  patchCount->InsertNextValue(static_cast<vtkIdType>(s.patches.size()));
  output->GetFieldData()->AddArray(patchCount);

  // The control net.
  vtkNew<vtkPoints> netPoints;
  netPoints->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines, verts;
  for (const auto& curve : s.edgeCurves)
  {
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
    {
      ids[k] = netPoints->InsertNextPoint(curve[static_cast<std::size_t>(k)].data());
    }
    lines->InsertNextCell(4, ids);
  }
  for (const auto& patch : s.patches)
  {
    for (const auto& q : patch.interior)
    {
      const vtkIdType id = netPoints->InsertNextPoint(q.data());
      verts->InsertNextCell(1, &id);
    }
  }
  net->SetPoints(netPoints);
  net->SetLines(lines);
  net->SetVerts(verts);
  this->UpdateProgress(1.0);
  return 1;
}
