// vtkLKCuttingGuideFilter: a cutting guide on a box (exact volume, slot and
// contact), on the TCIA mandible (closed, outward, outside the bone, free to
// come off along its approach), and on bad input.
#include "TestSupport.h"

#include "latticekit/SolidBooleans.h"

#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKCuttingGuideFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKRaisedLabel.h"
#include "vtkLKRayCast.h"
#include "vtkLKSectionLoops.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCleanPolyData.h>
#include <vtkCubeSource.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkImplicitPolyDataDistance.h>
#include <vtkLinearSubdivisionFilter.h>
#include <vtkMath.h>
#include <vtkPlane.h>
#include <vtkPlaneCollection.h>
#include <vtkPoints.h>
#include <vtkCellData.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkPolyDataNormals.h>
#include <vtkMassProperties.h>
#include <vtkStringArray.h>
#include <vtkStaticCellLocator.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace
{
/// A closed box 40 x 20 x 30 mm centred at the origin, in triangles.
vtkSmartPointer<vtkPolyData> box()
{
  return lktest::triangulatedBox(40, 20, 30, 2);
}

/// How many corners of the guide's inner face's border (seen along the
/// approach d) turn more than 45 degrees where an edge beside them rises
/// along d more steeply than 45 degrees: the teeth a stepped edge on a steep
/// face makes once swept.
int teethAtTheEdge(vtkPolyData* guide, const double d[3])
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(guide);
  normals->ComputeCellNormalsOn();
  normals->ComputePointNormalsOff();
  normals->SplittingOff();
  normals->ConsistencyOff();
  normals->Update();
  vtkPolyData* faces = normals->GetOutput();
  vtkDataArray* n = faces->GetCellData()->GetNormals();
  std::map<std::pair<vtkIdType, vtkIdType>, int> uses;
  vtkNew<vtkIdList> ids;
  for (vtkIdType i = 0; i < faces->GetNumberOfCells(); ++i)
  {
    double normal[3];
    n->GetTuple(i, normal);
    if (vtkMath::Dot(normal, d) > -0.2)
      continue; // not the inner face
    faces->GetCellPoints(i, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      const vtkIdType a = ids->GetId(k), b = ids->GetId((k + 1) % ids->GetNumberOfIds());
      ++uses[{ std::min(a, b), std::max(a, b) }];
    }
  }
  std::map<vtkIdType, std::vector<vtkIdType>> border;
  for (const auto& [edge, count] : uses)
    if (count == 1)
    {
      border[edge.first].push_back(edge.second);
      border[edge.second].push_back(edge.first);
    }
  int teeth = 0;
  for (const auto& [v, next] : border)
  {
    if (next.size() != 2)
      continue;
    double p[3], a[3], b[3];
    faces->GetPoint(v, p);
    faces->GetPoint(next[0], a);
    faces->GetPoint(next[1], b);
    double in[3], out[3];
    vtkMath::Subtract(p, a, in);
    vtkMath::Subtract(b, p, out);
    const double riseIn = vtkMath::Dot(in, d), riseOut = vtkMath::Dot(out, d);
    for (int k = 0; k < 3; ++k)
    {
      in[k] -= riseIn * d[k];
      out[k] -= riseOut * d[k];
    }
    const double lengthIn = vtkMath::Norm(in), lengthOut = vtkMath::Norm(out);
    if (!(lengthIn > 1e-9 && lengthOut > 1e-9))
      continue;
    const bool turns = vtkMath::Dot(in, out) < std::cos(vtkMath::RadiansFromDegrees(45.0)) * lengthIn * lengthOut;
    const bool steep = std::abs(riseIn) > lengthIn || std::abs(riseOut) > lengthOut;
    teeth += turns && steep;
  }
  return teeth;
}

double field(vtkPolyData* pd, const char* name, int component = 0)
{
  vtkDataArray* a = pd->GetFieldData()->GetArray(name);
  EXPECT_NE(a, nullptr) << name;
  return a ? a->GetComponent(0, component) : std::numeric_limits<double>::quiet_NaN();
}
} // namespace

