#include "TestMeshes.h"
#include "TestSupport.h"
#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKHomogenizedLoopFilter.h"
#include "vtkLKMedicalImageReader.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkLoopSubdivisionFilter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStaticPointLocator.h>

#include <cmath>
#include <map>

namespace
{
/// Largest distance from a point of `a` to the nearest point of `b`; the
/// point counts must match.
double setDistance(vtkPolyData* a, vtkPolyData* b)
{
  EXPECT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(b);
  locator->BuildLocator();
  double worst = 0.0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(locator->FindClosestPoint(p), q);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
  }
  return worst;
}

vtkSmartPointer<vtkPolyData> subdivide(vtkPolyData* in, int levels)
{
  vtkNew<vtkLKHomogenizedLoopFilter> f;
  f->SetInputData(in);
  f->SetNumberOfSubdivisions(levels);
  f->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(f->GetOutput());
  return out;
}

double nearest(vtkPolyData* pd, const double p[3])
{
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(pd);
  locator->BuildLocator();
  double q[3];
  pd->GetPoint(locator->FindClosestPoint(p), q);
  return std::sqrt(vtkMath::Distance2BetweenPoints(p, q));
}

vtkSmartPointer<vtkDoubleArray> ones(const char* name, vtkIdType n)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfTuples(n);
  a->Fill(1.0);
  return a;
}
} // namespace

namespace
{
/// Points rounded to float, as vtkLoopSubdivisionFilter stores them.
vtkSmartPointer<vtkPolyData> roundedToFloat(vtkPolyData* in)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(in);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    out->GetPoints()->SetPoint(i, static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
  }
  out->GetPointData()->Initialize();
  return out;
}

/// Our subdivision level by level with float rounding between levels (what
/// VTK 9.1 does: its output points are float at every level, whatever the
/// input's precision), against vtkLoopSubdivisionFilter.
void compareWithVtk(vtkPolyData* mesh, int maxLevels, double size)
{
  vtkSmartPointer<vtkPolyData> ours = roundedToFloat(mesh);
  for (int levels = 1; levels <= maxLevels; ++levels)
  {
    vtkNew<vtkLoopSubdivisionFilter> vtk;
    vtk->SetInputData(roundedToFloat(mesh));
    vtk->SetNumberOfSubdivisions(levels);
    vtk->Update();
    auto next = subdivide(ours, 1);
    // In double, before the rounding: within a few float ulps of VTK.
    const double d = setDistance(next, vtk->GetOutput());
    std::printf("%d levels: largest distance to VTK's point %.3g (%.3g of the size)\n", levels, d, d / size);
    EXPECT_LT(d, 4.0 * 1.2e-7 * size) << levels << " levels";
    ours = roundedToFloat(next);
    // Rounded like VTK's: the same point set up to one ulp.
    EXPECT_LT(setDistance(ours, vtk->GetOutput()), 2.0 * 1.2e-7 * size);
    EXPECT_EQ(ours->GetNumberOfPolys(), vtk->GetOutput()->GetNumberOfPolys());
    for (vtkIdType i = 0; i < next->GetNumberOfPoints(); i += 97)
      EXPECT_NEAR(next->GetPointData()->GetArray("HomogeneousWeight")->GetComponent(i, 0), 1.0, 1e-12);
  }
}
} // namespace

TEST(HomogenizedLoop, WeightOneIsVtkLoopSubdivision)
{
  auto sphere = lkvtk::fromTriangleMesh(lktest::icosphere(1, 3.0)); // valences 5 and 6
  auto cube = lkvtk::fromTriangleMesh(lktest::cube());                // valences 4 and 5
  auto tetra = lkvtk::fromTriangleMesh(lktest::icosphere(0, 1.0));
  compareWithVtk(sphere, 4, 3.0);
  compareWithVtk(cube, 4, 1.0);
  compareWithVtk(tetra, 4, 1.0);
}

TEST(HomogenizedLoop, WeightOneIsVtkLoopSubdivisionOnTheMandible)
{
  vtkSmartPointer<vtkPolyData> bone = lktest::tciaMandibleSurface();
  // Coordinates reach 1000 mm here, so one float ulp is 6e-5.
  double b[6];
  bone->GetBounds(b);
  double size = 0.0;
  for (int k = 0; k < 3; ++k)
    size = std::max({ size, std::abs(b[2 * k]), std::abs(b[2 * k + 1]) });
  compareWithVtk(bone, 2, size);
}

