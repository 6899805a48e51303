#include "TestSupport.h"
#include "vtkLKPatchDeformationFilter.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPlaneSource.h>
#include <vtkTriangleFilter.h>

#include <cmath>
#include <array>
#include <map>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> planarPatch(int resolution)
{
  vtkNew<vtkPlaneSource> plane; // [-0.5, 0.5]^2, normal +z
  plane->SetResolution(resolution, resolution);
  vtkNew<vtkTriangleFilter> tri;
  tri->SetInputConnection(plane->GetOutputPort());
  tri->Update();
  return tri->GetOutput();
}
} // namespace

TEST(PatchDeformationFilter, BumpBoxAndSmoothing)
{
  vtkNew<vtkLKPatchDeformationFilter> deform;
  deform->SetInputData(planarPatch(20));
  deform->AddFunctionalDeformation(0.0, 0.0, 0.0, 0.2, 40.0, 0.3); // (0, 0) is a grid point
  deform->AddRangeDeformation(0.25, 0.45, -0.45, -0.25, -1, 1, 0, 0, -0.1);
  deform->SetMaxLevel(3);
  lktest::ErrorRecorder errors(deform);
  deform->Update();
  EXPECT_EQ(errors.errors, 0) << errors.messages;
  vtkPolyData* out = deform->GetOutput();
  double bounds[6];
  out->GetBounds(bounds);
  EXPECT_NEAR(bounds[5], 0.2, 1e-12); // the peak is k
  EXPECT_NEAR(bounds[4], -0.1, 1e-12); // the box moved down
  // Locality: points farther than D from the centre and outside the box stay put.
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    const bool inBox = p[0] >= 0.25 && p[0] <= 0.45 && p[1] >= -0.45 && p[1] <= -0.25;
    if (std::hypot(p[0], p[1]) > 0.3 + 1e-9 && !inBox)
      ASSERT_EQ(p[2], 0.0) << i;
  }
  // Conforming: every edge has one or two triangles; refined where deformed.
  std::map<std::pair<vtkIdType, vtkIdType>, int> use;
  const vtkIdType* ids;
  vtkIdType n;
  auto polys = out->GetPolys();
  polys->InitTraversal();
  while (polys->GetNextCell(n, ids))
    for (int e = 0; e < 3; ++e)
      ++use[{ std::min(ids[e], ids[(e + 1) % 3]), std::max(ids[e], ids[(e + 1) % 3]) }];
  double border = 0.0;
  for (const auto& [e, c] : use)
  {
    ASSERT_LE(c, 2);
    if (c == 1)
    {
      double a[3], b[3];
      out->GetPoint(e.first, a);
      out->GetPoint(e.second, b);
      ASSERT_TRUE(std::abs(std::abs(a[0] + b[0]) - 1.0) < 1e-12 || std::abs(std::abs(a[1] + b[1]) - 1.0) < 1e-12)
        << "a crack inside the patch";
      border += std::hypot(a[0] - b[0], a[1] - b[1]);
    }
  }
  EXPECT_NEAR(border, 4.0, 1e-9); // exactly the patch's border: no cracks
  EXPECT_EQ(out->GetCellData()->GetArray("Level")->GetRange()[1], 3.0);
  // Smoothing the box's step lowers the largest jump along an edge.
  auto largestJump = [](vtkPolyData* pd) {
    double worst = 0.0;
    const vtkIdType* c;
    vtkIdType k;
    pd->GetPolys()->InitTraversal();
    while (pd->GetPolys()->GetNextCell(k, c))
      for (int e = 0; e < 3; ++e)
        worst = std::max(worst, std::abs(pd->GetPoint(c[e])[2] - pd->GetPoint(c[(e + 1) % 3])[2]));
    return worst;
  };
  const double before = largestJump(out);
  deform->AddSmoothingDeformation(0.35, -0.35, 0.0, 0.2, 4);
  deform->Update();
  EXPECT_LT(largestJump(deform->GetOutput()), before);
}

TEST(PatchDeformationFilter, BadInputGivesErrors)
{
  vtkNew<vtkLKPatchDeformationFilter> deform;
  vtkNew<vtkPolyData> empty;
  deform->SetInputData(empty);
  {
    lktest::ErrorRecorder errors(deform);
    deform->Update();
    EXPECT_GE(errors.errors, 1);
  }
  deform->SetInputData(planarPatch(4));
  deform->SetTolerance(-1.0);
  {
    lktest::ErrorRecorder errors(deform);
    deform->Update();
    EXPECT_NE(errors.messages.find("Tolerance"), std::string::npos) << errors.messages;
  }
  deform->SetTolerance(0.0);
  deform->AddFunctionalDeformation(0, 0, 0, 1.0, 1.0, -2.0); // D < 0
  {
    lktest::ErrorRecorder errors(deform);
    deform->Update();
    EXPECT_NE(errors.messages.find("D > 0"), std::string::npos) << errors.messages;
  }
}

