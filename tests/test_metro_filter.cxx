#include "TestSupport.h"
#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKMetroFilter.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataPointSampler.h>
#include <vtkQuadricDecimation.h>
#include <vtkSphereSource.h>
#include <vtkStaticCellLocator.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
vtkSmartPointer<vtkPolyData> plane(int resolution, double z)
{
  vtkNew<vtkPlaneSource> source;
  source->SetResolution(resolution, resolution);
  source->SetCenter(0, 0, z);
  source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  vtkNew<vtkTriangleFilter> tri;
  tri->SetInputConnection(source->GetOutputPort());
  tri->Update();
  return tri->GetOutput();
}

vtkSmartPointer<vtkPolyData> sphere(double radius, int resolution)
{
  vtkNew<vtkSphereSource> source;
  source->SetRadius(radius);
  source->SetThetaResolution(resolution);
  source->SetPhiResolution(resolution);
  source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  source->Update();
  return source->GetOutput();
}

double field(vtkPolyData* pd, const char* name)
{
  vtkDataArray* a = pd->GetFieldData()->GetArray(name);
  return a ? a->GetTuple1(0) : std::nan("");
}

/// Mandible surface from the TCIA label map, and a decimated copy.
struct MandiblePair
{
  vtkSmartPointer<vtkPolyData> surface, copy;
  MandiblePair()
  {
    vtkNew<vtkLKMedicalImageReader> reader;
    reader->SetFileName(lktest::sampleData("mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd").c_str());
    vtkNew<vtkLKBoneSurfaceFilter> bone;
    bone->SetInputConnection(reader->GetOutputPort());
    vtkNew<vtkQuadricDecimation> decimate;
    decimate->SetInputConnection(bone->GetOutputPort());
    decimate->SetTargetReduction(0.9);
    decimate->Update();
    surface = bone->GetOutput();
    copy = decimate->GetOutput();
  }
};

/// Independent of vtkLKMetroFilter (its sampler and CGAL): a regular
/// barycentric grid of spacing about h on every triangle (vertices and edges
/// included), integrated by the trapezoid rule (each grid point carries a
/// third of the area of every grid sub-triangle it touches), and VTK's
/// vtkStaticCellLocator for the closest points.
struct Independent
{
  double max = 0, mean = 0, rms = 0;
};
Independent independentDistance(vtkPolyData* from, vtkPolyData* to, double h)
{
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(to);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  Independent r;
  double wsum = 0.0;
  for (vtkIdType c = 0; c < from->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    from->GetCellPoints(c, n, ids);
    double a[3], b[3], p2[3];
    from->GetPoint(ids[0], a);
    from->GetPoint(ids[1], b);
    from->GetPoint(ids[2], p2);
    double e1[3], e2[3], cr[3];
    double longest = 0;
    for (int k = 0; k < 3; ++k)
    {
      e1[k] = b[k] - a[k];
      e2[k] = p2[k] - a[k];
    }
    cr[0] = e1[1] * e2[2] - e1[2] * e2[1];
    cr[1] = e1[2] * e2[0] - e1[0] * e2[2];
    cr[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const double area = 0.5 * std::sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
    longest = std::max({ std::hypot(e1[0], e1[1], e1[2]), std::hypot(e2[0], e2[1], e2[2]),
      std::hypot(b[0] - p2[0], b[1] - p2[1], b[2] - p2[2]) });
    const int k = std::max(1, static_cast<int>(std::ceil(longest / h)));
    const double third = area / (static_cast<double>(k) * k) / 3.0;
    for (int i = 0; i <= k; ++i)
    {
      for (int j = 0; i + j <= k; ++j)
      {
        // Sub-triangles touching grid point (i, j): up (a,b),(a+1,b),(a,b+1)
        // for a+b <= k-1; down (a+1,b),(a,b+1),(a+1,b+1) for a+b <= k-2.
        const int touching = (i + j <= k - 1) + (i >= 1 && i + j - 1 <= k - 1) +
          (j >= 1 && i + j - 1 <= k - 1) + (i >= 1 && i + j - 1 <= k - 2) +
          (j >= 1 && i + j - 1 <= k - 2) + (i >= 1 && j >= 1 && i + j - 2 <= k - 2);
        const double w = touching * third;
        double p[3], q[3], d2;
        for (int m = 0; m < 3; ++m)
        {
          p[m] = a[m] + (i * e1[m] + j * e2[m]) / k;
        }
        vtkIdType cellId;
        int subId;
        locator->FindClosestPoint(p, q, cell, cellId, subId, d2);
        const double d = std::sqrt(d2);
        r.max = std::max(r.max, d);
        r.mean += w * d;
        r.rms += w * d2;
        wsum += w;
      }
    }
  }
  r.mean /= wsum;
  r.rms = std::sqrt(r.rms / wsum);
  return r;
}
} // namespace

