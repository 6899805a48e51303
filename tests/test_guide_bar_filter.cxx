// vtkLKGuideBarFilter: two cutting guides joined by a bar, on a long box
// (where the bar must lie, its gap, the volume), three joined by two bars,
// overlapping guides merged into one block with their slots open (their
// labels and screws clear of each other when told of each other), guides
// apart in the chain whose saw planes cross (a V) cut by each other's slots,
// and on the TCIA mandible (one closed part outside the bone, screw holes left
// open), and bad input.
#include "TestSupport.h"

#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKCuttingGuideFilter.h"
#include "vtkLKGuideBarFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKRayCast.h"

#include <vtkCleanPolyData.h>
#include <vtkCubeSource.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkImplicitPolyDataDistance.h>
#include <vtkLinearSubdivisionFilter.h>
#include <vtkMath.h>
#include <vtkParametricFunctionSource.h>
#include <vtkParametricTorus.h>
#include <vtkPlane.h>
#include <vtkPlaneCollection.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkStaticCellLocator.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>

namespace
{
/// A closed box 100 x 20 x 30 mm centred at the origin, in triangles.
vtkSmartPointer<vtkPolyData> longBox()
{
  return lktest::triangulatedBox(100, 20, 30, 3);
}

/// The guide of the plane through `origin` with normal `normal`.
vtkSmartPointer<vtkPolyData> guideOn(vtkPolyData* bone, const double origin[3], const double normal[3],
  const double approach[3] = nullptr, double* volume = nullptr)
{
  vtkNew<vtkLKCuttingGuideFilter> guide;
  guide->SetInputData(bone);
  guide->SetPlaneOrigin(origin);
  guide->SetPlaneNormal(normal);
  if (approach)
    guide->SetApproach(approach);
  guide->Update();
  if (volume)
    *volume = guide->GetVolume();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(guide->GetOutput());
  return out;
}

/// The guide of plane `g` (0 or 1) of a pair, on `bone`: labelled `label`
/// (none for null), and given the other plane (OtherCutPlanes) when `told`.
/// `filter` makes it, and keeps its counts.
vtkSmartPointer<vtkPolyData> guideOfPair(vtkPolyData* bone, const double origins[2][3], const double normals[2][3],
  int g, const char* label, bool told, vtkLKCuttingGuideFilter* filter)
{
  filter->SetInputData(bone);
  filter->SetPlaneOrigin(origins[g]);
  filter->SetPlaneNormal(normals[g]);
  filter->SetLabel(label);
  vtkNew<vtkPlaneCollection> others;
  vtkNew<vtkPlane> other;
  other->SetOrigin(origins[1 - g]);
  other->SetNormal(normals[1 - g]);
  others->AddItem(other);
  if (told)
    filter->SetOtherCutPlanes(others);
  filter->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(filter->GetOutput());
  return out;
}

/// The part joining `guides` on `bone`, in their order, updated, with the
/// filter's errors and warnings recorded.
struct Joined
{
  Joined(vtkPolyData* bone, std::initializer_list<vtkPolyData*> guides)
  {
    bar->SetBoneData(bone);
    for (vtkPolyData* guide : guides)
      bar->AddGuideData(guide);
    bar->Update();
  }
  vtkNew<vtkLKGuideBarFilter> bar;
  lktest::ErrorRecorder messages{ bar };
};

vtkIdType regions(vtkPolyData* pd)
{
  vtkNew<vtkPolyDataConnectivityFilter> parts;
  parts->SetInputData(pd);
  parts->SetExtractionModeToAllRegions();
  parts->Update();
  return parts->GetNumberOfExtractedRegions();
}

/// The screw holes of `guide` whose axis, from the bone out along the
/// approach, meets `part` within 30 mm: holes a bar covers.
int coveredHoles(vtkPolyData* guide, vtkPolyData* part)
{
  vtkDataArray* holes = guide->GetFieldData()->GetArray("GuideScrewHoles");
  vtkDataArray* approach = guide->GetFieldData()->GetArray("GuideApproach");
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(part);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  int covered = 0;
  for (vtkIdType h = 0; h < holes->GetNumberOfTuples(); ++h)
  {
    double from[3], to[3], hit[3];
    for (int k = 0; k < 3; ++k)
    {
      from[k] = holes->GetComponent(h, k) + 0.01 * approach->GetComponent(0, k);
      to[k] = holes->GetComponent(h, k) + 30.0 * approach->GetComponent(0, k);
    }
    if (lkvtk::firstHit(locator, from, to, cell, hit))
      ++covered;
  }
  return covered;
}
/// Points of `part` inside a screw hole of `guide` (nearer its axis than
/// its radius less 0.02 mm, from 0.5 mm under the bone out), or inside its
/// slot (nearer its plane than half its width less 0.02 mm, within its
/// length less 0.02 mm): what would stop a screw or the saw.
int pointsInHolesOrSlot(vtkPolyData* guide, vtkPolyData* part)
{
  vtkFieldData* fd = guide->GetFieldData();
  double n[3], d[3], c[3], e[3];
  fd->GetArray("GuidePlaneNormal")->GetTuple(0, n);
  fd->GetArray("GuideApproach")->GetTuple(0, d);
  fd->GetArray("GuideSlotCentre")->GetTuple(0, c);
  vtkMath::Cross(n, d, e);
  vtkMath::Normalize(e);
  const double width = fd->GetArray("GuideSlotWidth")->GetComponent(0, 0);
  const double length = fd->GetArray("GuideSlotLength")->GetComponent(0, 0);
  const double radius = fd->GetArray("GuideScrewHoleDiameter")->GetComponent(0, 0) / 2.0;
  vtkDataArray* holes = fd->GetArray("GuideScrewHoles");
  int inside = 0;
  for (vtkIdType i = 0; i < part->GetNumberOfPoints(); ++i)
  {
    double x[3], q[3];
    part->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
      q[k] = x[k] - c[k];
    if (std::abs(vtkMath::Dot(q, n)) < width / 2.0 - 0.02 && std::abs(vtkMath::Dot(q, e)) < length / 2.0 - 0.02)
      ++inside;
    for (vtkIdType h = 0; holes && h < holes->GetNumberOfTuples(); ++h)
    {
      double axis[3];
      holes->GetTuple(h, axis);
      for (int k = 0; k < 3; ++k)
        q[k] = x[k] - axis[k];
      const double up = vtkMath::Dot(q, d);
      for (int k = 0; k < 3; ++k)
        q[k] -= up * d[k];
      if (up > -0.5 && vtkMath::Norm(q) < radius - 0.02)
        ++inside;
    }
  }
  return inside;
}
} // namespace