TEST(CuttingGuideFilter, OnABoxItIsTheContactSweptLessTheSlot)
{
  vtkNew<vtkLKCuttingGuideFilter> guide;
  guide->SetInputData(box());
  guide->SetPlaneOrigin(0, 0, 0);
  guide->SetPlaneNormal(2, 0, 0);
  guide->SetApproach(0.3, -1, 0); // the part along the normal is left out
  guide->SetClearance(0.5);
  guide->SetScrewHoleDiameter(0.0); // the holes: below
  guide->Update();
  vtkPolyData* out = guide->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  // The face y = -10 within 8 mm of the plane: 16 x 30 mm. The slot: 1.2 mm
  // wide, the contact's 30 mm less two bridges of 3 mm, 4 mm deep.
  EXPECT_NEAR(guide->GetContactArea(), 16.0 * 30.0 - 1.2 * 24.0, 1e-4);
  EXPECT_NEAR(guide->GetSlotLength(), 24.0, 1e-6);
  EXPECT_NEAR(guide->GetVolume(), 16.0 * 30.0 * 4.0 - 1.2 * 24.0 * 4.0, 1e-3);
  EXPECT_NEAR(lktest::signedVolume(out), guide->GetVolume(), 1e-3); // faces oriented outward
  EXPECT_NEAR(guide->GetApproachUsed()[0], 0.0, 1e-12);
  EXPECT_NEAR(guide->GetApproachUsed()[1], -1.0, 1e-12);
  EXPECT_NEAR(field(out, "GuideApproach", 1), -1.0, 1e-12);
  EXPECT_NEAR(field(out, "GuideSlotLength"), 24.0, 1e-6);
  EXPECT_NEAR(field(out, "GuideContactArea"), 480.0 - 28.8, 1e-4);
  EXPECT_NEAR(field(out, "GuideVolume"), guide->GetVolume(), 1e-9);
  // Where the guide is, for a bar that joins it to another: its plane, the
  // slot's middle on the bone, its sizes.
  EXPECT_NEAR(field(out, "GuidePlaneNormal", 0), 1.0, 1e-12);
  EXPECT_NEAR(field(out, "GuideSlotCentre", 0), 0.0, 1e-9);
  EXPECT_NEAR(field(out, "GuideSlotCentre", 1), -10.0, 1e-9);
  EXPECT_NEAR(field(out, "GuideSlotCentre", 2), 0.0, 1e-6);
  EXPECT_DOUBLE_EQ(field(out, "GuideSlotWidth"), 1.2);
  EXPECT_DOUBLE_EQ(field(out, "GuideThickness"), 4.0);
  EXPECT_DOUBLE_EQ(field(out, "GuideReach"), 8.0);
  EXPECT_DOUBLE_EQ(field(out, "GuideClearance"), 0.5);
  EXPECT_DOUBLE_EQ(field(out, "GuideScrewHoleDiameter"), 0.0); // none made
  // Where it lies: from the clearance to the wall's far side in y, within
  // the reach in x; nothing in the slot between the bridges.
  double b[6];
  out->GetBounds(b);
  EXPECT_NEAR(b[0], -8.0, 1e-9);
  EXPECT_NEAR(b[1], 8.0, 1e-9);
  EXPECT_NEAR(b[2], -14.5, 1e-9);
  EXPECT_NEAR(b[3], -10.5, 1e-9);
  EXPECT_NEAR(b[4], -15.0, 1e-9);
  EXPECT_NEAR(b[5], 15.0, 1e-9);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    EXPECT_FALSE(std::abs(x[0]) < 0.6 - 1e-9 && std::abs(x[2]) < 12.0 - 1e-9) << "a point in the slot";
  }

  // On the other side: the face y = 10, the same guide mirrored.
  guide->OtherSideOn();
  guide->Update();
  out->GetBounds(b);
  EXPECT_NEAR(b[2], 10.5, 1e-9);
  EXPECT_NEAR(b[3], 14.5, 1e-9);
  EXPECT_NEAR(guide->GetApproachUsed()[1], 1.0, 1e-12);
  EXPECT_NEAR(guide->GetVolume(), 16.0 * 30.0 * 4.0 - 1.2 * 24.0 * 4.0, 1e-3);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  guide->OtherSideOff();

  // Thicker, wider slot, no bridges short of the contact's ends but one:
  // the volume follows.
  guide->SetThickness(2.5);
  guide->SetSlotWidth(2.0);
  guide->SetBridge(1.0);
  guide->SetReach(5.0);
  guide->Update();
  EXPECT_NEAR(guide->GetVolume(), 10.0 * 30.0 * 2.5 - 2.0 * 28.0 * 2.5, 1e-3);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(guide->GetOutput()), 0);
  // No bridges: the slot runs the contact's length, and the guide is two
  // blocks, one on either side of the plane.
  guide->SetBridge(0.0);
  guide->Update();
  EXPECT_NEAR(guide->GetSlotLength(), 30.0, 1e-6);
  EXPECT_NEAR(guide->GetVolume(), 2.0 * 4.0 * 30.0 * 2.5, 1e-3);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(guide->GetOutput()), 0);
}

TEST(CuttingGuideFilter, TwoRoundScrewHolesBesideTheSlot)
{
  vtkNew<vtkLKCuttingGuideFilter> guide;
  guide->SetInputData(box());
  guide->SetPlaneNormal(1, 0, 0);
  guide->SetApproach(0, -1, 0);
  guide->Update();
  vtkPolyData* out = guide->GetOutput();
  ASSERT_EQ(guide->GetNumberOfScrewHoles(), 2);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  // Halfway between the slot (0.6 mm) and the edge (8 mm) across the plane,
  // at the middle along it, on the bone.
  vtkDataArray* centres = out->GetFieldData()->GetArray("GuideScrewHoles");
  ASSERT_NE(centres, nullptr);
  ASSERT_EQ(centres->GetNumberOfTuples(), 2);
  for (vtkIdType k = 0; k < 2; ++k)
  {
    const double* c = centres->GetTuple3(k);
    EXPECT_NEAR(std::abs(c[0]), 4.3, 1e-9);
    EXPECT_NEAR(c[1], -10.0, 1e-9);
    EXPECT_NEAR(c[2], 0.0, 1e-9);
  }
  EXPECT_LT(centres->GetTuple3(0)[0] * centres->GetTuple3(1)[0], 0.0); // one on each side
  // Round, 2.1 mm across, through the wall: no point of the guide within
  // them (but for the clip's chords across the 0.25 mm grid, 0.015 mm at
  // most), and the volume less two cylinders (the clipped polygon's within
  // 2 %).
  const double r = 1.05;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    const double fromAxis = std::hypot(std::abs(x[0]) - 4.3, x[2]);
    EXPECT_GT(fromAxis, r - 0.016) << "a point in a screw hole";
  }
  const double solid = 16.0 * 30.0 * 4.0 - 1.2 * 24.0 * 4.0, drilled = 2.0 * vtkMath::Pi() * r * r * 4.0;
  EXPECT_NEAR(guide->GetVolume(), solid - drilled, 0.02 * drilled);
  EXPECT_NEAR(lktest::signedVolume(out), guide->GetVolume(), 1e-3);
  // Too wide to fit beside the slot: refused.
  lktest::ErrorRecorder errors(guide);
  guide->SetReach(3.0);
  guide->Update();
  EXPECT_NE(errors.messages.find("a screw hole of 2.1 mm does not fit beside the slot"), std::string::npos)
    << errors.messages;
  EXPECT_EQ(guide->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(guide->GetNumberOfScrewHoles(), 0);
}