TEST(MetroFilter, ParallelPlanesAndBoundingBoxPercentages)
{
  auto a = plane(4, 0.0), b = plane(7, 0.3);
  vtkNew<vtkLKMetroFilter> metro;
  metro->SetInputData(a);
  metro->SetTargetData(b);
  metro->SetNumberOfSamples(20000);
  {
    lktest::ErrorRecorder rec(metro);
    metro->Update();
    EXPECT_EQ(rec.warnings, 0) << rec.warningMessages; // 0.3 apart is an approximation's offset
  }
  vtkPolyData* out = metro->GetOutput();
  const double diagonal = std::sqrt(1.0 + 1.0 + 0.09);
  EXPECT_NEAR(field(out, "BoundingBoxDiagonal"), diagonal, 1e-12);
  for (const char* p : { "AtoB", "BtoA", "Hausdorff" })
  {
    for (const char* s : { "_Max", "_Mean", "_RMS" })
    {
      EXPECT_NEAR(field(out, (std::string(p) + s).c_str()), 0.3, 1e-12) << p << s;
      EXPECT_NEAR(field(out, (std::string(p) + s + "Percent").c_str()), 30.0 / diagonal, 1e-10) << p << s;
    }
  }
  EXPECT_NEAR(metro->GetHausdorffDistance(), 0.3, 1e-12);
  EXPECT_GT(metro->GetNumberOfForwardSamples(), 20000);
  // Per-point distances on A, with colours.
  vtkDataArray* d = out->GetPointData()->GetArray("Distance");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->GetNumberOfTuples(), a->GetNumberOfPoints());
  EXPECT_NEAR(d->GetRange()[0], 0.3, 1e-12);
  EXPECT_NEAR(d->GetRange()[1], 0.3, 1e-12);
  auto* colors = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("DistanceColors"));
  ASSERT_NE(colors, nullptr);
  EXPECT_EQ(colors->GetNumberOfComponents(), 3);
  EXPECT_EQ(out->GetNumberOfCells(), a->GetNumberOfCells());
}

