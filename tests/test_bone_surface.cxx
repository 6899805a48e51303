#include "DicomTestFiles.h"
#include "TestSupport.h"
#include "latticekit/ManifoldRepair.h"
#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKMeshRepairFilter.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDICOMCompiler.h>
#include <vtkDICOMItem.h>
#include <vtkDICOMMetaData.h>
#include <vtkDICOMSequence.h>
#include <vtkDICOMValue.h>
#include <vtkDataArray.h>
#include <vtkExtractVOI.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMassProperties.h>
#include <vtkMath.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>
#include <vtkStripper.h>
#include <vtksys/SystemTools.hxx>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <set>
#include <string>
#include <vector>

namespace
{
struct Surface
{
  vtkSmartPointer<vtkPolyData> mesh;
  int errors = 0;
  std::string messages;
};

Surface extract(const std::string& file, double iso, int mode = vtkLKBoneSurfaceFilter::LARGEST_COMPONENT,
  const double* seed = nullptr, int smoothing = -1, vtkMatrix4x4* matrix = nullptr)
{
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(file.c_str());
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  lktest::ErrorRecorder rec(bone);
  bone->SetInputConnection(reader->GetOutputPort());
  bone->SetIsoValue(iso);
  bone->SetExtractionMode(mode);
  bone->SetSmoothingIterations(smoothing);
  if (seed)
  {
    bone->SetSeedPoint(seed[0], seed[1], seed[2]);
  }
  if (matrix)
  {
    bone->SetPatientMatrix(matrix);
  }
  bone->Update();
  Surface s;
  s.mesh = vtkSmartPointer<vtkPolyData>::New();
  s.mesh->DeepCopy(bone->GetOutput());
  s.errors = rec.errors;
  s.messages = rec.messages;
  return s;
}

/// The surface's "SPACE" field data (3D Slicer's tag for its coordinate system), or "".
std::string spaceTag(vtkPolyData* pd)
{
  auto* tag = vtkStringArray::SafeDownCast(pd->GetFieldData()->GetAbstractArray("SPACE"));
  return tag && tag->GetNumberOfValues() == 1 ? tag->GetValue(0) : std::string();
}

std::size_t components(vtkPolyData* pd)
{
  vtkNew<vtkPolyDataConnectivityFilter> c;
  c->SetInputData(pd);
  c->SetExtractionModeToAllRegions();
  c->Update();
  return static_cast<std::size_t>(c->GetNumberOfExtractedRegions());
}

const std::string cthead = lktest::sampleData("cthead/cthead_hu_approx.nii.gz");
const std::string mandibles[2] = { lktest::sampleData("mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd"),
  lktest::sampleData("mandible-tcia/test_oncologist_TCGA-CV-7236_Mandible.nrrd") };
} // namespace

TEST(BoneSurface, CtHeadAt300HUIsAManifoldMeshThatCgalAccepts)
{
  const Surface s = extract(cthead, 300.0);
  ASSERT_EQ(s.errors, 0) << s.messages;
  const lk::TriangleMesh m = lktest::toCore(s.mesh);
  EXPECT_EQ(static_cast<vtkIdType>(m.triangles.size()), s.mesh->GetNumberOfCells()); // triangles only
  EXPECT_GT(m.triangles.size(), 500000u);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  EXPECT_EQ(components(s.mesh), 1u);
  // The skull reaches the volume's edge (cervical spine), so the surface is open there.
  const vtkDataArray* boundary = s.mesh->GetFieldData()->GetArray("BoundaryEdges");
  ASSERT_NE(boundary, nullptr);
  EXPECT_EQ(static_cast<std::size_t>(const_cast<vtkDataArray*>(boundary)->GetTuple1(0)),
    lk::countBoundaryEdges(m));
  // Outward: the enclosed volume (nearly closed) is positive.
  EXPECT_GT(lk::signedVolume(m), 0.0);
  // The NIfTI gives no orientation: the surface claims no coordinate system.
  EXPECT_EQ(s.mesh->GetFieldData()->GetAbstractArray("SPACE"), nullptr);
}

TEST(BoneSurface, TciaLabelMapsGiveClosedSinglePieceMandibles)
{
  for (const std::string& file : mandibles)
  {
    const Surface s = extract(file, 300.0); // label map detected: iso 0.5
    ASSERT_EQ(s.errors, 0) << s.messages;
    const lk::TriangleMesh m = lktest::toCore(s.mesh);
    EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "") << file;
    EXPECT_EQ(lk::countBoundaryEdges(m), 0u) << file;
    EXPECT_EQ(components(s.mesh), 1u) << file;
    EXPECT_GT(m.points.size(), 9000u) << file;
    EXPECT_LT(m.points.size(), 16000u) << file;
    // A mandible holds some tens of millilitres of bone.
    const double ml = lk::signedVolume(m) / 1000.0;
    EXPECT_GT(ml, 20.0) << file;
    EXPECT_LT(ml, 150.0) << file;
    // The NRRD's LPS axes: the surface says so (3D Slicer's tag), beside the repair's counts.
    EXPECT_EQ(spaceTag(s.mesh), "LPS") << file;
    EXPECT_NE(s.mesh->GetFieldData()->GetArray("BoundaryEdges"), nullptr) << file;
  }
}

TEST(BoneSurface, MirroringPatientMatrixKeepsTheSurfaceOutward)
{
  vtkNew<vtkMatrix4x4> mirror;
  mirror->SetElement(0, 0, -1.0);
  vtkNew<vtkMatrix4x4> identity;
  const Surface plain = extract(mandibles[1], 0.5, vtkLKBoneSurfaceFilter::LARGEST_COMPONENT, nullptr, 0, identity);
  const Surface s = extract(mandibles[1], 0.5, vtkLKBoneSurfaceFilter::LARGEST_COMPONENT, nullptr, 0, mirror);
  ASSERT_EQ(s.errors + plain.errors, 0) << s.messages;
  const lk::TriangleMesh m = lktest::toCore(s.mesh);
  EXPECT_NEAR(s.mesh->GetBounds()[0], -plain.mesh->GetBounds()[1], 1e-9); // really mirrored
  EXPECT_NEAR(lk::signedVolume(m), lk::signedVolume(lktest::toCore(plain.mesh)), 1e-6);
  EXPECT_GT(lk::signedVolume(m), 0.0);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  // A matrix of the user's own names no coordinate system, though the NRRD's
  // does: neither the reader's tag nor its matrix reaches the surface.
  for (const Surface* given : { &plain, &s })
  {
    EXPECT_EQ(spaceTag(given->mesh), "");
    EXPECT_EQ(given->mesh->GetFieldData()->GetAbstractArray("PatientMatrix"), nullptr);
    EXPECT_NE(given->mesh->GetFieldData()->GetArray("BoundaryEdges"), nullptr); // the repair's counts stay
  }
}

TEST(BoneSurface, SeedSelectsTheComponentUnderIt)
{
  // At 800 HU the CT head falls apart into many pieces.
  const Surface all = extract(cthead, 800.0, vtkLKBoneSurfaceFilter::ALL_COMPONENTS);
  const Surface largest = extract(cthead, 800.0, vtkLKBoneSurfaceFilter::LARGEST_COMPONENT);
  ASSERT_EQ(all.errors + largest.errors, 0);
  EXPECT_GT(components(all.mesh), 1u);
  EXPECT_LT(largest.mesh->GetNumberOfCells(), all.mesh->GetNumberOfCells());
  // A point of the largest piece picks the largest piece.
  double seed[3];
  largest.mesh->GetPoint(largest.mesh->GetNumberOfPoints() / 2, seed);
  const Surface picked = extract(cthead, 800.0, vtkLKBoneSurfaceFilter::SEEDED_COMPONENT, seed);
  EXPECT_EQ(picked.mesh->GetNumberOfCells(), largest.mesh->GetNumberOfCells());
  // A point of another piece picks that piece, which contains the seed.
  vtkNew<vtkPolyDataConnectivityFilter> regions;
  regions->SetInputData(all.mesh);
  regions->SetExtractionModeToSpecifiedRegions();
  regions->ColorRegionsOn();
  regions->InitializeSpecifiedRegionList();
  regions->AddSpecifiedRegion(1);
  regions->Update();
  vtkNew<vtkPolyData> other;
  other->DeepCopy(regions->GetOutput());
  double otherSeed[3] = { 0, 0, 0 };
  for (vtkIdType c = 0; c < other->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    other->GetCellPoints(c, n, ids);
    other->GetPoint(ids[0], otherSeed);
    break;
  }
  const Surface second = extract(cthead, 800.0, vtkLKBoneSurfaceFilter::SEEDED_COMPONENT, otherSeed);
  ASSERT_EQ(second.errors, 0);
  EXPECT_LT(second.mesh->GetNumberOfCells(), largest.mesh->GetNumberOfCells());
  double closest = 1e300;
  for (vtkIdType i = 0; i < second.mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    second.mesh->GetPoint(i, p);
    closest = std::min(closest, std::hypot(p[0] - otherSeed[0], p[1] - otherSeed[1], p[2] - otherSeed[2]));
  }
  EXPECT_LT(closest, 1e-6);
}