TEST(CuttingGuideFilter, ItsLabelIsRaisedOnItsOuterFaceBesideTheSlot)
{
  // The box's face y = -10, the slot along z: "7" stands upright (its up
  // along +z), 0.6 mm proud of the outer face at y = -14, beside the slot
  // and clear of the screw holes (at z = 0, x = +-4.3).
  vtkNew<vtkLKCuttingGuideFilter> plain;
  plain->SetInputData(box());
  plain->SetApproach(0, -1, 0);
  plain->Update();
  vtkNew<vtkLKCuttingGuideFilter> guide;
  guide->SetInputData(box());
  guide->SetApproach(0, -1, 0);
  guide->SetLabel("7");
  lktest::ErrorRecorder recorder(guide);
  guide->Update();
  EXPECT_EQ(recorder.warnings, 0) << recorder.warningMessages;
  vtkPolyData* out = guide->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0);
  ASSERT_TRUE(guide->GetLabelPlaced());
  EXPECT_DOUBLE_EQ(guide->GetLabelHeightUsed(), 3.0);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  EXPECT_NEAR(lktest::signedVolume(out), guide->GetVolume(), 1e-6 * guide->GetVolume());
  auto* label = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("GuideLabel"));
  ASSERT_NE(label, nullptr);
  EXPECT_EQ(label->GetValue(0), "7");
  EXPECT_EQ(plain->GetOutput()->GetFieldData()->GetAbstractArray("GuideLabel"), nullptr);
  // What it adds: the text's area, 0.6 mm tall (the rest is in the wall).
  auto outline = lkvtk::textOutline("7", 3.0, 0.6, 0.3);
  ASSERT_TRUE(outline);
  vtkNew<vtkMassProperties> area;
  area->SetInputData(outline);
  area->Update();
  EXPECT_NEAR(guide->GetVolume() - plain->GetVolume(), 0.6 * area->GetSurfaceArea(), 1e-3 * guide->GetVolume());
  // Where: the points beyond the outer face, within the label's rectangle.
  double low[3] = { 1e9, 1e9, 1e9 }, high[3] = { -1e9, -1e9, -1e9 };
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    if (x[1] > -14.0 - 1e-6)
      continue;
    for (int k = 0; k < 3; ++k)
    {
      low[k] = std::min(low[k], x[k]);
      high[k] = std::max(high[k], x[k]);
    }
  }
  EXPECT_NEAR(low[1], -14.6, 1e-9);
  EXPECT_NEAR(high[2] - low[2], 3.0, 0.05); // upright: 3 mm along z
  EXPECT_LT(high[0] - low[0], 3.0);
  EXPECT_GT(std::min(std::abs(low[0]), std::abs(high[0])), 0.6 + 0.5 - 1e-6); // beside the slot
  EXPECT_LT(std::max(std::abs(low[0]), std::abs(high[0])), 8.0 - 0.5 + 1e-6); // inside the edge
  EXPECT_GT(std::min(std::abs(low[2]), std::abs(high[2])), 1.05 + 0.5 - 1e-6); // past the screw hole
  EXPECT_LT(std::max(std::abs(low[2]), std::abs(high[2])), 15.0 - 0.5 + 1e-6); // inside the end
}

TEST(CuttingGuideFilter, ALabelWithoutRoomOrCharactersIsLeftOutWithAWarning)
{
  const std::string huge(100000, 'A'); // refused before it is drawn
  for (const char* text : { "123456789012345678", "\xc3\xa9", " ", huge.c_str() })
  {
    vtkNew<vtkLKCuttingGuideFilter> guide;
    guide->SetInputData(box());
    guide->SetApproach(0, -1, 0);
    guide->SetLabel(text);
    lktest::ErrorRecorder recorder(guide);
    guide->Update();
    EXPECT_EQ(recorder.errors, 0);
    EXPECT_EQ(recorder.warnings, 1) << text;
    EXPECT_NE(recorder.warningMessages.find("The cutting guide is made without its label"), std::string::npos)
      << recorder.warningMessages;
    if (std::string(text).size() > 10 && std::string(text).size() < 40)
      EXPECT_NE(recorder.warningMessages.find("it is too long for the room beside the slot between a screw hole and "
                                              "the guide's end (12.9 by 6.4 mm, at 1.5 mm tall)"),
        std::string::npos)
        << recorder.warningMessages;
    EXPECT_GT(guide->GetOutput()->GetNumberOfCells(), 0);
    EXPECT_FALSE(guide->GetLabelPlaced());
    EXPECT_EQ(guide->GetOutput()->GetFieldData()->GetAbstractArray("GuideLabel"), nullptr);
  }
  // Too long at 3 mm, it is made smaller, down to 1.5 mm.
  vtkNew<vtkLKCuttingGuideFilter> guide;
  guide->SetInputData(box());
  guide->SetApproach(0, -1, 0);
  guide->SetLabel("1234567");
  guide->Update();
  EXPECT_TRUE(guide->GetLabelPlaced());
  EXPECT_LT(guide->GetLabelHeightUsed(), 3.0);
  EXPECT_GE(guide->GetLabelHeightUsed(), 1.5);
}

