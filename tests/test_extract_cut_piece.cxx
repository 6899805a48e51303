// vtkLKExtractCutPieceFilter: one piece of a cut, its cells and points in
// the cut's order every time, and its cut lines as feature lines that a
// lattice fit keeps.
#include "MandibleLoop.h"
#include "TestSupport.h"
#include "vtkLKClosedLineCutFilter.h"
#include "vtkLKExtractCutPieceFilter.h"
#include "vtkLKLatticeFitFilter.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTriangleFilter.h>

#include <array>
#include <set>
#include <vector>

namespace
{
using Edge = std::array<vtkIdType, 2>;

Edge edgeOf(vtkIdType a, vtkIdType b)
{
  return { std::min(a, b), std::max(a, b) };
}

/// The edges of `pd`'s polygons; with `cap` (cell data "Cap"), only those of
/// faces whose Cap is `capValue`.
std::set<Edge> faceEdges(vtkPolyData* pd, int capValue = -1)
{
  std::set<Edge> edges;
  vtkDataArray* cap = pd->GetCellData()->GetArray("Cap");
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
  {
    if (pd->GetCellType(c) != VTK_TRIANGLE && pd->GetCellType(c) != VTK_POLYGON && pd->GetCellType(c) != VTK_QUAD)
      continue;
    if (capValue >= 0 && cap && static_cast<int>(cap->GetTuple1(c)) != capValue)
      continue;
    pd->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      edges.insert(edgeOf(ids->GetId(k), ids->GetId((k + 1) % ids->GetNumberOfIds())));
  }
  return edges;
}

/// The cut lines' edges as the piece's point ids (MeshPointId), and how
/// many polylines there are and how many of them close.
struct CutLines
{
  std::set<Edge> edges;
  int lines = 0, closed = 0;
};
CutLines cutLinesOf(vtkPolyData* lines)
{
  CutLines out;
  vtkDataArray* ids = lines->GetPointData()->GetArray("MeshPointId");
  EXPECT_NE(ids, nullptr);
  if (!ids)
    return out;
  auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* pts;
    it->GetCurrentCell(n, pts);
    ++out.lines;
    out.closed += n > 2 && pts[0] == pts[n - 1];
    for (vtkIdType k = 0; k + 1 < n; ++k)
      out.edges.insert(edgeOf(static_cast<vtkIdType>(ids->GetTuple1(pts[k])),
        static_cast<vtkIdType>(ids->GetTuple1(pts[k + 1]))));
  }
  return out;
}
} // namespace