TEST(BoneSurface, SmoothingMovesPointsButKeepsTopology)
{
  const Surface raw = extract(mandibles[0], 0.5, vtkLKBoneSurfaceFilter::LARGEST_COMPONENT, nullptr, 0);
  const Surface smooth = extract(mandibles[0], 0.5, vtkLKBoneSurfaceFilter::LARGEST_COMPONENT, nullptr, 20);
  const Surface byDefault = extract(mandibles[0], 0.5); // a label map's: 20 iterations
  ASSERT_EQ(byDefault.mesh->GetNumberOfPoints(), smooth.mesh->GetNumberOfPoints());
  double p[3], q[3];
  byDefault.mesh->GetPoint(byDefault.mesh->GetNumberOfPoints() / 2, p);
  smooth.mesh->GetPoint(smooth.mesh->GetNumberOfPoints() / 2, q);
  EXPECT_EQ(std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]), 0.0);
  ASSERT_EQ(raw.mesh->GetNumberOfPoints(), smooth.mesh->GetNumberOfPoints());
  ASSERT_EQ(raw.mesh->GetNumberOfCells(), smooth.mesh->GetNumberOfCells());
  double moved = 0.0;
  for (vtkIdType i = 0; i < raw.mesh->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    raw.mesh->GetPoint(i, a);
    smooth.mesh->GetPoint(i, b);
    moved = std::max(moved, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
  }
  EXPECT_GT(moved, 1e-3);
  EXPECT_LT(moved, 2.0); // light: well under a voxel-diagonal or two
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(lktest::toCore(smooth.mesh)), "");
}

TEST(BoneSurface, FilledCavitiesLeaveTheOuterSkin)
{
  // The CT head's skin at -400 HU, cropped in front of the head rest as in
  // bench_fit. The sinuses, the airway and the mouth join it through the
  // nostrils and lips: Euler characteristic -507. Filled, about genus 11.
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(cthead.c_str());
  reader->Update();
  int e[6];
  reader->GetOutput()->GetExtent(e);
  e[3] = std::min(e[3], 226);
  vtkNew<vtkExtractVOI> crop;
  crop->SetInputConnection(reader->GetOutputPort());
  crop->SetVOI(e);
  long long chi[2] = { 0, 0 };
  double volume[2] = { 0.0, 0.0 };
  for (const bool fill : { false, true })
  {
    vtkNew<vtkLKBoneSurfaceFilter> skin;
    lktest::ErrorRecorder rec(skin);
    skin->SetInputConnection(crop->GetOutputPort());
    skin->SetIsoValue(-400.0);
    skin->SetLabelMapMode(vtkLKBoneSurfaceFilter::LABEL_MAP_OFF);
    skin->SetFillCavities(fill);
    skin->Update();
    ASSERT_EQ(rec.errors, 0) << rec.messages;
    const lk::TriangleMesh m = lktest::toCore(skin->GetOutput());
    EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
    EXPECT_EQ(components(skin->GetOutput()), 1u);
    std::set<std::pair<std::int64_t, std::int64_t>> edges;
    for (const auto& t : m.triangles)
      for (int i = 0; i < 3; ++i)
        edges.insert(std::minmax(t[i], t[(i + 1) % 3]));
    chi[fill] = static_cast<long long>(m.points.size()) - static_cast<long long>(edges.size()) +
      static_cast<long long>(m.triangles.size());
    volume[fill] = lk::signedVolume(m);
  }
  EXPECT_LT(chi[0], -400);
  EXPECT_GT(chi[1], -50);
  // Filling adds the cavities to the enclosed volume and moves no outer voxel.
  EXPECT_GT(volume[1], volume[0]);
}

TEST(BoneSurface, TheCropBoxIsInPatientCoordinatesAndTheCutIsClosed)
{
  // The TCIA mandible's volume has its origin at (-250.4, 155.6, -1178) mm
  // (LPS): a box in patient coordinates around its left half (x 0 to 70 mm)
  // keeps that half, closed where the box cuts it (the padding is air).
  auto crop = [](const double box[6]) {
    vtkNew<vtkLKMedicalImageReader> reader;
    reader->SetFileName(mandibles[0].c_str());
    vtkNew<vtkLKBoneSurfaceFilter> bone;
    bone->SetInputConnection(reader->GetOutputPort());
    bone->CroppingOn();
    bone->SetCropBox(box);
    Surface s;
    lktest::ErrorRecorder rec(bone);
    bone->Update();
    s.mesh = vtkSmartPointer<vtkPolyData>::New();
    s.mesh->DeepCopy(bone->GetOutput());
    s.errors = rec.errors;
    s.messages = rec.messages;
    return s;
  };
  const double half[6] = { 0, 70, 250, 360, -1000, -900 };
  const Surface s = crop(half);
  ASSERT_EQ(s.errors, 0) << s.messages;
  EXPECT_EQ(spaceTag(s.mesh), "LPS"); // the crop's padded volume has no field data of its own
  const Surface whole = extract(mandibles[0], 0.5);
  double b[6];
  s.mesh->GetBounds(b);
  EXPECT_GT(b[0], -2.0); // within two voxels (0.98 mm): the box rounded out to voxels, and the padding
  EXPECT_LT(b[1], 60.0); // the bone ends at x = 59 mm
  EXPECT_LT(whole.mesh->GetBounds()[0], -50.0);
  const lk::TriangleMesh m = lktest::toCore(s.mesh);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  EXPECT_EQ(lk::countBoundaryEdges(m), 0u); // closed at the cut
  EXPECT_GT(lk::signedVolume(m), 0.3 * lk::signedVolume(lktest::toCore(whole.mesh)));
  EXPECT_LT(lk::signedVolume(m), 0.7 * lk::signedVolume(lktest::toCore(whole.mesh)));

  // A box beside the volume, one whose voxel indices would overflow an int,
  // an inverted one, and one that holds only air.
  const double beside[6] = { 0, 70, 250, 360, 0, 100 }, far[6] = { 1e300, 2e300, 0, 1, 0, 1 },
               inverted[6] = { 70, 0, 250, 360, -1000, -900 }, air[6] = { 0, 70, 250, 360, -1170, -1100 };
  EXPECT_NE(crop(beside).messages.find("the crop box misses the volume"), std::string::npos);
  EXPECT_NE(crop(far).messages.find("the crop box misses the volume"), std::string::npos);
  EXPECT_NE(crop(inverted).messages.find("each min below its max"), std::string::npos);
  const Surface empty = crop(air);
  EXPECT_NE(empty.messages.find("within the crop box"), std::string::npos) << empty.messages;
  EXPECT_EQ(empty.mesh->GetNumberOfPoints(), 0);
}

TEST(BoneSurface, CloseAtBorderClosesBoneThatTheScansBorderCuts)
{
  // A rod of bone (1000 HU, radius 6 voxels of 1 mm) through every slice of
  // a 24 x 24 x 10 volume of soft tissue (0 HU): an open tube without
  // CloseAtBorder, a closed rod with it, capped half a voxel beyond the last
  // slices (the iso value 500 lies half-way to the padding's 0 HU).
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(24, 24, 10);
  volume->AllocateScalars(VTK_SHORT, 1);
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 24; ++j)
      for (int i = 0; i < 24; ++i)
        volume->SetScalarComponentFromDouble(
          i, j, k, 0, (i - 11.5) * (i - 11.5) + (j - 11.5) * (j - 11.5) <= 36.0 ? 1000.0 : 0.0);
  auto rod = [&](bool close) {
    vtkNew<vtkLKBoneSurfaceFilter> bone;
    bone->SetInputData(volume);
    bone->SetIsoValue(500.0);
    bone->SetCloseAtBorder(close);
    lktest::ErrorRecorder rec(bone);
    bone->Update();
    EXPECT_EQ(rec.errors, 0) << rec.messages;
    return lktest::toCore(bone->GetOutput());
  };
  const lk::TriangleMesh open = rod(false), closed = rod(true);
  EXPECT_GT(lk::countBoundaryEdges(open), 40u); // two rims
  EXPECT_EQ(lk::countBoundaryEdges(closed), 0u);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(closed), "");
  double zmin = 1e9, zmax = -1e9;
  for (const auto& p : closed.points)
  {
    zmin = std::min(zmin, p.z());
    zmax = std::max(zmax, p.z());
  }
  EXPECT_NEAR(zmin, -0.5, 1e-6);
  EXPECT_NEAR(zmax, 9.5, 1e-6);
  // The rod's volume: its section (the 112 voxels within radius 6, less the
  // corners the iso line cuts: about pi 6^2) times its length of 10 mm.
  const double expected = 3.14159265358979 * 6.0 * 6.0 * 10.0;
  EXPECT_NEAR(lk::signedVolume(closed), expected, 0.05 * expected);

  // The bundled head CT: its cervical spine reaches the last slice. Closed
  // there, the skull is one closed, CGAL-valid surface no larger than the
  // volume plus the half voxel of the cap.
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(cthead.c_str());
  vtkNew<vtkLKBoneSurfaceFilter> head;
  head->SetInputConnection(reader->GetOutputPort());
  head->CloseAtBorderOn();
  lktest::ErrorRecorder rec(head);
  head->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  const lk::TriangleMesh skull = lktest::toCore(head->GetOutput());
  EXPECT_EQ(lk::countBoundaryEdges(skull), 0u);
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(skull), "");
  EXPECT_EQ(components(head->GetOutput()), 1u);
  EXPECT_GT(lk::signedVolume(skull), 0.0);
  double vb[6], sb[6];
  reader->GetOutput()->GetBounds(vb);
  head->GetOutput()->GetBounds(sb);
  for (int c = 0; c < 3; ++c)
  {
    const double spacing = reader->GetOutput()->GetSpacing()[c];
    EXPECT_GE(sb[2 * c], vb[2 * c] - 0.5 * spacing - 1e-6);
    EXPECT_LE(sb[2 * c + 1], vb[2 * c + 1] + 0.5 * spacing + 1e-6);
  }
}