TEST(GuideBarFilter, OnALongBoxTheBarArchesItsStandOffAboveTheFace)
{
  vtkSmartPointer<vtkPolyData> bone = longBox();
  const double left[3] = { -30, 0, 0 }, right[3] = { 30, 0, 0 }, normal[3] = { 1, 0, 0 }, front[3] = { 0, -1, 0 };
  double volumes[2];
  vtkSmartPointer<vtkPolyData> a = guideOn(bone, left, normal, front, &volumes[0]);
  vtkSmartPointer<vtkPolyData> b = guideOn(bone, right, normal, front, &volumes[1]);
  ASSERT_GT(a->GetNumberOfCells(), 0);
  ASSERT_GT(b->GetNumberOfCells(), 0);

  vtkNew<vtkLKGuideBarFilter> bar;
  bar->SetBoneData(bone);
  bar->AddGuideData(a);
  bar->AddGuideData(b);
  lktest::ProgressRecorder progress(bar);
  bar->Update();
  vtkPolyData* out = bar->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0);
  // One closed part facing outward.
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  EXPECT_EQ(regions(out), 1);
  EXPECT_NEAR(lktest::signedVolume(out), bar->GetVolume(), 1e-6 * bar->GetVolume());
  // The bar: as thick as the walls (4 mm), from 6 mm past each slot (its
  // edge's 8 mm less the radius, clear of the hole) at the walls' middle
  // (y = -12), 2 mm above the face between the guides (y = -14).
  EXPECT_DOUBLE_EQ(bar->GetBarDiameter(), 4.0);
  EXPECT_GT(bar->GetBarLength(), 48.0);
  EXPECT_LT(bar->GetBarLength(), 49.0);
  EXPECT_NEAR(bar->GetBarGap(), 2.0, 0.03);
  double bounds[6];
  out->GetBounds(bounds);
  EXPECT_NEAR(bounds[2], -16.0, 0.03); // the bar's far side, 2 + 4 mm out
  // The volume: both guides and a 4 mm tube (24 sides) over the bar's
  // length less the 2 mm of each end inside a guide's wall.
  const double tube = 24.0 / 2.0 * std::sin(2.0 * vtkMath::Pi() / 24.0) * 4.0;
  EXPECT_NEAR(bar->GetVolume(), volumes[0] + volumes[1] + tube * (bar->GetBarLength() - 4.0), 0.01 * bar->GetVolume());
  // Outside the box, and the screw holes left open from above.
  vtkNew<vtkImplicitPolyDataDistance> inside;
  inside->SetInput(bone);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    ASSERT_GT(inside->EvaluateFunction(out->GetPoint(i)), -1e-6) << "point " << i << " inside the bone";
  EXPECT_EQ(coveredHoles(a, out), 0);
  EXPECT_EQ(coveredHoles(b, out), 0);
  // Field data and progress.
  EXPECT_NEAR(out->GetFieldData()->GetArray("GuideBarLength")->GetComponent(0, 0), bar->GetBarLength(), 1e-12);
  EXPECT_NEAR(out->GetFieldData()->GetArray("GuideVolume")->GetComponent(0, 0), bar->GetVolume(), 1e-12);
  ASSERT_GE(progress.progress.size(), 3u);
  EXPECT_DOUBLE_EQ(progress.progress.back(), 1.0);

  // A thicker bar stands higher at the guides (its lower side on the wall's)
  // and farther out.
  bar->SetDiameter(6.0);
  bar->SetStandOff(5.0);
  bar->Update();
  ASSERT_GT(out->GetNumberOfCells(), 0);
  EXPECT_EQ(regions(out), 1);
  EXPECT_NEAR(bar->GetBarGap(), 5.0, 0.03);
  out->GetBounds(bounds);
  EXPECT_NEAR(bounds[2], -10.0 - 5.0 - 6.0, 0.03);

  // Guides 28 mm apart: the bar, 16 mm between their edges, rises part of
  // the way only; the gap says how far.
  const double nearLeft[3] = { -14, 0, 0 }, nearRight[3] = { 14, 0, 0 };
  vtkNew<vtkLKGuideBarFilter> shortBar;
  shortBar->SetBoneData(bone);
  shortBar->AddGuideData(guideOn(bone, nearLeft, normal, front));
  shortBar->AddGuideData(guideOn(bone, nearRight, normal, front));
  shortBar->Update();
  ASSERT_GT(shortBar->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(shortBar->GetOutput()), 0);
  EXPECT_EQ(regions(shortBar->GetOutput()), 1);
  EXPECT_GT(shortBar->GetBarGap(), 0.3);
  EXPECT_LT(shortBar->GetBarGap(), 1.9);
  EXPECT_GT(shortBar->GetBarLength(), 16.0);
  EXPECT_LT(shortBar->GetBarLength(), 17.0);
}

TEST(GuideBarFilter, OnTheMandibleTheChinAndTheLeftBodyMakeOnePartOutsideTheBone)
{
  vtkSmartPointer<vtkPolyData> bone = lktest::tciaMandibleSurface();
  ASSERT_GT(bone->GetNumberOfCells(), 0);
  // The chin's mid-sagittal cut and one through the left body: a segment of
  // the anterior mandible between them.
  const double chin[3] = { 0.0728, 276.64, -982.1 }, sagittal[3] = { 1, 0, 0 };
  const double body[3] = { 30, 276.64, -982.1 }, across[3] = { 1, 0.3, 0 };
  double volumes[2];
  vtkSmartPointer<vtkPolyData> a = guideOn(bone, chin, sagittal, nullptr, &volumes[0]);
  vtkSmartPointer<vtkPolyData> b = guideOn(bone, body, across, nullptr, &volumes[1]);
  ASSERT_GT(a->GetNumberOfCells(), 0);
  ASSERT_GT(b->GetNumberOfCells(), 0);
  Joined part(bone, { a, b });
  vtkLKGuideBarFilter* bar = part.bar;
  vtkPolyData* out = bar->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0) << part.messages.messages;
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  EXPECT_EQ(regions(out), 1);
  EXPECT_NEAR(lktest::signedVolume(out), bar->GetVolume(), 1e-6 * bar->GetVolume());
  EXPECT_GT(bar->GetVolume(), volumes[0] + volumes[1]);
  EXPECT_GT(bar->GetBarLength(), 20.0);
  EXPECT_LT(bar->GetBarLength(), 60.0);
  EXPECT_GT(bar->GetBarGap(), 2.0 - 0.03);
  vtkNew<vtkImplicitPolyDataDistance> inside;
  inside->SetInput(bone);
  int within = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    within += inside->EvaluateFunction(out->GetPoint(i)) < -1e-3;
  EXPECT_EQ(within, 0);
  EXPECT_EQ(coveredHoles(a, out), 0);
  EXPECT_EQ(coveredHoles(b, out), 0);
}

