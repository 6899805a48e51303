#include "vtkLKSurfaceAttributes.h"

#include <vtkAbstractArray.h>
#include <vtkCell.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <array>
#include <utility>

namespace lkvtk
{
namespace
{
using Triple = std::array<vtkIdType, 3>;

/// The triangles of a surface by their corners (sorted), bucketed by the
/// smallest corner: a triangle is found by its corners in a scan of the few
/// triangles that share its smallest one (a hash map of a skull's 1.5
/// million triangles cost a second a stroke in cache misses).
class TrianglesByCorners
{
public:
  /// `triangles`: a value (its input cell) and the sorted corners of each,
  /// corners below `points`.
  TrianglesByCorners(vtkIdType points, std::vector<std::pair<vtkIdType, Triple>> triangles)
    : Offsets(static_cast<std::size_t>(points) + 1, 0)
  {
    for (const auto& t : triangles)
      ++this->Offsets[static_cast<std::size_t>(t.second[0]) + 1];
    for (std::size_t i = 1; i < this->Offsets.size(); ++i)
      this->Offsets[i] += this->Offsets[i - 1];
    this->Entries.resize(triangles.size());
    std::vector<vtkIdType> next(this->Offsets.begin(), this->Offsets.end() - 1);
    // In the order given, so a bucket's first match is the first triangle
    // with those corners.
    for (auto& t : triangles)
      this->Entries[static_cast<std::size_t>(next[static_cast<std::size_t>(t.second[0])]++)] = std::move(t);
  }