TEST(BoneSurface, CavitiesAreFilledInACropBoxAndWithTheBorderClosed)
{
  // A hollow cube of bone (1000 HU, walls 3 voxels thick, 6 x 6 x 6 voxels of
  // air inside) in soft tissue (0 HU), touching the volume's border at x = 0.
  // FillCavities takes the air inside, within a crop box and with the border
  // closed too (the flood fill took the uncropped volume's size, and both
  // stopped the program).
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(20, 20, 20);
  volume->AllocateScalars(VTK_SHORT, 1);
  for (int k = 0; k < 20; ++k)
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i)
      {
        const bool block = i <= 11 && j >= 3 && j <= 14 && k >= 3 && k <= 14;
        const bool cavity = i >= 3 && i <= 8 && j >= 6 && j <= 11 && k >= 6 && k <= 11;
        volume->SetScalarComponentFromDouble(i, j, k, 0, block && !cavity ? 1000.0 : 0.0);
      }
  auto surface = [&](bool crop, bool close, bool fill, int* errors) {
    vtkNew<vtkLKBoneSurfaceFilter> bone;
    bone->SetInputData(volume);
    bone->SetIsoValue(500.0);
    bone->SetCropping(crop);
    const double box[6] = { 0.0, 16.0, 1.0, 17.0, 1.0, 17.0 };
    bone->SetCropBox(box);
    bone->SetCloseAtBorder(close);
    bone->SetFillCavities(fill);
    bone->SetExtractionModeToAllComponents();
    lktest::ErrorRecorder rec(bone);
    bone->Update();
    *errors = rec.errors;
    return lktest::toCore(bone->GetOutput());
  };
  for (const bool crop : { true, false })
  {
    SCOPED_TRACE(crop ? "in a crop box" : "with the border closed");
    int errors = 0;
    const lk::TriangleMesh hollow = surface(crop, !crop, false, &errors);
    ASSERT_EQ(errors, 0);
    const lk::TriangleMesh filled = surface(crop, !crop, true, &errors);
    ASSERT_EQ(errors, 0);
    EXPECT_EQ(lk::countBoundaryEdges(filled), 0u);
    EXPECT_EQ(lk::cgalSurfaceMeshProblem(filled), "");
    // Filled: the block alone, 12 x 12 x 12 voxels, its border half a
    // voxel beyond its last voxels where it meets the padding (x = -0.5)
    // and about that elsewhere; hollow: less the cavity's 6^3.
    EXPECT_NEAR(lk::signedVolume(filled), 12.0 * 12.0 * 12.0, 0.05 * 1728.0);
    EXPECT_NEAR(lk::signedVolume(hollow), 1728.0 - 216.0, 0.06 * 1728.0);
    EXPECT_LT(filled.points.size(), hollow.points.size());
  }
}

TEST(BoneSurface, ALabelMapsSurfaceDoesNotDependOnTheEmptyGridAroundIt)
{
  // The filter smooths and contours only a label map's content and a margin
  // of background. The same ball of label in a 50^3 grid (background more
  // than twice the Gaussian's reach round it) and in a 130^3 grid, its origin
  // moved so that the ball's voxels lie at the same points, gives the same
  // surface point for point (to the float points' rounding); and so does a
  // ball cut by the grid's low x edge with the grid larger on its other sides
  // only.
  auto ball = [](int n, int offset, double cx, double sigma) {
    vtkNew<vtkImageData> volume;
    volume->SetDimensions(n, n, n);
    volume->SetOrigin(-offset * 1.5, -offset * 1.0, -offset * 2.5);
    volume->SetSpacing(1.5, 1.0, 2.5);
    volume->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
    auto* v = static_cast<unsigned char*>(volume->GetScalarPointer());
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
          const double x = i - offset - cx, y = j - offset - 24.5, z = k - offset - 24.5;
          *v++ = x * x + 0.8 * y * y + 1.3 * z * z <= 64.0;
        }
    vtkNew<vtkLKBoneSurfaceFilter> bone;
    bone->SetInputData(volume);
    bone->SetImageSmoothing(sigma);
    bone->SetExtractionModeToAllComponents();
    lktest::ErrorRecorder rec(bone);
    bone->Update();
    EXPECT_EQ(rec.errors, 0) << rec.messages;
    EXPECT_TRUE(bone->GetTreatedAsLabelMap());
    vtkSmartPointer<vtkPolyData> out = vtkSmartPointer<vtkPolyData>::New();
    out->DeepCopy(bone->GetOutput());
    return out;
  };
  auto expectSame = [](vtkPolyData* a, vtkPolyData* b) {
    ASSERT_GT(a->GetNumberOfPoints(), 100);
    ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
    ASSERT_EQ(a->GetNumberOfPolys(), b->GetNumberOfPolys());
    double largest = 0.0;
    for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
      largest = std::max(largest, std::sqrt(vtkMath::Distance2BetweenPoints(a->GetPoint(i), b->GetPoint(i))));
    EXPECT_LT(largest, 1e-4); // the points are floats: 36 mm from another origin rounds at 1.5e-5
    vtkDataArray* ca = a->GetPolys()->GetConnectivityArray();
    vtkDataArray* cb = b->GetPolys()->GetConnectivityArray();
    vtkIdType differ = 0;
    for (vtkIdType i = 0; i < ca->GetNumberOfValues(); ++i)
      differ += ca->GetComponent(i, 0) != cb->GetComponent(i, 0);
    EXPECT_EQ(differ, 0);
  };
  for (const double sigma : { 1.0, 2.5, 0.0 })
  {
    SCOPED_TRACE("sigma " + std::to_string(sigma));
    expectSame(ball(50, 0, 24.5, sigma), ball(130, 40, 24.5, sigma));
    expectSame(ball(50, 0, 5.0, sigma), ball(130, 0, 5.0, sigma));
  }
}

TEST(BoneSurface, IsoValueOutsideTheDataRangeIsAClearError)
{
  const Surface s = extract(cthead, 5000.0);
  EXPECT_EQ(s.errors, 1);
  EXPECT_NE(s.messages.find("outside the volume's range"), std::string::npos) << s.messages;
  EXPECT_EQ(s.messages.find("same value"), std::string::npos) << s.messages;
  EXPECT_EQ(s.mesh->GetNumberOfCells(), 0);

  // A volume of one value (air everywhere: a series whose compressed pixel
  // data decoded to nothing) says so, beside the range.
  vtkNew<vtkImageData> blank;
  blank->SetDimensions(8, 8, 8);
  blank->AllocateScalars(VTK_SHORT, 1);
  blank->GetPointData()->GetScalars()->Fill(-1024);
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  lktest::ErrorRecorder rec(bone);
  bone->SetInputData(blank);
  bone->Update();
  EXPECT_EQ(rec.errors, 1);
  EXPECT_NE(rec.messages.find("range [-1024, -1024]: no surface. Every voxel holds the same value: the scan is "
                              "blank, or its pixel data could not be decoded"),
    std::string::npos)
    << rec.messages;
}

// A segmentation with several labels (3D Slicer saves one label per
// segment): the mandible's label map with its right half (voxel i < 256)
// relabelled 2. Each label is a closed surface of its own, and the two
// halves' volumes make up the whole.
TEST(BoneSurface, LabelTakesOneLabelOfASegmentationWithSeveral)
{
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(mandibles[0].c_str());
  reader->Update();
  vtkNew<vtkImageData> labels;
  labels->DeepCopy(reader->GetOutput());
  int dims[3];
  labels->GetDimensions(dims);
  vtkDataArray* v = labels->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < v->GetNumberOfTuples(); ++i)
    if (v->GetTuple1(i) == 1.0 && i % dims[0] < dims[0] / 2)
      v->SetTuple1(i, 2.0);
  auto surface = [&](int label, Surface& out) {
    vtkNew<vtkLKBoneSurfaceFilter> bone;
    lktest::ErrorRecorder rec(bone);
    bone->SetInputData(labels);
    bone->SetLabel(label);
    bone->Update();
    out.mesh = vtkSmartPointer<vtkPolyData>::New();
    out.mesh->DeepCopy(bone->GetOutput());
    out.errors = rec.errors;
    out.messages = rec.messages;
    return bone->GetTreatedAsLabelMap();
  };
  auto volume = [](vtkPolyData* pd) {
    vtkNew<vtkMassProperties> mass;
    mass->SetInputData(pd);
    mass->Update();
    return mass->GetVolume();
  };
  const Surface whole = extract(mandibles[0], 0.5);
  Surface one, two;
  EXPECT_TRUE(surface(1, one));
  EXPECT_TRUE(surface(2, two));
  ASSERT_EQ(one.errors + two.errors, 0) << one.messages << two.messages;
  for (const Surface* half : { &one, &two })
  {
    EXPECT_EQ(components(half->mesh), 1u);
    EXPECT_EQ(lk::countBoundaryEdges(lktest::toCore(half->mesh)), 0u);
    EXPECT_EQ(spaceTag(half->mesh), "LPS"); // the reader's matrix and tag come through
    EXPECT_GT(volume(half->mesh), 0.3 * volume(whole.mesh));
  }
  // The halves do not overlap: one lies left of the other in patient x.
  double b1[6], b2[6];
  one.mesh->GetBounds(b1);
  two.mesh->GetBounds(b2);
  EXPECT_TRUE(b1[1] <= b2[0] + 2.0 || b2[1] <= b1[0] + 2.0) << b1[0] << " " << b1[1] << " / " << b2[0] << " " << b2[1];
  EXPECT_NEAR(volume(one.mesh) + volume(two.mesh), volume(whole.mesh), 0.02 * volume(whole.mesh));

  // Without a label the iso value (300) misses the values 0, 1, 2; the
  // error says how to take one.
  Surface none;
  surface(0, none);
  EXPECT_EQ(none.errors, 1);
  EXPECT_NE(none.messages.find("The volume holds only the values 0, 1, 2: if it is a label map with several labels, "
                               "Label (--label N) takes one of them."),
    std::string::npos)
    << none.messages;
  // A label that is not there, or a volume that is not of integers.
  Surface missing;
  surface(3, missing);
  EXPECT_EQ(missing.errors, 1);
  EXPECT_NE(missing.messages.find("No voxel holds label 3; the volume's values are 0, 1, 2."), std::string::npos)
    << missing.messages;
  vtkNew<vtkImageData> ct;
  ct->SetDimensions(8, 8, 8);
  ct->AllocateScalars(VTK_FLOAT, 1);
  ct->GetPointData()->GetScalars()->Fill(1.0);
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  lktest::ErrorRecorder rec(bone);
  bone->SetInputData(ct);
  bone->SetLabel(1);
  bone->Update();
  EXPECT_EQ(rec.errors, 1);
  EXPECT_NE(rec.messages.find("Label 1 needs a label map of integers; this volume holds float values."),
    std::string::npos)
    << rec.messages;
}