TEST(GuideBarFilter, RoundACornerOfTheBoneTheBarStaysClearOfBothFaces)
{
  // A guide on the front of the box (y = -10) and one on its end (x = 50),
  // 90 degrees apart: the bar goes round the corner between them, away from
  // both faces, level with the guides' middles (z = 0).
  vtkSmartPointer<vtkPolyData> bone = longBox();
  const double onFront[3] = { -30, 0, 0 }, normal[3] = { 1, 0, 0 }, front[3] = { 0, -1, 0 };
  const double onEnd[3] = { 46, 0, 0 }, across[3] = { 0, 1, 0 }, end[3] = { 1, 0, 0 };
  vtkSmartPointer<vtkPolyData> a = guideOn(bone, onFront, normal, front), b = guideOn(bone, onEnd, across, end);
  Joined part(bone, { a, b });
  vtkLKGuideBarFilter* bar = part.bar;
  vtkPolyData* out = bar->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0) << part.messages.messages;
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  EXPECT_EQ(regions(out), 1);
  EXPECT_NEAR(bar->GetBarGap(), 2.0, 0.03);
  vtkNew<vtkImplicitPolyDataDistance> inside;
  inside->SetInput(bone);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    ASSERT_GT(inside->EvaluateFunction(out->GetPoint(i)), -1e-6) << "point " << i << " inside the bone";
  // Level: the bar keeps within the guides' height (z within +-15 mm, the
  // box's) rather than going over the box's top or under its bottom.
  double bounds[6];
  out->GetBounds(bounds);
  EXPECT_GE(bounds[4], -15.0 - 1e-6);
  EXPECT_LE(bounds[5], 15.0 + 1e-6);
  EXPECT_GT(bounds[1], 50.0 + 4.0); // beyond the end face: the guide there and the bar round to it
  // Put on along the corner's diagonal, between the two faces' directions:
  // each contact (a flat face) 45 degrees from it.
  const double* approach = bar->GetApproachUsed();
  EXPECT_NEAR(approach[0], std::sqrt(0.5), 0.01);
  EXPECT_NEAR(approach[1], -std::sqrt(0.5), 0.01);
  EXPECT_NEAR(approach[2], 0.0, 0.01);
  EXPECT_NEAR(bar->GetInsertionMargin(), 45.0, 0.5);
  vtkDataArray* fields = out->GetFieldData()->GetArray("GuideApproach");
  ASSERT_NE(fields, nullptr);
  EXPECT_DOUBLE_EQ(fields->GetComponent(0, 0), approach[0]);
  EXPECT_DOUBLE_EQ(out->GetFieldData()->GetArray("GuideInsertionMargin")->GetComponent(0, 0),
    bar->GetInsertionMargin());
}

