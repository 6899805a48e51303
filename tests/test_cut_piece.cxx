// lkapp::cutPiece: one region of a cut, its cells in the cut's order and
// its points in the cut's order, with their data, every time (the VTK
// filters it replaced gave the cells in another order from run to run).
#include "common/CutReport.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

TEST(CutPiece, KeepsTheCutsOrderAndItsData)
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

  for (const int r : { 0, 1 })
  {
    vtkSmartPointer<vtkPolyData> piece = lkapp::cutPiece(cut, r, true);
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
    // Without attributes: the same cells, no data but the field data.
    vtkSmartPointer<vtkPolyData> bare = lkapp::cutPiece(cut, r);
    EXPECT_EQ(bare->GetNumberOfCells(), piece->GetNumberOfCells());
    EXPECT_EQ(bare->GetNumberOfPoints(), piece->GetNumberOfPoints());
    EXPECT_EQ(bare->GetCellData()->GetNumberOfArrays(), 0);
    EXPECT_EQ(bare->GetPointData()->GetNumberOfArrays(), 0);
    EXPECT_NE(bare->GetFieldData()->GetAbstractArray("SPACE"), nullptr);
  }
  EXPECT_EQ(lkapp::cutPiece(cut, 7)->GetNumberOfCells(), 0);
}

TEST(CutLineFacts, AreaAndExtentInTheLinesPlane)
{
  // A closed 10 x 30 mm rectangle in the plane x = 5 (a sagittal cut), its
  // corners repeated at the end, and an open line.
  vtkNew<vtkPoints> points;
  const double corners[4][3] = { { 5, 0, 0 }, { 5, 10, 0 }, { 5, 10, 30 }, { 5, 0, 30 } };
  for (const auto& c : corners)
    points->InsertNextPoint(c);
  vtkNew<vtkCellArray> lines;
  const vtkIdType loop[5] = { 0, 1, 2, 3, 0 }, open[3] = { 0, 1, 2 };
  lines->InsertNextCell(5, loop);
  lines->InsertNextCell(3, open);
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(points);
  pd->SetLines(lines);
  const std::vector<lkapp::LineFacts> facts = lkapp::lineFacts(pd);
  ASSERT_EQ(facts.size(), 2u);
  const lkapp::LineFacts& f = facts[0];
  EXPECT_TRUE(f.closed);
  EXPECT_NEAR(f.length, 80.0, 1e-9);
  EXPECT_NEAR(f.area, 300.0, 1e-9);
  // Sagittal: up is the head (S-I, along z), right is back (A-P, along y).
  EXPECT_NEAR(f.extentUp, 30.0, 1e-9);
  EXPECT_NEAR(f.extentRight, 10.0, 1e-9);
  EXPECT_EQ(f.upAxis, "S-I");
  EXPECT_EQ(f.rightAxis, "A-P");
  EXPECT_FALSE(facts[1].closed);
  EXPECT_EQ(facts[1].area, 0.0);
  const std::string withAxes = lkapp::lineFactsText(facts, true), without = lkapp::lineFactsText(facts);
  EXPECT_NE(withAxes.find("cut line 1: 4 vertices, 80.00 mm long"), std::string::npos) << withAxes;
  EXPECT_NE(withAxes.find("; it encloses 300.0 mm^2 and spans 30.00 mm (S-I) by 10.00 mm (A-P) in that plane\n"),
    std::string::npos)
    << withAxes;
  EXPECT_NE(without.find("; it encloses 300.0 mm^2 and spans 30.00 by 10.00 mm in that plane\n"), std::string::npos)
    << without;
  EXPECT_EQ(withAxes.find("cut line 2"), std::string::npos); // open lines are left out
}