  /// The value given with the first triangle that has these (sorted)
  /// corners, or -1.
  vtkIdType find(const Triple& corners) const
  {
    if (corners[0] < 0 || corners[0] + 1 >= static_cast<vtkIdType>(this->Offsets.size()))
      return -1;
    const auto begin = static_cast<std::size_t>(this->Offsets[static_cast<std::size_t>(corners[0])]);
    const auto end = static_cast<std::size_t>(this->Offsets[static_cast<std::size_t>(corners[0]) + 1]);
    for (std::size_t i = begin; i < end; ++i)
      if (this->Entries[i].second == corners)
        return this->Entries[i].first;
    return -1;
  }

private:
  std::vector<vtkIdType> Offsets;
  std::vector<std::pair<vtkIdType, Triple>> Entries;
};

template <typename F>
void forEachTriangle(vtkCellArray* cells, F&& f)
{
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
}

/// The input triangle nearest x: its input-numbered corners and the
/// barycentric weights of the point of it nearest x.
class NearestTriangle
{
public:
  explicit NearestTriangle(vtkPolyData* triangles)
    : Triangles(triangles)
  {
  }
  vtkIdType find(const double x[3], vtkIdList* corners, double weights[3])
  {
    if (!this->Locator)
    {
      this->Locator = vtkSmartPointer<vtkStaticCellLocator>::New();
      this->Locator->SetDataSet(this->Triangles);
      this->Locator->BuildLocator();
    }
    double closest[3], d2, pcoords[3];
    vtkIdType cellId = -1;
    int subId = 0;
    this->Locator->FindClosestPoint(x, closest, cellId, subId, d2);
    vtkCell* cell = this->Triangles->GetCell(cellId);
    cell->EvaluatePosition(closest, nullptr, subId, pcoords, d2, weights);
    corners->DeepCopy(cell->GetPointIds());
    return cellId;
  }

private:
  vtkPolyData* Triangles;
  vtkSmartPointer<vtkStaticCellLocator> Locator;
};

/// vtkDataSetAttributes::NullData fills numeric arrays only: a string array
/// left short gets empty values up to n.
void padShortArrays(vtkDataSetAttributes* out, vtkIdType n)
{
  for (int i = 0; i < out->GetNumberOfArrays(); ++i)
    if (vtkAbstractArray* array = out->GetAbstractArray(i))
      if (array->GetNumberOfTuples() < n)
        array->SetNumberOfTuples(n);
}
} // namespace

void carrySurfaceAttributes(vtkPolyData* input, vtkPolyData* triangles, const std::vector<vtkIdType>& cellOf,
  const std::vector<vtkIdType>& pointSource, const std::vector<vtkIdType>& corner, vtkPolyData* output,
  bool keepNormals)
{
  vtkPointData* inPD = input->GetPointData();
  vtkCellData* inCD = input->GetCellData();
  if (inPD->GetNumberOfArrays() == 0 && inCD->GetNumberOfArrays() == 0)
    return;
  NearestTriangle nearest(triangles);
  vtkNew<vtkIdList> corners;
  double weights[3];

  vtkPointData* outPD = output->GetPointData();
  const vtkIdType nOut = output->GetNumberOfPoints();
  outPD->SetCopyNormals(keepNormals);
  if (std::find(pointSource.begin(), pointSource.end(), vtkIdType(-1)) != pointSource.end())
    outPD->InterpolateAllocate(inPD, nOut);
  else
    outPD->CopyAllocate(inPD, nOut);
  for (vtkIdType j = 0; j < nOut; ++j)
  {
    const vtkIdType from = pointSource[static_cast<std::size_t>(j)];
    if (from >= 0)
    {
      outPD->CopyData(inPD, from, j);
      continue;
    }
    double x[3];
    output->GetPoint(j, x);
    nearest.find(x, corners, weights);
    outPD->InterpolatePoint(inPD, j, corners, weights);
  }

  // Input triangles by their corners.
  auto cornerOf = [&](vtkIdType p) { return corner.empty() ? p : corner[static_cast<std::size_t>(p)]; };
  auto key = [&](vtkIdType a, vtkIdType b, vtkIdType c) {
    Triple t{ { cornerOf(a), cornerOf(b), cornerOf(c) } };
    std::sort(t.begin(), t.end());
    return t;
  };
  std::vector<std::pair<vtkIdType, Triple>> inputTriangles;
  inputTriangles.reserve(static_cast<std::size_t>(triangles->GetNumberOfPolys()));
  forEachTriangle(triangles->GetPolys(), [&](vtkIdType t, const vtkIdType* ids) {
    inputTriangles.emplace_back(cellOf[static_cast<std::size_t>(t)], key(ids[0], ids[1], ids[2]));
  });
  const TrianglesByCorners cellOfCorners(input->GetNumberOfPoints(), std::move(inputTriangles));
  vtkCellData* outCD = output->GetCellData();
  outCD->SetCopyNormals(keepNormals);
  outCD->CopyAllocate(inCD, output->GetNumberOfCells());
  const vtkIdType firstPoly = output->GetNumberOfVerts() + output->GetNumberOfLines();
  for (vtkIdType c = 0; c < firstPoly; ++c)
    outCD->NullData(c);
  forEachTriangle(output->GetPolys(), [&](vtkIdType t, const vtkIdType* ids) {
    const vtkIdType a = pointSource[static_cast<std::size_t>(ids[0])], b = pointSource[static_cast<std::size_t>(ids[1])],
                    c = pointSource[static_cast<std::size_t>(ids[2])];
    vtkIdType from = -1;
    if (a >= 0 && b >= 0 && c >= 0)
      from = cellOfCorners.find(key(a, b, c));
    if (from < 0)
    {
      double centre[3] = { 0, 0, 0 }, x[3];
      for (int k = 0; k < 3; ++k)
      {
        output->GetPoint(ids[k], x);
        for (int d = 0; d < 3; ++d)
          centre[d] += x[d] / 3.0;
      }
      from = cellOf[static_cast<std::size_t>(nearest.find(centre, corners, weights))];
    }
    outCD->CopyData(inCD, from, firstPoly + t);
  });
  padShortArrays(outPD, nOut);
  padShortArrays(outCD, output->GetNumberOfCells());
}

void carryByOrigin(vtkDataSetAttributes* in, vtkDataSetAttributes* out, vtkIdTypeArray* origin)
{
  const vtkIdType n = origin->GetNumberOfValues();
  out->CopyNormalsOff();
  out->CopyAllocate(in, n);
  for (vtkIdType id = 0; id < n; ++id)
  {
    const vtkIdType from = origin->GetValue(id);
    if (from >= 0)
      out->CopyData(in, from, id);
    else
      out->NullData(id);
  }
  padShortArrays(out, n);
}
} // namespace lkvtk