namespace
{
/// Points and triangles, compared exactly.
void expectSameMesh(vtkPolyData* a, vtkPolyData* b)
{
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  ASSERT_EQ(a->GetNumberOfPolys(), b->GetNumberOfPolys());
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_EQ(a->GetPoint(i)[c], b->GetPoint(i)[c]) << "point " << i;
  vtkIdType na, nb;
  const vtkIdType *ia, *ib;
  a->GetPolys()->InitTraversal();
  b->GetPolys()->InitTraversal();
  while (a->GetPolys()->GetNextCell(na, ia) && b->GetPolys()->GetNextCell(nb, ib))
  {
    ASSERT_EQ(na, nb);
    for (vtkIdType k = 0; k < na; ++k)
      ASSERT_EQ(ia[k], ib[k]);
  }
}

vtkSmartPointer<vtkPolyData> fromScratch(vtkPolyData* input, const std::vector<std::array<double, 3>>& bumps)
{
  vtkNew<vtkLKPatchDeformationFilter> f;
  f->SetInputData(input);
  f->SetMaxLevel(3);
  for (const auto& b : bumps)
    f->AddFunctionalDeformation(b[0], b[1], 0.0, b[2], 40.0, 0.3);
  f->Update();
  return f->GetOutput();
}
} // namespace

// The interactive path (a drag replaces the last deformation every mouse
// move; a brush appends; undo removes the last) gives, to the bit, what the
// same list gives from scratch.
TEST(PatchDeformationFilter, IncrementalUpdatesEqualFromScratch)
{
  auto patch = planarPatch(16);
  vtkNew<vtkLKPatchDeformationFilter> live;
  live->SetInputData(patch);
  live->SetMaxLevel(3);
  live->AddFunctionalDeformation(-0.1, 0.0, 0.0, 0.05, 40.0, 0.3);
  live->Update();
  // A drag: k grows from 0.02 to 0.3, then shrinks to 0.12.
  live->AddFunctionalDeformation(0.15, 0.1, 0.0, 0.0, 40.0, 0.3);
  for (double k : { 0.02, 0.1, 0.2, 0.3, 0.12 })
  {
    live->RemoveLastDeformation();
    live->AddFunctionalDeformation(0.15, 0.1, 0.0, k, 40.0, 0.3);
    live->Update();
  }
  expectSameMesh(live->GetOutput(), fromScratch(patch, { { -0.1, 0.0, 0.05 }, { 0.15, 0.1, 0.12 } }));
  // Brush dabs appended one by one.
  for (double x : { -0.3, -0.25, -0.2 })
  {
    live->AddFunctionalDeformation(x, -0.2, 0.0, 0.03, 40.0, 0.3);
    live->Update();
  }
  expectSameMesh(live->GetOutput(),
    fromScratch(patch,
      { { -0.1, 0.0, 0.05 }, { 0.15, 0.1, 0.12 }, { -0.3, -0.2, 0.03 }, { -0.25, -0.2, 0.03 },
        { -0.2, -0.2, 0.03 } }));
  // Undo twice, then a new drag on the shortened list.
  live->RemoveLastDeformation();
  live->Update();
  expectSameMesh(live->GetOutput(),
    fromScratch(patch, { { -0.1, 0.0, 0.05 }, { 0.15, 0.1, 0.12 }, { -0.3, -0.2, 0.03 }, { -0.25, -0.2, 0.03 } }));
  live->RemoveLastDeformation();
  live->RemoveLastDeformation();
  live->AddFunctionalDeformation(0.3, 0.3, 0.0, 0.2, 40.0, 0.3);
  live->Update();
  expectSameMesh(
    live->GetOutput(), fromScratch(patch, { { -0.1, 0.0, 0.05 }, { 0.15, 0.1, 0.12 }, { 0.3, 0.3, 0.2 } }));
  // A changed input starts again from it.
  vtkNew<vtkPolyData> moved;
  moved->DeepCopy(patch);
  moved->GetPoints()->SetPoint(0, -0.5, -0.5, 0.01);
  live->SetInputData(moved);
  live->Update();
  expectSameMesh(
    live->GetOutput(), fromScratch(moved, { { -0.1, 0.0, 0.05 }, { 0.15, 0.1, 0.12 }, { 0.3, 0.3, 0.2 } }));
  live->RemoveAllDeformations();
  live->RemoveLastDeformation(); // nothing to remove: no error
  live->Update();
  expectSameMesh(live->GetOutput(), fromScratch(moved, {}));
}