TEST(ExtractCutPiece, KeepsTheCutsOrderAndItsData)
{
  // A strip of 40 triangles over 42 points; triangles alternate between
  // regions 0 and 1 in runs of three; a line in region 1.
  vtkNew<vtkPoints> points;
  vtkNew<vtkIntArray> pointTag;
  pointTag->SetName("InputPointId");
  for (int i = 0; i < 42; ++i)
  {
    points->InsertNextPoint(0.5 * i, i % 2, 0.0);
    pointTag->InsertNextValue(1000 + i);
  }
  vtkNew<vtkCellArray> polys, lines;
  vtkNew<vtkIntArray> region, cellTag;
  region->SetName("RegionId");
  cellTag->SetName("InputCellId");
  const vtkIdType line[2] = { 40, 41 };
  lines->InsertNextCell(2, line);
  region->InsertNextValue(1);
  cellTag->InsertNextValue(-1);
  for (int t = 0; t < 40; ++t)
  {
    const vtkIdType tri[3] = { t, t + 1, t + 2 };
    polys->InsertNextCell(3, tri);
    region->InsertNextValue((t / 3) % 2);
    cellTag->InsertNextValue(t);
  }
  vtkNew<vtkPolyData> cut;
  cut->SetPoints(points);
  cut->SetLines(lines);
  cut->SetPolys(polys);
  cut->GetPointData()->AddArray(pointTag);
  cut->GetCellData()->AddArray(region);
  cut->GetCellData()->AddArray(cellTag);
  vtkNew<vtkStringArray> space;
  space->SetName("SPACE");
  space->InsertNextValue("LPS");
  cut->GetFieldData()->AddArray(space);

  vtkNew<vtkLKExtractCutPieceFilter> extract;
  extract->SetInputData(cut);
  for (const int r : { 0, 1 })
  {
    extract->SetPiece(r);
    extract->PassAttributesOn();
    extract->Update();
    vtkPolyData* piece = extract->GetOutput();
    vtkDataArray* tags = piece->GetCellData()->GetArray("InputCellId");
    vtkDataArray* pointTags = piece->GetPointData()->GetArray("InputPointId");
    ASSERT_NE(tags, nullptr);
    ASSERT_NE(pointTags, nullptr);
    EXPECT_EQ(piece->GetNumberOfLines(), r == 1 ? 1 : 0);
    // The triangles in the cut's order, each with its own corners.
    int previous = -1;
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = piece->GetNumberOfLines(); c < piece->GetNumberOfCells(); ++c)
    {
      const int t = static_cast<int>(tags->GetTuple1(c));
      EXPECT_EQ((t / 3) % 2, r);
      EXPECT_GT(t, previous);
      previous = t;
      piece->GetCellPoints(c, ids);
      for (vtkIdType k = 0; k < 3; ++k)
        EXPECT_EQ(pointTags->GetTuple1(ids->GetId(k)), 1000 + t + k);
    }
    // The points in the cut's order, only those used.
    for (vtkIdType i = 1; i < piece->GetNumberOfPoints(); ++i)
      EXPECT_GT(pointTags->GetTuple1(i), pointTags->GetTuple1(i - 1));
    EXPECT_NE(piece->GetFieldData()->GetAbstractArray("SPACE"), nullptr);
    // An open strip, not cut anywhere: its borders are no cut lines.
    EXPECT_EQ(extract->GetCutLinesOutput()->GetNumberOfLines(), 0);
    // Without attributes: the same cells, no data but the field data.
    const vtkIdType cells = piece->GetNumberOfCells(), count = piece->GetNumberOfPoints();
    extract->PassAttributesOff();
    extract->Update();
    EXPECT_EQ(piece->GetNumberOfCells(), cells);
    EXPECT_EQ(piece->GetNumberOfPoints(), count);
    EXPECT_EQ(piece->GetCellData()->GetNumberOfArrays(), 0);
    EXPECT_EQ(piece->GetPointData()->GetNumberOfArrays(), 0);
    EXPECT_NE(piece->GetFieldData()->GetAbstractArray("SPACE"), nullptr);
  }
  // A piece the cut does not have: empty, no error.
  {
    lktest::ErrorRecorder errors(extract);
    extract->SetPiece(7);
    extract->Update();
    EXPECT_EQ(errors.errors, 0);
    EXPECT_EQ(extract->GetOutput()->GetNumberOfCells(), 0);
    EXPECT_EQ(extract->GetCutLinesOutput()->GetNumberOfCells(), 0);
    EXPECT_EQ(extract->GetCutLinesOutput()->GetFieldData()->GetArray("CutLineEdges")->GetTuple1(0), 0.0);
  }
  // An empty input: empty outputs, no error, no cut-line edges.
  {
    vtkNew<vtkPolyData> empty;
    vtkNew<vtkLKExtractCutPieceFilter> none;
    none->SetInputData(empty);
    lktest::ErrorRecorder errors(none);
    none->Update();
    EXPECT_EQ(errors.errors, 0);
    EXPECT_EQ(none->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(none->GetCutLinesOutput()->GetFieldData()->GetArray("CutLineEdges")->GetTuple1(0), 0.0);
  }
  // Not a cut: a clear error.
  {
    cut->GetCellData()->RemoveArray("RegionId");
    cut->Modified();
    lktest::ErrorRecorder errors(extract);
    extract->SetPiece(0);
    extract->Update();
    EXPECT_EQ(errors.errors, 1);
    EXPECT_NE(errors.messages.find("RegionId"), std::string::npos) << errors.messages;
    EXPECT_EQ(extract->GetOutput()->GetNumberOfCells(), 0);
  }
}

