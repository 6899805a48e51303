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