TEST(HomogenizedLoop, WeightsPullTheSurfaceMonotonically)
{
  const lk::TriangleMesh tm = lktest::icosphere(0, 1.0); // icosahedron
  const double ws[] = { 1.0, 2.0, 4.0, 6.0 };
  // Vertex 0.
  double last = 1e9;
  for (double w : ws)
  {
    auto mesh = lkvtk::fromTriangleMesh(tm);
    auto a = ones("LoopWeight", mesh->GetNumberOfPoints());
    a->SetValue(0, w);
    mesh->GetPointData()->AddArray(a);
    auto out = subdivide(mesh, 4);
    double p[3], q[3];
    mesh->GetPoint(0, p);
    out->GetPoint(0, q); // vertices keep their ids
    const double d = std::sqrt(vtkMath::Distance2BetweenPoints(p, q));
    std::printf("vertex weight %.0f: distance to the control vertex %.5f\n", w, d);
    EXPECT_LT(d, last);
    last = d;
  }
  // Edge (0, 11): a line cell with cell data LoopWeight.
  last = 1e9;
  for (double w : ws)
  {
    auto mesh = lkvtk::fromTriangleMesh(tm);
    vtkNew<vtkCellArray> lines;
    const vtkIdType e[2] = { 0, 11 };
    lines->InsertNextCell(2, e);
    mesh->SetLines(lines);
    auto cw = ones("LoopWeight", mesh->GetNumberOfCells());
    cw->SetValue(0, w); // lines come before polygons
    mesh->GetCellData()->AddArray(cw);
    auto out = subdivide(mesh, 4);
    double a[3], b[3], m[3];
    mesh->GetPoint(0, a);
    mesh->GetPoint(11, b);
    for (int k = 0; k < 3; ++k)
      m[k] = 0.5 * (a[k] + b[k]);
    const double d = nearest(out, m);
    std::printf("edge weight %.0f: distance to the edge midpoint %.5f\n", w, d);
    EXPECT_LT(d, last);
    last = d;
  }
  // Face 0.
  last = 1e9;
  for (double w : ws)
  {
    auto mesh = lkvtk::fromTriangleMesh(tm);
    auto cw = ones("LoopWeight", mesh->GetNumberOfCells());
    cw->SetValue(0, w);
    mesh->GetCellData()->AddArray(cw);
    auto out = subdivide(mesh, 4);
    double c[3] = { 0, 0, 0 };
    for (int i = 0; i < 3; ++i)
    {
      double p[3];
      mesh->GetPoint(tm.triangles[0][static_cast<std::size_t>(i)], p);
      for (int k = 0; k < 3; ++k)
        c[k] += p[k] / 3.0;
    }
    const double d = nearest(out, c);
    std::printf("face weight %.0f: distance to the face centroid %.5f\n", w, d);
    EXPECT_LT(d, last);
    last = d;
  }
}

TEST(HomogenizedLoop, HoleKeepsItsBoundaryOnTheBoundaryCurve)
{
  lk::TriangleMesh tm = lktest::icosphere(1, 1.0);
  const lk::Triangle removed = tm.triangles.back();
  tm.triangles.pop_back(); // a triangular hole
  auto mesh = lkvtk::fromTriangleMesh(tm);
  const int L = 3;
  auto out = subdivide(mesh, L);
  // The refined boundary polygon, walked from the hole's first corner.
  lk::TriangleMesh o = lktest::toCore(out);
  std::map<std::int64_t, std::int64_t> next;
  {
    std::map<std::pair<std::int64_t, std::int64_t>, int> directed;
    for (const auto& t : o.triangles)
      for (int i = 0; i < 3; ++i)
        directed[{ t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)] }] = 1;
    for (const auto& [e, one] : directed)
      if (!directed.count({ e.second, e.first }))
        next[e.second] = e.first; // the boundary walked against the faces
  }
  // The walk follows the removed face's own corner order.
  const std::int64_t P[3] = { removed[0], removed[1], removed[2] };
  ASSERT_EQ(next.size(), static_cast<std::size_t>(3 << L));
  std::vector<std::int64_t> polygon{ P[0] };
  while (polygon.size() < next.size())
    polygon.push_back(next[polygon.back()]);
  ASSERT_EQ(polygon[std::size_t(1) << L], P[1]) << "the refined boundary does not run through the hole's corners";
  auto ctrl = [&](int j) { return tm.points[static_cast<std::size_t>(P[((j % 3) + 3) % 3])]; };
  const std::size_t m = polygon.size();
  double worst = 0.0;
  for (std::size_t i = 0; i < m; ++i)
  {
    // Limit point of the refined polygon at i ...
    const lk::Vec3 limit = (o.points[static_cast<std::size_t>(polygon[(i + m - 1) % m])] +
                             4.0 * o.points[static_cast<std::size_t>(polygon[i])] +
                             o.points[static_cast<std::size_t>(polygon[(i + 1) % m])]) /
      6.0;
    // ... against the original boundary's cubic B-spline at t = i / 2^L.
    const int j = static_cast<int>(i >> L);
    const double u = static_cast<double>(i - (static_cast<std::size_t>(j) << L)) / static_cast<double>(1 << L);
    const lk::Vec3 curve = ((1 - u) * (1 - u) * (1 - u) * ctrl(j - 1) + (3 * u * u * u - 6 * u * u + 4) * ctrl(j) +
                             (-3 * u * u * u + 3 * u * u + 3 * u + 1) * ctrl(j + 1) + u * u * u * ctrl(j + 2)) /
      6.0;
    worst = std::max(worst, (limit - curve).norm());
  }
  EXPECT_LT(worst, 1e-12);
  // Face weights elsewhere leave the boundary alone.
  auto cw = ones("LoopWeight", mesh->GetNumberOfCells());
  cw->SetValue(0, 5.0);
  mesh->GetCellData()->AddArray(cw);
  auto weighted = subdivide(mesh, L);
  for (std::int64_t v : polygon)
  {
    double a[3], b[3];
    out->GetPoint(v, a);
    weighted->GetPoint(v, b);
    EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(a, b)), 1e-12);
  }
}