TEST(GuideBarFilter, StopsWhenAsked)
{
  vtkSmartPointer<vtkPolyData> bone = longBox();
  const double left[3] = { -30, 0, 0 }, right[3] = { 30, 0, 0 }, normal[3] = { 1, 0, 0 }, front[3] = { 0, -1, 0 };
  vtkNew<vtkLKGuideBarFilter> bar;
  bar->SetBoneData(bone);
  bar->AddGuideData(guideOn(bone, left, normal, front));
  bar->AddGuideData(guideOn(bone, right, normal, front));
  lktest::ProgressRecorder progress(bar);
  progress.stopAt = 0.1;
  bar->Update();
  EXPECT_EQ(bar->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_LT(progress.progress.back(), 1.0);
}

TEST(GuideBarFilter, ThreeGuidesInTheirOrderAlongTheBoxAreOnePartWithTwoBars)
{
  vtkSmartPointer<vtkPolyData> bone = longBox();
  const double normal[3] = { 1, 0, 0 }, front[3] = { 0, -1, 0 };
  const double xs[3] = { -40, 0, 40 };
  vtkSmartPointer<vtkPolyData> guide[3];
  double volumes[3];
  for (int i = 0; i < 3; ++i)
  {
    const double origin[3] = { xs[i], 0, 0 };
    guide[i] = guideOn(bone, origin, normal, front, &volumes[i]);
    ASSERT_GT(guide[i]->GetNumberOfCells(), 0);
  }
  vtkNew<vtkLKGuideBarFilter> bar;
  bar->SetBoneData(bone);
  for (int i : { 0, 1, 2 })
    bar->AddGuideData(guide[i]);
  lktest::ProgressRecorder progress(bar);
  bar->Update();
  vtkPolyData* out = bar->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  EXPECT_EQ(regions(out), 1);
  EXPECT_NEAR(lktest::signedVolume(out), bar->GetVolume(), 1e-6 * bar->GetVolume());
  // Two bars, each from 6 mm past one slot to 6 mm before the next (28 mm
  // between the ends, and the rise to the walls' middle), 2 mm off the face.
  ASSERT_EQ(bar->GetNumberOfBars(), 2);
  for (int b = 0; b < 2; ++b)
  {
    EXPECT_GT(bar->GetBarLength(b), 28.0) << b;
    EXPECT_LT(bar->GetBarLength(b), 29.5) << b;
    EXPECT_NEAR(bar->GetBarGap(b), 2.0, 0.05) << b;
  }
  EXPECT_NEAR(bar->GetBarLength(), bar->GetBarLength(0) + bar->GetBarLength(1), 1e-12);
  EXPECT_DOUBLE_EQ(bar->GetBarGap(), std::min(bar->GetBarGap(0), bar->GetBarGap(1)));
  EXPECT_EQ(bar->GetBarLength(2), 0.0);
  EXPECT_EQ(bar->GetBarLength(-1), 0.0);
  const double tube = 24.0 / 2.0 * std::sin(2.0 * vtkMath::Pi() / 24.0) * 4.0;
  EXPECT_NEAR(bar->GetVolume(),
    volumes[0] + volumes[1] + volumes[2] + tube * (bar->GetBarLength() - 8.0), 0.01 * bar->GetVolume());
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(coveredHoles(guide[i], out), 0) << i;
  vtkDataArray* lengths = out->GetFieldData()->GetArray("GuideBarLength");
  vtkDataArray* gaps = out->GetFieldData()->GetArray("GuideBarGap");
  ASSERT_NE(lengths, nullptr);
  ASSERT_NE(gaps, nullptr);
  ASSERT_EQ(lengths->GetNumberOfTuples(), 2);
  ASSERT_EQ(gaps->GetNumberOfTuples(), 2);
  for (int b = 0; b < 2; ++b)
  {
    EXPECT_DOUBLE_EQ(lengths->GetComponent(b, 0), bar->GetBarLength(b));
    EXPECT_DOUBLE_EQ(gaps->GetComponent(b, 0), bar->GetBarGap(b));
  }
  ASSERT_GE(progress.progress.size(), 3u);
  EXPECT_TRUE(std::is_sorted(progress.progress.begin(), progress.progress.end()));
  EXPECT_DOUBLE_EQ(progress.progress.back(), 1.0);

  // Two guides make one bar again; the filter forgets the third's.
  bar->RemoveAllInputConnections(1);
  bar->AddGuideData(guide[0]);
  bar->AddGuideData(guide[2]);
  bar->Update();
  EXPECT_EQ(bar->GetNumberOfBars(), 1);
  EXPECT_EQ(bar->GetBarLength(1), 0.0);
  EXPECT_GT(bar->GetBarLength(), 68.0);
}

TEST(GuideBarFilter, OverlappingGuidesAreMergedIntoOneBlockWithEverySlotAndHoleOpen)
{
  vtkSmartPointer<vtkPolyData> bone = longBox();
  const double normal[3] = { 1, 0, 0 }, front[3] = { 0, -1, 0 };
  // Saw lines 12 mm apart (the guides overlap over 4 mm), then 6 mm apart
  // (each slot and the hole beside it within the other guide's reach).
  for (const double apart : { 12.0, 6.0 })
  {
    const double left[3] = { -apart / 2.0, 0, 0 }, right[3] = { apart / 2.0, 0, 0 };
    double volumes[2];
    vtkSmartPointer<vtkPolyData> guide[2] = { guideOn(bone, left, normal, front, &volumes[0]),
      guideOn(bone, right, normal, front, &volumes[1]) };
    ASSERT_GT(guide[0]->GetNumberOfCells(), 0);
    ASSERT_GT(guide[1]->GetNumberOfCells(), 0);
    vtkNew<vtkLKGuideBarFilter> bar;
    bar->SetBoneData(bone);
    bar->AddGuideData(guide[0]);
    bar->AddGuideData(guide[1]);
    lktest::ProgressRecorder progress(bar);
    bar->Update();
    vtkPolyData* out = bar->GetOutput();
    ASSERT_GT(out->GetNumberOfCells(), 0) << apart;
    // One closed block, no bar.
    EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0) << apart;
    EXPECT_EQ(regions(out), 1) << apart;
    EXPECT_TRUE(bar->GetMerged(0));
    EXPECT_FALSE(bar->GetMerged(1));
    EXPECT_EQ(bar->GetNumberOfMerges(), 1);
    EXPECT_EQ(bar->GetNumberOfBars(), 0);
    EXPECT_EQ(bar->GetBarLength(), 0.0);
    EXPECT_EQ(bar->GetBarDiameter(), 0.0);
    // Made alone, 6 mm apart: the screw hole between the slots (4.3 mm from
    // its own, 1.05 mm wide each side) is 0.65 mm from the other kerf.
    EXPECT_EQ(bar->GetNumberOfScrewHolesInSawPaths(), apart < 10.0 ? 2 : 0) << apart;
    vtkDataArray* merged = out->GetFieldData()->GetArray("GuideMerged");
    ASSERT_NE(merged, nullptr);
    ASSERT_EQ(merged->GetNumberOfTuples(), 1);
    EXPECT_EQ(merged->GetComponent(0, 0), 1.0);
    EXPECT_EQ(out->GetFieldData()->GetArray("GuideBarLength")->GetNumberOfTuples(), 0);
    // Less than the two guides apart (they overlap), more than either.
    EXPECT_NEAR(lktest::signedVolume(out), bar->GetVolume(), 1e-6 * bar->GetVolume());
    EXPECT_LT(bar->GetVolume(), volumes[0] + volumes[1] - 1.0) << apart;
    EXPECT_GT(bar->GetVolume(), std::max(volumes[0], volumes[1])) << apart;
    // Outside the box.
    vtkNew<vtkImplicitPolyDataDistance> inBone;
    inBone->SetInput(bone);
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      ASSERT_GT(inBone->EvaluateFunction(out->GetPoint(i)), -1e-6) << "point " << i << " inside the bone";
    // Each slot open from end to end through the whole block: its middle
    // plane, at the wall's middle height and just under the top, is 0.6
    // mm (half the slot) from the part, or its distance to the slot's end;
    // and each screw hole is open from the bone out.
    vtkNew<vtkImplicitPolyDataDistance> inPart;
    inPart->SetInput(out);
    for (int g = 0; g < 2; ++g)
    {
      vtkFieldData* fd = guide[g]->GetFieldData();
      const double length = fd->GetArray("GuideSlotLength")->GetComponent(0, 0);
      double centre[3];
      fd->GetArray("GuideSlotCentre")->GetTuple(0, centre);
      for (const double height : { 2.0, 3.9 })
        for (double t = -length / 2.0 + 0.3; t <= length / 2.0 - 0.3; t += 0.5)
        {
          double x[3] = { centre[0], centre[1] - height, t };
          EXPECT_GT(inPart->EvaluateFunction(x), std::min(0.55, length / 2.0 - std::abs(t) - 0.05)) << apart << " mm apart, slot " << g << " at z = " << t
                                                        << ", " << height << " mm out";
        }
      EXPECT_EQ(coveredHoles(guide[g], out), 0) << apart << " mm apart, guide " << g;
      EXPECT_EQ(pointsInHolesOrSlot(guide[g], out), 0) << apart << " mm apart, guide " << g;
    }
    ASSERT_GE(progress.progress.size(), 3u);
    EXPECT_DOUBLE_EQ(progress.progress.back(), 1.0);
  }
}