TEST(CuttingGuideFilter, BesideAnotherSawLineItsLabelAndScrewHolesKeepClear)
{
  // The box's face y = -10, this saw at x = 0 and another 4 mm away at x =
  // 4 (a wedge, or a short segment: their guides merged into one block).
  // Alone, the label "7" and the screw hole at x = +4.3 lie where the other
  // guide's wall and slot go; told of the other plane, the hole is left out
  // (its screw would meet that saw) and the label goes to the far side,
  // beyond the other guide's reach (8 mm from x = 4). Its own plane and a
  // plane that cuts the bone far away change nothing.
  auto make = [](vtkPlaneCollection* others, std::string* warnings) {
    auto guide = vtkSmartPointer<vtkLKCuttingGuideFilter>::New();
    guide->SetInputData(box());
    guide->SetApproach(0, -1, 0);
    guide->SetLabel("7");
    guide->SetOtherCutPlanes(others);
    lktest::ErrorRecorder recorder(guide);
    guide->Update();
    EXPECT_EQ(recorder.errors, 0) << recorder.messages;
    *warnings = recorder.warningMessages;
    return guide;
  };
  auto plane = [](double x, double nx, double ny) {
    vtkNew<vtkPlane> p;
    p->SetOrigin(x, 0, 0);
    p->SetNormal(nx, ny, 0);
    return vtkSmartPointer<vtkPlane>(p);
  };
  // The label's rectangle: its corners' x.
  auto labelX = [](vtkLKCuttingGuideFilter* guide) {
    vtkDataArray* box = guide->GetOutput()->GetFieldData()->GetArray("GuideLabelBox");
    std::vector<double> x;
    if (!box || box->GetNumberOfTuples() != 3)
      return x;
    double corner[3], wide[3], up[3];
    box->GetTuple(0, corner);
    box->GetTuple(1, wide);
    box->GetTuple(2, up);
    for (const double a : { 0.0, 1.0 })
      for (const double b : { 0.0, 1.0 })
        x.push_back(corner[0] + a * wide[0] + b * up[0]);
    return x;
  };
  std::string warnings;
  auto alone = make(nullptr, &warnings);
  EXPECT_EQ(warnings, "");
  EXPECT_EQ(alone->GetNumberOfScrewHoles(), 2);
  const std::vector<double> aloneX = labelX(alone);
  ASSERT_EQ(aloneX.size(), 4u);
  const double nearest = *std::min_element(
    aloneX.begin(), aloneX.end(), [](double a, double b) { return std::abs(a - 4.0) < std::abs(b - 4.0); });
  EXPECT_LT(std::abs(nearest - 4.0), 8.0); // under the other guide

  vtkNew<vtkPlaneCollection> others;
  others->AddItem(plane(4.0, 1.0, 0.0));
  auto beside = make(others, &warnings);
  ASSERT_GT(beside->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_NE(warnings.find("The cutting guide's screw hole on the slot's side the plane's normal points to is left "
                          "out: its screw (2.1 mm, 10 mm into the bone) would lie in the path of the saw of another "
                          "cut plane (OtherCutPlanes) nearby."),
    std::string::npos)
    << warnings;
  ASSERT_EQ(beside->GetNumberOfScrewHoles(), 1);
  vtkDataArray* holes = beside->GetOutput()->GetFieldData()->GetArray("GuideScrewHoles");
  EXPECT_NEAR(holes->GetComponent(0, 0), -4.3, 1e-9); // the far one
  ASSERT_TRUE(beside->GetLabelPlaced());
  EXPECT_DOUBLE_EQ(beside->GetLabelHeightUsed(), 3.0);
  for (const double x : labelX(beside))
  {
    EXPECT_LE(x, 4.0 - 8.0 - 0.5 + 0.1) << "the label reaches under the other guide";
    EXPECT_GE(x, -8.0 + 0.5 - 1e-6) << "the label reaches past the guide's edge";
  }
  EXPECT_EQ(lktest::openOrNonManifoldEdges(beside->GetOutput()), 0);

  // Its own plane (normal reversed), and a plane across the box's far end:
  // as alone.
  vtkNew<vtkPlaneCollection> passed;
  passed->AddItem(plane(0.0, -2.0, 0.0));
  passed->AddItem(plane(19.0, 1.0, 0.1));
  auto same = make(passed, &warnings);
  EXPECT_EQ(warnings, "");
  EXPECT_EQ(same->GetNumberOfScrewHoles(), 2);
  EXPECT_EQ(labelX(same), aloneX);
  EXPECT_NEAR(same->GetVolume(), alone->GetVolume(), 1e-9 * alone->GetVolume());
  // A plane moved afterwards makes the guide anew (its time counts).
  others->GetItem(0)->SetOrigin(30.0, 0, 0);
  alone->SetOtherCutPlanes(others);
  const vtkMTimeType before = alone->GetOutput()->GetMTime();
  alone->Update();
  EXPECT_GT(alone->GetOutput()->GetMTime(), before);
}

TEST(CuttingGuideFilter, FacesTooSteepOrHiddenAreLeftOut)
{
  // Seen from (0, -1, 1) at 45 degrees, the box's faces y = -10 and
  // z = 15 both face it within 50 degrees; at 40 degrees neither does. The
  // slot runs over both (its extent 50 / sqrt 2 mm along the plane less the
  // bridges, sqrt 2 times that on the faces); the grid's cells over the
  // edge between them cut it by less than 2 mm^2.
  vtkNew<vtkLKCuttingGuideFilter> guide;
  guide->SetInputData(box());
  guide->SetPlaneNormal(1, 0, 0);
  guide->SetApproach(0, -1, 1);
  guide->SetMaximumContactAngle(50);
  guide->SetScrewHoleDiameter(0.0);
  guide->Update();
  EXPECT_NEAR(guide->GetContactArea(), 16.0 * 30.0 + 16.0 * 20.0 - 1.2 * (50.0 / std::sqrt(2.0) - 6.0) * std::sqrt(2.0), 2.0);
  EXPECT_NEAR(guide->GetSlotLength(), 50.0 / std::sqrt(2.0) - 6.0, 1e-6);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(guide->GetOutput()), 0);
  EXPECT_NEAR(lktest::signedVolume(guide->GetOutput()), guide->GetVolume(), 1e-3);
  EXPECT_GT(guide->GetVolume(), 0.0);

  lktest::ErrorRecorder errors(guide);
  guide->SetMaximumContactAngle(40);
  guide->Update();
  EXPECT_EQ(errors.errors, 1);
  EXPECT_NE(errors.messages.find("within 40 degrees over 0 mm only: no face of the bone at the cut faces the approach"),
    std::string::npos)
    << errors.messages;
  EXPECT_EQ(guide->GetOutput()->GetNumberOfCells(), 0);
}