TEST(MetroFilter, MeshesInTwoCoordinateSystemsAreWarnedOf)
{
  // A sphere of radius 10 centred 300 along y (as a mandible in LPS), the
  // same with y mirrored (an untagged RAS copy), and the same in metres.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(10.0);
  sphere->SetCenter(0.0, 300.0, 0.0);
  sphere->Update();
  auto transformed = [&](double sx, double sy, double sz) {
    vtkNew<vtkTransform> t;
    t->Scale(sx, sy, sz);
    vtkNew<vtkTransformPolyDataFilter> f;
    f->SetTransform(t);
    f->SetInputConnection(sphere->GetOutputPort());
    f->Update();
    return vtkSmartPointer<vtkPolyData>(f->GetOutput());
  };
  // A sphere 20 times smaller inside it (same centre).
  vtkNew<vtkSphereSource> smallSphere;
  smallSphere->SetRadius(0.5);
  smallSphere->SetCenter(0.0, 300.0, 0.0);
  smallSphere->Update();
  vtkSmartPointer<vtkPolyData> small = smallSphere->GetOutput();
  struct Case
  {
    vtkSmartPointer<vtkPolyData> b;
    bool symmetric;
    std::string expected; // "" for no warning
  };
  const std::vector<Case> cases{ { transformed(1.0, 1.0, 1.0), true, "" },
    { transformed(-1.0, -1.0, 1.0), true, "lie far apart" },
    { transformed(0.001, 0.001, 0.001), true, "lie far apart" },
    { transformed(1.0, 1.001, 1.0), true, "" },
    { small, true, "differ in size 20-fold" },
    { small, false, "" } }; // a small part measured against the whole: one way
  for (const Case& c : cases)
  {
    vtkNew<vtkLKMetroFilter> metro;
    metro->SetInputData(sphere->GetOutput());
    metro->SetTargetData(c.b);
    metro->SetNumberOfSamples(2000);
    metro->SetSymmetric(c.symmetric);
    lktest::ErrorRecorder rec(metro);
    metro->Update();
    EXPECT_EQ(rec.errors, 0) << rec.messages;
    if (c.expected.empty())
      EXPECT_EQ(rec.warnings, 0) << rec.warningMessages;
    else
    {
      EXPECT_EQ(rec.warnings, 1) << c.expected;
      EXPECT_NE(rec.warningMessages.find(c.expected), std::string::npos) << rec.warningMessages;
      EXPECT_NE(rec.warningMessages.find("two coordinate systems"), std::string::npos) << rec.warningMessages;
    }
  }
}

TEST(MetroFilter, ColoursRunFromBlueToRed)
{
  // A tilted plane against a flat one: distance grows along x.
  auto a = plane(10, 0.0);
  vtkNew<vtkTransform> tilt;
  tilt->RotateY(20);
  vtkNew<vtkTransformPolyDataFilter> tilted;
  tilted->SetInputData(a);
  tilted->SetTransform(tilt);
  tilted->Update();
  vtkNew<vtkLKMetroFilter> metro;
  metro->SetInputConnection(tilted->GetOutputPort());
  metro->SetTargetData(plane(3, 0.0));
  metro->SetColorMaximum(0.2);
  metro->Update();
  vtkPolyData* out = metro->GetOutput();
  vtkDataArray* d = out->GetPointData()->GetArray("Distance");
  auto* colors = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("DistanceColors"));
  vtkIdType nearest = 0, farthest = 0;
  for (vtkIdType i = 0; i < d->GetNumberOfTuples(); ++i)
  {
    nearest = d->GetTuple1(i) < d->GetTuple1(nearest) ? i : nearest;
    farthest = d->GetTuple1(i) > d->GetTuple1(farthest) ? i : farthest;
  }
  EXPECT_GT(colors->GetTypedComponent(nearest, 2), 200);  // blue
  EXPECT_LT(colors->GetTypedComponent(nearest, 0), 50);
  EXPECT_GT(colors->GetTypedComponent(farthest, 0), 200); // red
  EXPECT_LT(colors->GetTypedComponent(farthest, 2), 50);
  EXPECT_DOUBLE_EQ(metro->GetEffectiveColorMaximum(), 0.2);
}

TEST(MetroFilter, MeshAgainstItselfAndSwappedInputs)
{
  auto s = sphere(10.0, 40);
  vtkNew<vtkLKMetroFilter> metro;
  metro->SetInputData(s);
  metro->SetTargetData(s);
  metro->Update();
  EXPECT_LT(metro->GetHausdorffDistance(), 1e-12);
  EXPECT_LT(metro->GetOutput()->GetPointData()->GetArray("Distance")->GetRange()[1], 1e-12);

  // Swapping A and B swaps the directions exactly (deterministic sampling).
  auto a = sphere(10.0, 40), b = sphere(10.5, 17);
  vtkNew<vtkLKMetroFilter> ab, ba;
  for (auto* f : { ab.GetPointer(), ba.GetPointer() })
  {
    f->SetFaceSamplingMethodToSimilarTriangles();
    f->SetNumberOfSamples(30000);
  }
  ab->SetInputData(a);
  ab->SetTargetData(b);
  ba->SetInputData(b);
  ba->SetTargetData(a);
  ab->Update();
  ba->Update();
  EXPECT_EQ(ab->GetForwardMaximum(), ba->GetBackwardMaximum());
  EXPECT_EQ(ab->GetForwardMean(), ba->GetBackwardMean());
  EXPECT_EQ(ab->GetBackwardRMS(), ba->GetForwardRMS());
  EXPECT_EQ(ab->GetHausdorffDistance(), ba->GetHausdorffDistance());
  // Concentric spheres 0.5 apart; the coarse outer one's faces sag inward by
  // up to R (1 - cos(pi / 17)) = 0.18, which lowers the distances.
  EXPECT_GT(ab->GetForwardMean(), 0.5 - 0.18);
  EXPECT_LT(ab->GetForwardMean(), 0.5);
  EXPECT_GT(ab->GetBackwardMean(), 0.5 - 0.18);
  EXPECT_LT(ab->GetBackwardMean(), 0.5);
}

