#include "TestSupport.h"
#include "vtkLKWrinklyNetSource.h"
#include "vtkLKWrinklySurfaceFilter.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>

#include <cmath>

namespace
{
vtkSmartPointer<vtkPolyData> run(vtkLKWrinklySurfaceFilter* f)
{
  f->Update();
  return f->GetOutput();
}
} // namespace

TEST(WrinklySurfaceFilter, NetThroughTheFilter)
{
  vtkNew<vtkLKWrinklyNetSource> net;
  net->SetNetTypeToPolygon();
  net->SetSides(6);
  vtkNew<vtkLKWrinklySurfaceFilter> wrinkly;
  wrinkly->SetInputConnection(net->GetOutputPort());
  wrinkly->SetIterations(2);
  lktest::ErrorRecorder errors(wrinkly);
  auto out = run(wrinkly);
  EXPECT_EQ(errors.errors, 0) << errors.messages;
  // 6 x 3 x 3 - ... real points, 9 x 9 samples per patch (K = 2, M = 1).
  net->Update();
  EXPECT_GT(out->GetNumberOfPolys(), 1000);
  ASSERT_NE(out->GetPointData()->GetArray("Height"), nullptr);
  ASSERT_NE(out->GetPointData()->GetArray("RGB"), nullptr);
  ASSERT_NE(out->GetPointData()->GetArray("Colors"), nullptr);
  ASSERT_NE(out->GetCellData()->GetArray("ControlPointId"), nullptr);
  EXPECT_EQ(wrinkly->GetUsedIterations(), 2);
  // The colours stay inside the range of the control points' colours.
  double lo = 1e9, hi = -1e9;
  vtkDataArray* rgb = out->GetPointData()->GetArray("RGB");
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    lo = std::min(lo, rgb->GetComponent(i, 0));
    hi = std::max(hi, rgb->GetComponent(i, 0));
  }
  EXPECT_GE(lo, 0.0);
  EXPECT_LE(hi, 1.0);
  EXPECT_GT(hi - lo, 0.2);
}

TEST(WrinklySurfaceFilter, ZeroHeightsLieOnTheBaseSurface)
{
  vtkNew<vtkLKWrinklyNetSource> net;
  net->SetHeightAmplitude(0.0);
  vtkNew<vtkLKWrinklySurfaceFilter> wrinkly;
  wrinkly->SetInputConnection(net->GetOutputPort());
  auto out = run(wrinkly);
  double bounds[6];
  out->GetBounds(bounds);
  EXPECT_EQ(bounds[4], 0.0); // a flat net stays flat
  EXPECT_EQ(bounds[5], 0.0);
}

TEST(WrinklySurfaceFilter, ToleranceChoosesTheIterations)
{
  vtkNew<vtkLKWrinklyNetSource> net;
  vtkNew<vtkLKWrinklySurfaceFilter> wrinkly;
  wrinkly->SetInputConnection(net->GetOutputPort());
  wrinkly->SetSamplingTolerance(0.05);
  auto fine = run(wrinkly);
  const int kFine = wrinkly->GetUsedIterations();
  wrinkly->SetSamplingTolerance(0.5);
  auto coarse = run(wrinkly);
  const int kCoarse = wrinkly->GetUsedIterations();
  EXPECT_GT(kFine, kCoarse);
  EXPECT_EQ(vtkArrayDownCast<vtkDataArray>(wrinkly->GetOutput()->GetFieldData()->GetArray("Iterations"))
              ->GetComponent(0, 0),
    kCoarse);
}

TEST(WrinklySurfaceFilter, BadInputGivesErrors)
{
  vtkNew<vtkLKWrinklyNetSource> net;
  net->SetNetTypeToPolygon();
  net->SetSides(5); // one group of axes
  vtkNew<vtkLKWrinklySurfaceFilter> wrinkly;
  wrinkly->SetInputConnection(net->GetOutputPort());
  {
    lktest::ErrorRecorder errors(wrinkly);
    wrinkly->Update();
    EXPECT_GE(errors.errors, 1);
    EXPECT_NE(errors.messages.find("one group"), std::string::npos) << errors.messages;
  }
  net->SetSides(6);
  wrinkly->SetHeightArrayName("NoSuchArray");
  {
    lktest::ErrorRecorder errors(wrinkly);
    wrinkly->Update();
    EXPECT_NE(errors.messages.find("NoSuchArray"), std::string::npos) << errors.messages;
  }
  wrinkly->SetHeightArrayName("Height");
  wrinkly->SetAlpha0(0.9);
  {
    lktest::ErrorRecorder errors(wrinkly);
    wrinkly->Update();
    EXPECT_NE(errors.messages.find("alpha0"), std::string::npos) << errors.messages;
  }
  wrinkly->SetAlpha0(0.5);
  wrinkly->SetSamplingTolerance(-1.0);
  {
    lktest::ErrorRecorder errors(wrinkly);
    wrinkly->Update();
    EXPECT_GE(errors.errors, 1);
  }
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkLKWrinklySurfaceFilter> none;
  none->SetInputData(empty);
  lktest::ErrorRecorder errors(none);
  none->Update();
  EXPECT_GE(errors.errors, 1);
}

TEST(WrinklySurfaceFilter, ControlMeshWithOtherCellsIsRefusedNotPartlyUsed)
{
  // The net's polygons and one line cell beside them: the line would be
  // left out without a word, so the mesh is refused, and the counts said.
  vtkNew<vtkLKWrinklyNetSource> net;
  net->SetNetTypeToPolygon();
  net->SetSides(6);
  net->Update();
  vtkNew<vtkPolyData> mixed;
  mixed->DeepCopy(net->GetOutput());
  vtkNew<vtkCellArray> lines;
  const vtkIdType ends[2] = { 0, 1 };
  lines->InsertNextCell(2, ends);
  mixed->SetLines(lines);
  vtkNew<vtkLKWrinklySurfaceFilter> wrinkly;
  wrinkly->SetInputData(mixed);
  wrinkly->SetIterations(1);
  lktest::ErrorRecorder errors(wrinkly);
  auto out = run(wrinkly);
  EXPECT_GE(errors.errors, 1);
  EXPECT_NE(errors.messages.find("0 vertex, 1 line and 0 strip cells"), std::string::npos) << errors.messages;
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
  // Without the line it is made.
  vtkNew<vtkCellArray> noLines;
  mixed->SetLines(noLines);
  lktest::ErrorRecorder none(wrinkly);
  EXPECT_GT(run(wrinkly)->GetNumberOfPolys(), 100);
  EXPECT_EQ(none.errors, 0) << none.messages;
}