TEST(HomogenizedLoop, AttributesFollowTheRationalMasks)
{
  const lk::TriangleMesh tm = lktest::icosphere(1, 2.0);
  auto mesh = lkvtk::fromTriangleMesh(tm);
  vtkNew<vtkDoubleArray> x;
  x->SetName("X");
  auto w = ones("LoopWeight", mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    x->InsertNextValue(mesh->GetPoint(i)[0]);
    w->SetValue(i, 1.0 + (i % 4));
  }
  mesh->GetPointData()->AddArray(x);
  mesh->GetPointData()->AddArray(w);
  vtkNew<vtkIdTypeArray> id;
  id->SetName("FaceTag");
  for (vtkIdType c = 0; c < mesh->GetNumberOfPolys(); ++c)
    id->InsertNextValue(100 + c);
  mesh->GetCellData()->AddArray(id);
  auto out = subdivide(mesh, 2);
  vtkDataArray* ox = out->GetPointData()->GetArray("X");
  ASSERT_TRUE(ox);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    EXPECT_NEAR(ox->GetComponent(i, 0), out->GetPoint(i)[0], 1e-12);
  vtkDataArray* tag = out->GetCellData()->GetArray("FaceTag");
  vtkDataArray* origin = out->GetCellData()->GetArray("InputCellId");
  ASSERT_TRUE(tag && origin);
  EXPECT_EQ(out->GetNumberOfPolys(), 16 * mesh->GetNumberOfPolys());
  for (vtkIdType c = 0; c < out->GetNumberOfPolys(); ++c)
  {
    EXPECT_EQ(tag->GetComponent(c, 0), 100 + origin->GetComponent(c, 0));
    EXPECT_EQ(origin->GetComponent(c, 0), static_cast<double>(c / 16));
  }
}

TEST(HomogenizedLoop, BadWeightsAndMeshesAreClearErrors)
{
  auto check = [](vtkPolyData* mesh, const std::string& text) {
    vtkNew<vtkLKHomogenizedLoopFilter> f;
    f->SetInputData(mesh);
    lktest::ErrorRecorder errors(f);
    f->Update();
    EXPECT_EQ(errors.errors, 1) << text;
    EXPECT_NE(errors.messages.find(text), std::string::npos) << errors.messages;
    EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
  };
  for (double bad : { 0.0, -1.0, std::nan("") })
  {
    auto mesh = lkvtk::fromTriangleMesh(lktest::icosphere(0, 1.0));
    auto w = ones("LoopWeight", mesh->GetNumberOfPoints());
    w->SetValue(3, bad);
    mesh->GetPointData()->AddArray(w);
    check(mesh, "weights must be finite and above 0");
    auto mesh2 = lkvtk::fromTriangleMesh(lktest::icosphere(0, 1.0));
    auto cw = ones("LoopWeight", mesh2->GetNumberOfCells());
    cw->SetValue(5, bad);
    mesh2->GetCellData()->AddArray(cw);
    check(mesh2, "weights must be finite and above 0");
  }
  {
    auto mesh = lkvtk::fromTriangleMesh(lktest::icosphere(0, 1.0));
    vtkNew<vtkCellArray> lines;
    const vtkIdType e[2] = { 0, 3 }; // 0 and 3 are not neighbours on the icosahedron
    lines->InsertNextCell(2, e);
    mesh->SetLines(lines);
    auto cw = ones("LoopWeight", mesh->GetNumberOfCells());
    mesh->GetCellData()->AddArray(cw);
    check(mesh, "not an edge of the mesh");
  }
  {
    lk::TriangleMesh bow;
    bow.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { -1, 0, 0 }, { 0, -1, 0 }, { 0, 0, -1 } };
    bow.triangles = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 }, { 0, 4, 5 }, { 0, 6, 4 }, { 0, 5, 6 },
      { 4, 6, 5 } };
    check(lkvtk::fromTriangleMesh(bow), "manifold");
  }
  vtkNew<vtkPolyData> empty;
  check(empty, "Cannot subdivide");
  {
    // 327,680 triangles subdivided 6 times: 1.3 billion, about 175 GB. Refused
    // at once, not after minutes of work ending in std::bad_alloc. (A machine
    // with that much memory would make it.)
    vtkNew<vtkLKHomogenizedLoopFilter> f;
    f->SetInputData(lkvtk::fromTriangleMesh(lktest::icosphere(7, 1.0)));
    f->SetNumberOfSubdivisions(6);
    lktest::ErrorRecorder errors(f);
    f->Update();
    EXPECT_EQ(errors.errors, 1);
    EXPECT_NE(errors.messages.find("more than this machine's memory"), std::string::npos) << errors.messages;
    EXPECT_NE(errors.messages.find("1342177280 triangles"), std::string::npos) << errors.messages;
    EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
  }
}
