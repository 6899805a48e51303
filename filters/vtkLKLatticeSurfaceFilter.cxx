#include "vtkLKLatticeSurfaceFilter.h"
#include "vtkLKAbort.h"
#include "vtkLKMemory.h"

#include "latticekit/LatticeSurface.h"
#include "latticekit/LatticeSurfaceLocator.h"
#include "vtkLKPolyDataConversion.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
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

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <map>
#include <set>
#include <stdexcept>

vtkStandardNewMacro(vtkLKLatticeSurfaceFilter);


struct vtkLKLatticeSurfaceFilter::Internals
{
  lk::LatticeSurface surface;
  std::unique_ptr<lk::LatticeSurfaceLocator> locator; // built on the first query
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
  os << indent << "ChordalTolerance: " << this->ChordalTolerance
     << (this->ChordalTolerance > 0.0 ? "" : " (off: Resolution decides)") << "\n";
  os << indent << "SplitCreases: " << (this->SplitCreases ? "on" : "off") << "\n";
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
  const lk::Vec3 n = p.normalFrom(a, b, u, v);
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

double vtkLKLatticeSurfaceFilter::FindClosestPoint(const double query[3], double closest[3])
{
  if (this->Internal->surface.patches.empty())
  {
    vtkErrorMacro("FindClosestPoint needs an updated surface.");
    return -1.0;
  }
  if (!this->Internal->locator)
  {
    this->Internal->locator = std::make_unique<lk::LatticeSurfaceLocator>(this->Internal->surface, 8);
  }
  const auto r = this->Internal->locator->closest(lk::Vec3(query[0], query[1], query[2]));
  for (int k = 0; k < 3; ++k)
  {
    closest[k] = r.point[k];
  }
  this->LastClosestPatch = static_cast<vtkIdType>(r.patch);
  this->LastClosestUV[0] = r.u;
  this->LastClosestUV[1] = r.v;
  return r.distance;
}

int vtkLKLatticeSurfaceFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* net = vtkPolyData::GetData(outputVector, 1);
  this->Internal->surface = lk::LatticeSurface();
  this->Internal->locator.reset();
  this->EffectiveResolution = 0;
  if (std::isnan(this->ChordalTolerance))
  {
    vtkErrorMacro("ChordalTolerance must be a distance (0: use Resolution), not NaN.");
    return 0;
  }