TEST(CuttingGuideFilter, ALedgeThatEndsInsideTheContactLeavesNoNotchInItsEdge)
{
  // A block (a 0/1 label map of 0.5 mm voxels, contoured without smoothing)
  // whose front face y = -10 carries a ledge on its half x > 0, above z =
  // 3: 0.5 mm higher every 0.5 mm up to 2.5 mm. The cut's plane is z = 0,
  // so the contact runs to z = 8 (its Reach) across the ledge's foot. Where
  // the ledge is 1.5 mm high or more, the grid's cells over its wall (x = 0)
  // are steeper than 80 degrees to the approach; they were left out, as a
  // wall at the contact's edge is, though the contact lies on both sides of
  // them: a crack 4 mm long from its edge, which the smoothed edge widened
  // into a notch. (The TCIA mandible's smoothed surface has such a ledge
  // under the chin.)
  const double h = 0.5;
  const int n[3] = { 61, 71, 61 };
  vtkNew<vtkImageData> image;
  image->SetDimensions(n[0], n[1], n[2]);
  image->SetSpacing(h, h, h);
  image->SetOrigin(-15.0, -20.0, -15.0);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* v = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
      {
        const double x = -15.0 + i * h, y = -20.0 + j * h, z = -15.0 + k * h;
        const double ledge = x > 0.0 && z > 2.0 ? std::min(5.0, 2.0 * h * std::floor((z - 2.0) / h)) : 0.0;
        v[(k * n[1] + j) * n[0] + i] = std::abs(x) <= 12.0 && y <= 10.0 && y >= -10.0 - ledge && std::abs(z) <= 12.0;
      }
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  bone->SetInputData(image);
  bone->SetImageSmoothing(0.0);
  bone->SetSmoothingIterations(0);
  vtkNew<vtkLKCuttingGuideFilter> guide;
  guide->SetInputConnection(bone->GetOutputPort());
  guide->SetPlaneOrigin(0, -10, 0);
  guide->SetPlaneNormal(0, 0, 1);
  guide->SetApproach(0, -1, 0);
  guide->SetScrewHoleDiameter(0.0);
  guide->Update();
  vtkPolyData* out = guide->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  EXPECT_NEAR(lktest::signedVolume(out), guide->GetVolume(), 1e-3);
  // Seen along the approach, the guide covers its rectangle (within 1 mm of
  // its outline) but for the slot: rays 0.05 mm apart across the ledge's
  // wall, 0.25 mm along it, all meet it.
  double bounds[6];
  out->GetBounds(bounds);
  EXPECT_NEAR(bounds[4], -8.0, 0.01);
  EXPECT_NEAR(bounds[5], 8.0, 0.01);
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(out);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  int rays = 0, missed = 0;
  for (double x = bounds[0] + 1.0; x < bounds[1] - 1.0; x += 0.05)
    for (double z = -7.0; z < 7.0; z += 0.25)
    {
      if (std::abs(z) < 1.0)
        continue; // the slot, 1.2 mm wide
      const double from[3] = { x, -30.0, z }, to[3] = { x, 0.0, z };
      double hit[3];
      ++rays;
      missed += !lkvtk::firstHit(locator, from, to, cell, hit);
    }
  EXPECT_GT(rays, 15000);
  EXPECT_EQ(missed, 0) << "the guide's edge has a notch at the ledge";
}

