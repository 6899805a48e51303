#include "vtkLKExtractCutPieceFilter.h"
#include "vtkLKAbort.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
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
#include <array>
#include <cmath>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkLKExtractCutPieceFilter);

namespace
{
using Edge = std::pair<vtkIdType, vtkIdType>; // smaller id first

struct EdgeHash
{
  std::size_t operator()(const Edge& e) const
  {
    return std::hash<vtkIdType>()(e.first) ^ (std::hash<vtkIdType>()(e.second) * 0x9E3779B97F4A7C15ULL);
  }
};

Edge edgeOf(vtkIdType a, vtkIdType b)
{
  return a < b ? Edge{ a, b } : Edge{ b, a };
}

/// Calls f(cell id, kind, point count, point ids) for every cell of `pd`, in
/// id order: a polydata's cells go vertices, lines, polygons, strips (kind 0
/// to 3), each kind in its own order.
template <typename F>
void forEachCell(vtkPolyData* pd, F f)
{
  vtkCellArray* arrays[4] = { pd->GetVerts(), pd->GetLines(), pd->GetPolys(), pd->GetStrips() };
  vtkIdType id = 0;
  for (int kind = 0; kind < 4; ++kind)
  {
    if (!arrays[kind])
      continue;
    auto it = vtk::TakeSmartPointer(arrays[kind]->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++id)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      f(id, kind, n, ids);
    }
  }
}

/// The cells of `region` and the points they use, both in the cut's order;
/// `newId` gets each cut point's id in the piece (-1: not in it).
void extractRegion(vtkPolyData* cut, const std::vector<int>& regions, int region, bool attributes, vtkPolyData* out,
  std::vector<vtkIdType>& newId)
{
  const vtkIdType pointCount = cut->GetNumberOfPoints();
  newId.assign(static_cast<std::size_t>(pointCount), -1);
  forEachCell(cut, [&](vtkIdType c, int, vtkIdType n, const vtkIdType* ids) {
    if (regions[static_cast<std::size_t>(c)] == region)
      for (vtkIdType k = 0; k < n; ++k)
        newId[static_cast<std::size_t>(ids[k])] = 0;
  });
  vtkNew<vtkPoints> points;
  points->SetDataType(cut->GetPoints()->GetDataType());
  vtkPointData* pointData = out->GetPointData();
  if (attributes)
    pointData->CopyAllocate(cut->GetPointData());
  for (vtkIdType i = 0; i < pointCount; ++i)
    if (newId[static_cast<std::size_t>(i)] == 0)
    {
      newId[static_cast<std::size_t>(i)] = points->InsertNextPoint(cut->GetPoint(i));
      if (attributes)
        pointData->CopyData(cut->GetPointData(), i, newId[static_cast<std::size_t>(i)]);
    }
  out->SetPoints(points);
  vtkNew<vtkCellArray> verts, lines, polys, strips;
  vtkCellArray* arrays[4] = { verts, lines, polys, strips };
  vtkCellData* cellData = out->GetCellData();
  if (attributes)
    cellData->CopyAllocate(cut->GetCellData());
  vtkIdType next = 0;
  std::vector<vtkIdType> renumbered;
  forEachCell(cut, [&](vtkIdType c, int kind, vtkIdType n, const vtkIdType* ids) {
    if (regions[static_cast<std::size_t>(c)] != region)
      return;
    renumbered.resize(static_cast<std::size_t>(n));
    for (vtkIdType k = 0; k < n; ++k)
      renumbered[static_cast<std::size_t>(k)] = newId[static_cast<std::size_t>(ids[k])];
    arrays[kind]->InsertNextCell(n, renumbered.data());
    if (attributes)
      cellData->CopyData(cut->GetCellData(), c, next);
    ++next;
  });
  out->SetVerts(verts);
  out->SetLines(lines);
  out->SetPolys(polys);
  out->SetStrips(strips);
}

/// The edges of `region` where the cut went through the surface, as cut
/// point ids (see the class comment): edges of one non-cap face of a piece
/// whose two end points are also those of another such edge. Only edges
/// between points the cut made twice are looked at: points whose
/// InputPointId another point has too, or none (-1: a cap's or an inner
/// wall's), or without that array points that share their place.
std::vector<Edge> cutEdges(vtkPolyData* cut, const std::vector<int>& regions, int region)
{
  const auto pointCount = static_cast<std::size_t>(cut->GetNumberOfPoints());
  std::vector<char> twin(pointCount, 0);
  if (vtkDataArray* input = cut->GetPointData()->GetArray("InputPointId"))
  {
    std::unordered_map<vtkIdType, vtkIdType> first;
    for (std::size_t i = 0; i < pointCount; ++i)
    {
      const auto id = static_cast<vtkIdType>(input->GetTuple1(static_cast<vtkIdType>(i)));
      if (id < 0)
      {
        twin[i] = 1;
        continue;
      }
      const auto [it, added] = first.emplace(id, static_cast<vtkIdType>(i));
      if (!added)
        twin[i] = twin[static_cast<std::size_t>(it->second)] = 1;
    }
  }
  else
  {
    std::map<std::array<double, 3>, std::size_t> first;
    for (std::size_t i = 0; i < pointCount; ++i)
    {
      std::array<double, 3> p;
      cut->GetPoint(static_cast<vtkIdType>(i), p.data());
      const auto [it, added] = first.emplace(p, i);
      if (!added)
        twin[i] = twin[it->second] = 1;
    }
  }
  vtkDataArray* cap = cut->GetCellData()->GetArray("Cap");
  struct Use
  {
    int faces = 0;
    int region = 0;
  };
  std::unordered_map<Edge, Use, EdgeHash> uses;
  forEachCell(cut, [&](vtkIdType c, int kind, vtkIdType n, const vtkIdType* ids) {
    if (kind != 2 || (cap && cap->GetTuple1(c) != 0.0))
      return;
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = ids[k], b = ids[(k + 1) % n];
      if (!twin[static_cast<std::size_t>(a)] || !twin[static_cast<std::size_t>(b)])
        continue;
      Use& use = uses[edgeOf(a, b)];
      ++use.faces;
      use.region = regions[static_cast<std::size_t>(c)];
    }
  });
  // The edges with one face, by where their ends lie: a cut edge's other
  // side has the same two points (the cut duplicated them).
  using Place = std::array<double, 6>;
  std::map<Place, int> sides;
  std::vector<std::pair<Edge, Place>> single;
  for (const auto& [edge, use] : uses)
    if (use.faces == 1)
    {
      std::array<double, 3> a, b;
      cut->GetPoint(edge.first, a.data());
      cut->GetPoint(edge.second, b.data());
      if (b < a)
        std::swap(a, b);
      const Place place{ a[0], a[1], a[2], b[0], b[1], b[2] };
      ++sides[place];
      if (use.region == region)
        single.emplace_back(edge, place);
    }
  std::vector<Edge> edges;
  for (const auto& [edge, place] : single)
    if (sides[place] >= 2)
      edges.push_back(edge);
  std::sort(edges.begin(), edges.end());
  return edges;
}