TEST(GuideBarFilter, GuidesWhoseEdgesAreNearerThanTheBarAreJoinedByAStraightOne)
{
  // Saw lines 18 mm apart: the guides' edges 2 mm apart, less than the bar's
  // 4 mm, so no room to arch out. A straight bar from 6 mm past each slot
  // (inside each wall, clear of the holes) to the other: 6 mm long, on the
  // face (no gap), one part, every slot and hole open.
  vtkSmartPointer<vtkPolyData> bone = longBox();
  const double normal[3] = { 1, 0, 0 }, front[3] = { 0, -1, 0 }, left[3] = { -9, 0, 0 }, right[3] = { 9, 0, 0 };
  double volumes[2];
  vtkSmartPointer<vtkPolyData> a = guideOn(bone, left, normal, front, &volumes[0]);
  vtkSmartPointer<vtkPolyData> b = guideOn(bone, right, normal, front, &volumes[1]);
  Joined part(bone, { a, b });
  vtkLKGuideBarFilter* bar = part.bar;
  vtkPolyData* out = bar->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0) << part.messages.messages;
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  EXPECT_EQ(regions(out), 1);
  EXPECT_EQ(bar->GetNumberOfMerges(), 0);
  ASSERT_EQ(bar->GetNumberOfBars(), 1);
  EXPECT_NEAR(bar->GetBarLength(), 6.0, 1e-6);
  EXPECT_NEAR(bar->GetBarGap(), 0.0, 1e-6);
  const double tube = 24.0 / 2.0 * std::sin(2.0 * vtkMath::Pi() / 24.0) * 4.0;
  EXPECT_NEAR(bar->GetVolume(), volumes[0] + volumes[1] + tube * 2.0, 0.01 * bar->GetVolume());
  EXPECT_EQ(coveredHoles(a, out), 0);
  EXPECT_EQ(coveredHoles(b, out), 0);
}

TEST(GuideBarFilter, ABarRisingSteeplyOffTheBoneLeavesTheScrewHolesBesideItOpen)
{
  // Two cuts 17 mm apart across mandible 1's left ramus, the second tilted
  // 8 degrees: the bar rises off the bone at once, its end tilts, and its
  // cap reached into the screw hole beside it in each wall (30 and 21 points
  // of the part inside them). Every hole and slot is open.
  vtkSmartPointer<vtkPolyData> bone = lktest::tciaMandibleSurface();
  ASSERT_GT(bone->GetNumberOfCells(), 0);
  const double first[3] = { -48.362, 328.09, -928.0 }, across[3] = { -0.264, 0.964, 0.042 };
  const double second[3] = { first[0] + 17 * across[0], first[1] + 17 * across[1], first[2] + 17 * across[2] },
               tilted[3] = { -0.264, 0.964, 0.183 };
  vtkSmartPointer<vtkPolyData> a = guideOn(bone, first, across), b = guideOn(bone, second, tilted);
  ASSERT_GT(a->GetNumberOfCells(), 0);
  ASSERT_GT(b->GetNumberOfCells(), 0);
  Joined part(bone, { a, b });
  vtkLKGuideBarFilter* bar = part.bar;
  vtkPolyData* out = bar->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0) << part.messages.messages;
  EXPECT_EQ(bar->GetNumberOfBars(), 1);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  EXPECT_EQ(regions(out), 1);
  EXPECT_EQ(pointsInHolesOrSlot(a, out), 0);
  EXPECT_EQ(pointsInHolesOrSlot(b, out), 0);
}

TEST(GuideBarFilter, MergedGuidesToldOfEachOtherKeepTheirLabelsAndScrewsClearOfTheOthersSaw)
{
  // A wedge out of mandible 1's left body: saws 4 mm apart at the top,
  // 6 degrees between them. Made alone, each guide's label lies under the
  // other's wall or slot, and its screw hole between the slots in the other
  // saw's path: the block is made, and each is warned of. Each guide told
  // of the other's plane (OtherCutPlanes) leaves that hole out and puts its
  // label on its far side, beyond the other's reach: nothing to warn of.
  vtkSmartPointer<vtkPolyData> bone = lktest::tciaMandibleSurface();
  ASSERT_GT(bone->GetNumberOfCells(), 0);
  const double origins[2][3] = { { -30.0, 276.64, -982.1 }, { -26.0, 276.64, -982.1 } };
  const double normals[2][3] = { { 1, -0.3, 0 }, { 1, -0.2, 0 } };
  for (const bool told : { false, true })
  {
    vtkSmartPointer<vtkPolyData> guide[2];
    for (int g = 0; g < 2; ++g)
    {
      vtkNew<vtkLKCuttingGuideFilter> filter;
      guide[g] = guideOfPair(bone, origins, normals, g, g == 0 ? "1" : "2", told, filter);
      EXPECT_EQ(filter->GetNumberOfScrewHoles(), told ? 1 : 2) << g;
      EXPECT_TRUE(filter->GetLabelPlaced()) << g;
      ASSERT_GT(guide[g]->GetNumberOfCells(), 0);
      vtkNew<vtkPlane> other;
      other->SetOrigin(origins[1 - g]);
      other->SetNormal(normals[1 - g]);
      // The label's rectangle: its nearest corner's distance from the
      // other plane, against the guide's reach.
      vtkDataArray* box = guide[g]->GetFieldData()->GetArray("GuideLabelBox");
      ASSERT_NE(box, nullptr);
      double corner[3], wide[3], up[3];
      box->GetTuple(0, corner);
      box->GetTuple(1, wide);
      box->GetTuple(2, up);
      double nearest = 1e9;
      for (const double a : { 0.0, 1.0 })
        for (const double b : { 0.0, 1.0 })
        {
          double x[3];
          for (int k = 0; k < 3; ++k)
            x[k] = corner[k] + a * wide[k] + b * up[k];
          nearest = std::min(nearest, std::abs(other->DistanceToPlane(x)));
        }
      std::printf("guide %d, %s: label %.2f mm from the other plane\n", g + 1, told ? "told" : "alone", nearest);
      if (told)
        EXPECT_GT(nearest, 8.0) << g;
      else
        EXPECT_LT(nearest, 8.0) << g;
    }
    Joined part(bone, { guide[0], guide[1] });
    vtkLKGuideBarFilter* bar = part.bar;
    vtkPolyData* out = bar->GetOutput();
    ASSERT_GT(out->GetNumberOfCells(), 0) << part.messages.messages;
    EXPECT_TRUE(bar->GetMerged(0));
    EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
    EXPECT_EQ(regions(out), 1);
    EXPECT_EQ(pointsInHolesOrSlot(guide[0], out), 0);
    EXPECT_EQ(pointsInHolesOrSlot(guide[1], out), 0);
    EXPECT_EQ(bar->GetNumberOfLabelsCovered(), told ? 0 : 2);
    EXPECT_EQ(bar->GetNumberOfScrewHolesInSawPaths(), told ? 0 : 2);
    if (told)
      EXPECT_EQ(part.messages.warnings, 0) << part.messages.warningMessages;
    else
    {
      for (const char* text : { "The label '1' of guide 1 is partly covered or cut in the joined part",
             "The label '2' of guide 2 is partly covered", "A screw hole of guide 1 lies in the path of guide 2's saw",
             "A screw hole of guide 2 lies in the path of guide 1's saw", "(OtherCutPlanes)" })
        EXPECT_NE(part.messages.warningMessages.find(text), std::string::npos) << text << ": " << part.messages.warningMessages;
    }
  }
}

