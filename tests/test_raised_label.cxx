// Text raised on a surface (filters/vtkLKRaisedLabel): the outline of a
// text, and its solid on a flat face, on a curved one, and where there is
// no room.
#include "TestSupport.h"

#include "vtkLKRaisedLabel.h"

#include <vtkCellArrayIterator.h>
#include <vtkCylinderSource.h>
#include <vtkMassProperties.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkTriangleFilter.h>

#include <cmath>
#include <map>
#include <utility>

namespace
{
/// How many border loops a flat triangle mesh has, and whether every edge
/// is used by one triangle or two, and the largest edge.
struct OutlineShape
{
  int borderEdges = 0;
  bool manifold = true;
  double longestEdge = 0.0;
  double area = 0.0;
  bool counterClockwise = true;
};

OutlineShape shapeOf(vtkPolyData* outline)
{
  OutlineShape shape;
  std::map<std::pair<vtkIdType, vtkIdType>, int> uses;
  auto it = vtk::TakeSmartPointer(outline->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    double p[3][3];
    for (int c = 0; c < 3; ++c)
      outline->GetPoint(ids[c], p[c]);
    const double area = 0.5 * ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]));
    shape.area += area;
    shape.counterClockwise = shape.counterClockwise && area > 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const vtkIdType a = ids[c], b = ids[(c + 1) % 3];
      ++uses[{ std::min(a, b), std::max(a, b) }];
      shape.longestEdge = std::max(shape.longestEdge, std::sqrt(vtkMath::Distance2BetweenPoints(p[c], p[(c + 1) % 3])));
    }
  }
  for (const auto& [edge, count] : uses)
  {
    shape.borderEdges += count == 1;
    shape.manifold = shape.manifold && count <= 2;
  }
  return shape;
}
} // namespace

TEST(RaisedLabel, ATextsOutlineIsAsTallAsAskedCounterClockwiseAndFine)
{
  auto outline = lkvtk::textOutline("1-3", 3.0, 0.6, 0.3);
  ASSERT_TRUE(outline);
  double b[6];
  outline->GetBounds(b);
  EXPECT_NEAR(b[0], 0.0, 1e-9);
  EXPECT_NEAR(b[2], 0.0, 1e-9);
  EXPECT_NEAR(b[3] - b[2], 3.0, 0.1);
  EXPECT_GT(b[1] - b[0], 1.5 * 3.0); // three characters side by side
  EXPECT_LT(b[1] - b[0], 2.5 * 3.0);
  const OutlineShape shape = shapeOf(outline);
  EXPECT_TRUE(shape.manifold);
  EXPECT_TRUE(shape.counterClockwise);
  EXPECT_LE(shape.longestEdge, 0.3 + 1e-9);
  EXPECT_GT(shape.borderEdges, 0);
  // Thickened strokes cover more than the font's own.
  auto thin = lkvtk::textOutline("1-3", 3.0, 0.0, 0.3);
  ASSERT_TRUE(thin);
  EXPECT_GT(shape.area, 1.2 * shapeOf(thin).area);
}

TEST(RaisedLabel, NothingPrintableGivesNoOutline)
{
  EXPECT_FALSE(lkvtk::textOutline("", 3.0, 0.6, 0.3));
  EXPECT_FALSE(lkvtk::textOutline("   ", 3.0, 0.6, 0.3));
  EXPECT_FALSE(lkvtk::textOutline("1", 0.0, 0.6, 0.3));
  EXPECT_FALSE(lkvtk::textOutline("1", 3.0, 0.6, 0.0));
  EXPECT_FALSE(lkvtk::textOutline("1", 0.5, 0.6, 0.3)); // thinner than its strokes
}

