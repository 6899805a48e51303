// latticekit-planner: each piece's lattice (l, L), its lines kept, fitted again
// only when the piece, the count or the lines changed.
#include "planner/Planner.h"
#include "planner/PlannerShared.h"

#include "common/AppSupport.h"

#include "vtkLKLatticeFitFilter.h"
#include "vtkLKLatticeSurfaceFilter.h"
#include "latticekit/FeatureChains.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkMath.h>
#include <vtkProperty.h>
#include <vtkTextProperty.h>
#include <vtkMatrix4x4.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <set>
#include <cstdlib>
#include <string>
#include <vector>

namespace lkplanner
{

namespace
{
/// `edges` of a cut piece on `deformed`, that piece after the patch
/// deformation, which keeps the cut piece's `kept` points first, in order,
/// and splits edges at new points (its adaptive refinement): an edge still
/// there stays; a split one becomes its parts, through the new point joined
/// to both ends that lies nearest the straight path, as often as it was
/// split. `lost` counts the edges for which no such path was found.
FeatureEdges onDeformed(const FeatureEdges& edges, vtkPolyData* deformed, vtkIdType kept, std::size_t& lost)
{
  const FeatureEdges all = faceEdgesOf(deformed);
  std::vector<std::vector<vtkIdType>> around(static_cast<std::size_t>(deformed->GetNumberOfPoints()));
  for (const auto& e : all)
  {
    around[static_cast<std::size_t>(e[0])].push_back(e[1]);
    around[static_cast<std::size_t>(e[1])].push_back(e[0]);
  }
  auto has = [&](vtkIdType a, vtkIdType b) {
    return std::binary_search(all.begin(), all.end(), std::array<vtkIdType, 2>{ std::min(a, b), std::max(a, b) });
  };
  auto length = [&](vtkIdType a, vtkIdType b) {
    double x[3], y[3];
    deformed->GetPoint(a, x);
    deformed->GetPoint(b, y);
    return std::sqrt(vtkMath::Distance2BetweenPoints(x, y));
  };
  std::set<std::array<vtkIdType, 2>> out;
  std::function<bool(vtkIdType, vtkIdType, int)> path = [&](vtkIdType a, vtkIdType b, int depth) {
    if (has(a, b))
    {
      out.insert({ std::min(a, b), std::max(a, b) });
      return true;
    }
    vtkIdType middle = -1;
    double shortest = VTK_DOUBLE_MAX;
    for (const vtkIdType m : around[static_cast<std::size_t>(a)])
      if (m >= kept && has(m, b) && length(a, m) + length(m, b) < shortest)
      {
        middle = m;
        shortest = length(a, m) + length(m, b);
      }
    return depth > 0 && middle >= 0 && path(a, middle, depth - 1) && path(middle, b, depth - 1);
  };
  lost = 0;
  for (const auto& e : edges)
    if (e[1] >= deformed->GetNumberOfPoints() || !path(e[0], e[1], 16))
      ++lost;
  return FeatureEdges(out.begin(), out.end());
}
} // namespace

Planner::FittedLattice& Planner::latticeOf(std::size_t p)
{
  vtkPolyData* piece = pieces[p];
  // The cut piece's feature edges, on the piece as its deformations left it.
  FeatureEdges features;
  std::size_t refined = 0;
  if (p < cut.featureEdges.size())
  {
    features = cut.featureEdges[p];
    if (piece != cut.pieces[p].Get())
      features = onDeformed(features, piece, cut.pieces[p]->GetNumberOfPoints(), refined);
  }
  // The lines keep the points that hold them within kLineTolerance, exactly,
  // as lattice vertices (as the main job keeps its cut line): a split line
  // has a vertex at every mesh edge it crosses, and each one kept made the
  // lattice a fan of slivers there. The rest of the bone keeps at least as
  // many vertices again, or a long line would leave it a few coarse faces.
  std::set<vtkIdType> onLines;
  std::vector<std::pair<std::int64_t, std::int64_t>> lineEdges;
  for (const auto& e : features)
  {
    onLines.insert(e.begin(), e.end());
    lineEdges.emplace_back(e[0], e[1]);
  }
  std::size_t needed = 0;
  if (!lineEdges.empty())
  {
    std::vector<lk::Vec3> points(static_cast<std::size_t>(piece->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
    {
      double x[3];
      piece->GetPoint(i, x);
      points[static_cast<std::size_t>(i)] = lk::Vec3(x[0], x[1], x[2]);
    }
    needed = lk::featureVerticesToKeep(points, lineEdges, kLineTolerance);
  }
  const vtkIdType wanted = std::max<vtkIdType>(session.latticeVertices, 2 * static_cast<vtkIdType>(needed));
  const vtkIdType vertices = std::min<vtkIdType>(wanted, piece->GetNumberOfPoints() / 2);
  const std::uint64_t key = geometryKey(piece, vertices, features);
  if (lattices.size() <= p)
    lattices.resize(p + 1);
  FittedLattice& fitted = lattices[p];
  if (fitted.lattice && fitted.key == key)
  {
    ++latticesReused;
    return fitted;
  }
  ++latticeFits;
  vtkNew<vtkLKLatticeFitFilter> fit;
  fit->SetInputData(piece);
  fit->SetTargetNumberOfVertices(vertices);
  if (!features.empty())
  {
    vtkNew<vtkPolyData> lines;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> cells;
    vtkNew<vtkIdTypeArray> ids;
    ids->SetName("MeshPointId");
    for (const auto& e : features)
    {
      cells->InsertNextCell(2);
      for (const vtkIdType v : e)
      {
        cells->InsertCellPoint(points->InsertNextPoint(piece->GetPoint(v)));
        ids->InsertNextValue(v);
      }
    }
    lines->SetPoints(points);
    lines->SetLines(cells);
    lines->GetPointData()->AddArray(ids);
    fit->SetFeatureLinesData(lines);
    fit->LockFeaturesOn();
    fit->SetFeatureTolerance(kLineTolerance);
  }
  fit->QuadPairingOn();
  fit->ComputeErrorOff();
  vtkNew<vtkLKLatticeSurfaceFilter> smooth;
  smooth->SetInputConnection(fit->GetOutputPort());
  smooth->SetResolution(4);
  const int before = lkapp::errorCount();
  smooth->Update();
  fitted.key = key;
  fitted.errors = lkapp::errorCount() > before ? lkapp::errorsSince(before) : "";
  fitted.featureEdges = static_cast<std::size_t>(lkapp::fieldValue(fit->GetOutput(), "FeatureEdges"));
  fitted.featureEdgesRefined = refined;
  fitted.creaseEdges = static_cast<std::size_t>(lkapp::fieldValue(fit->GetOutput(), "CreaseEdges"));
  fitted.lineVertices = onLines.size();
  fitted.neededLineVertices = needed;
  {
    // The lattice's vertices on the lines: those the lines need, and any
    // whose collapse along its line would have folded the lattice.
    std::set<vtkIdType> kept;
    vtkNew<vtkIdList> ids;
    vtkCellArray* cells = fit->GetOutput()->GetLines();
    for (cells->InitTraversal(); cells->GetNextCell(ids);)
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
        kept.insert(ids->GetId(k));
    fitted.keptLineVertices = kept.size();
  }
  fitted.raised = wanted > session.latticeVertices;
  fitted.lattice = vtkSmartPointer<vtkPolyData>::New();
  fitted.lattice->ShallowCopy(fit->GetOutput());
  fitted.surface = vtkSmartPointer<vtkPolyData>::New();
  fitted.surface->ShallowCopy(smooth->GetOutput());
  fitted.metro = nullptr;
  return fitted;
}

std::uint64_t Planner::geometryKey(vtkPolyData* pd, vtkIdType count, const FeatureEdges& edges)
{
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](const void* data, std::size_t bytes) {
    const auto* c = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; i += 8)
    {
      std::uint64_t word = 0;
      std::memcpy(&word, c + i, std::min<std::size_t>(8, bytes - i));
      word = (word ^ (word >> 30)) * 0xbf58476d1ce4e5b9ULL;
      word = (word ^ (word >> 27)) * 0x94d049bb133111ebULL;
      word ^= word >> 31;
      h = (h ^ word) * 1099511628211ULL;
    }
  };
  mix(&count, sizeof count);
  const vtkIdType n = pd->GetNumberOfPoints();
  mix(&n, sizeof n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    pd->GetPoint(i, x);
    mix(x, sizeof x);
  }
  auto it = vtk::TakeSmartPointer(pd->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    it->GetCurrentCell(size, ids);
    mix(&size, sizeof size);
    mix(ids, sizeof(vtkIdType) * static_cast<std::size_t>(size));
  }
  const std::size_t edgeCount = edges.size();
  mix(&edgeCount, sizeof edgeCount);
  if (!edges.empty())
    mix(edges.data(), sizeof(edges[0]) * edges.size());
  return h;
}

vtkSmartPointer<vtkPolyData> Planner::facesOnly(vtkPolyData* surface)
{
  auto faces = vtkSmartPointer<vtkPolyData>::New();
  faces->ShallowCopy(surface);
  vtkNew<vtkCellArray> none;
  faces->SetLines(none);
  return faces;
}

} // namespace lkplanner