TEST(GuideBarFilter, ABarLeavesAGuideBesideItsLabelNotOverIt)
{
  // Mandible 1, the five-saw plan's lines 2 (left body) and 5 (right
  // ramus). Line 5's label stands beside its slot between the screw hole
  // and the guide's end nearer line 2, and the bar, leaving the guide's
  // edge across from the slot's middle, would bend along that edge toward
  // line 2 and stand over a corner of the "5" (1 label covered). Its end
  // moves along the slot, away from the label, until it clears it.
  vtkSmartPointer<vtkPolyData> bone = lktest::tciaMandibleSurface();
  ASSERT_GT(bone->GetNumberOfCells(), 0);
  const double origins[2][3] = { { 25.03, 293.20, -973.57 }, { 43.46, 324.20, -954.76 } };
  const double normals[2][3] = { { 0.9578, 0.2873, 0 }, { 0, -0.2873, -0.9578 } };
  vtkSmartPointer<vtkPolyData> guide[2];
  for (int g = 0; g < 2; ++g)
  {
    vtkNew<vtkLKCuttingGuideFilter> filter;
    guide[g] = guideOfPair(bone, origins, normals, g, g == 0 ? "2" : "5", false, filter);
    EXPECT_TRUE(filter->GetLabelPlaced()) << g;
    ASSERT_GT(guide[g]->GetNumberOfCells(), 0);
  }
  Joined part(bone, { guide[0], guide[1] });
  vtkLKGuideBarFilter* bar = part.bar;
  vtkPolyData* out = bar->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0) << part.messages.messages;
  EXPECT_EQ(bar->GetNumberOfBars(), 1);
  EXPECT_EQ(bar->GetNumberOfLabelsCovered(), 0);
  EXPECT_EQ(part.messages.warnings, 0) << part.messages.warningMessages;
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  EXPECT_EQ(regions(out), 1);
  EXPECT_GT(bar->GetBarGap(), 2.0 - 0.03);
  for (int g = 0; g < 2; ++g)
  {
    EXPECT_EQ(coveredHoles(guide[g], out), 0) << g;
    EXPECT_EQ(pointsInHolesOrSlot(guide[g], out), 0) << g;
  }
}

TEST(GuideBarFilter, GuidesInEachOthersWayAreMergedThoughTheirSlotsAreFarApart)
{
  // Mandible 1's left ramus: a long saw line down the ramus and one across
  // its top whose planes cross near the bone, 18 mm apart along it. Their
  // slots are farther apart along the bone than the guides reach, but the
  // long guide runs on under the short one: joined by a bar, each guide's
  // wall stood in the other's slot (140 and 231 points of the part). They
  // are merged instead, each less the other's slot and screw holes.
  vtkSmartPointer<vtkPolyData> bone = lktest::tciaMandibleSurface();
  ASSERT_GT(bone->GetNumberOfCells(), 0);
  const double origins[2][3] = { { -44.59, 332.10, -935.5 }, { -42.82, 316.33, -930.5 } };
  const double normals[2][3] = { { 0.2928, -0.9026, 0.3156 }, { 0.3034, 0.2871, -0.6879 } };
  vtkSmartPointer<vtkPolyData> guide[2];
  for (int g = 0; g < 2; ++g)
  {
    vtkNew<vtkLKCuttingGuideFilter> filter;
    guide[g] = guideOfPair(bone, origins, normals, g, nullptr, true, filter);
    ASSERT_GT(guide[g]->GetNumberOfCells(), 0);
  }
  Joined part(bone, { guide[0], guide[1] });
  vtkLKGuideBarFilter* bar = part.bar;
  vtkPolyData* out = bar->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0) << part.messages.messages;
  EXPECT_TRUE(bar->GetMerged(0));
  EXPECT_EQ(bar->GetNumberOfBars(), 0);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  EXPECT_EQ(regions(out), 1);
  for (int g = 0; g < 2; ++g)
    EXPECT_EQ(pointsInHolesOrSlot(guide[g], out), 0) << g;
  EXPECT_EQ(bar->GetNumberOfScrewHolesInSawPaths(), 0);
}