TEST(CuttingGuideFilter, OnTheMandibleItSitsOutsideTheBoneAndComesOffAlongItsApproach)
{
  // On the label map's surface as made by default, and as it was until
  // December 2026 (a Gaussian of one voxel, no smoothing of the surface).
  for (const bool oneVoxel : { false, true })
  {
    vtkSmartPointer<vtkPolyData> surface = lktest::tciaMandibleSurface("0522c0017", oneVoxel);
    ASSERT_GT(surface->GetNumberOfCells(), 0);

    // The mid-sagittal plane of the chin (the session's saw line), and a cut
    // through the left body: the guide goes on the front and the outer side
    // without being told.
    struct Case
    {
      double origin[3], normal[3];
    };
    for (const Case& c :
      { Case{ { 0.0728, 276.64, -982.1 }, { 1, 0, 0 } }, Case{ { 30, 276.64, -982.1 }, { 1, 0.3, 0 } } })
    {
      vtkNew<vtkLKCuttingGuideFilter> guide;
      guide->SetInputData(surface);
      guide->SetPlaneOrigin(c.origin);
      guide->SetPlaneNormal(c.normal);
      guide->SetLabel("12");
      lktest::ProgressRecorder progress(guide);
      guide->Update();
      vtkPolyData* out = guide->GetOutput();
      ASSERT_GT(out->GetNumberOfCells(), 0);
      EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
      EXPECT_TRUE(guide->GetLabelPlaced());
      EXPECT_GT(guide->GetVolume(), 500.0);
      EXPECT_NEAR(lktest::signedVolume(out), guide->GetVolume(), 1e-6 * guide->GetVolume());
      EXPECT_GT(guide->GetSlotLength(), 15.0);
      EXPECT_GT(guide->GetContactArea(), 300.0);
      const double* d = guide->GetApproachUsed();
      EXPECT_LT(d[1], -0.8) << "the guide is not on the front of the jaw";
      EXPECT_NEAR(vtkMath::Dot(d, c.normal), 0.0, 1e-9);
      if (c.origin[0] > 1.0)
      {
        EXPECT_GT(d[0], 0.1) << "the guide on the left body is not on its outer side";
      }
      ASSERT_GE(progress.progress.size(), 4u);
      EXPECT_DOUBLE_EQ(progress.progress.back(), 1.0);

      // No point of the guide inside the bone, and each can leave along the
      // approach without meeting it.
      vtkNew<vtkImplicitPolyDataDistance> inside;
      inside->SetInput(surface);
      vtkNew<vtkStaticCellLocator> locator;
      locator->SetDataSet(surface);
      locator->BuildLocator();
      vtkNew<vtkGenericCell> cell;
      int within = 0, blocked = 0;
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        double x[3], from[3], to[3], hit[3];
        out->GetPoint(i, x);
        if (inside->EvaluateFunction(x) < -1e-3)
          ++within;
        for (int k = 0; k < 3; ++k)
        {
          from[k] = x[k] + 1e-2 * d[k];
          to[k] = x[k] + 500.0 * d[k];
        }
        if (lkvtk::firstHit(locator, from, to, cell, hit))
          ++blocked;
      }
      EXPECT_EQ(within, 0);
      EXPECT_EQ(blocked, 0);
      // On the default surface the chin guide's lower and upper edges cross
      // ledges of the bone about 1 mm high, whose steps the edge follows down
      // and up (15 and 5 corners counted so; NOTES, session 73); the count is
      // the one of a stepped edge on a steep face on the other.
      if (oneVoxel)
        EXPECT_LE(teethAtTheEdge(out, d), 4) << "the guide's edge stands in teeth on a steep face";
      vtkNew<vtkPolyDataConnectivityFilter> parts;
      parts->SetInputData(out);
      parts->SetExtractionModeToAllRegions();
      parts->Update();
      EXPECT_EQ(parts->GetNumberOfExtractedRegions(), 1); // no sliver beside it
    }
  }
}

TEST(CuttingGuideFilter, AcrossTheMandibleEachGuideIsOneSolidWithItsLabel)
{
  // Planes every 5 mm along the TCIA mandible, turned with the arch, on the
  // side the filter chooses and on the other: each guide is made, is one
  // closed solid that crosses nothing (CGAL's test in lk::solidUnion) and
  // carries its label. (The lingual guide at x = 35 crossed itself, 25
  // pairs, while the smooth edge's line could pass a hair from a grid point
  // on a face nearly along the approach; its label could not be joined.)
  vtkSmartPointer<vtkPolyData> bone = lktest::tciaMandibleSurface();
  ASSERT_GT(bone->GetNumberOfCells(), 0);
  int made = 0;
  for (int x = -50; x <= 50; x += 5)
    for (const bool otherSide : { false, true })
    {
      vtkNew<vtkLKCuttingGuideFilter> guide;
      guide->SetInputData(bone);
      guide->SetPlaneOrigin(x, 276.64, -982.1);
      guide->SetPlaneNormal(1, 0.01 * x, 0);
      guide->SetOtherSide(otherSide);
      guide->SetLabel(std::to_string(std::abs(x)).c_str());
      guide->Update();
      vtkPolyData* out = guide->GetOutput();
      const std::string where = "x = " + std::to_string(x) + (otherSide ? ", other side" : "");
      ASSERT_GT(out->GetNumberOfCells(), 0) << where;
      ++made;
      EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0) << where;
      lk::TriangleMesh solid;
      EXPECT_EQ(lk::solidUnion({ lktest::toCore(out) }, solid), "") << where;
      EXPECT_TRUE(guide->GetLabelPlaced()) << where;
    }
  EXPECT_EQ(made, 42);
}

TEST(CuttingGuideFilter, OnTheRamusEdgeWhatTheSmoothEdgeCutsOffIsLeftOut)
{
  // A cut across the back edge of the TCIA mandible's left ramus: on the
  // wing beside the slot toward the edge, the smooth edge's line crossed a
  // narrow neck of the contact and left a piece of 37 mm^3 loose, which a
  // printed guide would drop (and which made a part of two pieces when the
  // guide was merged with a neighbour). The guide is one piece.
  vtkSmartPointer<vtkPolyData> bone = lktest::tciaMandibleSurface();
  ASSERT_GT(bone->GetNumberOfCells(), 0);
  vtkNew<vtkLKCuttingGuideFilter> guide;
  guide->SetInputData(bone);
  guide->SetPlaneOrigin(-52.32, 342.55, -927.37);
  guide->SetPlaneNormal(-0.264, 0.964, -0.119);
  guide->SetLabel("2");
  guide->Update();
  vtkPolyData* out = guide->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  vtkNew<vtkPolyDataConnectivityFilter> parts;
  parts->SetInputData(out);
  parts->SetExtractionModeToAllRegions();
  parts->Update();
  EXPECT_EQ(parts->GetNumberOfExtractedRegions(), 1);
}

