// What the tools report about a cut (apps/common/CutReport.h): where a cut
// line lies.
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