TEST(RaisedLabel, OnAFlatFaceTheSolidIsClosedOutwardAndAsThickAsAsked)
{
  auto box = lktest::triangulatedBox(20, 20, 10, 2); // top face at z = 5
  auto outline = lkvtk::textOutline("08", 4.0, 0.6, 0.5);
  ASSERT_TRUE(outline);
  const double origin[3] = { -3, -2, 0 }, x[3] = { 1, 0, 0 }, y[3] = { 0, 1, 0 };
  std::string why;
  auto solid = lkvtk::raisedLabel(box, outline, origin, x, y, 0.6, 1.0, why);
  ASSERT_TRUE(solid) << why;
  EXPECT_EQ(lktest::openOrNonManifoldEdges(solid), 0);
  const double area = shapeOf(outline).area;
  EXPECT_NEAR(lktest::signedVolume(solid), area * 1.6, 1e-6 * area);
  double b[6];
  solid->GetBounds(b);
  EXPECT_NEAR(b[4], 4.0, 1e-9);
  EXPECT_NEAR(b[5], 5.6, 1e-9);
  // "0" and "8" keep their holes: five border loops, the solid's walls
  // round each (closed, above).
  vtkNew<vtkFeatureEdges> border;
  border->SetInputData(outline);
  border->BoundaryEdgesOn();
  border->FeatureEdgesOff();
  border->NonManifoldEdgesOff();
  border->ManifoldEdgesOff();
  vtkNew<vtkPolyDataConnectivityFilter> loops;
  loops->SetInputConnection(border->GetOutputPort());
  loops->SetExtractionModeToAllRegions();
  loops->Update();
  EXPECT_EQ(loops->GetNumberOfExtractedRegions(), 5);
}

TEST(RaisedLabel, OnACurvedFaceTheTextFollowsIt)
{
  // A cylinder of radius 10 along x, seen from +z: the text across its top.
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetRadius(10.0);
  cylinder->SetHeight(40.0);
  cylinder->SetResolution(720);
  cylinder->CappingOn();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cylinder->GetOutputPort());
  triangles->Update(); // its axis is y
  auto outline = lkvtk::textOutline("12", 4.0, 0.6, 0.25);
  ASSERT_TRUE(outline);
  const double origin[3] = { -3, -2, 0 }, x[3] = { 1, 0, 0 }, y[3] = { 0, 1, 0 };
  std::string why;
  auto solid = lkvtk::raisedLabel(triangles->GetOutput(), outline, origin, x, y, 0.5, 0.8, why);
  ASSERT_TRUE(solid) << why;
  EXPECT_EQ(lktest::openOrNonManifoldEdges(solid), 0);
  EXPECT_GT(lktest::signedVolume(solid), 0.0);
  // Every top point 0.5 above the cylinder along z, every bottom one 0.8
  // below (the facets of 0.5 degrees lie within 0.0004 of the circle).
  const vtkIdType count = solid->GetNumberOfPoints() / 2;
  for (vtkIdType i = 0; i < count; ++i)
  {
    double top[3], beneath[3];
    solid->GetPoint(i, top);
    solid->GetPoint(count + i, beneath);
    const double onCylinder = std::sqrt(100.0 - top[0] * top[0]);
    ASSERT_NEAR(top[2], onCylinder + 0.5, 1e-3);
    ASSERT_NEAR(beneath[2], onCylinder - 0.8, 1e-3);
  }
}

TEST(RaisedLabel, WhereThereIsNoRoomItSaysWhy)
{
  auto box = lktest::triangulatedBox(10, 10, 10, 1);
  auto outline = lkvtk::textOutline("123", 4.0, 0.6, 0.5);
  ASSERT_TRUE(outline);
  const double x[3] = { 1, 0, 0 }, y[3] = { 0, 1, 0 };
  std::string why;
  const double beyond[3] = { 3, 0, 0 }; // runs past the box's edge at x = 5
  EXPECT_FALSE(lkvtk::raisedLabel(box, outline, beyond, x, y, 0.6, 1.0, why));
  EXPECT_EQ(why, "the text would reach beyond the surface");
  // Over the box's side, seen from a steep angle: the face is turned away.
  const double side[3] = { 1, -2, 0 }, tilted[3] = { 0, 0.2, -0.98 };
  double yTilted[3];
  vtkMath::Cross(tilted, x, yTilted); // up = x cross y = tilted
  EXPECT_FALSE(lkvtk::raisedLabel(box, outline, side, x, yTilted, 0.6, 1.0, why));
  EXPECT_FALSE(why.empty());
  EXPECT_FALSE(lkvtk::raisedLabel(nullptr, outline, side, x, y, 0.6, 1.0, why));
}