TEST(MetroFilter, MonteCarloIsReproducibleForASeed)
{
  auto a = sphere(10.0, 30), b = sphere(10.2, 13);
  double means[3];
  int k = 0;
  for (int seed : { 11, 11, 12 })
  {
    vtkNew<vtkLKMetroFilter> m;
    m->SetInputData(a);
    m->SetTargetData(b);
    m->SetFaceSamplingMethodToMonteCarlo();
    m->SetRandomSeed(seed);
    m->Update();
    means[k++] = m->GetForwardMean();
  }
  EXPECT_EQ(means[0], means[1]);
  EXPECT_NE(means[0], means[2]);
  EXPECT_NEAR(means[0], means[2], 0.05 * means[0]); // sampling noise of ~17,000 samples
}

TEST(MetroFilter, AgreesWithAnIndependentComputationOnTheMandible)
{
  MandiblePair pair;
  ASSERT_GT(pair.surface->GetNumberOfPoints(), 9000);
  vtkNew<vtkLKMetroFilter> metro;
  metro->SetInputData(pair.surface);
  metro->SetTargetData(pair.copy);
  const double h = 0.1; // mm, both methods at about the same density
  metro->SetSampleDensity(1.0 / (h * h));
  metro->Update();
  const Independent fwd = independentDistance(pair.surface, pair.copy, h);
  const Independent bwd = independentDistance(pair.copy, pair.surface, h);
  std::printf("A->B  max %.5f / %.5f  mean %.6f / %.6f  rms %.6f / %.6f (latticekit / independent)\n",
    metro->GetForwardMaximum(), fwd.max, metro->GetForwardMean(), fwd.mean, metro->GetForwardRMS(), fwd.rms);
  std::printf("B->A  max %.5f / %.5f  mean %.6f / %.6f  rms %.6f / %.6f\n", metro->GetBackwardMaximum(),
    bwd.max, metro->GetBackwardMean(), bwd.mean, metro->GetBackwardRMS(), bwd.rms);
  EXPECT_NEAR(metro->GetForwardMaximum(), fwd.max, 0.01 * fwd.max);
  EXPECT_NEAR(metro->GetForwardMean(), fwd.mean, 0.01 * fwd.mean);
  EXPECT_NEAR(metro->GetForwardRMS(), fwd.rms, 0.01 * fwd.rms);
  EXPECT_NEAR(metro->GetBackwardMaximum(), bwd.max, 0.01 * bwd.max);
  EXPECT_NEAR(metro->GetBackwardMean(), bwd.mean, 0.01 * bwd.mean);
  EXPECT_NEAR(metro->GetBackwardRMS(), bwd.rms, 0.01 * bwd.rms);
}