namespace
{
// The balls of scripts/make_label_test_data.py (40 x 30 x 30 voxels of
// 1 x 1 x 2 mm from (-20, -15, -30)) as a DICOM SEG, as segmentation tools
// write one: a frame per segment and slice where the segment is, placed by
// its own position, frames of the segments interleaved. BINARY frames are
// bit-packed; FRACTIONAL ones hold 255 inside and, as a trap, 100 (below
// half) in a shell around it.
struct SegSegment
{
  int number;
  const char* name;
  std::function<bool(int, int, int)> inside; // at x, y, z (mm)
};

enum class SegType
{
  Binary,
  Fractional,
  LabelMap // one frame per slice, each pixel the number of its segment
};

std::string writeSeg(const std::string& name, const std::vector<SegSegment>& segments, SegType type,
  int claimedSegment = 0, double spacingBetweenSlices = 2.0, const std::string& referencedSeries = std::string())
{
  const bool fractional = type == SegType::Fractional, labelMap = type == SegType::LabelMap;
  const int NX = 40, NY = 30, NZ = 30;
  const std::string dir = std::string(LATTICEKIT_TEST_TMP) + "/" + name;
  vtksys::SystemTools::RemoveADirectory(dir);
  vtksys::SystemTools::MakeDirectory(dir);
  vtkNew<vtkDICOMMetaData> meta;
  meta->Set(DC::SOPClassUID, "1.2.840.10008.5.1.4.1.1.66.4"); // Segmentation Storage
  meta->Set(DC::Modality, "SEG");
  meta->Set(DC::PatientID, "seg");
  meta->Set(DC::SeriesNumber, 100.0);
  meta->Set(DC::InstanceNumber, 1.0);
  meta->Set(DC::ImageType, "DERIVED\\PRIMARY");
  meta->Set(DC::Rows, static_cast<double>(NY));
  meta->Set(DC::Columns, static_cast<double>(NX));
  meta->Set(DC::SamplesPerPixel, 1.0);
  meta->Set(DC::PhotometricInterpretation, "MONOCHROME2");
  meta->Set(DC::BitsAllocated, fractional || labelMap ? 8.0 : 1.0);
  meta->Set(DC::BitsStored, fractional || labelMap ? 8.0 : 1.0);
  meta->Set(DC::HighBit, fractional || labelMap ? 7.0 : 0.0);
  meta->Set(DC::PixelRepresentation, 0.0);
  meta->Set(DC::SegmentationType, fractional ? "FRACTIONAL" : labelMap ? "LABELMAP" : "BINARY");
  if (fractional)
  {
    meta->Set(DC::SegmentationFractionalType, "OCCUPANCY");
    meta->Set(DC::MaximumFractionalValue, 255.0);
  }
  vtkDICOMSequence list;
  for (const SegSegment& seg : segments)
  {
    vtkDICOMItem item;
    item.Set(DC::SegmentNumber, static_cast<double>(seg.number));
    item.Set(DC::SegmentLabel, seg.name);
    item.Set(DC::SegmentAlgorithmType, "MANUAL");
    list.AddItem(item);
  }
  meta->Set(DC::SegmentSequence, list);
  if (!referencedSeries.empty()) // the CT it was drawn on
  {
    vtkDICOMItem series;
    series.Set(DC::SeriesInstanceUID, referencedSeries);
    meta->Set(DC::ReferencedSeriesSequence, vtkDICOMSequence(series));
  }
  vtkDICOMItem measures, plane, shared;
  measures.Set(DC::PixelSpacing, "1\\1");
  measures.Set(DC::SliceThickness, 2.0);
  measures.Set(DC::SpacingBetweenSlices, spacingBetweenSlices);
  plane.Set(DC::ImageOrientationPatient, "1\\0\\0\\0\\1\\0");
  shared.Set(DC::PixelMeasuresSequence, vtkDICOMSequence(measures));
  shared.Set(DC::PlaneOrientationSequence, vtkDICOMSequence(plane));
  meta->Set(DC::SharedFunctionalGroupsSequence, vtkDICOMSequence(shared));
  vtkDICOMSequence perFrame;
  std::vector<std::vector<unsigned char>> frames;
  for (int k = 0; k < NZ && labelMap; ++k)
  {
    std::vector<unsigned char> frame(NX * NY, 0);
    for (int j = 0; j < NY; ++j)
      for (int i = 0; i < NX; ++i)
        for (const SegSegment& seg : segments)
          if (seg.inside(-20 + i, -15 + j, -30 + 2 * k))
            frame[static_cast<std::size_t>(j * NX + i)] = static_cast<unsigned char>(seg.number);
    if (std::all_of(frame.begin(), frame.end(), [](unsigned char v) { return v == 0; }))
      continue;
    frames.push_back(frame);
    vtkDICOMItem position, item;
    position.Set(DC::ImagePositionPatient, "-20\\-15\\" + std::to_string(-30 + 2 * k));
    item.Set(DC::PlanePositionSequence, vtkDICOMSequence(position));
    perFrame.AddItem(item);
  }
  for (int k = 0; k < NZ && !labelMap; ++k)
    for (const SegSegment& seg : segments)
    {
      std::vector<unsigned char> frame(fractional ? NX * NY : NX * NY / 8, 0);
      bool any = false;
      for (int j = 0; j < NY; ++j)
        for (int i = 0; i < NX; ++i)
        {
          const int x = -20 + i, y = -15 + j, z = -30 + 2 * k, n = j * NX + i;
          const bool in = seg.inside(x, y, z);
          any = any || in;
          if (fractional)
            frame[static_cast<std::size_t>(n)] = in ? 255 : (seg.inside(x + 1, y, z) || seg.inside(x - 1, y, z)) ? 100 : 0;
          else if (in)
            frame[static_cast<std::size_t>(n / 8)] |= static_cast<unsigned char>(1 << (n % 8));
        }
      if (!any)
        continue;
      frames.push_back(frame);
      vtkDICOMItem position, ident, item;
      position.Set(DC::ImagePositionPatient, "-20\\-15\\" + std::to_string(-30 + 2 * k));
      ident.Set(DC::ReferencedSegmentNumber, static_cast<double>(claimedSegment ? claimedSegment : seg.number));
      item.Set(DC::PlanePositionSequence, vtkDICOMSequence(position));
      item.Set(DC::SegmentIdentificationSequence, vtkDICOMSequence(ident));
      perFrame.AddItem(item);
    }
  meta->Set(DC::NumberOfFrames, static_cast<double>(frames.size()));
  meta->Set(DC::PerFrameFunctionalGroupsSequence, perFrame);
  meta->Set(DC::PixelData, vtkDICOMValue(vtkDICOMVR::OB));
  vtkNew<vtkDICOMCompiler> compiler;
  compiler->SetFileName((dir + "/seg.dcm").c_str());
  compiler->SetMetaData(meta);
  compiler->WriteHeader();
  for (const auto& frame : frames)
    compiler->WriteFrame(frame.data(), static_cast<vtkIdType>(frame.size()));
  compiler->Close();
  EXPECT_EQ(compiler->GetErrorCode(), 0u);
  return dir + "/seg.dcm";
}

bool mandibleBall(int x, int y, int z)
{
  return (x + 9) * (x + 9) + y * y + z * z < 64;
}
bool maxillaBall(int x, int y, int z)
{
  return (x - 9) * (x - 9) + y * y + z * z < 49;
}
bool tumourBall(int x, int y, int z)
{
  return (x + 1) * (x + 1) + y * y + z * z < 36;
}

/// The surface of one segment (by name, or by number when name is null).
Surface segmentSurface(const std::string& file, const char* name, int label = 0, int* effective = nullptr)
{
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(file.c_str());
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  lktest::ErrorRecorder rec(bone);
  bone->SetInputConnection(reader->GetOutputPort());
  bone->SetLabelName(name);
  bone->SetLabel(label);
  bone->Update();
  Surface s;
  s.mesh = vtkSmartPointer<vtkPolyData>::New();
  s.mesh->DeepCopy(bone->GetOutput());
  s.errors = rec.errors;
  s.messages = rec.messages;
  if (effective)
    *effective = bone->GetEffectiveLabel();
  return s;
}

double volumeOf(vtkPolyData* pd)
{
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(pd);
  mass->Update();
  return mass->GetVolume();
}

/// The same segment's surfaces from two files: the same place and size.
void expectSameSurface(const Surface& a, const Surface& b, const std::string& what)
{
  ASSERT_EQ(a.errors + b.errors, 0) << what << ": " << a.messages << b.messages;
  ASSERT_GT(a.mesh->GetNumberOfPoints(), 100) << what;
  double ba[6], bb[6];
  a.mesh->GetBounds(ba);
  b.mesh->GetBounds(bb);
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(ba[i], bb[i], 0.3) << what << " bound " << i;
  EXPECT_NEAR(volumeOf(a.mesh), volumeOf(b.mesh), 0.01 * volumeOf(b.mesh)) << what;
  EXPECT_EQ(lk::countBoundaryEdges(lktest::toCore(a.mesh)), 0u) << what;
}
} // namespace