// A deformation taken from the middle of the list: the rest, applied again
// from the input, give what that list gives from scratch; an index out of
// range is an error that changes nothing.
TEST(PatchDeformationFilter, RemovingOneDeformationKeepsTheOthers)
{
  auto patch = planarPatch(16);
  vtkNew<vtkLKPatchDeformationFilter> live;
  live->SetInputData(patch);
  live->SetMaxLevel(3);
  live->AddFunctionalDeformation(-0.1, 0.0, 0.0, 0.05, 40.0, 0.3);
  live->AddFunctionalDeformation(0.15, 0.1, 0.0, 0.12, 40.0, 0.3);
  live->AddFunctionalDeformation(0.3, 0.3, 0.0, 0.2, 40.0, 0.3);
  live->Update();
  const vtkIdType refined = live->GetOutput()->GetNumberOfPoints();
  live->RemoveDeformation(1);
  EXPECT_EQ(live->GetNumberOfDeformations(), 2);
  live->Update();
  expectSameMesh(live->GetOutput(), fromScratch(patch, { { -0.1, 0.0, 0.05 }, { 0.3, 0.3, 0.2 } }));
  EXPECT_LT(live->GetOutput()->GetNumberOfPoints(), refined); // its refinement went with it
  {
    lktest::ErrorRecorder recorder(live);
    live->RemoveDeformation(2);
    live->RemoveDeformation(-1);
    EXPECT_EQ(recorder.errors, 2);
    EXPECT_NE(recorder.messages.find("no deformation 2 (the filter has 2, from 0)"), std::string::npos)
      << recorder.messages;
  }
  EXPECT_EQ(live->GetNumberOfDeformations(), 2);
  live->RemoveDeformation(0);
  live->Update();
  expectSameMesh(live->GetOutput(), fromScratch(patch, { { 0.3, 0.3, 0.2 } }));
}

#include <vtkAppendPolyData.h>
#include <vtkFieldData.h>
#include <vtkSphereSource.h>

#include <string>

TEST(PatchDeformationFilter, ADeformationThroughTheOtherSideIsReported)
{
  // A unit sphere pushed in at the north pole along its normal: 0.2 deep it
  // stays a solid; 2.5 deep (more than its diameter) the dent comes out
  // through the south side, and the output says so.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  sphere->Update();
  struct Result
  {
    vtkSmartPointer<vtkPolyData> out = vtkSmartPointer<vtkPolyData>::New();
    int warnings = 0;
    std::string warningMessages;
    double field(const char* name) const
    {
      vtkDataArray* a = out->GetFieldData()->GetArray(name);
      return a ? a->GetTuple1(0) : -1.0;
    }
  };
  auto deformed = [&](double k, bool check) {
    vtkNew<vtkLKPatchDeformationFilter> deform;
    deform->SetInputData(sphere->GetOutput());
    deform->SetCheckCrossings(check);
    deform->AddFunctionalDeformation(0.0, 0.0, 1.0, k, 4.0, 0.8);
    lktest::ErrorRecorder recorder(deform);
    deform->Update();
    EXPECT_EQ(recorder.errors, 0) << recorder.messages;
    Result r;
    r.out->ShallowCopy(deform->GetOutput());
    r.warnings = recorder.warnings;
    r.warningMessages = recorder.warningMessages;
    return r;
  };
  const Result shallow = deformed(-0.2, true);
  EXPECT_EQ(shallow.field("SelfCrossings"), 0.0);
  EXPECT_EQ(shallow.field("SelfCrossingDepth"), 0.0);
  EXPECT_EQ(shallow.warnings, 0) << shallow.warningMessages;
  const Result deep = deformed(-2.5, true);
  double bounds[6];
  deep.out->GetBounds(bounds);
  EXPECT_LT(bounds[4], -1.2); // the dent's tip is below the south pole
  EXPECT_GT(deep.field("SelfCrossings"), 10.0);
  EXPECT_GT(deep.field("SelfCrossingDepth"), 0.01);
  EXPECT_EQ(deep.warnings, 1);
  EXPECT_NE(deep.warningMessages.find("passes through itself"), std::string::npos) << deep.warningMessages;
  EXPECT_EQ(deep.field("SelfCrossingsBefore"), 0.0); // the sphere did not cross itself
  const Result unchecked = deformed(-2.5, false);
  EXPECT_EQ(unchecked.out->GetFieldData()->GetArray("SelfCrossings"), nullptr);
  EXPECT_EQ(unchecked.warnings, 0);

  // Crossings the input already had, near the moved faces, are told apart:
  // two unit spheres through each other (their circle of contact at x = 0.6,
  // radius 0.8), the first dented slightly beside that circle.
  vtkNew<vtkSphereSource> second;
  second->SetCenter(1.2, 0.0, 0.0);
  second->SetRadius(1.0);
  second->SetThetaResolution(32);
  second->SetPhiResolution(32);
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(sphere->GetOutputPort());
  both->AddInputConnection(second->GetOutputPort());
  both->Update();
  vtkNew<vtkLKPatchDeformationFilter> deform;
  deform->SetInputConnection(both->GetOutputPort());
  deform->AddFunctionalDeformation(0.55, 0.8, 0.0, -0.05, 20.0, 0.3);
  lktest::ErrorRecorder recorder(deform);
  deform->Update();
  EXPECT_EQ(recorder.errors, 0) << recorder.messages;
  vtkFieldData* fd = deform->GetOutput()->GetFieldData();
  EXPECT_GT(fd->GetArray("SelfCrossings")->GetTuple1(0), 0.0);
  EXPECT_GT(fd->GetArray("SelfCrossingsBefore")->GetTuple1(0), 0.0);
  EXPECT_NE(recorder.warningMessages.find("where the input already did"), std::string::npos) << recorder.warningMessages;
}
