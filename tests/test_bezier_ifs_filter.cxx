#include "TestSupport.h"
#include "latticekit/BezierIFS.h"
#include "vtkLKBezierIFSFilter.h"

#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

namespace
{
vtkSmartPointer<vtkPolyData> controlPoints(const std::vector<lk::Vec3>& pts)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> p;
  for (const auto& x : pts)
    p->InsertNextPoint(x.data());
  pd->SetPoints(p);
  return pd;
}
const std::vector<lk::Vec3> kCubic = { { 0, 0, 0 }, { 1, 2, 0 }, { 3, 2, 1 }, { 4, 0, 0 } };
} // namespace

TEST(BezierIFSFilter, DeterministicCurveIsAPolylineOnTheCurve)
{
  vtkNew<vtkLKBezierIFSFilter> f;
  f->SetInputData(controlPoints(kCubic));
  f->SetSplitParameter(0.3);
  f->SetDepth(6);
  f->Update();
  vtkPolyData* out = f->GetOutput();
  EXPECT_EQ(out->GetNumberOfPoints(), 65);
  EXPECT_EQ(out->GetNumberOfLines(), 1);
  vtkDataArray* t = out->GetPointData()->GetArray("Parameter");
  ASSERT_TRUE(t);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    if (i > 0)
      EXPECT_GT(t->GetComponent(i, 0), t->GetComponent(i - 1, 0));
    double p[3];
    out->GetPoint(i, p);
    EXPECT_LT((lk::Vec3(p[0], p[1], p[2]) - lk::deCasteljau(kCubic, t->GetComponent(i, 0))).norm(), 1e-12 * 4);
  }
  EXPECT_EQ(t->GetComponent(0, 0), 0.0);
  EXPECT_NEAR(t->GetComponent(64, 0), 1.0, 1e-15);
}

TEST(BezierIFSFilter, SurfaceQuadsAndChaosTexture)
{
  std::vector<lk::Vec3> net;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      net.emplace_back(i, j, (i == 1 || i == 2) && (j == 1 || j == 2) ? 2.0 : 0.0);
  vtkNew<vtkLKBezierIFSFilter> f;
  f->SetInputData(controlPoints(net));
  f->SetShapeToSurface();
  f->SetDepth(3);
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 81);
  EXPECT_EQ(f->GetOutput()->GetNumberOfPolys(), 64);

  auto densitySpread = [&](vtkDoubleArray* p) {
    vtkNew<vtkLKBezierIFSFilter> chaos;
    chaos->SetInputData(controlPoints(net));
    chaos->SetShapeToSurface();
    chaos->SetAlgorithmToChaosGame();
    chaos->SetNumberOfPoints(100000);
    chaos->SetDensityBins(8);
    chaos->SetProbabilities(p);
    chaos->Update();
    vtkDataArray* d = chaos->GetOutput()->GetPointData()->GetArray("HitDensity");
    EXPECT_EQ(chaos->GetOutput()->GetNumberOfVerts(), 100000);
    double range[2];
    d->GetRange(range);
    return range[1] / range[0];
  };
  const double uniform = densitySpread(nullptr);
  vtkNew<vtkDoubleArray> skew;
  for (double v : { 0.1, 0.2, 0.3, 0.4 })
    skew->InsertNextValue(v);
  const double skewed = densitySpread(skew);
  std::printf("hit density max/min: equal probabilities %.2f, (0.1, 0.2, 0.3, 0.4) %.2f\n", uniform, skewed);
  EXPECT_LT(uniform, 1.3);
  EXPECT_GT(skewed, 10.0);
}

TEST(BezierIFSFilter, BadInputIsAClearError)
{
  auto expectError = [](vtkLKBezierIFSFilter* f, const std::string& text) {
    lktest::ErrorRecorder errors(f);
    f->Update();
    EXPECT_EQ(errors.errors, 1) << text;
    EXPECT_NE(errors.messages.find(text), std::string::npos) << errors.messages;
    EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
  };
  {
    vtkNew<vtkLKBezierIFSFilter> f;
    f->SetInputData(controlPoints(kCubic));
    f->SetShapeToSurface();
    expectError(f, "NetDimensions 4 x 4");
  }
  {
    vtkNew<vtkLKBezierIFSFilter> f;
    f->SetInputData(controlPoints(kCubic));
    f->SetSplitParameter(1.5);
    expectError(f, "inside (0, 1)");
  }
  {
    vtkNew<vtkLKBezierIFSFilter> f;
    f->SetInputData(controlPoints(kCubic));
    f->SetAlgorithmToChaosGame();
    vtkNew<vtkDoubleArray> p;
    p->InsertNextValue(1.0);
    f->SetProbabilities(p);
    expectError(f, "one probability per map");
  }
  {
    vtkNew<vtkLKBezierIFSFilter> f;
    f->SetInputData(controlPoints({ { 0, 0, 0 }, { 1, 1, 1 }, { 2, 2, 2 } }));
    f->SetShapeToQuadraticPlanar();
    expectError(f, "collinear");
  }
  {
    vtkNew<vtkLKBezierIFSFilter> f;
    f->SetInputData(controlPoints({ { 0, 0, 0 } }));
    expectError(f, "at least 2 control points");
  }
  {
    // 10^14 chaos-game points (12 PB): refused at once, not std::bad_alloc.
    vtkNew<vtkLKBezierIFSFilter> f;
    f->SetInputData(controlPoints(kCubic));
    f->SetAlgorithmToChaosGame();
    f->SetNumberOfPoints(100000000000000LL);
    expectError(f, "more than this machine's memory");
  }
  {
    // 2^31 - 1 maps: refused when the filter runs (building their breaks
    // took 17 GB in the setter, their maps far more, and the kernel killed
    // the program).
    vtkNew<vtkLKBezierIFSFilter> f;
    f->SetInputData(controlPoints(kCubic));
    f->SetNumberOfMaps(2147483647);
    expectError(f, "NumberOfMaps must be from 2 to 10000, not 2147483647");
    f->SetNumberOfMaps(1);
    expectError(f, "NumberOfMaps must be from 2 to 10000, not 1");
    f->SetNumberOfMaps(3); // a valid count clears the refusal
    f->Update();
    EXPECT_GT(f->GetOutput()->GetNumberOfPoints(), 0);
  }
  {
    // 100 x 100 maps of a degree-20 net would take 15 GB of matrices.
    std::vector<lk::Vec3> net;
    for (int i = 0; i < 21; ++i)
      for (int j = 0; j < 21; ++j)
        net.emplace_back(i, j, 0.0);
    vtkNew<vtkLKBezierIFSFilter> f;
    f->SetInputData(controlPoints(net));
    f->SetShapeToSurface();
    f->SetNetDimensions(21, 21);
    f->SetNumberOfMaps(100);
    expectError(f, "would take more than 1 GB");
  }
}