// 3D Slicer's .seg.nrrd names its segments in the header; LabelName takes
// one by its name (as written, else ignoring case), and the errors list them.
TEST(BoneSurface, LabelNameTakesASegmentOfASlicerSegmentation)
{
  const std::string file = std::string(LATTICEKIT_TEST_DATA) + "/two_segments.seg.nrrd";
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  auto* names = vtkStringArray::SafeDownCast(reader->GetOutput()->GetFieldData()->GetAbstractArray("SegmentNames"));
  vtkDataArray* values = reader->GetOutput()->GetFieldData()->GetArray("SegmentLabelValues");
  ASSERT_TRUE(names && values);
  ASSERT_EQ(names->GetNumberOfValues(), 2);
  EXPECT_EQ(names->GetValue(0), "left condyle");
  EXPECT_EQ(names->GetValue(1), "Right Condyle");
  EXPECT_EQ(values->GetComponent(1, 0), 2.0);

  auto run = [&](const char* name, int label, Surface& out) {
    int effective = 0;
    out = segmentSurface(file, name, label, &effective);
    return effective;
  };
  Surface byValue, byName, byOtherCase;
  EXPECT_EQ(run(nullptr, 2, byValue), 2);
  EXPECT_EQ(run("Right Condyle", 0, byName), 2);
  EXPECT_EQ(run("right condyle", 1, byOtherCase), 2); // the name wins over Label
  ASSERT_EQ(byValue.errors + byName.errors + byOtherCase.errors, 0) << byName.messages << byOtherCase.messages;
  EXPECT_EQ(byName.mesh->GetNumberOfPoints(), byValue.mesh->GetNumberOfPoints());
  EXPECT_EQ(byOtherCase.mesh->GetNumberOfPoints(), byValue.mesh->GetNumberOfPoints());
  double b[6];
  byName.mesh->GetBounds(b);
  EXPECT_GT(b[0], 0.0); // the ball at x = +9, not the one at -9

  Surface missing, none;
  run("maxilla", 0, missing);
  EXPECT_EQ(missing.errors, 1);
  EXPECT_NE(missing.messages.find("No segment is named 'maxilla'; its segments are 1 'left condyle', 2 'Right "
                                  "Condyle'."),
    std::string::npos)
    << missing.messages;
  run(nullptr, 0, none); // the threshold misses: the hint names the segments
  EXPECT_NE(none.messages.find("The volume holds only the values 0, 1, 2 (segments: 1 'left condyle', 2 'Right "
                               "Condyle'): if it is a label map"),
    std::string::npos)
    << none.messages;
  // A label map that names no segments.
  vtkNew<vtkLKBoneSurfaceFilter> plain;
  lktest::ErrorRecorder rec(plain);
  vtkNew<vtkLKMedicalImageReader> mha;
  mha->SetFileName((std::string(LATTICEKIT_TEST_DATA) + "/two_labels.mha").c_str());
  plain->SetInputConnection(mha->GetOutputPort());
  plain->SetLabelName("mandible");
  plain->Update();
  EXPECT_NE(rec.messages.find("No segment is named 'mandible'; the volume names no segments (a 3D Slicer .seg.nrrd, "
                              "a DICOM SEG or an RT structure set does)."),
    std::string::npos)
    << rec.messages;
}

// A segmentation whose segments overlap: 3D Slicer saves it in layers (a
// 4D NRRD), each layer numbering its segments from 1. The reader keeps a
// component per layer; a segment is taken by its name, or by a label value
// only one segment has, whole (the overlap stays in both).
TEST(BoneSurface, OverlappingSegmentsAreTakenFromTheirLayers)
{
  const std::string file = std::string(LATTICEKIT_TEST_DATA) + "/overlapping_segments.seg.nrrd";
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder readErrors(reader);
  reader->SetFileName(file.c_str());
  reader->Update();
  ASSERT_EQ(readErrors.errors, 0) << readErrors.messages;
  vtkImageData* volume = reader->GetOutput();
  ASSERT_EQ(volume->GetNumberOfScalarComponents(), 2);
  vtkDataArray* layers = volume->GetFieldData()->GetArray("SegmentLayers");
  ASSERT_TRUE(layers);
  ASSERT_EQ(layers->GetNumberOfTuples(), 3);
  EXPECT_EQ(layers->GetComponent(0, 0), 0.0);
  EXPECT_EQ(layers->GetComponent(2, 0), 1.0);

  auto run = [&](const char* name, int label, Surface& out) { out = segmentSurface(file, name, label); };
  const double pi = 3.14159265358979;
  // Balls (LPS, mm): mandible r 8 at x = -9, maxilla r 7 at x = +9 (layer
  // 0), tumour r 6 at x = -1 (layer 1), which overlaps both.
  Surface mandible, maxilla, tumour;
  run("mandible", 0, mandible);
  run(nullptr, 2, maxilla); // only one segment has label 2
  run("Tumour", 0, tumour);
  ASSERT_EQ(mandible.errors + maxilla.errors + tumour.errors, 0)
    << mandible.messages << maxilla.messages << tumour.messages;
  double b[6];
  tumour.mesh->GetBounds(b);
  EXPECT_NEAR(0.5 * (b[0] + b[1]), -1.0, 1.0);
  EXPECT_NEAR(b[1] - b[0], 12.0, 2.0);
  mandible.mesh->GetBounds(b);
  EXPECT_NEAR(0.5 * (b[0] + b[1]), -9.0, 1.0);
  EXPECT_GT(b[1], -2.5); // the part the tumour overlaps is still the mandible's
  maxilla.mesh->GetBounds(b);
  EXPECT_NEAR(0.5 * (b[0] + b[1]), 9.0, 1.0);
  // A ball of 6 mm on 1 x 1 x 2 mm voxels, smoothed: about 80 % of its
  // volume (the whole volume, mis-read, gave 17 %).
  EXPECT_NEAR(volumeOf(tumour.mesh), 0.8 * 4.0 / 3.0 * pi * 216.0, 0.1 * 4.0 / 3.0 * pi * 216.0);
  for (const Surface* s : { &mandible, &maxilla, &tumour })
    EXPECT_EQ(lk::countBoundaryEdges(lktest::toCore(s->mesh)), 0u);
  // Layer 0 holds the voxels of two_segments.seg.nrrd: the same surfaces.
  const std::string single = std::string(LATTICEKIT_TEST_DATA) + "/two_segments.seg.nrrd";
  for (const auto& [name, layered] : { std::pair<const char*, Surface*>{ "left condyle", &mandible },
         std::pair<const char*, Surface*>{ "Right Condyle", &maxilla } })
  {
    const Surface same = segmentSurface(single, name);
    EXPECT_EQ(same.mesh->GetNumberOfPoints(), layered->mesh->GetNumberOfPoints()) << name;
    EXPECT_NEAR(volumeOf(same.mesh), volumeOf(layered->mesh), 1e-9) << name;
  }

  // Label 1 is two segments; no label, or one no segment has, is no segment.
  Surface ambiguous, none, missing;
  run(nullptr, 1, ambiguous);
  run(nullptr, 0, none);
  run(nullptr, 3, missing);
  const std::string byName = " by its name (LabelName, --label NAME)";
  const std::string byEither = byName + " or by a label value only it has (Label, --label N)";
  const std::string listed = ". Its segments are 1 'mandible' (layer 0), 2 'maxilla' (layer 0), 1 'tumour' (layer 1).";
  EXPECT_NE(ambiguous.messages.find("The input is a segmentation whose segments overlap, in 2 layers; 2 segments have "
                                    "label 1; choose one" + byName + listed),
    std::string::npos)
    << ambiguous.messages;
  EXPECT_NE(none.messages.find("in 2 layers; choose one segment" + byEither + listed), std::string::npos)
    << none.messages;
  EXPECT_NE(missing.messages.find("in 2 layers; no segment has label 3; choose one" + byEither + listed),
    std::string::npos)
    << missing.messages;
  for (const Surface* s : { &ambiguous, &none, &missing })
  {
    EXPECT_EQ(s->errors, 1);
    EXPECT_EQ(s->mesh->GetNumberOfPoints(), 0);
  }

  // Field data made by hand that puts a segment in a layer the volume does
  // not have: an error, not a read beyond the voxels' values.
  vtkNew<vtkImageData> one;
  one->SetDimensions(volume->GetDimensions());
  one->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  one->GetPointData()->GetScalars()->Fill(1.0);
  one->GetFieldData()->ShallowCopy(volume->GetFieldData());
  vtkNew<vtkLKBoneSurfaceFilter> beyond;
  lktest::ErrorRecorder beyondErrors(beyond);
  beyond->SetInputData(one);
  beyond->SetLabelName("tumour");
  beyond->Update();
  EXPECT_EQ(beyondErrors.errors, 1);
  EXPECT_NE(beyondErrors.messages.find("Segment 'tumour' is in layer 1, but the volume has 1 component."),
    std::string::npos)
    << beyondErrors.messages;
}