TEST(MetroFilter, MeanOverAllSamplesPoolsTheThreeKindsOfSample)
{
  // Metro 4's mean counts every sample once: it is the three kinds' own
  // means weighted by their counts. The samples do not depend on which kinds
  // are on (edges and faces are seeded by their own index).
  MandiblePair pair;
  auto run = [&](bool vertex, bool edge, bool face, bool all) {
    auto m = vtkSmartPointer<vtkLKMetroFilter>::New();
    m->SetInputData(pair.copy);
    m->SetTargetData(pair.surface);
    m->SetVertexSampling(vertex);
    m->SetEdgeSampling(edge);
    m->SetFaceSampling(face);
    m->SetMeanOverAllSamples(all);
    m->Update();
    return m;
  };
  auto pooled = run(true, true, true, true), area = run(true, true, true, false);
  auto v = run(true, false, false, true), e = run(false, true, false, true), f = run(false, false, true, true);
  vtkPolyData* out = pooled->GetOutput();
  const double nv = field(out, "AtoB_VertexSamples"), ne = field(out, "AtoB_EdgeSamples"),
               nf = field(out, "AtoB_FaceSamples");
  ASSERT_GT(nv, 0.0);
  ASSERT_GT(ne, 0.0);
  ASSERT_GT(nf, 0.0);
  const double n = nv + ne + nf;
  const double mean = (nv * v->GetForwardMean() + ne * e->GetForwardMean() + nf * f->GetForwardMean()) / n;
  EXPECT_NEAR(pooled->GetForwardMean(), mean, 1e-9 * mean);
  const double ms = (nv * std::pow(v->GetForwardRMS(), 2) + ne * std::pow(e->GetForwardRMS(), 2) +
                      nf * std::pow(f->GetForwardRMS(), 2)) / n;
  EXPECT_NEAR(pooled->GetForwardRMS(), std::sqrt(ms), 1e-9 * std::sqrt(ms));
  EXPECT_EQ(pooled->GetForwardMaximum(), area->GetForwardMaximum());
  // The decimated copy's vertices lie off the surface more than its faces do
  // on average, so counting them moves the mean.
  EXPECT_GT(v->GetForwardMean(), area->GetForwardMean());
  EXPECT_GT(std::abs(pooled->GetForwardMean() - area->GetForwardMean()), 0.01 * area->GetForwardMean());
}

TEST(MetroFilter, SingleTriangleIsMeasuredNotRefused)
{
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->InsertNextPoint(0, 0, 0);
  pts->InsertNextPoint(1, 0, 0);
  pts->InsertNextPoint(0, 1, 0);
  vtkNew<vtkCellArray> cells;
  const vtkIdType ids[3] = { 0, 1, 2 };
  cells->InsertNextCell(3, ids);
  vtkNew<vtkPolyData> tri;
  tri->SetPoints(pts);
  tri->SetPolys(cells);
  vtkNew<vtkPolyData> lifted;
  lifted->DeepCopy(tri);
  lifted->GetPoints()->SetPoint(0, 0, 0, 0.1);
  lifted->GetPoints()->SetPoint(1, 1, 0, 0.1);
  lifted->GetPoints()->SetPoint(2, 0, 1, 0.1);
  vtkNew<vtkLKMetroFilter> metro;
  lktest::ErrorRecorder rec(metro);
  metro->SetInputData(tri);
  metro->SetTargetData(lifted);
  metro->Update();
  EXPECT_EQ(rec.errors, 0);
  EXPECT_NEAR(metro->GetHausdorffDistance(), 0.1, 1e-12);
  EXPECT_NEAR(metro->GetForwardMean(), 0.1, 1e-12);
}

TEST(MetroFilter, ATriangleThatRepeatsAVertexIsMeasuredAsItsSegment)
{
  // Meshes from other tools carry such triangles (zero area): the distances
  // to one were NaN, and so were the means, without a word.
  auto a = plane(8, 0.0);
  auto b = plane(8, 0.5);
  vtkIdType ids[3] = { 3, 3, 4 };
  b->GetPolys()->InsertNextCell(3, ids);
  vtkNew<vtkLKMetroFilter> metro;
  lktest::ErrorRecorder rec(metro);
  metro->SetInputData(a);
  metro->SetTargetData(b);
  metro->Update();
  EXPECT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_NEAR(metro->GetForwardMean(), 0.5, 1e-12);
  EXPECT_NEAR(metro->GetBackwardMean(), 0.5, 1e-12);
  EXPECT_NEAR(metro->GetHausdorffDistance(), 0.5, 1e-12);
  vtkDataArray* d = metro->GetOutput()->GetPointData()->GetArray("Distance");
  ASSERT_NE(d, nullptr);
  for (vtkIdType i = 0; i < d->GetNumberOfTuples(); ++i)
    ASSERT_NEAR(d->GetTuple1(i), 0.5, 1e-12) << i;
}