TEST(CuttingGuideFilter, OnBothMandiblesItGoesOnTheOuterSideHoweverTheCutIsSlanted)
{
  // Saw planes across both TCIA mandibles (z up): the body and chin saws of
  // the sessions, slanted body saws, cuts across the rami at slants, and
  // horizontal cuts through the chin. Each guide goes on the bone's outer
  // side: its approach points away from the bone's centre (across, in the
  // horizontal), buccal on the body, lateral on the ramus, in front at the
  // chin. The side was once chosen away from the centre of the bone within
  // twice the section's size alone: on slanted cuts the ramus above and the
  // chin in front pulled that centre outside the arch, and seven of these
  // guides went on the inner side (the second mandible's body saw at x =
  // -18.6 among them). The horizontal chin cuts have both ends of their
  // section on the bone's convex hull and keep that rule.
  struct Cut
  {
    const char* patient;
    double origin[3], normal[3];
  };
  const Cut cuts[] = {
    { "0522c0017", { -30, 276.64, -982.1 }, { 1, -0.3, 0 } },       // body saws and chin
    { "0522c0017", { 30, 276.64, -982.1 }, { 1, 0.3, 0 } },
    { "0522c0017", { 0, 270.03, -988 }, { 1, 0, 0 } },
    { "0522c0017", { -40, 325, -955 }, { 0, 0.3, 1 } },              // rami
    { "0522c0017", { 40, 325, -955 }, { 0, 0.3, 1 } },
    { "0522c0017", { 33.5, 319.3, -945.5 }, { 0.5, 0.41, 0.77 } },  // slanted, on the inner side before
    { "0522c0017", { 41.5, 337.9, -953.0 }, { 0.19, 0.05, 0.98 } },
    { "0522c0017", { -39.7, 326.8, -938.0 }, { 0.41, -0.5, -0.77 } },
    { "0522c0017", { -36.8, 316.9, -975.5 }, { 0.44, -0.76, -0.47 } },
    { "0522c0017", { -0.5, 275.9, -988 }, { 0, 0, 1 } },             // horizontal through the chin
    { "TCGA-CV-7236", { -18.6, -14.5, -978.0 }, { 1, -0.3, 0 } },    // on the inner side before
    { "TCGA-CV-7236", { -23.5, 7.1, -948.0 }, { 0.39, -0.41, -0.82 } },
    { "TCGA-CV-7236", { 45.9, 14.9, -948.9 }, { 0.39, 0.4, 0.83 } },
    { "TCGA-CV-7236", { -33.0, 13.9, -930.5 }, { 0.04, 0.8, -0.6 } },
    { "TCGA-CV-7236", { 9.8, -27.6, -980.5 }, { 0.29, -0.22, -0.93 } }, // horizontal through the chin
    { "TCGA-CV-7236", { 11.7, -36.5, -985.5 }, { 0, 0, 1 } },
  };
  struct Bone
  {
    vtkSmartPointer<vtkPolyData> surface;
    double centre[3] = { 0, 0, 0 }; ///< of its points
  };
  std::map<std::string, Bone> bones;
  for (const Cut& cut : cuts)
  {
    Bone& b = bones[cut.patient];
    if (!b.surface)
    {
      b.surface = lktest::tciaMandibleSurface(cut.patient);
      for (vtkIdType i = 0; i < b.surface->GetNumberOfPoints(); ++i)
        for (int k = 0; k < 3; ++k)
          b.centre[k] += b.surface->GetPoint(i)[k] / static_cast<double>(b.surface->GetNumberOfPoints());
    }
    vtkPolyData* bone = b.surface;
    const double* centre = b.centre;
    ASSERT_GT(bone->GetNumberOfCells(), 0) << cut.patient;
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(cut.origin);
    plane->SetNormal(cut.normal);
    const auto sections = lkvtk::sectionPolylines(bone, plane);
    const int nearest = lkvtk::nearestPolyline(sections, { cut.origin[0], cut.origin[1], cut.origin[2] });
    ASSERT_GE(nearest, 0);
    double sectionCentre[3] = { 0, 0, 0 };
    const auto& loop = sections[static_cast<std::size_t>(nearest)];
    for (const auto& x : loop)
      for (int k = 0; k < 3; ++k)
        sectionCentre[k] += x[k] / static_cast<double>(loop.size());

    vtkNew<vtkLKCuttingGuideFilter> guide;
    guide->SetInputData(bone);
    guide->SetPlaneOrigin(cut.origin);
    guide->SetPlaneNormal(cut.normal);
    guide->Update();
    const std::string where = std::string(cut.patient) + " at (" + std::to_string(cut.origin[0]) + ", " +
      std::to_string(cut.origin[1]) + ", " + std::to_string(cut.origin[2]) + ")";
    ASSERT_GT(guide->GetOutput()->GetNumberOfCells(), 0) << where;
    const double* d = guide->GetApproachUsed();
    const double outward = (sectionCentre[0] - centre[0]) * d[0] + (sectionCentre[1] - centre[1]) * d[1];
    EXPECT_GT(outward, 5.0) << where << ": approach (" << d[0] << ", " << d[1] << ", " << d[2] << ")";
  }
}