// 3D Slicer 4.10 and older saved each segment as a 0/1 map in a layer of
// its own, without LabelValue and Layer keys: segment N is label 1 of layer
// N, as Slicer reads it.
TEST(BoneSurface, SegmentsOfOlderSlicerFilesAreTakenFromTheirLayers)
{
  const std::string older = std::string(LATTICEKIT_TEST_DATA) + "/slicer4_segments.seg.nrrd";
  const std::string current = std::string(LATTICEKIT_TEST_DATA) + "/two_segments.seg.nrrd";
  for (const char* name : { "left condyle", "Right Condyle" })
  {
    int effective = 0;
    const Surface a = segmentSurface(older, name, 0, &effective);
    const Surface b = segmentSurface(current, name);
    ASSERT_EQ(a.errors, 0) << a.messages;
    EXPECT_EQ(effective, 1) << name;
    // The same voxels, so the same surface.
    EXPECT_GT(a.mesh->GetNumberOfPoints(), 100) << name;
    EXPECT_EQ(a.mesh->GetNumberOfPoints(), b.mesh->GetNumberOfPoints()) << name;
    double ba[6], bb[6];
    a.mesh->GetBounds(ba);
    b.mesh->GetBounds(bb);
    for (int i = 0; i < 6; ++i)
      EXPECT_DOUBLE_EQ(ba[i], bb[i]) << name;
  }
  const Surface ambiguous = segmentSurface(older, nullptr, 1);
  EXPECT_NE(ambiguous.messages.find("2 segments have label 1; choose one by its name (LabelName, --label NAME). Its "
                                    "segments are 1 'left condyle' (layer 0), 1 'Right Condyle' (layer 1)."),
    std::string::npos)
    << ambiguous.messages;
}