TEST(MetroFilter, BadInputGivesClearErrors)
{
  auto good = plane(2, 0.0);
  struct Case
  {
    vtkSmartPointer<vtkPolyData> a, b;
    std::string expected;
  };
  std::vector<Case> cases;
  cases.push_back({ vtkSmartPointer<vtkPolyData>::New(), good, "Mesh A (input 0): the mesh is empty" });
  cases.push_back({ good, vtkSmartPointer<vtkPolyData>::New(), "Mesh B (input 1): the mesh is empty" });
  {
    vtkNew<vtkPlaneSource> quads; // not triangulated
    quads->Update();
    cases.push_back({ quads->GetOutput(), good, "only triangles are accepted" });
  }
  {
    auto nan = vtkSmartPointer<vtkPolyData>::New();
    nan->DeepCopy(good);
    nan->GetPoints()->SetPoint(1, std::nan(""), 0, 0);
    cases.push_back({ good, nan, "NaN" });
  }
  {
    auto flat = vtkSmartPointer<vtkPolyData>::New();
    flat->DeepCopy(good);
    for (vtkIdType i = 0; i < flat->GetNumberOfPoints(); ++i)
    {
      flat->GetPoints()->SetPoint(i, 0, 0, 0);
    }
    cases.push_back({ flat, good, "zero area" });
  }
  {
    auto lines = vtkSmartPointer<vtkPolyData>::New();
    lines->SetPoints(good->GetPoints());
    vtkNew<vtkCellArray> l;
    const vtkIdType ids[2] = { 0, 1 };
    l->InsertNextCell(2, ids);
    lines->SetLines(l);
    cases.push_back({ good, lines, "line" });
  }
  for (const Case& c : cases)
  {
    vtkNew<vtkLKMetroFilter> metro;
    lktest::ErrorRecorder rec(metro);
    metro->SetInputData(c.a);
    metro->SetTargetData(c.b);
    metro->Update();
    EXPECT_EQ(rec.errors, 1) << c.expected;
    EXPECT_NE(rec.messages.find(c.expected), std::string::npos) << rec.messages;
    EXPECT_EQ(metro->GetHausdorffDistance(), 0.0);
  }
  // More samples than a run measures in reasonable time (a typo, an extra
  // digit or ten): refused before the work starts. (The samples are measured
  // a block at a time, so their number no longer meets the machine's memory.)
  {
    vtkNew<vtkLKMetroFilter> metro;
    lktest::ErrorRecorder rec(metro);
    metro->SetInputData(good);
    metro->SetTargetData(good);
    metro->SetNumberOfSamples(VTK_ID_MAX / 64);
    metro->Update();
    EXPECT_EQ(rec.errors, 1);
    EXPECT_NE(rec.messages.find("samples, more than the 1000000000 one run measures"), std::string::npos)
      << rec.messages;
    EXPECT_EQ(metro->GetHausdorffDistance(), 0.0);
  }
  // No second input at all: the executive refuses to run the filter.
  vtkNew<vtkLKMetroFilter> lonely;
  lonely->SetInputData(good);
  lonely->Update();
  EXPECT_EQ(lonely->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(lonely->GetHausdorffDistance(), 0.0);
  // Nothing to sample.
  vtkNew<vtkLKMetroFilter> none;
  lktest::ErrorRecorder rec2(none);
  none->SetInputData(good);
  none->SetTargetData(good);
  none->VertexSamplingOff();
  none->EdgeSamplingOff();
  none->FaceSamplingOff();
  none->Update();
  EXPECT_EQ(rec2.errors, 1);
}