TEST(CuttingGuideFilter, StopsWhenAsked)
{
  vtkNew<vtkLKCuttingGuideFilter> guide;
  guide->SetInputData(box());
  guide->SetApproach(0, -1, 0);
  lktest::ProgressRecorder progress(guide);
  progress.stopAt = 0.4;
  guide->Update();
  EXPECT_EQ(guide->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_LT(progress.progress.back(), 1.0);
}

TEST(CuttingGuideFilter, BadInputAndParametersAreRefused)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vtkSmartPointer<vtkPolyData> solid = box();
  struct Case
  {
    const char* why;
    std::function<void(vtkLKCuttingGuideFilter*)> set;
    const char* message;
  };
  const Case cases[] = {
    { "zero normal", [](vtkLKCuttingGuideFilter* f) { f->SetPlaneNormal(0, 0, 0); }, "PlaneNormal finite and not zero" },
    { "NaN origin", [&](vtkLKCuttingGuideFilter* f) { f->SetPlaneOrigin(nan, 0, 0); }, "PlaneOrigin must be finite" },
    { "NaN approach", [&](vtkLKCuttingGuideFilter* f) { f->SetApproach(0, nan, 0); }, "Approach must be finite" },
    { "approach along the normal", [](vtkLKCuttingGuideFilter* f) { f->SetApproach(-3, 0, 0); },
      "the Approach lies along the plane's normal" },
    { "no thickness", [](vtkLKCuttingGuideFilter* f) { f->SetThickness(0); }, "Thickness must be 0.1 to 100 mm" },
    { "NaN slot", [&](vtkLKCuttingGuideFilter* f) { f->SetSlotWidth(nan); }, "SlotWidth must be" },
    { "negative clearance", [](vtkLKCuttingGuideFilter* f) { f->SetClearance(-1); }, "Clearance must be 0 to 10" },
    { "NaN screw hole", [&](vtkLKCuttingGuideFilter* f) { f->SetScrewHoleDiameter(nan); },
      "ScrewHoleDiameter must be 0 to 10 mm" },
    { "tiny label", [](vtkLKCuttingGuideFilter* f) { f->SetLabelHeight(1); }, "LabelHeight must be 1.5 to 20 mm" },
    { "other plane without a normal",
      [](vtkLKCuttingGuideFilter* f) {
        vtkNew<vtkPlaneCollection> planes;
        vtkNew<vtkPlane> fine, flat;
        fine->SetNormal(1, 0, 0);
        flat->SetNormal(0, 0, 0);
        planes->AddItem(fine);
        planes->AddItem(flat);
        f->SetOtherCutPlanes(planes);
      },
      "other cut plane 1 needs a finite origin and a finite normal that is not zero" },
    { "right angle", [](vtkLKCuttingGuideFilter* f) { f->SetMaximumContactAngle(90); },
      "MaximumContactAngle must be 1 to 89 degrees, not 90" },
    { "reach inside the slot", [](vtkLKCuttingGuideFilter* f) { f->SetReach(0.5); },
      "Reach (0.5 mm) must be more than half the SlotWidth" },
    { "plane beside the bone", [](vtkLKCuttingGuideFilter* f) { f->SetPlaneOrigin(50, 0, 0); },
      "the plane meets no part of the bone" },
    { "bridges longer than the contact", [](vtkLKCuttingGuideFilter* f) { f->SetBridge(15); },
      "30 mm long along the plane, too short for a slot between two bridges of 15 mm" },
  };
  for (const Case& c : cases)
  {
    vtkNew<vtkLKCuttingGuideFilter> guide;
    guide->SetInputData(solid);
    guide->SetApproach(0, -1, 0);
    c.set(guide);
    lktest::ErrorRecorder errors(guide);
    guide->Update();
    EXPECT_EQ(errors.errors, 1) << c.why;
    EXPECT_NE(errors.messages.find(c.message), std::string::npos) << c.why << ": " << errors.messages;
    EXPECT_EQ(guide->GetOutput()->GetNumberOfCells(), 0) << c.why;
    EXPECT_EQ(guide->GetSlotLength(), 0.0) << c.why;
  }
  // No surface at all, and a point that is not a number.
  vtkNew<vtkLKCuttingGuideFilter> guide;
  vtkNew<vtkPolyData> empty;
  guide->SetInputData(empty);
  {
    lktest::ErrorRecorder errors(guide);
    guide->Update();
    EXPECT_NE(errors.messages.find("the input has no surface"), std::string::npos) << errors.messages;
  }
  // Every point in one place, and points too far apart to measure (in
  // double: x from -1.6e308 to 1.6e308, finite, their range not).
  for (const bool together : { true, false })
  {
    vtkNew<vtkPolyData> squeezed;
    squeezed->DeepCopy(solid);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (vtkIdType i = 0; i < solid->GetNumberOfPoints(); ++i)
    {
      double x[3];
      solid->GetPoint(i, x);
      points->InsertNextPoint(together ? 1.0 : x[0] * 8e306, together ? 1.0 : x[1], together ? 1.0 : x[2]);
    }
    squeezed->SetPoints(points);
    guide->SetInputData(squeezed);
    lktest::ErrorRecorder errors(guide);
    guide->Update();
    EXPECT_NE(errors.messages.find(together ? "every point is in one place" : "too large to measure"),
      std::string::npos)
      << errors.messages;
    EXPECT_EQ(guide->GetOutput()->GetNumberOfCells(), 0);
  }
  vtkNew<vtkPolyData> broken;
  broken->DeepCopy(solid);
  broken->GetPoints()->SetPoint(3, nan, 0, 0);
  guide->SetInputData(broken);
  {
    lktest::ErrorRecorder errors(guide);
    guide->Update();
    EXPECT_NE(errors.messages.find("point 3 is not finite"), std::string::npos) << errors.messages;
    EXPECT_EQ(guide->GetOutput()->GetNumberOfCells(), 0);
  }
}