  // Line cells over lattice edges carry edge weights; the rest is the lattice.
  lk::LatticeWeights weights;
  vtkNew<vtkPolyData> polygons;
  if (input)
  {
    polygons->ShallowCopy(input);
    vtkNew<vtkCellArray> noLines;
    polygons->SetLines(noLines);
  }
  lk::PolygonMesh lattice;
  std::string problem = lkvtk::toPolygonMesh(polygons, lattice);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot build the lattice surface: " << problem << ".");
    return 0;
  }
  if (vtkDataArray* vw = input->GetPointData()->GetArray("RoundingWeight"))
  {
    weights.vertex.resize(static_cast<std::size_t>(input->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      weights.vertex[static_cast<std::size_t>(i)] = vw->GetComponent(i, 0);
    }
  }
  if (input->GetNumberOfLines() > 0)
  {
    vtkDataArray* ew = input->GetCellData()->GetArray("RoundingWeight");
    // Lines come after vertex cells in VTK's cell numbering.
    const vtkIdType firstLine = input->GetNumberOfVerts();
    auto it = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
    vtkIdType cell = firstLine;
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      const double w = ew ? ew->GetComponent(cell, 0) : 0.0;
      for (vtkIdType k = 0; k + 1 < n; ++k)
      {
        weights.edge[{ ids[k], ids[k + 1] }] = w;
      }
    }
  }
  try
  {
    this->Internal->surface = lk::buildLatticeSurface(lattice, weights);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot build the lattice surface: " << e.what() << ".");
    return 0;
  }
  this->UpdateProgress(0.2);
  const lk::LatticeSurface& s = this->Internal->surface;

  int full = this->Resolution + (this->Resolution % 2);
  if (this->ChordalTolerance > 0.0)
  {
    // The smallest even resolution whose grid cells' centres all lie within
    // the tolerance of the mean of their corners (split patches at half).
    for (full = 2; full < 256; full *= 2)
    {
      double worst = 0.0;
      for (std::size_t p = 0; p < s.patches.size() && worst <= this->ChordalTolerance; ++p)
      {
        const int m = lk::isSplitPatch(s, p) ? std::max(1, full / 2) : full;
        for (int j = 0; j < m && worst <= this->ChordalTolerance; ++j)
        {
          for (int i = 0; i < m; ++i)
          {
            const double u0 = static_cast<double>(i) / m, u1 = static_cast<double>(i + 1) / m;
            const double v0 = static_cast<double>(j) / m, v1 = static_cast<double>(j + 1) / m;
            const lk::GregoryPatch& g = s.patches[p];
            const lk::Vec3 mean = 0.25 * (g.evaluate(u0, v0) + g.evaluate(u1, v0) + g.evaluate(u1, v1) + g.evaluate(u0, v1));
            worst = std::max(worst, (g.evaluate(0.5 * (u0 + u1), 0.5 * (v0 + v1)) - mean).norm());
          }
        }
      }
      if (worst <= this->ChordalTolerance)
      {
        break;
      }
    }
  }
  const int half = full / 2;
  {
    // A dense mesh taken for a lattice at a high resolution makes billions of
    // triangles: refuse before the allocation fails. Per grid cell: two
    // triangles (connectivity, offsets, face and patch ids, 96 bytes), about
    // one point with its normal (48) and its entry in `named` (about 80).
    double cells = 0.0;
    for (std::size_t p = 0; p < s.patches.size(); ++p)
    {
      const double m = lk::isSplitPatch(s, p) ? std::max(1, half) : full;
      cells += m * m;
    }
    std::string tooLarge;
    if (lkvtk::exceedsMemory(224.0 * cells, tooLarge))
    {
      vtkErrorMacro("The tessellation at resolution " << full << " would have " << static_cast<long long>(2.0 * cells) << " triangles ("
                                                      << tooLarge << "): lower the Resolution"
                                                      << (this->ChordalTolerance > 0.0 ? " or raise the ChordalTolerance" : "")
                                                      << ", or give a coarser lattice (" << s.patches.size()
                                                      << " patches here).");
      return 0;
    }
  }
  this->EffectiveResolution = full;

  // Watertight by construction: every sample on a patch side is named by the
  // curve it lies on and its step along it (lattice vertex; step K of a
  // lattice edge counted from its lower-numbered end; step k of a face's
  // inner curve; face centre), and samples with one name become one point.
  // Quad patches take `full` steps a side, split patches `half`, which is
  // half a lattice edge, so names agree across neighbours.
  // With SplitCreases, a sample on a crease is named by the face too, and a
  // lattice vertex by its sector (the faces around it between creases), so
  // each side keeps its own points and normals.
  using Name = std::array<std::int64_t, 4>; // kind, a, b, step
  std::map<Name, vtkIdType> named;
  const auto& faces = lattice.faces;
  std::set<std::pair<std::int64_t, std::int64_t>> splitEdges;
  for (std::size_t e = 0; this->SplitCreases && e < s.edgeCurves.size(); ++e)
  {
    if (s.edgeCrease[e])
    {
      splitEdges.insert({ s.edgeVertices[e][0], s.edgeVertices[e][1] });
    }
  }
  auto vertexName = [&](std::int64_t v, std::size_t f) {
    const auto sector = this->SplitCreases ? s.sectorOf.at({ static_cast<std::size_t>(v), f }) : 0;
    return Name{ 0, v, static_cast<std::int64_t>(sector), 0 };
  };
  auto edgeName = [&](std::int64_t from, std::int64_t to, int k, std::size_t f) {
    const std::int64_t a = std::min(from, to), b = std::max(from, to);
    const int K = from == a ? k : full - k;
    if (K == 0)
    {
      return vertexName(a, f);
    }
    if (K == full)
    {
      return vertexName(b, f);
    }
    if (splitEdges.count({ a, b }))
    {
      return Name{ 4, static_cast<std::int64_t>(f), a * static_cast<std::int64_t>(lattice.points.size()) + b, K };
    }
    return Name{ 1, a, b, K };
  };
  auto innerName = [&](std::size_t f, std::size_t c, int k) {
    const auto& face = faces[f];
    if (k == 0)
    {
      return edgeName(face[c], face[(c + 1) % face.size()], half, f);
    }
    if (k == half)
    {
      return Name{ 3, static_cast<std::int64_t>(f), 0, 0 };
    }
    return Name{ 2, static_cast<std::int64_t>(f), static_cast<std::int64_t>(c), k };
  };

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkIdTypeArray> faceIds, patchIds;
  faceIds->SetName("LatticeFaceId");
  patchIds->SetName("PatchId");
  std::vector<vtkIdType> grid;
  for (std::size_t p = 0; p < s.patches.size(); ++p)
  {
    const auto f = static_cast<std::size_t>(s.patchFace[p]);
    const auto& face = faces[f];
    const std::size_t n = face.size();
    const bool split = lk::isSplitPatch(s, p);
    const int m = split ? half : full;
    const auto c = static_cast<std::size_t>(split ? s.patchCorner[p] : 0);
    // The name of grid point (i, j) if it lies on a side.
    auto sideName = [&](int i, int j, Name& name) {
      if (!split)
      {
        if (j == 0)
          name = edgeName(face[0], face[1], i, f);
        else if (i == m)
          name = edgeName(face[1], face[2], j, f);
        else if (j == m)
          name = edgeName(face[3], face[2], i, f);
        else if (i == 0)
          name = edgeName(face[0], face[3], j, f);
        else
          return false;
        return true;
      }
      const std::int64_t v = face[c], next = face[(c + 1) % n], prev = face[(c + n - 1) % n];
      if (j == 0)
        name = edgeName(v, next, i, f);
      else if (i == m)
        name = innerName(f, c, j);
      else if (j == m)
        name = innerName(f, (c + n - 1) % n, i);
      else if (i == 0)
        name = edgeName(v, prev, j, f);
      else
        return false;
      return true;
    };
    grid.assign(static_cast<std::size_t>((m + 1) * (m + 1)), -1);
    for (int j = 0; j <= m; ++j)
    {
      for (int i = 0; i <= m; ++i)
      {
        Name name;
        const bool onSide = sideName(i, j, name);
        if (onSide)
        {
          auto it = named.find(name);
          if (it != named.end())
          {
            grid[static_cast<std::size_t>(j * (m + 1) + i)] = it->second;
            continue;
          }
        }
        const double u = static_cast<double>(i) / m, v = static_cast<double>(j) / m;
        lk::Vec3 du, dv;
        const lk::Vec3 x = s.patches[p].evaluate(u, v, &du, &dv);
        const lk::Vec3 nrm = s.patches[p].normalFrom(du, dv, u, v);
        const vtkIdType id = points->InsertNextPoint(x.data());
        normals->InsertNextTuple(nrm.data());
        grid[static_cast<std::size_t>(j * (m + 1) + i)] = id;
        if (onSide)
        {
          named.emplace(name, id);
        }
      }
    }
    for (int j = 0; j < m; ++j)
    {
      for (int i = 0; i < m; ++i)
      {
        auto at = [&](int a, int b) { return grid[static_cast<std::size_t>(b * (m + 1) + a)]; };
        const vtkIdType t0[3] = { at(i, j), at(i + 1, j), at(i + 1, j + 1) };
        const vtkIdType t1[3] = { at(i, j), at(i + 1, j + 1), at(i, j + 1) };
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
      this->UpdateProgress(0.2 + 0.7 * static_cast<double>(p) / static_cast<double>(s.patches.size()));
      if (lkvtk::stopRequested(this, { output, net }))
      {
        return 1;
      }
    }
  }
  output->SetPoints(points);
  output->SetPolys(triangles);
  output->GetPointData()->SetNormals(normals);
  output->GetCellData()->AddArray(faceIds);
  output->GetCellData()->AddArray(patchIds);
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
