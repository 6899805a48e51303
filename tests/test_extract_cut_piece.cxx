// vtkLKExtractCutPieceFilter: one piece of a cut, its cells and points in
// the cut's order every time, and its cut lines as feature lines that a
// lattice fit keeps.
#include "MandibleLoop.h"
#include "TestSupport.h"
#include "vtkLKClosedLineCutFilter.h"
#include "vtkLKExtractCutPieceFilter.h"
#include "vtkLKLatticeFitFilter.h"
#include "vtkLKStrokeFeatureLineFilter.h"
#include "latticekit/FeatureChains.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkMath.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
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

/// The TCIA mandible cut along a pen stroke round the body near its loop
/// (as ScriptedClosedStrokeOnTheMandibleCutsIt: split mode, capped), ready
/// to extract a piece; the pipeline lives as long as the filter. `loop`, when
/// given, receives the loop along mesh edges the stroke was drawn near.
vtkSmartPointer<vtkLKExtractCutPieceFilter> mandibleCutAlongAStroke(vtkSmartPointer<vtkPolyData>* loop = nullptr)
{
  auto bone = lktest::tciaMandible();
  std::vector<lk::EdgeKey> loopEdges;
  auto line = lktest::mandibleLoop(bone, loopEdges);
  if (loop)
    *loop = line;
  vtkNew<vtkLKStrokeFeatureLineFilter> split;
  split->SetInputData(bone);
  split->SetStrokeData(lktest::strokeNearLoop(line));
  split->SetModeToSplit();
  vtkNew<vtkLKClosedLineCutFilter> cut;
  cut->SetInputConnection(split->GetOutputPort());
  cut->SetLinesConnection(split->GetOutputPort(1));
  cut->CappingOn();
  auto extract = vtkSmartPointer<vtkLKExtractCutPieceFilter>::New();
  extract->SetInputConnection(cut->GetOutputPort());
  return extract;
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

// A cut line split into the mandible (a stroke round its body) has a vertex
// wherever it crosses a mesh edge, a few tenths of a millimetre apart. Locked
// whole, each piece's lattice spends a vertex on every one. With a feature
// tolerance each piece keeps the points that hold the line within it (the
// same in both pieces), exactly where they were, the line within the
// tolerance of the chords between them, and the vertices saved go to the
// surface, which fits closer.
TEST(ExtractCutPiece, AFeatureToleranceKeepsThePointsASplitCutLineNeedsInBothPieces)
{
  // A pen stroke round the body, near the mandible's loop.
  auto extract = mandibleCutAlongAStroke();
  const double tolerance = 0.05;
  std::set<std::array<double, 3>> keptInPiece[2];
  for (int r = 0; r < 2; ++r)
  {
    extract->SetPiece(r);
    extract->Update();
    const CutLines cl = cutLinesOf(extract->GetCutLinesOutput());
    ASSERT_EQ(cl.closed, 1);
    ASSERT_GT(cl.edges.size(), 80u) << "a line split into the surface";
    double mean[2] = { 0, 0 };
    for (const double t : { 0.0, tolerance })
    {
      vtkNew<vtkLKLatticeFitFilter> fit;
      fit->SetInputConnection(extract->GetOutputPort(0));
      fit->SetFeatureLinesConnection(extract->GetOutputPort(1));
      fit->LockFeaturesOn();
      fit->SetFeatureTolerance(t);
      fit->SetTargetNumberOfVertices(r == 0 ? 600 : 300);
      lktest::ErrorRecorder errors(fit);
      fit->Update();
      ASSERT_EQ(errors.errors, 0) << errors.messages;
      vtkPolyData* lattice = fit->GetOutput();
      mean[t > 0] = lattice->GetFieldData()->GetArray("Hausdorff_Mean")->GetTuple1(0);
      const double featureEdges = lattice->GetFieldData()->GetArray("FeatureEdges")->GetTuple1(0);
      if (t == 0.0)
      {
        EXPECT_EQ(featureEdges, static_cast<double>(cl.edges.size()));
        continue;
      }
      EXPECT_LT(featureEdges, 0.6 * static_cast<double>(cl.edges.size())) << "piece " << r;
      EXPECT_GE(featureEdges, 4.0);
      // The lattice's feature edges: chords between points of the piece.
      std::vector<std::array<lk::Vec3, 2>> chords;
      vtkDataArray* isFeature = lattice->GetCellData()->GetArray("FeatureEdge");
      vtkNew<vtkIdList> ids;
      for (vtkIdType c = 0; c < lattice->GetNumberOfCells(); ++c)
      {
        if (isFeature->GetTuple1(c) != 1.0)
          continue;
        lattice->GetCellPoints(c, ids);
        ASSERT_EQ(ids->GetNumberOfIds(), 2);
        std::array<lk::Vec3, 2> chord;
        for (int k = 0; k < 2; ++k)
        {
          double p[3];
          lattice->GetPoint(ids->GetId(k), p);
          chord[static_cast<std::size_t>(k)] = lk::Vec3(p[0], p[1], p[2]);
          keptInPiece[r].insert({ p[0], p[1], p[2] });
        }
        chords.push_back(chord);
      }
      EXPECT_EQ(static_cast<double>(chords.size()), featureEdges);
      // Every point of the cut line lies within the tolerance of a chord.
      vtkPolyData* piece = extract->GetOutput(0);
      std::set<vtkIdType> linePoints;
      for (const Edge& e : cl.edges)
        linePoints.insert(e.begin(), e.end());
      for (const vtkIdType id : linePoints)
      {
        double q[3];
        piece->GetPoint(id, q);
        const lk::Vec3 p(q[0], q[1], q[2]);
        double nearest = 1e9;
        for (const auto& [a, b] : chords)
        {
          const double s = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
          nearest = std::min(nearest, (p - (a + s * (b - a))).norm());
        }
        EXPECT_LE(nearest, tolerance + 1e-6) << "line point " << id << " of piece " << r;
      }
    }
    EXPECT_LT(mean[1], mean[0]) << "piece " << r << ": the vertices saved on the line fit the surface";
  }
  // Both pieces keep the points the line's shape needs (chainVerticesToKeep,
  // from the points alone): the same in both. A few more stay where the
  // collapse along the line would fold the surface; those differ.
  std::set<std::array<double, 3>> needed;
  {
    extract->SetPiece(0);
    extract->Update();
    vtkPolyData* piece = extract->GetOutput(0);
    std::vector<std::pair<std::int64_t, std::int64_t>> lineEdges;
    for (const Edge& e : cutLinesOf(extract->GetCutLinesOutput()).edges)
      lineEdges.emplace_back(e[0], e[1]);
    std::vector<lk::Vec3> points(static_cast<std::size_t>(piece->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
    {
      double q[3];
      piece->GetPoint(i, q);
      points[static_cast<std::size_t>(i)] = lk::Vec3(q[0], q[1], q[2]);
    }
    const auto chains = lk::featureChains(lineEdges);
    ASSERT_EQ(chains.size(), 1u);
    ASSERT_EQ(chains[0].front(), chains[0].back()) << "one closed loop";
    const std::vector<char> keep = lk::chainVerticesToKeep(points, chains[0], tolerance);
    for (std::size_t k = 0; k < keep.size(); ++k)
      if (keep[k])
      {
        const lk::Vec3& p = points[static_cast<std::size_t>(chains[0][k])];
        needed.insert({ p.x(), p.y(), p.z() });
      }
  }
  EXPECT_GE(needed.size(), 20u);
  for (int r = 0; r < 2; ++r)
  {
    for (const auto& p : needed)
      EXPECT_TRUE(keptInPiece[r].count(p)) << "piece " << r << " keeps the needed point " << p[0] << " " << p[1]
                                           << " " << p[2];
    EXPECT_LE(keptInPiece[r].size(), needed.size() + needed.size() / 4) << "piece " << r;
  }
}

TEST(ExtractCutPiece, ACutPiecesRimIsACreaseOfItsLatticeAndALineOnSmoothBoneIsNot)
{
  vtkSmartPointer<vtkPolyData> loop;
  auto extract = mandibleCutAlongAStroke(&loop);
  // Round smooth bone: the loop along mesh edges stays smooth.
  {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(lktest::tciaMandible());
    fit->SetFeatureLinesData(loop);
    fit->LockFeaturesOn();
    fit->SetFeatureTolerance(0.05);
    fit->SetTargetNumberOfVertices(600);
    fit->ComputeErrorOff();
    lktest::ErrorRecorder errors(fit);
    fit->Update();
    ASSERT_EQ(errors.errors, 0) << errors.messages;
    EXPECT_GT(fit->GetOutput()->GetFieldData()->GetArray("FeatureEdges")->GetTuple1(0), 10.0);
    EXPECT_EQ(fit->GetOutput()->GetFieldData()->GetArray("CreaseEdges")->GetTuple1(0), 0.0)
      << "a line on smooth bone bends by a few degrees on average";
  }
  // The rim of a cut piece, where the cap meets the bone.
  extract->SetPiece(0);
  extract->Update();
  vtkPolyData* piece = extract->GetOutput(0);
  // The piece's points within 1.5 mm of its cut line.
  std::vector<vtkIdType> nearRim;
  {
    const CutLines cl = cutLinesOf(extract->GetCutLinesOutput());
    ASSERT_EQ(cl.closed, 1);
    std::set<vtkIdType> onLine;
    for (const Edge& e : cl.edges)
      onLine.insert(e.begin(), e.end());
    for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
    {
      double p[3];
      piece->GetPoint(i, p);
      for (const vtkIdType j : onLine)
      {
        double q[3];
        piece->GetPoint(j, q);
        if (vtkMath::Distance2BetweenPoints(p, q) < 1.5 * 1.5)
        {
          nearRim.push_back(i);
          break;
        }
      }
    }
    ASSERT_GT(nearRim.size(), 200u);
  }
  double rimMean[2] = { 0, 0 }, mean[2] = { 0, 0 };
  for (const double angle : { 45.0, 180.0 })
  {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputConnection(extract->GetOutputPort(0));
    fit->SetFeatureLinesConnection(extract->GetOutputPort(1));
    fit->LockFeaturesOn();
    fit->SetFeatureTolerance(0.05);
    fit->SetCreaseAngle(angle);
    fit->SetTargetNumberOfVertices(600);
    lktest::ErrorRecorder errors(fit);
    fit->Update();
    ASSERT_EQ(errors.errors, 0) << errors.messages;
    vtkPolyData* lattice = fit->GetOutput();
    const double featureEdges = lattice->GetFieldData()->GetArray("FeatureEdges")->GetTuple1(0);
    const double creases = lattice->GetFieldData()->GetArray("CreaseEdges")->GetTuple1(0);
    ASSERT_GT(featureEdges, 10.0);
    EXPECT_EQ(creases, angle < 180.0 ? featureEdges : 0.0);
    vtkDataArray* isFeature = lattice->GetCellData()->GetArray("FeatureEdge");
    vtkDataArray* weight = lattice->GetCellData()->GetArray("RoundingWeight");
    for (vtkIdType c = 0; c < lattice->GetNumberOfCells(); ++c)
      EXPECT_EQ(weight->GetTuple1(c), isFeature->GetTuple1(c) == 1.0 && angle < 180.0 ? 0.0 : 1.0) << "cell " << c;
    const int k = angle < 180.0 ? 0 : 1;
    vtkDataArray* distance = fit->GetVertexMapOutput()->GetPointData()->GetArray("Distance");
    for (const vtkIdType i : nearRim)
      rimMean[k] += distance->GetTuple1(i) / static_cast<double>(nearRim.size());
    mean[k] = lattice->GetFieldData()->GetArray("Hausdorff_Mean")->GetTuple1(0);
  }
  std::cout << "near the rim: creased " << rimMean[0] << " mm, rounded " << rimMean[1] << " mm; Metro mean "
            << mean[0] << " and " << mean[1] << "\n";
  EXPECT_LT(rimMean[0], 0.8 * rimMean[1]) << "the crease keeps the rim's edge";
  EXPECT_LT(mean[0], mean[1]);
}

TEST(ExtractCutPiece, LockedLinesThatTakeMostOfTheVerticesAreWarnedOf)
{
  // Piece 1 at 100 vertices: its cut line, kept whole, takes 137 (the fit
  // stops at 193, with a warning of its own); with a tolerance, a few dozen.
  auto extract = mandibleCutAlongAStroke();
  extract->SetPiece(1);
  for (const double tolerance : { 0.0, 0.05 })
  {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputConnection(extract->GetOutputPort(0));
    fit->SetFeatureLinesConnection(extract->GetOutputPort(1));
    fit->LockFeaturesOn();
    fit->SetFeatureTolerance(tolerance);
    fit->SetTargetNumberOfVertices(100);
    fit->ComputeErrorOff();
    lktest::ErrorRecorder errors(fit);
    fit->Update();
    ASSERT_EQ(errors.errors, 0) << errors.messages;
    const bool warned = errors.warningMessages.find("The locked feature lines keep ") != std::string::npos;
    EXPECT_EQ(warned, tolerance == 0.0) << errors.warningMessages;
    if (tolerance == 0.0)
      EXPECT_NE(errors.warningMessages.find("ask for more vertices (twice the lines' leaves it as many), or let each "
                                            "line keep only the points it needs (a feature tolerance)"),
        std::string::npos)
        << errors.warningMessages;
  }
}