// A DICOM SEG (as AI segmentation tools and PACS store segmentations) gave
// "images cannot be stacked into one volume". Its segments are now read by
// number and name, each frame placed by its own position: the same surfaces
// as the same balls in 3D Slicer's .seg.nrrd.
TEST(BoneSurface, DicomSegSegmentsAreReadByNumberAndName)
{
  const std::string seg =
    writeSeg("dicom_seg_binary", { { 1, "Mandible", mandibleBall }, { 2, "Maxilla", maxillaBall } }, SegType::Binary);
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(seg.c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_STREQ(reader->GetFileFormat(), "DICOM SEG");
  EXPECT_EQ(reader->GetOutput()->GetNumberOfScalarComponents(), 1); // they do not overlap: one layer
  double range[2];
  reader->GetOutput()->GetPointData()->GetScalars()->GetRange(range);
  EXPECT_EQ(range[1], 2.0);
  auto* names = vtkStringArray::SafeDownCast(reader->GetOutput()->GetFieldData()->GetAbstractArray("SegmentNames"));
  ASSERT_TRUE(names);
  ASSERT_EQ(names->GetNumberOfValues(), 2);
  EXPECT_EQ(names->GetValue(1), "Maxilla");

  const std::string nrrd = std::string(LATTICEKIT_TEST_DATA) + "/two_segments.seg.nrrd";
  int effective = 0;
  expectSameSurface(segmentSurface(seg, "mandible"), segmentSurface(nrrd, "left condyle"), "Mandible by name");
  expectSameSurface(segmentSurface(seg, nullptr, 2, &effective), segmentSurface(nrrd, "Right Condyle"), "Maxilla by number");
  EXPECT_EQ(effective, 2);

  // The same segments as a LABELMAP SEG (one frame per slice, the pixels
  // holding segment numbers).
  const std::string labels =
    writeSeg("dicom_seg_labelmap", { { 1, "Mandible", mandibleBall }, { 2, "Maxilla", maxillaBall } }, SegType::LabelMap);
  expectSameSurface(segmentSurface(labels, "Maxilla"), segmentSurface(nrrd, "Right Condyle"), "LABELMAP maxilla");
  expectSameSurface(segmentSurface(labels, nullptr, 1), segmentSurface(nrrd, "left condyle"), "LABELMAP mandible");

  // One segment numbered 3: no 0/1 map, so it needs its label, and the
  // error says so.
  const std::string one = writeSeg("dicom_seg_one", { { 3, "Mandible", mandibleBall } }, SegType::Binary);
  const Surface unnamed = segmentSurface(one, nullptr);
  EXPECT_NE(unnamed.messages.find("The volume holds only the values 0, 3 (segments: 3 'Mandible'): if it is a label "
                                  "map with several labels, Label (--label N) takes one of them."),
    std::string::npos)
    << unnamed.messages;
  expectSameSurface(segmentSurface(one, nullptr, 3), segmentSurface(nrrd, "left condyle"), "one segment, number 3");

  // A frame that names a segment the SEG does not list.
  const std::string wrong = writeSeg("dicom_seg_wrong", { { 1, "Mandible", mandibleBall } }, SegType::Binary, 7);
  vtkNew<vtkLKMedicalImageReader> bad;
  lktest::ErrorRecorder badRec(bad);
  bad->SetFileName(wrong.c_str());
  bad->Update();
  EXPECT_EQ(badRec.errors, 1);
  EXPECT_NE(badRec.messages.find("frame 1 of the DICOM segmentation names segment 7, which its SegmentSequence does "
                                 "not list."),
    std::string::npos)
    << badRec.messages;
  EXPECT_EQ(bad->GetOutput()->GetNumberOfPoints(), 0);
  // Frames 2 mm apart, but a SpacingBetweenSlices of 3 mm.
  const std::string offGrid = writeSeg("dicom_seg_off_grid", { { 1, "Mandible", mandibleBall } }, SegType::Binary, 0, 3.0);
  badRec.errors = 0;
  badRec.messages.clear();
  bad->SetFileName(offGrid.c_str());
  bad->Update();
  EXPECT_EQ(badRec.errors, 1);
  EXPECT_NE(badRec.messages.find("the frames of the DICOM segmentation do not lie on a grid of 3 mm slices."),
    std::string::npos)
    << badRec.messages;
}

// A SEG beside the CT it was drawn on (in its folder, or in a folder beside
// its own, as a study exported one series to a folder lies) names that CT,
// so that what is made from its segments (vtkLKStructureSetWriter) goes back
// to the CT's patient and slices; a SEG whose CT is elsewhere names none.
TEST(BoneSurface, ADicomSegNamesTheCTItWasDrawnOnWhenItLiesBesideIt)
{
  // Elsewhere: not in a folder beside the SEG's, but one further down.
  const std::string ctDir = std::string(LATTICEKIT_TEST_TMP) + "/dicom_seg_its_ct/elsewhere";
  vtksys::SystemTools::RemoveADirectory(vtksys::SystemTools::GetFilenamePath(ctDir));
  vtksys::SystemTools::MakeDirectory(ctDir);
  vtkNew<vtkImageData> ct;
  ct->SetDimensions(40, 30, 30);
  ct->SetSpacing(1.0, 1.0, 2.0);
  ct->SetOrigin(-20.0, -15.0, -30.0);
  ct->AllocateScalars(VTK_SHORT, 1);
  ct->GetPointData()->GetScalars()->Fill(1024.0);
  const std::string uid = lktest::writeCT(ctDir, ct);
  ASSERT_FALSE(uid.empty());

  const std::string seg =
    writeSeg("dicom_seg_beside_its_ct", { { 1, "Mandible", mandibleBall } }, SegType::Binary, 0, 2.0, uid);
  const auto referenceOf = [](const std::string& file) {
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName(file.c_str());
    reader->Update();
    EXPECT_EQ(rec.errors, 0) << rec.messages;
    EXPECT_STREQ(reader->GetFileFormat(), "DICOM SEG");
    return std::string(reader->GetReferenceImageFileName());
  };
  EXPECT_EQ(referenceOf(seg), ""); // its CT is elsewhere
  ASSERT_TRUE(vtksys::SystemTools::CopyADirectory(ctDir, vtksys::SystemTools::GetFilenamePath(seg)));
  const std::string reference = referenceOf(seg);
  EXPECT_EQ(vtksys::SystemTools::GetFilenamePath(reference), vtksys::SystemTools::GetFilenamePath(seg));
  EXPECT_EQ(vtksys::SystemTools::GetFilenameName(reference).rfind("ct_", 0), 0u) << reference;
  // A study exported one series to a folder: the SEG's CT in a folder
  // beside the SEG's (with another series' folder and a licence's).
  const std::string study = std::string(LATTICEKIT_TEST_TMP) + "/dicom_seg_study";
  vtksys::SystemTools::RemoveADirectory(study);
  ASSERT_TRUE(vtksys::SystemTools::CopyADirectory(ctDir, study + "/2-CT"));
  ASSERT_TRUE(vtksys::SystemTools::MakeDirectory(study + "/0-docs"));
  std::ofstream(study + "/0-docs/LICENSE") << "not DICOM\n";
  ASSERT_TRUE(vtksys::SystemTools::MakeDirectory(study + "/1-CT-other"));
  lktest::writeCT(study + "/1-CT-other", ct);
  ASSERT_TRUE(vtksys::SystemTools::MakeDirectory(study + "/3-SEG"));
  ASSERT_TRUE(vtksys::SystemTools::CopyAFile(seg, study + "/3-SEG/seg.dcm"));
  const std::string inStudy = referenceOf(study + "/3-SEG/seg.dcm");
  EXPECT_EQ(vtksys::SystemTools::GetFilenamePath(inStudy), study + "/2-CT") << inStudy;
  EXPECT_EQ(lktest::seriesUIDOf(inStudy), uid);
  // The CT read itself names a file of its own series.
  vtkNew<vtkLKMedicalImageReader> ctReader;
  ctReader->SetFileName(ctDir.c_str());
  ctReader->Update();
  EXPECT_EQ(vtksys::SystemTools::GetFilenamePath(ctReader->GetReferenceImageFileName()), ctDir);
  // A NRRD belongs to no DICOM series.
  vtkNew<vtkLKMedicalImageReader> nrrd;
  nrrd->SetFileName((std::string(LATTICEKIT_TEST_DATA) + "/two_segments.seg.nrrd").c_str());
  nrrd->Update();
  EXPECT_STREQ(nrrd->GetReferenceImageFileName(), "");
}

// FRACTIONAL frames (occupancy 0 to 255) count from half the maximum; a
// segment that overlaps another goes to a layer of its own, as in 3D
// Slicer's layered .seg.nrrd.
TEST(BoneSurface, DicomSegOverlappingFractionalSegmentsGoToLayers)
{
  const std::string seg = writeSeg("dicom_seg_fractional",
    { { 1, "mandible", mandibleBall }, { 2, "maxilla", maxillaBall }, { 3, "tumour", tumourBall } },
    SegType::Fractional);
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(seg.c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_EQ(reader->GetOutput()->GetNumberOfScalarComponents(), 2);
  vtkDataArray* layers = reader->GetOutput()->GetFieldData()->GetArray("SegmentLayers");
  ASSERT_TRUE(layers);
  EXPECT_EQ(layers->GetComponent(0, 0), 0.0);
  EXPECT_EQ(layers->GetComponent(1, 0), 0.0);
  EXPECT_EQ(layers->GetComponent(2, 0), 1.0);

  const std::string nrrd = std::string(LATTICEKIT_TEST_DATA) + "/overlapping_segments.seg.nrrd";
  expectSameSurface(segmentSurface(seg, nullptr, 3), segmentSurface(nrrd, "tumour"), "tumour by number");
  expectSameSurface(segmentSurface(seg, "mandible"), segmentSurface(nrrd, "mandible"), "mandible by name");
}

TEST(BoneSurface, EmptyAndFlatVolumesAreClearErrors)
{
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  lktest::ErrorRecorder rec(bone);
  vtkNew<vtkImageData> empty;
  bone->SetInputData(empty);
  bone->Update();
  EXPECT_EQ(rec.errors, 1);
  EXPECT_NE(rec.messages.find("empty"), std::string::npos);

  vtkNew<vtkImageData> flat;
  flat->SetDimensions(8, 8, 1);
  flat->AllocateScalars(VTK_SHORT, 1);
  bone->SetInputData(flat);
  bone->Update();
  EXPECT_EQ(rec.errors, 2);
  EXPECT_NE(rec.messages.find("at least 2 voxels"), std::string::npos);

  vtkNew<vtkImageData> nanVolume;
  nanVolume->SetDimensions(4, 4, 4);
  nanVolume->AllocateScalars(VTK_FLOAT, 1);
  bone->SetInputData(nanVolume);
  bone->SetIsoValue(std::nan(""));
  bone->Update();
  EXPECT_EQ(rec.errors, 3);
  EXPECT_NE(rec.messages.find("finite"), std::string::npos);

  // A volume whose geometry folds it flat: zero or NaN spacing, a singular
  // direction matrix. Without the check the first gave a heap of degenerate faces.
  bone->SetIsoValue(0.5);
  vtkNew<vtkImageData> ball;
  ball->SetDimensions(9, 9, 9);
  ball->AllocateScalars(VTK_FLOAT, 1);
  for (int z = 0; z < 9; ++z)
    for (int y = 0; y < 9; ++y)
      for (int x = 0; x < 9; ++x)
        ball->SetScalarComponentFromDouble(x, y, z, 0, (x - 4) * (x - 4) + (y - 4) * (y - 4) + (z - 4) * (z - 4) < 9);
  bone->SetInputData(ball);
  bone->Update();
  EXPECT_EQ(rec.errors, 3) << rec.messages;
  EXPECT_GT(bone->GetOutput()->GetNumberOfPolys(), 0);
  int errors = 3;
  for (int bad = 0; bad < 3; ++bad)
  {
    vtkNew<vtkImageData> folded;
    folded->DeepCopy(ball);
    if (bad == 0)
      folded->SetSpacing(1.0, 1.0, 0.0);
    else if (bad == 1)
      folded->SetSpacing(1.0, std::nan(""), 1.0);
    else
      folded->SetDirectionMatrix(1, 0, 0, 0, 1, 0, 1, 0, 0);
    bone->SetInputData(folded);
    bone->Update();
    EXPECT_EQ(rec.errors, ++errors) << bad;
    EXPECT_NE(rec.messages.find("geometry is invalid"), std::string::npos) << bad;
    EXPECT_EQ(bone->GetOutput()->GetNumberOfPolys(), 0) << bad;
  }
}

TEST(MeshRepairFilter, TriangulatesAndRepairsASoup)
{
  vtkNew<vtkSphereSource> sphere; // triangles with a seam of duplicate points
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(12);
  vtkNew<vtkLKMeshRepairFilter> repair;
  repair->SetInputConnection(sphere->GetOutputPort());
  repair->Update();
  const lk::TriangleMesh m = lktest::toCore(repair->GetOutput());
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  EXPECT_EQ(lk::countBoundaryEdges(m), 0u);
  EXPECT_GT(lk::signedVolume(m), 0.0);

  vtkNew<vtkPolyData> nothing;
  lktest::ErrorRecorder rec(repair);
  repair->SetInputData(nothing);
  repair->Update();
  EXPECT_EQ(rec.errors, 1);
}

TEST(MeshRepairFilter, ProgressMovesThroughTheRepairAndAStopInItEmptiesTheOutput)
{
  // The CGAL repair reported nothing between 10 % and 90 % (17 s frozen on a
  // clinical CT's surface): its steps report now, and a stop between them
  // ends the filter as every latticekit filter ends.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(12);
  vtkNew<vtkLKMeshRepairFilter> repair;
  repair->SetInputConnection(sphere->GetOutputPort());
  lktest::ProgressRecorder seen(repair);
  repair->Update();
  const auto inside = std::count_if(
    seen.progress.begin(), seen.progress.end(), [](double p) { return p > 0.1 && p < 0.9; });
  EXPECT_GE(inside, 5) << "events inside the repair";
  EXPECT_GT(repair->GetOutput()->GetNumberOfPolys(), 0);

  seen.progress.clear();
  seen.stopAt = 0.5;
  repair->Modified();
  lktest::ErrorRecorder rec(repair);
  repair->Update();
  EXPECT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_NE(rec.warningMessages.find("Aborted."), std::string::npos);
  EXPECT_EQ(repair->GetOutput()->GetNumberOfPoints(), 0);
  ASSERT_FALSE(seen.progress.empty());
  EXPECT_LT(seen.progress.back(), 0.9) << "it went on after the stop";
}

TEST(MeshRepairFilter, RepairsASurfaceMadeOfTriangleStripsOnly)
{
  // vtkStripper's output (and vtkSuperquadricSource's) has no polygon cells:
  // the repair triangulates strips as well, so it must not refuse them.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(10);
  vtkNew<vtkStripper> strips;
  strips->SetInputConnection(sphere->GetOutputPort());
  strips->Update();
  ASSERT_EQ(strips->GetOutput()->GetNumberOfPolys(), 0);
  ASSERT_GT(strips->GetOutput()->GetNumberOfStrips(), 0);
  vtkNew<vtkLKMeshRepairFilter> repair;
  lktest::ErrorRecorder rec(repair);
  repair->SetInputConnection(strips->GetOutputPort());
  repair->Update();
  EXPECT_EQ(rec.errors, 0) << rec.messages;
  const lk::TriangleMesh m = lktest::toCore(repair->GetOutput());
  EXPECT_EQ(m.triangles.size(), 16u * 2u * (10u - 2u));
  EXPECT_EQ(lk::cgalSurfaceMeshProblem(m), "");
  EXPECT_EQ(lk::countBoundaryEdges(m), 0u);
  EXPECT_GT(lk::signedVolume(m), 0.0);
}

// A label thinner than the label maps' smoothing reaches (a plate two slices
// of 2.5 mm thick: a printed guide's wall read back from a structure set)
// keeps about half its volume inside the surface: a warning says so and how
// to keep it. A plate of four slices, or the same plate unsmoothed, gets
// none.
TEST(BoneSurface, ALabelThinnerThanItsSmoothingIsSaidToLoseVolume)
{
  auto plate = [](int slices) {
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(40, 40, 20);
    image->SetSpacing(1.0, 1.0, 2.5);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
    auto* v = static_cast<unsigned char*>(image->GetScalarPointer());
    for (int k = 0; k < 20; ++k)
      for (int j = 0; j < 40; ++j)
        for (int i = 0; i < 40; ++i)
          v[(k * 40 + j) * 40 + i] = i >= 5 && i < 35 && j >= 5 && j < 35 && k >= 8 && k < 8 + slices;
    return image;
  };
  struct Case
  {
    int slices;
    double smoothing; // -1: the label maps' default (half a voxel; 1: the default until December 2026)
    int warnings;
  };
  for (const Case& c : { Case{ 2, 1.0, 1 }, Case{ 1, -1.0, 1 }, Case{ 2, -1.0, 0 }, Case{ 2, 0.0, 0 }, Case{ 4, 1.0, 0 } })
  {
    vtkNew<vtkLKBoneSurfaceFilter> surface;
    surface->SetInputData(plate(c.slices));
    surface->SetImageSmoothing(c.smoothing);
    lktest::ErrorRecorder messages(surface);
    surface->Update();
    EXPECT_EQ(messages.errors, 0) << messages.messages;
    EXPECT_GT(surface->GetOutput()->GetNumberOfPolys(), 0);
    EXPECT_EQ(messages.warnings, c.warnings) << c.slices << " slices: " << messages.warningMessages;
    if (c.warnings)
      EXPECT_NE(messages.warningMessages.find("% of the labelled voxels' volume inside the surface: a structure a few "
                                              "voxels thin (a guide's wall) is eaten away; ImageSmoothing 0"),
        std::string::npos)
        << messages.warningMessages;
  }
}

TEST(BoneSurface, AThinRingOnThickSlicesIsFollowedBetterByTheDefaultThanByTheOneVoxelGaussianOfBefore)
{
  // A ring 6 mm thick (R 20, r 3 mm: a coronoid process's thickness),
  // tilted 35 degrees to the slices, as a 0/1 label map on a planning CT's
  // grid (0.98 x 0.98 x 2.5 mm). The label maps' Gaussian of one voxel (the
  // default until December 2026) is 2.5 mm across the slices and wears the
  // ring down (71 % of its volume left); half a voxel and 20 windowed-sinc
  // iterations on the surface, the default now, follow the ring more closely
  // (NOTES, sessions 72 and 73).
  const double R = 20.0, r = 3.0, tilt = 35.0 * vtkMath::Pi() / 180.0;
  auto ringDistance = [&](const double p[3]) {
    // Into the ring's frame: turned back by the tilt about x.
    const double y = std::cos(tilt) * p[1] + std::sin(tilt) * p[2], z = -std::sin(tilt) * p[1] + std::cos(tilt) * p[2];
    return std::hypot(std::hypot(p[0], y) - R, z) - r;
  };
  auto image = vtkSmartPointer<vtkImageData>::New();
  const double spacing[3] = { 0.98, 0.98, 2.5 }, origin[3] = { -30.3, -30.1, -20.7 };
  const int dims[3] = { 63, 63, 18 };
  image->SetDimensions(dims[0], dims[1], dims[2]);
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* v = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
      {
        const double p[3] = { origin[0] + i * spacing[0], origin[1] + j * spacing[1], origin[2] + k * spacing[2] };
        v[(k * dims[1] + j) * dims[0] + i] = ringDistance(p) <= 0.0 ? 1 : 0;
      }
  struct Fit
  {
    double mean = 0.0, max = 0.0;
    int warnings = 0;
  };
  // before: the automatic settings as they were (a session saved then).
  auto fit = [&](double gaussian, int iterations, bool before = false) {
    vtkNew<vtkLKBoneSurfaceFilter> surface;
    surface->SetInputData(image);
    surface->SetImageSmoothing(gaussian);
    surface->SetSmoothingIterations(iterations);
    if (before)
    {
      surface->SetLabelMapImageSmoothing(1.0);
      surface->SetLabelMapSmoothingIterations(0);
    }
    lktest::ErrorRecorder messages(surface);
    surface->Update();
    EXPECT_EQ(messages.errors, 0) << messages.messages;
    EXPECT_TRUE(surface->GetTreatedAsLabelMap());
    EXPECT_EQ(surface->GetEffectiveImageSmoothing(), gaussian >= 0.0 ? gaussian : before ? 1.0 : 0.5);
    EXPECT_EQ(surface->GetEffectiveSmoothingIterations(), iterations >= 0 ? iterations : before ? 0 : 20);
    vtkPolyData* pd = surface->GetOutput();
    EXPECT_GT(pd->GetNumberOfPoints(), 1000);
    Fit f;
    f.warnings = messages.warnings;
    for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
    {
      double p[3];
      pd->GetPoint(i, p);
      const double d = std::abs(ringDistance(p));
      f.mean += d / static_cast<double>(pd->GetNumberOfPoints());
      f.max = std::max(f.max, d);
    }
    return f;
  };
  const Fit oneVoxel = fit(1.0, 0), half = fit(0.5, 0), byDefault = fit(-1.0, -1), asBefore = fit(-1.0, -1, true),
            explicitly = fit(0.5, 20);
  // Measured: mean 0.48 / 0.29 / 0.21 mm, max 1.29 / 1.11 / 0.86 mm.
  EXPECT_EQ(oneVoxel.warnings, 1); // the volume lost is said
  EXPECT_EQ(byDefault.warnings, 0);
  EXPECT_LT(half.mean, 0.7 * oneVoxel.mean);
  EXPECT_LT(byDefault.mean, half.mean);
  EXPECT_LT(byDefault.max, oneVoxel.max);
  // The defaults are those settings, and the ones of before can be asked for.
  EXPECT_EQ(byDefault.mean, explicitly.mean);
  EXPECT_EQ(asBefore.mean, oneVoxel.mean);
  EXPECT_EQ(asBefore.warnings, 1);
  std::cout << "ring: one voxel mean " << oneVoxel.mean << " max " << oneVoxel.max << "; 0.5 voxel mean " << half.mean
            << " max " << half.max << "; the default (0.5 voxel, 20 iterations) mean " << byDefault.mean << " max "
            << byDefault.max << " mm\n";
}

TEST(BoneSurface, ALabelMapWithAMillionSurfacePointsIsCheckedForThinWalls)
{
  // Twenty closed slabs, 4 voxels thick and 156 wide, in a 160^3 label map:
  // about two million triangles. The check for thin walls (is the contour
  // closed, and does it keep the labelled volume) used vtkFeatureEdges,
  // which in VTK 9.1 reserves points^2 / 200 ids for its lines: 40 GB here,
  // and the program stopped. No repair, to keep the test short.
  const int n = 160;
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, n);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* v = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        *v++ = i >= 2 && i < n - 2 && j >= 2 && j < n - 2 && k % 8 >= 2 && k % 8 < 6;
  vtkNew<vtkLKBoneSurfaceFilter> surface;
  surface->SetInputData(image);
  surface->SetExtractionModeToAllComponents();
  surface->RepairOff();
  lktest::ErrorRecorder messages(surface);
  surface->Update();
  EXPECT_EQ(messages.errors, 0) << messages.messages;
  EXPECT_EQ(messages.warnings, 0) << messages.warningMessages; // 4 voxels keep their volume
  EXPECT_TRUE(surface->GetTreatedAsLabelMap());
  EXPECT_GT(surface->GetOutput()->GetNumberOfPoints(), 900000);
  EXPECT_EQ(components(surface->GetOutput()), 20u);
}

TEST(BoneSurface, ALabelTheSmoothingTakesAwayIsSaidSo)
{
  // One labelled voxel: the label maps' Gaussian (half a voxel) leaves it at 0.31, below the
  // iso value 0.5, and "No surface" alone did not say why (nor that
  // ImageSmoothing 0 keeps it; --label 1 on a CT ends the same way).
  vtkNew<vtkImageData> image;
  image->SetDimensions(10, 10, 10);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  image->GetPointData()->GetScalars()->Fill(0.0);
  image->SetScalarComponentFromDouble(5, 5, 5, 0, 1.0);
  for (const double smoothing : { -1.0, 0.0 })
  {
    vtkNew<vtkLKBoneSurfaceFilter> surface;
    surface->SetInputData(image);
    surface->SetImageSmoothing(smoothing);
    lktest::ErrorRecorder messages(surface);
    surface->Update();
    if (smoothing < 0.0)
    {
      EXPECT_EQ(messages.errors, 1);
      EXPECT_NE(messages.messages.find("No surface at iso value 0.5. The label map's 1 labelled voxel lies too thin or "
                                       "too far apart: the Gaussian of 0.5 voxel (ImageSmoothing) leaves none at 0.5; "
                                       "ImageSmoothing 0 (--image-smooth 0) keeps them."),
        std::string::npos)
        << messages.messages;
    }
    else
    {
      EXPECT_EQ(messages.errors, 0) << messages.messages;
      EXPECT_GT(surface->GetOutput()->GetNumberOfPolys(), 0);
    }
  }
}
