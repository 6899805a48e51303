#include "vtkLKPatchDeformationFilter.h"
#include "vtkLKAbort.h"

#include "latticekit/AdaptivePatchMesh.h"
#include "latticekit/FaceCrossings.h"
#include "vtkLKPolyDataConversion.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

vtkStandardNewMacro(vtkLKPatchDeformationFilter);

/// The refined mesh kept between updates: after every deformation of
/// `fullList` and after every one of `prefixList` (all but the last).
class vtkLKPatchDeformationFilter::vtkInternals
{
public:
  vtkPolyData* input = nullptr;
  vtkMTimeType inputTime = 0;
  int maxLevel = -1;
  double tolerance = -1.0;
  lk::TriangleMesh base;
  std::vector<Deformation> fullList, prefixList;
  std::unique_ptr<lk::AdaptivePatchMesh> full, prefix;

  void reset()
  {
    input = nullptr;
    full.reset();
    prefix.reset();
    fullList.clear();
    prefixList.clear();
  }
  static bool startsWith(const std::vector<Deformation>& list, const std::vector<Deformation>& head)
  {
    return head.size() <= list.size() && std::equal(head.begin(), head.end(), list.begin());
  }
};

vtkLKPatchDeformationFilter::vtkLKPatchDeformationFilter()
  : Internals(new vtkInternals)
{
}

vtkLKPatchDeformationFilter::~vtkLKPatchDeformationFilter()
{
  delete this->Internals;
}

void vtkLKPatchDeformationFilter::AddFunctionalDeformation(double x, double y, double z, double k, double a, double D)
{
  this->Deformations.push_back({ Deformation::Functional, { { x, y, z, k, a, D, 0, 0, 0 } } });
  this->Modified();
}

void vtkLKPatchDeformationFilter::AddRangeDeformation(double xmin, double xmax, double ymin, double ymax,
  double zmin, double zmax, double dx, double dy, double dz)
{
  this->Deformations.push_back({ Deformation::Range, { { xmin, xmax, ymin, ymax, zmin, zmax, dx, dy, dz } } });
  this->Modified();
}

void vtkLKPatchDeformationFilter::AddSmoothingDeformation(double x, double y, double z, double D, int iterations)
{
  this->Deformations.push_back({ Deformation::Smoothing, { { x, y, z, D, static_cast<double>(iterations), 0, 0, 0, 0 } } });
  this->Modified();
}

void vtkLKPatchDeformationFilter::RemoveAllDeformations()
{
  this->Deformations.clear();
  this->Modified();
}

void vtkLKPatchDeformationFilter::RemoveLastDeformation()
{
  if (this->Deformations.empty())
    return;
  this->Deformations.pop_back();
  this->Modified();
}

void vtkLKPatchDeformationFilter::RemoveDeformation(int index)
{
  if (index < 0 || index >= this->GetNumberOfDeformations())
  {
    vtkErrorMacro("RemoveDeformation: no deformation " << index << " (the filter has "
                                                       << this->GetNumberOfDeformations() << ", from 0)");
    return;
  }
  this->Deformations.erase(this->Deformations.begin() + index);
  this->Modified();
}

namespace
{
/// The input's point data, interpolated at the midpoints the refinement made
/// (as VTK's subdivision filters do), and its cell data, copied to every
/// triangle cut from an input triangle. Normals are left out: the deformed
/// surface's differ (the input's are in "BaseNormals").
void carryAttributes(vtkPolyData* input, const lk::AdaptivePatchMesh& mesh, vtkPolyData* output)
{
  vtkPointData* inPD = input->GetPointData();
  vtkCellData* inCD = input->GetCellData();
  if (inPD->GetNumberOfArrays() == 0 && inCD->GetNumberOfArrays() == 0)
    return; // nothing to carry: no walk over every vertex and triangle on each drag
  vtkPointData* outPD = output->GetPointData();
  const auto np = static_cast<vtkIdType>(mesh.vertexCount());
  const auto nIn = static_cast<vtkIdType>(mesh.inputVertexCount());
  outPD->CopyNormalsOff();
  outPD->InterpolateAllocate(inPD, np);
  for (vtkIdType v = 0; v < nIn; ++v)
    outPD->CopyData(inPD, v, v);
  if (np > nIn && inPD->GetNumberOfArrays() > 0)
  {
    // Each midpoint is an affine combination of at most three input points
    // (the corners of the input triangle it lies in).
    struct Weights
    {
      vtkIdType id[3];
      double w[3];
      int n = 0;
      void add(const Weights& o, double f)
      {
        for (int i = 0; i < o.n; ++i)
        {
          int k = 0;
          while (k < n && id[k] != o.id[i])
            ++k;
          if (k == n)
          {
            if (n == 3) // cannot happen: a midpoint lies in one input triangle
              continue;
            id[n] = o.id[i];
            w[n++] = 0.0;
          }
          w[k] += f * o.w[i];
        }
      }
    };
    std::vector<Weights> weights(static_cast<std::size_t>(np));
    for (vtkIdType v = 0; v < nIn; ++v)
    {
      weights[static_cast<std::size_t>(v)].id[0] = v;
      weights[static_cast<std::size_t>(v)].w[0] = 1.0;
      weights[static_cast<std::size_t>(v)].n = 1;
    }
    vtkNew<vtkIdList> ids;
    for (vtkIdType v = nIn; v < np; ++v)
    {
      const auto ends = mesh.midpointEnds(static_cast<int>(v));
      Weights& w = weights[static_cast<std::size_t>(v)];
      w.add(weights[static_cast<std::size_t>(ends[0])], 0.5);
      w.add(weights[static_cast<std::size_t>(ends[1])], 0.5);
      ids->SetNumberOfIds(w.n);
      for (int k = 0; k < w.n; ++k)
        ids->SetId(k, w.id[k]);
      outPD->InterpolatePoint(inPD, v, ids, w.w);
    }
  }
  vtkCellData* outCD = output->GetCellData();
  const auto origins = mesh.triangleOrigins();
  outCD->CopyNormalsOff();
  outCD->CopyAllocate(inCD, static_cast<vtkIdType>(origins.size()));
  for (std::size_t t = 0; t < origins.size(); ++t)
    outCD->CopyData(inCD, origins[t], static_cast<vtkIdType>(t));
}
} // namespace

int vtkLKPatchDeformationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!(this->Tolerance >= 0.0) || !std::isfinite(this->Tolerance))
  {
    vtkErrorMacro("Tolerance must be 0 (automatic) or a positive length, not " << this->Tolerance << ".");
    return 0;
  }
  double tolerance = this->Tolerance;
  if (tolerance == 0.0)
    tolerance = 1e-3 * input->GetLength();
  vtkInternals& state = *this->Internals;
  if (state.input != input || state.inputTime != input->GetMTime() || state.maxLevel != this->MaxLevel ||
    state.tolerance != tolerance)
  {
    state.reset();
    const std::string problem = lkvtk::toTriangleMesh(input, state.base);
    if (!problem.empty())
    {
      vtkErrorMacro("Cannot deform: " << problem << ".");
      return 0;
    }
    state.input = input;
    state.inputTime = input->GetMTime();
    state.maxLevel = this->MaxLevel;
    state.tolerance = tolerance;
  }
  try
  {
    const std::vector<Deformation>& list = this->Deformations;
    const std::size_t n = list.size();
    if (!state.full || state.fullList != list)
    {
      // Start from the longest kept state whose list begins this one.
      std::unique_ptr<lk::AdaptivePatchMesh> work;
      std::size_t done = 0;
      const bool fromFull = state.full && vtkInternals::startsWith(list, state.fullList);
      const bool fromPrefix = state.prefix && vtkInternals::startsWith(list, state.prefixList);
      if (fromFull && (!fromPrefix || state.fullList.size() >= state.prefixList.size()))
      {
        done = state.fullList.size();
        work = std::move(state.full);
      }
      else if (fromPrefix)
      {
        done = state.prefixList.size();
        work = std::make_unique<lk::AdaptivePatchMesh>(*state.prefix);
      }
      else
        work = std::make_unique<lk::AdaptivePatchMesh>(state.base, this->MaxLevel);
      state.full.reset();
      state.fullList.clear();
      for (std::size_t i = done; i < n; ++i)
      {
        // Keep the state before the last deformation, unless the kept prefix
        // already is that state.
        if (i + 1 == n && !(fromPrefix && state.prefixList.size() == i))
        {
          state.prefix = std::make_unique<lk::AdaptivePatchMesh>(*work);
          state.prefixList.assign(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(i));
        }
        const auto& p = list[i].p;
        if (list[i].kind == Deformation::Functional)
          work->functionalDeformation(lk::Vec3(p[0], p[1], p[2]), p[3], p[4], p[5], tolerance);
        else if (list[i].kind == Deformation::Range)
          work->rangeDeformation(lk::Vec3(p[0], p[2], p[4]), lk::Vec3(p[1], p[3], p[5]), lk::Vec3(p[6], p[7], p[8]));
        else
          work->smoothingDeformation(lk::Vec3(p[0], p[1], p[2]), p[3], static_cast<int>(p[4]));
        this->UpdateProgress(0.9 * static_cast<double>(i + 1 - done) / static_cast<double>(n - done));
        if (lkvtk::stopRequested(this, { output }))
        {
          state.reset(); // the kept states are partly deformed
          return 1;
        }
      }
      state.full = std::move(work);
      state.fullList = list;
    }
    if (lkvtk::stopRequested(this, { output })) // the kept states are whole here
      return 1;
    const lk::AdaptivePatchMesh& mesh = *state.full;
    const auto tris = mesh.triangles();
    const auto levels = mesh.triangleLevels();
    const auto np = static_cast<vtkIdType>(mesh.vertexCount());
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(np);
    vtkNew<vtkDoubleArray> displacement, normals;
    displacement->SetName("Displacement");
    displacement->SetNumberOfComponents(3);
    displacement->SetNumberOfTuples(np);
    normals->SetName("BaseNormals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(np);
    for (vtkIdType v = 0; v < np; ++v)
    {
      const lk::Vec3 q = mesh.position(static_cast<int>(v));
      points->SetPoint(v, q.data());
      displacement->SetTuple(v, mesh.displacement(static_cast<int>(v)).data());
      normals->SetTuple(v, mesh.baseNormal(static_cast<int>(v)).data());
    }
    vtkNew<vtkCellArray> cells;
    vtkNew<vtkIntArray> level;
    level->SetName("Level");
    for (std::size_t t = 0; t < tris.size(); ++t)
    {
      const vtkIdType ids[3] = { tris[t][0], tris[t][1], tris[t][2] };
      cells->InsertNextCell(3, ids);
      level->InsertNextValue(levels[t]);
    }
    output->SetPoints(points);
    output->SetPolys(cells);
    carryAttributes(input, mesh, output);
    output->GetPointData()->AddArray(displacement);
    output->GetPointData()->AddArray(normals);
    output->GetCellData()->AddArray(level);
    if (this->CheckCrossings)
    {
      // Only faces with a moved corner can cross where the input did not.
      lk::PolygonMesh surface;
      surface.points.reserve(static_cast<std::size_t>(np));
      for (vtkIdType v = 0; v < np; ++v)
        surface.points.push_back(mesh.position(static_cast<int>(v)));
      std::vector<char> moved(tris.size(), 0);
      surface.faces.reserve(tris.size());
      for (std::size_t t = 0; t < tris.size(); ++t)
      {
        surface.faces.push_back({ tris[t][0], tris[t][1], tris[t][2] });
        for (const auto v : tris[t])
          moved[t] = moved[t] || mesh.displacement(static_cast<int>(v)).squaredNorm() > 0.0;
      }
      const lk::FaceCrossings crossings = lk::markedFaceCrossings(surface, moved);
      // Whether the input already crossed itself there (a cut piece whose
      // cap crosses the bone): its faces that meet the moved faces' box,
      // before and after the move.
      lk::FaceCrossings before;
      if (crossings.pairs > 0)
      {
        lk::Vec3 low = lk::Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
        for (std::size_t t = 0; t < tris.size(); ++t)
          if (moved[t])
            for (const auto v : tris[t])
              for (const lk::Vec3& q : { mesh.position(v), lk::Vec3(mesh.position(v) - mesh.displacement(v)) })
              {
                low = low.cwiseMin(q);
                high = high.cwiseMax(q);
              }
        before = lk::crossingsInBox(lk::asPolygonMesh(state.base), low, high);
      }
      vtkNew<vtkIdTypeArray> count, countBefore;
      count->SetName("SelfCrossings");
      count->InsertNextValue(static_cast<vtkIdType>(crossings.pairs));
      countBefore->SetName("SelfCrossingsBefore");
      countBefore->InsertNextValue(static_cast<vtkIdType>(before.pairs));
      vtkNew<vtkDoubleArray> depth;
      depth->SetName("SelfCrossingDepth");
      depth->InsertNextValue(crossings.depth);
      output->GetFieldData()->AddArray(count);
      output->GetFieldData()->AddArray(countBefore);
      output->GetFieldData()->AddArray(depth);
      if (crossings.pairs > 0 && before.pairs > 0)
        vtkWarningMacro("The deformed surface passes through itself: "
          << crossings.pairs << " pairs of faces cross, up to " << crossings.depth
          << " through each other, where the input already did (" << before.pairs
          << " pairs of its faces there), so it is no valid solid (field data SelfCrossings).");
      else if (crossings.pairs > 0)
        vtkWarningMacro("The deformed surface passes through itself: "
          << crossings.pairs << " pairs of faces cross, up to " << crossings.depth
          << " through each other (a deformation deeper than the bone is thick, or sharper than its curvature), so it "
             "is no valid solid (field data SelfCrossings).");
      else if (!crossings.checked)
        vtkWarningMacro("The deformed surface could not be checked for places where it passes through itself.");
    }
  }
  catch (const std::exception& e)
  {
    state.reset();
    vtkErrorMacro("Cannot deform: " << e.what() << ".");
    return 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLKPatchDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Deformations: " << this->Deformations.size() << "\n";
  os << indent << "MaxLevel: " << this->MaxLevel << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "CheckCrossings: " << (this->CheckCrossings ? "on" : "off") << "\n";
}