TEST(ExtractCutPiece, TheCutLinesOfAnOpenSheetLeaveItsOwnBorderOut)
{
  // A 10 x 10 grid of squares, each two triangles, cut along the border of
  // the square from grid point (3, 3) to (7, 7): the inner square and the
  // frame around it. The frame's border is the sheet's own, not the cut's.
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(10, 10);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  triangles->Update();
  auto grid = [](int i, int j) { return static_cast<vtkIdType>(i + 11 * j); };
  std::vector<vtkIdType> loop;
  for (int i = 3; i < 7; ++i)
    loop.push_back(grid(i, 3));
  for (int j = 3; j < 7; ++j)
    loop.push_back(grid(7, j));
  for (int i = 7; i > 3; --i)
    loop.push_back(grid(i, 7));
  for (int j = 7; j > 3; --j)
    loop.push_back(grid(3, j));
  vtkPolyData* sheet = triangles->GetOutput();
  vtkNew<vtkPoints> lp;
  vtkNew<vtkCellArray> lc;
  vtkNew<vtkIdTypeArray> meshIds;
  meshIds->SetName("MeshPointId");
  lc->InsertNextCell(static_cast<vtkIdType>(loop.size() + 1));
  for (std::size_t k = 0; k <= loop.size(); ++k)
  {
    const vtkIdType v = loop[k % loop.size()];
    lc->InsertCellPoint(lp->InsertNextPoint(sheet->GetPoint(v)));
    meshIds->InsertNextValue(v);
  }
  vtkNew<vtkPolyData> lines;
  lines->SetPoints(lp);
  lines->SetLines(lc);
  lines->GetPointData()->AddArray(meshIds);
  // (Not capped: a flat cap would lie on the inner square's own faces.)
  {
    vtkNew<vtkLKClosedLineCutFilter> cut;
    cut->SetInputData(sheet);
    cut->SetLinesData(lines);
    cut->Update();
    ASSERT_EQ(cut->GetNumberOfPieces(), 2);
    vtkNew<vtkLKExtractCutPieceFilter> extract;
    extract->SetInputConnection(cut->GetOutputPort());
    std::size_t inner = 0;
    for (int r = 0; r < 2; ++r)
    {
      extract->SetPiece(r);
      extract->Update();
      vtkPolyData* piece = extract->GetOutput();
      const CutLines cl = cutLinesOf(extract->GetCutLinesOutput());
      EXPECT_EQ(cl.edges.size(), 16u) << "piece " << r;
      EXPECT_EQ(cl.lines, 1);
      EXPECT_EQ(cl.closed, 1);
      EXPECT_EQ(extract->GetCutLinesOutput()->GetFieldData()->GetArray("CutLineEdges")->GetTuple1(0), 16.0);
      // Every one an edge of the piece, on the loop's square.
      const std::set<Edge> edges = faceEdges(piece);
      for (const Edge& e : cl.edges)
      {
        EXPECT_TRUE(edges.count(e));
        for (const vtkIdType v : e)
        {
          double p[3];
          piece->GetPoint(v, p);
          // vtkPlaneSource spans -0.5..0.5: the square is -0.2..0.2.
          EXPECT_NEAR(std::max(std::abs(p[0]), std::abs(p[1])), 0.2, 1e-6); // float points
        }
      }
      double b[6];
      piece->GetBounds(b);
      inner += b[1] - b[0] < 0.5;
    }
    EXPECT_EQ(inner, 1u); // one of the two is the inner square
    // A cut without InputPointId (written by another tool): the points the
    // cut made twice are found by their places instead.
    vtkNew<vtkPolyData> bare;
    bare->DeepCopy(cut->GetOutput());
    bare->GetPointData()->RemoveArray("InputPointId");
    extract->SetInputData(bare);
    for (int r = 0; r < 2; ++r)
    {
      extract->SetPiece(r);
      extract->Update();
      EXPECT_EQ(cutLinesOf(extract->GetCutLinesOutput()).edges.size(), 16u) << "piece " << r << ", no InputPointId";
    }
  }
}

TEST(ExtractCutPiece, AFitKeepsTheMandiblesCutLineExactly)
{
  // "Cut, extract a piece, fit it with its cut line locked" as one pipeline.
  auto bone = lktest::tciaMandible();
  std::vector<lk::EdgeKey> edges;
  auto loop = lktest::mandibleLoop(bone, edges);
  vtkNew<vtkLKClosedLineCutFilter> cut;
  cut->SetInputData(bone);
  cut->SetLinesData(loop);
  cut->CappingOn();
  vtkNew<vtkLKExtractCutPieceFilter> extract;
  extract->SetInputConnection(cut->GetOutputPort());
  vtkNew<vtkLKLatticeFitFilter> fit;
  fit->SetInputConnection(extract->GetOutputPort(0));
  fit->SetFeatureLinesConnection(extract->GetOutputPort(1));
  fit->LockFeaturesOn();
  fit->SetTargetNumberOfVertices(400);
  fit->ComputeErrorOff();
  for (int r = 0; r < 2; ++r)
  {
    extract->SetPiece(r);
    lktest::ErrorRecorder errors(fit);
    fit->Update();
    ASSERT_EQ(errors.errors, 0) << errors.messages;
    const CutLines cl = cutLinesOf(extract->GetCutLinesOutput());
    EXPECT_EQ(cl.edges.size(), edges.size());
    EXPECT_EQ(cl.closed, 1);
    // Each cut-line edge is a lattice edge, between the very points of the
    // piece (the lattice keeps the piece's points it keeps).
    vtkPolyData* lattice = fit->GetOutput();
    EXPECT_EQ(lattice->GetFieldData()->GetArray("FeatureEdges")->GetTuple1(0), static_cast<double>(edges.size()));
    std::set<std::array<double, 6>> latticeEdges;
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < lattice->GetNumberOfCells(); ++c)
    {
      lattice->GetCellPoints(c, ids);
      const vtkIdType n = ids->GetNumberOfIds();
      for (vtkIdType k = 0; k < n; ++k)
      {
        std::array<double, 3> a, b;
        lattice->GetPoint(ids->GetId(k), a.data());
        lattice->GetPoint(ids->GetId((k + 1) % n), b.data());
        if (b < a)
          std::swap(a, b);
        latticeEdges.insert({ a[0], a[1], a[2], b[0], b[1], b[2] });
      }
    }
    vtkPolyData* piece = extract->GetOutput();
    // Where the cap meets the bone.
    const std::set<Edge> bone = faceEdges(piece, 0), caps = faceEdges(piece, 1);
    for (const Edge& e : cl.edges)
    {
      EXPECT_TRUE(bone.count(e));
      EXPECT_TRUE(caps.count(e));
      std::array<double, 3> a, b;
      piece->GetPoint(e[0], a.data());
      piece->GetPoint(e[1], b.data());
      if (b < a)
        std::swap(a, b);
      EXPECT_TRUE(latticeEdges.count({ a[0], a[1], a[2], b[0], b[1], b[2] }));
    }
  }
}