TEST(GuideBarFilter, GuidesWhoseSawPlanesCrossAreCutByEachOthersSlotsThoughABarIsBetweenThem)
{
  // A box 50 mm high. A V on its front: saw planes tilted 39 degrees either
  // way, 28 mm apart at its middle height, their guides overlapping at the
  // V's point (each slot reaching into the other's wall: stacked on one flat
  // face, their tops in one plane); a third guide on the top between them,
  // given between them in the order, so a bar joins each arm to it. Then an
  // X (two saw planes crossing on the front, merged) with a bar to a third
  // guide, leaving the X from its wall next to the other arm's slot.
  vtkSmartPointer<vtkPolyData> bone = lktest::triangulatedBox(100, 20, 50, 3);
  struct Plan
  {
    const char* what;
    double origins[3][3], normals[3][3], approaches[3][3];
    int bars, merges, crossings;
  };
  const Plan plans[] = {
    { "a V and a guide on the top", { { -14, 0, 0 }, { 0, 0, 0 }, { 14, 0, 0 } },
      { { 1, 0, 0.8 }, { 1, 0, 0 }, { 1, 0, -0.8 } }, { { 0, -1, 0 }, { 0, 0, 1 }, { 0, -1, 0 } }, 2, 0, 1 },
    { "an X and a guide beside it", { { 0, 0, 0 }, { 5, 0, 0 }, { 40, 0, 0 } },
      { { 1, 0, 0.8 }, { 1, 0, -0.8 }, { 1, 0, 0 } }, { { 0, -1, 0 }, { 0, -1, 0 }, { 0, -1, 0 } }, 1, 1, 0 },
  };
  for (const Plan& plan : plans)
  {
    vtkSmartPointer<vtkPolyData> guide[3];
    for (int g = 0; g < 3; ++g)
    {
      guide[g] = guideOn(bone, plan.origins[g], plan.normals[g], plan.approaches[g]);
      ASSERT_GT(guide[g]->GetNumberOfCells(), 0) << plan.what << ", guide " << g;
    }
    Joined part(bone, { guide[0], guide[1], guide[2] });
    vtkLKGuideBarFilter* bar = part.bar;
    vtkPolyData* out = bar->GetOutput();
    ASSERT_GT(out->GetNumberOfCells(), 0) << plan.what << ": " << part.messages.messages;
    EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0) << plan.what;
    EXPECT_EQ(regions(out), 1) << plan.what;
    EXPECT_EQ(bar->GetNumberOfBars(), plan.bars) << plan.what;
    EXPECT_EQ(bar->GetNumberOfMerges(), plan.merges) << plan.what;
    EXPECT_EQ(bar->GetNumberOfCrossings(), plan.crossings) << plan.what;
    EXPECT_EQ(bar->GetCrossed(0, 2), plan.crossings == 1) << plan.what;
    EXPECT_EQ(bar->GetCrossed(2, 0), plan.crossings == 1) << plan.what;
    EXPECT_FALSE(bar->GetCrossed(0, 1)) << plan.what;
    vtkDataArray* crossings = out->GetFieldData()->GetArray("GuideCrossings");
    ASSERT_NE(crossings, nullptr) << plan.what;
    EXPECT_EQ(crossings->GetNumberOfTuples(), plan.crossings) << plan.what;
    if (plan.crossings == 1 && crossings->GetNumberOfTuples() == 1)
    {
      EXPECT_EQ(crossings->GetComponent(0, 0), 0.0);
      EXPECT_EQ(crossings->GetComponent(0, 1), 2.0);
    }
    // Every slot and screw hole open through the part: without the cuts
    // the V's arms fill the ends of each other's slots (528 points of the
    // part in each).
    for (int g = 0; g < 3; ++g)
    {
      EXPECT_EQ(pointsInHolesOrSlot(guide[g], out), 0) << plan.what << ", guide " << g;
      EXPECT_EQ(coveredHoles(guide[g], out), 0) << plan.what << ", guide " << g;
    }
  }
}

TEST(GuideBarFilter, ThreeGuidesMergedWhereAHorizontalCutCrossesTwoVerticalOnesAreJoined)
{
  // Mandible 1's left body: a cut along the body (a rim resection's floor,
  // its slot 85 mm long) crossed by two vertical cuts 18 mm apart, in that
  // order. All three overlap: one block, each guide less the others' slots
  // and holes. Cut by the same slot, two guides had faces in the same
  // planes, and CGAL's union of the three never ended (the test ran out of
  // time); the cutters now differ by 0.002 mm from one guide to the next.
  vtkSmartPointer<vtkPolyData> bone = lktest::tciaMandibleSurface();
  const double origins[3][3] = { { -34.9, 295.73, -972.79 }, { -24.63, 281.31, -979.61 },
    { -14.58, 273.92, -982.81 } };
  const double normals[3][3] = { { 0.427, -0.157, 0.89 }, { 0.874, -0.475, -0.101 }, { 0.796, -0.602, -0.063 } };
  vtkSmartPointer<vtkPolyData> guide[3];
  for (int g = 0; g < 3; ++g)
  {
    guide[g] = guideOn(bone, origins[g], normals[g]);
    ASSERT_GT(guide[g]->GetNumberOfCells(), 0) << g;
  }
  Joined part(bone, { guide[0], guide[1], guide[2] });
  vtkLKGuideBarFilter* bar = part.bar;
  vtkPolyData* out = bar->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0) << part.messages.messages;
  EXPECT_EQ(bar->GetNumberOfMerges(), 2);
  EXPECT_EQ(bar->GetNumberOfBars(), 0);
  EXPECT_EQ(lktest::openOrNonManifoldEdges(out), 0);
  EXPECT_EQ(regions(out), 1);
  EXPECT_NEAR(lktest::signedVolume(out), bar->GetVolume(), 1e-6 * bar->GetVolume());
  for (int g = 0; g < 3; ++g)
    EXPECT_EQ(pointsInHolesOrSlot(guide[g], out), 0) << g;
}