/// `edges` (point ids) chained into polylines: from each point where other
/// than two edges meet, then the closed loops left, which end where they
/// start. Deterministic for sorted edges.
std::vector<std::vector<vtkIdType>> chain(const std::vector<Edge>& edges)
{
  std::map<vtkIdType, std::vector<std::size_t>> at; // point -> its edges
  for (std::size_t e = 0; e < edges.size(); ++e)
  {
    at[edges[e].first].push_back(e);
    at[edges[e].second].push_back(e);
  }
  std::vector<char> used(edges.size(), 0);
  std::vector<std::vector<vtkIdType>> lines;
  auto walk = [&](vtkIdType start, std::size_t first) {
    std::vector<vtkIdType> line{ start };
    vtkIdType v = start;
    std::size_t e = first;
    while (true)
    {
      used[e] = 1;
      v = edges[e].first == v ? edges[e].second : edges[e].first;
      line.push_back(v);
      const std::vector<std::size_t>& next = at[v];
      if (next.size() != 2 || v == start)
        break;
      e = next[0] == e ? next[1] : next[0];
      if (used[e])
        break;
    }
    lines.push_back(std::move(line));
  };
  for (const auto& [v, es] : at)
    if (es.size() != 2)
      for (const std::size_t e : es)
        if (!used[e])
          walk(v, e);
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (!used[e])
      walk(edges[e].first, e);
  return lines;
}
} // namespace

vtkLKExtractCutPieceFilter::vtkLKExtractCutPieceFilter()
{
  this->SetNumberOfOutputPorts(2);
}

vtkPolyData* vtkLKExtractCutPieceFilter::GetCutLinesOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkLKExtractCutPieceFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* cut = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* piece = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* lines = vtkPolyData::GetData(outputVector, 1);
  if (!cut || !piece || !lines)
    return 0;
  auto countEdges = [lines](vtkIdType edges) {
    vtkNew<vtkIdTypeArray> count;
    count->SetName("CutLineEdges");
    count->InsertNextValue(edges);
    lines->GetFieldData()->AddArray(count);
  };
  if (cut->GetNumberOfCells() == 0 || !cut->GetPoints())
  {
    countEdges(0); // nothing cut, nothing to extract
    return 1;
  }
  vtkDataArray* regions = cut->GetCellData()->GetArray("RegionId");
  if (!regions)
  {
    vtkErrorMacro("the input has no cell data 'RegionId': give it a cut (vtkLKClosedLineCutFilter's output)");
    return 1;
  }
  std::vector<int> region(static_cast<std::size_t>(cut->GetNumberOfCells()));
  for (vtkIdType c = 0; c < cut->GetNumberOfCells(); ++c)
    region[static_cast<std::size_t>(c)] = static_cast<int>(std::lround(regions->GetTuple1(c)));
  std::vector<vtkIdType> newId;
  extractRegion(cut, region, this->Piece, this->PassAttributes, piece, newId);
  piece->GetFieldData()->ShallowCopy(cut->GetFieldData()); // SPACE, as the filters pass it
  this->UpdateProgress(0.5);
  if (lkvtk::stopRequested(this, { piece, lines }))
    return 1;

  vtkNew<vtkPoints> linePoints;
  linePoints->SetDataType(cut->GetPoints()->GetDataType());
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkIdTypeArray> meshIds;
  meshIds->SetName("MeshPointId");
  const std::vector<Edge> edges = cutEdges(cut, region, this->Piece);
  std::map<vtkIdType, vtkIdType> lineId; // piece point -> its point in the lines
  for (const std::vector<vtkIdType>& chained : chain(edges))
  {
    cells->InsertNextCell(static_cast<vtkIdType>(chained.size()));
    for (const vtkIdType v : chained)
    {
      const vtkIdType id = newId[static_cast<std::size_t>(v)];
      auto [it, added] = lineId.emplace(id, linePoints->GetNumberOfPoints());
      if (added)
      {
        linePoints->InsertNextPoint(piece->GetPoint(id));
        meshIds->InsertNextValue(id);
      }
      cells->InsertCellPoint(it->second);
    }
  }
  lines->SetPoints(linePoints);
  lines->SetLines(cells);
  lines->GetPointData()->AddArray(meshIds);
  countEdges(static_cast<vtkIdType>(edges.size()));
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLKExtractCutPieceFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Piece: " << this->Piece << "\n";
  os << indent << "PassAttributes: " << this->PassAttributes << "\n";
}