TEST(GuideBarFilter, RoundARingNoOneDirectionPutsThreeGuidesOn)
{
  // A ring (a torus, 40 mm round, its tube 10 mm), guides on its outside at
  // 0, 90 and 180 degrees: each pair faces 90 degrees apart, but the first
  // and the last face each other across the ring, so no direction puts the
  // part on (a box would let a U slide along it: its faces are flat).
  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(40);
  torus->SetCrossSectionRadius(10);
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(torus);
  source->SetUResolution(120);
  source->SetVResolution(40);
  source->SetScalarModeToNone();
  source->GenerateTextureCoordinatesOff();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkCleanPolyData> ring;
  ring->SetInputConnection(triangles->GetOutputPort());
  ring->SetTolerance(1e-6);
  ring->Update();
  ASSERT_EQ(lktest::openOrNonManifoldEdges(ring->GetOutput()), 0);
  const double origins[3][3] = { { 50, 0, 0 }, { 0, 50, 0 }, { -50, 0, 0 } };
  const double normals[3][3] = { { 0, 1, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  const double outward[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 } };
  vtkNew<vtkLKGuideBarFilter> bar;
  bar->SetBoneData(ring->GetOutput());
  for (int i = 0; i < 3; ++i)
  {
    vtkSmartPointer<vtkPolyData> g = guideOn(ring->GetOutput(), origins[i], normals[i], outward[i]);
    ASSERT_GT(g->GetNumberOfCells(), 0) << i;
    bar->AddGuideData(g);
  }
  lktest::ErrorRecorder errors(bar);
  bar->Update();
  EXPECT_EQ(errors.errors, 1);
  EXPECT_NE(errors.messages.find("no one direction puts them all on the bone at once: along the best, guide "),
    std::string::npos)
    << errors.messages;
  EXPECT_NE(errors.messages.find("more than 10 degrees or 5 % of the contact"), std::string::npos);
  EXPECT_EQ(bar->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(bar->GetNumberOfBars(), 0);
  EXPECT_EQ(bar->GetInsertionMargin(), 0.0);
}

TEST(GuideBarFilter, BadInputAndParametersAreRefused)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vtkSmartPointer<vtkPolyData> bone = longBox();
  const double left[3] = { -30, 0, 0 }, right[3] = { 30, 0, 0 }, normal[3] = { 1, 0, 0 }, front[3] = { 0, -1, 0 },
               back[3] = { 0, 1, 0 };
  const double centre[3] = { 0, 0, 0 };
  vtkSmartPointer<vtkPolyData> a = guideOn(bone, left, normal, front), b = guideOn(bone, right, normal, front),
                               behind = guideOn(bone, right, normal, back), middle = guideOn(bone, centre, normal, front);
  // Round the box's corner at x = 50: a guide on the front near it and one
  // on the end face.
  const double nearCorner[3] = { 40, 0, 0 }, onEnd[3] = { 46, 0, 0 }, across[3] = { 0, 1, 0 }, end[3] = { 1, 0, 0 };
  vtkSmartPointer<vtkPolyData> cornerFront = guideOn(bone, nearCorner, normal, front),
                               cornerEnd = guideOn(bone, onEnd, across, end);
  // Saw lines too near for two slots in one block.
  const double x1[3] = { -1.5, 0, 0 }, x2[3] = { 1.5, 0, 0 };
  vtkSmartPointer<vtkPolyData> threeLeft = guideOn(bone, x1, normal, front), threeRight = guideOn(bone, x2, normal, front);
  struct Case
  {
    const char* why;
    std::function<void(vtkLKGuideBarFilter*)> set;
    const char* message;
  };
  const Case cases[] = {
    { "one guide", [&](vtkLKGuideBarFilter* f) { f->AddGuideData(a); }, "a bar joins two guides, and port 1 has 1" },
    { "three guides, the last two one", [&](vtkLKGuideBarFilter* f) { f->AddGuideData(a); f->AddGuideData(b); f->AddGuideData(b); },
      "guides 2 and 3: their slots are 0 mm apart along the bone, too near" },
    { "three guides out of their order",
      [&](vtkLKGuideBarFilter* f) { f->AddGuideData(a); f->AddGuideData(b); f->AddGuideData(middle); },
      "guides 1 and 3 lie on one side of guide 2's slot, so their bars would leave it on one side (give the guides "
      "in their order along the bone)" },
    { "three guides, the third on the back",
      [&](vtkLKGuideBarFilter* f) { f->AddGuideData(a); f->AddGuideData(middle); f->AddGuideData(behind); },
      "guides 2 and 3: they are put on from directions 180 degrees apart" },
    { "a plain mesh", [&](vtkLKGuideBarFilter* f) { f->AddGuideData(a); f->AddGuideData(bone); },
      "guide 2 has no GuideApproach of finite values (guides come from vtkLKCuttingGuideFilter)" },
    { "the same guide twice", [&](vtkLKGuideBarFilter* f) { f->AddGuideData(a); f->AddGuideData(a); },
      "their slots are 0 mm apart along the bone, too near for a wall of 2 mm between them (one saw cut?)" },
    { "slots 3 mm apart", [&](vtkLKGuideBarFilter* f) { f->AddGuideData(threeLeft); f->AddGuideData(threeRight); },
      "their slots are 3 mm apart along the bone, too near for a wall of 2 mm between them" },

    { "a guide of no thickness",
      [&](vtkLKGuideBarFilter* f) {
        auto odd = vtkSmartPointer<vtkPolyData>::New();
        odd->DeepCopy(b);
        odd->GetFieldData()->GetArray("GuideThickness")->SetComponent(0, 0, 0.0);
        f->AddGuideData(a);
        f->AddGuideData(odd);
      },
      "guide 2's field data do not describe a guide" },
    { "opposite sides", [&](vtkLKGuideBarFilter* f) { f->AddGuideData(a); f->AddGuideData(behind); },
      "180 degrees apart (more than 120)" },
    { "too far", [&](vtkLKGuideBarFilter* f) { f->AddGuideData(a); f->AddGuideData(b); f->SetMaximumLength(50); },
      "60 mm apart, more than MaximumLength (50 mm)" },
    { "thin bar", [&](vtkLKGuideBarFilter* f) { f->AddGuideData(a); f->AddGuideData(b); f->SetDiameter(0.5); },
      "Diameter must be 1 to 20 mm" },
    { "NaN stand-off", [&](vtkLKGuideBarFilter* f) { f->AddGuideData(a); f->AddGuideData(b); f->SetStandOff(nan); },
      "StandOff must be 0 to 50 mm" },
    { "guides too near for a bar, round a corner from each other",
      [&](vtkLKGuideBarFilter* f) { f->AddGuideData(cornerFront); f->AddGuideData(cornerEnd); },
      "their slots are 10 mm apart along the bone, nearer than their reaches, so no bar fits between them, "
      "and the guides do not meet to be one block" },
    { "a bar to stand 50 mm off the bone",
      [&](vtkLKGuideBarFilter* f) { f->AddGuideData(a); f->AddGuideData(b); f->SetStandOff(50); },
      "the bar would bend tighter than its radius (2 mm) on its way between them" },
  };
  for (const Case& c : cases)
  {
    vtkNew<vtkLKGuideBarFilter> bar;
    bar->SetBoneData(bone);
    c.set(bar);
    lktest::ErrorRecorder errors(bar);
    bar->Update();
    EXPECT_EQ(errors.errors, 1) << c.why;
    EXPECT_NE(errors.messages.find(c.message), std::string::npos) << c.why << ": " << errors.messages;
    EXPECT_EQ(bar->GetOutput()->GetNumberOfCells(), 0) << c.why;
  }
}
