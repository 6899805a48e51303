#include "LatticeSurfaceSides.h"
#include "MandibleLoop.h"
#include "TestSupport.h"
#include "latticekit/EdgePath.h"
#include "latticekit/FaceCrossings.h"
#include "latticekit/LatticeSimplification.h"
#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKLatticeFitFilter.h"
#include "vtkLKLatticeSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKPolyDataConversion.h"
#include "vtkLKQuadPairingFilter.h"

#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkMath.h>
#include <vtkOBJReader.h>
#include <vtkAlgorithm.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace
{
double field(vtkPolyData* pd, const char* name)
{
  vtkDataArray* a = pd->GetFieldData()->GetArray(name);
  return a ? a->GetComponent(0, 0) : std::nan("");
}

std::set<lk::EdgeKey> latticeEdges(vtkPolyData* lattice)
{
  std::set<lk::EdgeKey> edges;
  auto it = vtk::TakeSmartPointer(lattice->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k)
      edges.insert(lk::edgeKey(ids[k], ids[(k + 1) % n]));
  }
  return edges;
}

/// A mesh of tests/data (.vtp or .obj).
vtkSmartPointer<vtkPolyData> readTestData(const std::string& name)
{
  const std::string path = std::string(LATTICEKIT_TEST_DATA) + "/" + name;
  vtkSmartPointer<vtkAlgorithm> reader;
  if (name.size() > 4 && name.substr(name.size() - 4) == ".obj")
  {
    auto obj = vtkSmartPointer<vtkOBJReader>::New();
    obj->SetFileName(path.c_str());
    reader = obj;
  }
  else
  {
    auto xml = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    xml->SetFileName(path.c_str());
    reader = xml;
  }
  reader->Update();
  vtkSmartPointer<vtkPolyData> pd = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  return pd;
}
/// Runs `filter`: no error, exactly one warning, and it contains `text`.
void expectOneWarning(vtkAlgorithm* filter, const std::string& text)
{
  lktest::ErrorRecorder messages(filter);
  filter->Update();
  EXPECT_EQ(messages.errors, 0) << messages.messages;
  EXPECT_EQ(messages.warnings, 1) << messages.warningMessages;
  EXPECT_NE(messages.warningMessages.find(text), std::string::npos) << messages.warningMessages;
}
} // namespace

TEST(LatticeFitFilter, MandibleLatticeWithErrorAndVertexMap)
{
  auto bone = lktest::tciaMandible();
  vtkNew<vtkLKLatticeFitFilter> fit;
  fit->SetInputData(bone);
  fit->SetTargetNumberOfVertices(2000);
  lktest::ProgressRecorder seen(fit);
  fit->Update();
  vtkPolyData* lattice = fit->GetOutput();
  EXPECT_EQ(lattice->GetNumberOfPoints(), 2000);
  EXPECT_EQ(lattice->GetNumberOfPolys(), 2 * 2000 - 4); // closed, genus 0
  EXPECT_GT(seen.progress.size(), 20u);
  const double mean = field(lattice, "Hausdorff_MeanPercent"), max = field(lattice, "Hausdorff_MaxPercent");
  std::printf("mandible, 2000 vertices: Metro max %.4f %%, mean %.4f %%\n", max, mean);
  EXPECT_GT(mean, 0.0);
  EXPECT_LT(mean, 0.05);
  EXPECT_LT(max, 0.5);
  EXPECT_GT(field(lattice, "DisplayPolygons"), 3 * 3996 * 8);
  vtkPolyData* map = fit->GetVertexMapOutput();
  ASSERT_EQ(map->GetNumberOfPoints(), bone->GetNumberOfPoints());
  vtkDataArray* faces = map->GetPointData()->GetArray("LatticeFaceId");
  vtkDataArray* verts = map->GetPointData()->GetArray("LatticeVertexId");
  vtkDataArray* dist = map->GetPointData()->GetArray("Distance");
  ASSERT_TRUE(faces && verts && dist);
  double dmax = 0.0;
  for (vtkIdType i = 0; i < map->GetNumberOfPoints(); ++i)
  {
    EXPECT_GE(faces->GetComponent(i, 0), 0);
    EXPECT_LT(faces->GetComponent(i, 0), lattice->GetNumberOfPolys());
    EXPECT_GE(verts->GetComponent(i, 0), 0);
    EXPECT_LT(verts->GetComponent(i, 0), 2000);
    dmax = std::max(dmax, dist->GetComponent(i, 0));
  }
  // The vertices' distances cannot exceed the Hausdorff distance (up to the
  // tessellation's chordal error).
  EXPECT_LT(dmax, 1.05 * field(lattice, "Hausdorff_Max") + 1e-3);
}

TEST(LatticeFitFilter, TheMandiblesFittedSurfacesDoNotFoldAlongTheirCurves)
{
  // The fitted lattices of both TCIA mandibles at 2,000 vertices fold
  // sharply at a few edges. There, before session 78, the patches beside 10
  // (first mandible) and 31 (second) of the surface's curves lay on the same
  // side of them, with opposite normals: dark streaks in a rendering with the
  // surface's own normals, and the surface passing through itself.
  for (const std::string patient : { "0522c0017", "TCGA-CV-7236" })
  {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(lktest::tciaMandibleSurface(patient));
    fit->SetTargetNumberOfVertices(2000);
    fit->Update();
    lk::PolygonMesh lattice;
    ASSERT_EQ(lkvtk::toPolygonMesh(fit->GetOutput(), lattice), "");
    const lk::LatticeSurface surface = lk::buildLatticeSurface(lattice);
    const double size = fit->GetOutput()->GetLength();
    std::size_t pairs = 0;
    const std::size_t folded = lktest::foldedSidePairs(surface, size, &pairs);
    std::printf("mandible %s, 2000 vertices: %zu of %zu side sample pairs folded over\n", patient.c_str(), folded, pairs);
    EXPECT_GT(pairs, 500000u);
    EXPECT_EQ(folded, 0u) << patient;
  }
}

TEST(LatticeFitFilter, TheRefinementDoesNotFoldTheSurface)
{
  // The refinement moves the lattice vertices to bring the surface closer to
  // the bone. Before session 79 it also turned small lattice faces over and
  // folded patches into thin fins lying along the bone: on the second TCIA
  // mandible's quad lattice at 2,000 vertices the refined surface passed
  // through itself at 423 pairs of display triangles (resolution 4), against
  // 68 before the refinement. The refinement may no longer fold the surface
  // (57 here); the crossings left come from the fit before it.
  auto bone = lktest::tciaMandibleSurface("TCGA-CV-7236");
  auto crossings = [&](bool refine) {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(bone);
    fit->SetTargetNumberOfVertices(2000);
    fit->SetQuadPairing(true);
    fit->SetRefinement(refine);
    vtkNew<vtkLKLatticeSurfaceFilter> surface;
    surface->SetInputConnection(fit->GetOutputPort());
    surface->SetResolution(4);
    surface->Update();
    lk::PolygonMesh mesh;
    EXPECT_EQ(lkvtk::toPolygonMesh(surface->GetOutput(), mesh), "");
    const lk::FaceCrossings c = lk::markedFaceCrossings(mesh, std::vector<char>(mesh.faces.size(), 1));
    EXPECT_TRUE(c.checked);
    return c.pairs;
  };
  const std::size_t fitted = crossings(false), refined = crossings(true);
  std::printf("second mandible, 2000 vertices with quads: %zu pairs of display triangles cross, %zu after the refinement\n",
    fitted, refined);
  EXPECT_GT(fitted, 0u); // the measure sees the fit's own crossings
  EXPECT_LE(refined, fitted);
}

TEST(LatticeFitFilter, LockedFeaturesAreLatticeEdges)
{
  auto bone = lktest::tciaMandible();
  std::vector<lk::EdgeKey> edges;
  auto lines = lktest::mandibleLoop(bone, edges);
  ASSERT_GT(edges.size(), 30u);
  vtkNew<vtkLKLatticeFitFilter> fit;
  fit->SetInputData(bone);
  fit->SetFeatureLinesData(lines);
  fit->SetTargetNumberOfVertices(1500);
  fit->LockFeaturesOn();
  {
    lktest::ErrorRecorder rec(fit);
    fit->Update();
    EXPECT_EQ(rec.warnings, 0) << rec.warningMessages; // the lines lie on the points they name
  }
  vtkPolyData* lattice = fit->GetOutput();
  vtkDataArray* vmap = fit->GetVertexMapOutput()->GetPointData()->GetArray("LatticeVertexId");
  const auto latt = latticeEdges(lattice);
  EXPECT_EQ(lattice->GetNumberOfLines(), static_cast<vtkIdType>(edges.size()));
  EXPECT_EQ(field(lattice, "FeatureEdges"), static_cast<double>(edges.size()));
  for (const auto& e : edges)
  {
    const auto a = static_cast<vtkIdType>(vmap->GetComponent(e.first, 0));
    const auto b = static_cast<vtkIdType>(vmap->GetComponent(e.second, 0));
    EXPECT_TRUE(latt.count(lk::edgeKey(a, b))) << e.first << "-" << e.second;
    double p[3], q[3];
    lattice->GetPoint(a, p);
    bone->GetPoint(e.first, q);
    EXPECT_EQ(p[0], q[0]);
    EXPECT_EQ(p[1], q[1]);
    EXPECT_EQ(p[2], q[2]);
  }
  // With InterpolateFeatures (default) the surface passes through the
  // feature vertices: they lie on the tessellation (patch corners).
  vtkDataArray* dist = fit->GetVertexMapOutput()->GetPointData()->GetArray("Distance");
  for (const auto& e : edges)
    EXPECT_LT(dist->GetComponent(e.first, 0), 1e-9);
  // Line cells come first: FeatureEdge 1 on them, 0 on faces.
  vtkDataArray* flag = lattice->GetCellData()->GetArray("FeatureEdge");
  ASSERT_TRUE(flag);
  EXPECT_EQ(flag->GetComponent(0, 0), 1.0);
  EXPECT_EQ(flag->GetComponent(lattice->GetNumberOfCells() - 1, 0), 0.0);
}

TEST(LatticeFitFilter, FeatureWeightsHalveTheErrorNearTheFeature)
{
  auto bone = lktest::tciaMandible();
  std::vector<lk::EdgeKey> edges;
  auto lines = lktest::mandibleLoop(bone, edges);
  std::set<vtkIdType> featureVertices;
  for (const auto& e : edges)
  {
    featureVertices.insert(e.first);
    featureVertices.insert(e.second);
  }
  auto nearError = [&](bool withFeatures) {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(bone);
    if (withFeatures)
      fit->SetFeatureLinesData(lines);
    fit->SetTargetNumberOfVertices(1000);
    fit->Update();
    vtkDataArray* d = fit->GetVertexMapOutput()->GetPointData()->GetArray("Distance");
    double sum = 0.0;
    for (auto v : featureVertices)
      sum += d->GetComponent(v, 0);
    return sum / static_cast<double>(featureVertices.size());
  };
  const double plain = nearError(false), weighted = nearError(true);
  std::printf("mean distance of the feature line's vertices to the surface: %.5f without, %.5f with k = 1000\n",
    plain, weighted);
  EXPECT_LT(weighted, 0.5 * plain);
}

TEST(LatticeFitFilter, RefinementWinsBackWhatQuadsLose)
{
  auto bone = lktest::tciaMandible();
  auto run = [&](bool quads, bool refine) {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(bone);
    fit->SetTargetNumberOfVertices(1000);
    fit->SetQuadPairing(quads);
    fit->SetRefinement(refine);
    fit->SetRefinementIterations(3);
    fit->Update();
    return std::make_pair(field(fit->GetOutput(), "Hausdorff_MeanPercent"), field(fit->GetOutput(), "Quads"));
  };
  const auto tri = run(false, false), triRefined = run(false, true), quadRefined = run(true, true);
  std::printf("mandible at 1000 vertices, mean %%: triangles %.4f, refined %.4f; %.0f quads refined %.4f\n", tri.first,
    triRefined.first, quadRefined.second, quadRefined.first);
  EXPECT_GT(quadRefined.second, 50.0);
  EXPECT_LT(triRefined.first, tri.first);
  EXPECT_LT(quadRefined.first, 1.05 * triRefined.first);
}

TEST(LatticeFitFilter, InsertionsKeepTheTargetAndLowerTheMax)
{
  auto bone = lktest::tciaMandible();
  auto run = [&](int insertions) {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(bone);
    fit->SetTargetNumberOfVertices(1500);
    fit->SetRefinement(true);
    fit->SetRefinementIterations(8);
    if (insertions >= 0)
      fit->SetRefinementInsertions(insertions); // else the default, 1 per 100 vertices
    fit->Update();
    vtkPolyData* out = fit->GetOutput();
    EXPECT_EQ(field(out, "ControlVertices"), 1500.0);
    EXPECT_EQ(field(out, "RefinementInsertions"), insertions >= 0 ? insertions : 15);
    EXPECT_EQ(field(out, "RefinementInsertionsRefused"), 0.0);
    return std::make_pair(field(out, "Hausdorff_MaxPercent"), field(out, "Hausdorff_MeanPercent"));
  };
  const auto tail = run(0), inserted = run(-1);
  std::printf("mandible at 1500 vertices, max / mean %%: tail penalty %.4f / %.4f; 15 insertions %.4f / %.4f\n",
    tail.first, tail.second, inserted.first, inserted.second);
  // At 1,500 vertices 0.2529 / 0.0121 against 0.2485 / 0.0117 (the CLI's
  // figures): the same tail weight (the default, 10) in a single pass, and
  // in a second pass after the default 15 insertions. The max is one point
  // and noisy: at 1,000 vertices, since the fold guard (session 79), the
  // insertions no longer lower it (0.2734 against 0.2729) and are undone;
  // before it, 0.1944 against 0.2066 there.
  EXPECT_LT(inserted.first, tail.first);
  EXPECT_LT(inserted.second, 1.02 * tail.second);
}

TEST(LatticeFitFilter, InsertionsThatDoNotLowerTheMaxAreUndone)
{
  // The main job's smaller osteotomy piece, its cut line locked: 252 of the
  // 403 lattice vertices sit on the line. Its 4 insertions chase a CT streak
  // artefact and the second pass does not lower the max (before the fold
  // guard of session 79 it bulged: Metro max 4.3 % against 1.6 %), so the
  // filter redoes the fit without them: the whole target to the QEM, one
  // refinement pass without the tail penalty. (Its fitted surface crosses
  // itself at 13,000 pairs of display triangles before any refinement, and
  // the fold guard leaves the refinement little to do: Metro 4.9 % / 0.39 %,
  // against 2.0 % / 0.19 % when it could fold the surface further.)
  auto piece = readTestData("mandible_piece.vtp");
  auto line = readTestData("mandible_piece_cut_line.vtp");
  ASSERT_EQ(piece->GetNumberOfPoints(), 4357);
  auto run = [&](bool defaults) {
    auto fit = vtkSmartPointer<vtkLKLatticeFitFilter>::New();
    fit->SetInputData(piece);
    fit->SetFeatureLinesData(line);
    fit->LockFeaturesOn();
    fit->SetTargetNumberOfVertices(403);
    fit->QuadPairingOn();
    fit->RefinementOn();
    if (!defaults)
    {
      fit->SetRefinementInsertions(0);
      fit->SetRefinementTailWeight(0.0);
    }
    fit->Update();
    return fit;
  };
  auto undone = run(true), plain = run(false);
  vtkPolyData* a = undone->GetOutput();
  vtkPolyData* b = plain->GetOutput();
  std::printf("osteotomy piece at 403 vertices, max / mean %%: %.4f / %.4f (insertions refused: %.0f)\n",
    field(a, "Hausdorff_MaxPercent"), field(a, "Hausdorff_MeanPercent"), field(a, "RefinementInsertionsRefused"));
  EXPECT_EQ(field(a, "RefinementInsertionsRefused"), 4.0);
  EXPECT_EQ(field(a, "RefinementInsertions"), 0.0);
  EXPECT_EQ(field(b, "RefinementInsertionsRefused"), 0.0);
  EXPECT_EQ(field(a, "ControlVertices"), 403.0);
  EXPECT_EQ(field(a, "FeatureEdges"), 252.0);
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  double largest = 0.0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    largest = std::max(largest, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
  }
  EXPECT_EQ(largest, 0.0);
  EXPECT_EQ(field(a, "Hausdorff_MaxPercent"), field(b, "Hausdorff_MaxPercent"));
}

TEST(LatticeFitFilter, BadInputIsAClearError)
{
  auto bone = lktest::tciaMandible();
  auto expectError = [&](vtkLKLatticeFitFilter* fit, const std::string& text) {
    lktest::ErrorRecorder errors(fit);
    fit->Update();
    EXPECT_EQ(errors.errors, 1) << text;
    EXPECT_NE(errors.messages.find(text), std::string::npos) << errors.messages;
    EXPECT_EQ(fit->GetOutput()->GetNumberOfPoints(), 0);
  };
  {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(bone);
    fit->SetTargetNumberOfVertices(bone->GetNumberOfPoints());
    expectError(fit, "not below the input");
  }
  {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(bone);
    fit->SetTargetNumberOfVertices(500);
    fit->SetFeatureWeight(0.0);
    expectError(fit, "feature weight");
  }
  {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(bone);
    fit->SetTargetNumberOfVertices(500);
    fit->SetFeatureNeighbourWeight(-2.0);
    expectError(fit, "next to a feature");
  }
  // A feature tolerance: a distance, and only for locked lines.
  for (const double tolerance : { -0.1, std::nan(""), std::numeric_limits<double>::infinity() })
  {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(bone);
    fit->SetTargetNumberOfVertices(500);
    fit->LockFeaturesOn();
    fit->SetFeatureTolerance(tolerance);
    expectError(fit, "FeatureTolerance must be a finite distance >= 0");
  }
  {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(bone);
    fit->SetTargetNumberOfVertices(500);
    fit->SetFeatureTolerance(0.05);
    expectError(fit, "FeatureTolerance (0.05) is for locked lines: turn LockFeatures on");
  }
  {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(bone);
    fit->SetTargetNumberOfVertices(500);
    fit->SetRefinement(true);
    fit->SetRefinementTailWeight(-1.0);
    expectError(fit, "tail weight");
    vtkNew<vtkLKLatticeFitFilter> fit2;
    fit2->SetInputData(bone);
    fit2->SetTargetNumberOfVertices(500);
    fit2->SetRefinementTailThreshold(0.0);
    expectError(fit2, "threshold above 0");
    vtkNew<vtkLKLatticeFitFilter> fit3;
    fit3->SetInputData(bone);
    fit3->SetTargetNumberOfVertices(10);
    fit3->SetRefinement(true);
    fit3->SetRefinementInsertions(7);
    expectError(fit3, "insertions leave fewer than 4");
  }
  {
    vtkNew<vtkPolyData> lines;
    vtkNew<vtkPoints> pts;
    pts->InsertNextPoint(bone->GetPoint(0));
    pts->InsertNextPoint(bone->GetPoint(1));
    vtkNew<vtkIdTypeArray> ids;
    ids->SetName("MeshPointId");
    ids->InsertNextValue(0);
    ids->InsertNextValue(bone->GetNumberOfPoints() + 5);
    vtkNew<vtkCellArray> cells;
    const vtkIdType c[2] = { 0, 1 };
    cells->InsertNextCell(2, c);
    lines->SetPoints(pts);
    lines->SetLines(cells);
    lines->GetPointData()->AddArray(ids);
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(bone);
    fit->SetFeatureLinesData(lines);
    fit->SetTargetNumberOfVertices(500);
    expectError(fit, "has MeshPointId " + std::to_string(bone->GetNumberOfPoints() + 5) + ", outside the mesh's point ids");
    ids->SetValue(1, 5000); // in range, but not joined to 0 by an edge
    ids->Modified();
    pts->SetPoint(1, bone->GetPoint(5000));
    vtkNew<vtkLKLatticeFitFilter> fit2;
    fit2->SetInputData(bone);
    fit2->SetFeatureLinesData(lines);
    fit2->SetTargetNumberOfVertices(500);
    expectError(fit2, "not an edge of the mesh");
    // Both ends on one mesh point: no feature edge at all. The fit goes on
    // without features, and says so (it was silent).
    ids->SetValue(1, 0);
    ids->Modified();
    pts->SetPoint(1, bone->GetPoint(0));
    vtkNew<vtkLKLatticeFitFilter> fit3;
    fit3->SetInputData(bone);
    fit3->SetFeatureLinesData(lines);
    fit3->SetTargetNumberOfVertices(500);
    expectOneWarning(fit3, "no edge between two different mesh points");
    EXPECT_EQ(fit3->GetOutput()->GetNumberOfPoints(), 500);
  }
  {
    // A fan of four triangles around point 0 and a fifth on 0-2-1, the first
    // one reversed: edges 0-1, 1-2 and 0-2 each carry three triangles.
    vtkNew<vtkPolyData> fan;
    vtkNew<vtkPoints> pts;
    pts->InsertNextPoint(0, 0, 0);
    pts->InsertNextPoint(1, 0, 0);
    pts->InsertNextPoint(0, 1, 0);
    pts->InsertNextPoint(-1, 0, 0);
    pts->InsertNextPoint(0, -1, 0);
    vtkNew<vtkCellArray> tris;
    const vtkIdType t1[3] = { 0, 1, 2 }, t2[3] = { 0, 3, 4 }, t3[3] = { 0, 2, 3 }, t4[3] = { 0, 4, 1 },
                    t5[3] = { 0, 2, 1 };
    tris->InsertNextCell(3, t1);
    tris->InsertNextCell(3, t2);
    tris->InsertNextCell(3, t3);
    tris->InsertNextCell(3, t4);
    tris->InsertNextCell(3, t5);
    fan->SetPoints(pts);
    fan->SetPolys(tris);
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(fan);
    fit->SetTargetNumberOfVertices(4);
    expectError(fit, "do not form a manifold");
    // Two triangles sharing one vertex only (a bow tie): a non-manifold vertex.
    vtkNew<vtkCellArray> bowTris;
    bowTris->InsertNextCell(3, t1);
    bowTris->InsertNextCell(3, t2);
    vtkNew<vtkPolyData> bow;
    bow->SetPoints(pts);
    bow->SetPolys(bowTris);
    vtkNew<vtkLKLatticeFitFilter> fit2;
    fit2->SetInputData(bow);
    fit2->SetTargetNumberOfVertices(4);
    expectError(fit2, "do not form a manifold");
  }
  {
    vtkNew<vtkPolyData> empty;
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(empty);
    expectError(fit, "Cannot fit a lattice");
  }
  {
    // Every point in one place: with refinement, the samples' exception
    // ("zero area") ended the program before the mesh check could speak.
    vtkNew<vtkPolyData> collapsed;
    collapsed->DeepCopy(bone);
    for (vtkIdType i = 0; i < collapsed->GetNumberOfPoints(); ++i)
      collapsed->GetPoints()->SetPoint(i, 1.0, 2.0, 3.0);
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(collapsed);
    fit->SetTargetNumberOfVertices(500);
    fit->SetRefinement(true);
    expectError(fit, "Cannot fit a lattice: the mesh has a degenerate (zero-area) triangle.");
  }
}

TEST(LatticeFitFilter, OpenMeshIsFittedWithItsBorder)
{
  // Documented behaviour: open meshes are fitted; the lattice keeps a border.
  auto bone = lktest::tciaMandible();
  vtkNew<vtkPolyData> open;
  open->DeepCopy(bone);
  // Remove one triangle: a hole.
  vtkNew<vtkCellArray> polys;
  auto it = vtk::TakeSmartPointer(bone->GetPolys()->NewIterator());
  vtkIdType c = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++c)
  {
    if (c == 100)
      continue;
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    polys->InsertNextCell(n, ids);
  }
  open->SetPolys(polys);
  vtkNew<vtkLKLatticeFitFilter> fit;
  fit->SetInputData(open);
  fit->SetTargetNumberOfVertices(1000);
  lktest::ErrorRecorder errors(fit);
  fit->Update();
  EXPECT_EQ(errors.errors, 0) << errors.messages;
  EXPECT_EQ(fit->GetOutput()->GetNumberOfPoints(), 1000);
  EXPECT_LT(field(fit->GetOutput(), "Hausdorff_MeanPercent"), 0.1);
}

TEST(LatticeFitFilter, UnreachableTargetIsAWarning)
{
  // A torus cannot be simplified to 5 vertices without changing its
  // topology: the lattice stops above the target, and the filter says so.
  // The 16 x 8 torus of the command-line test (radii 3 and 1).
  auto torus = readTestData("torus.obj");
  ASSERT_EQ(torus->GetNumberOfPoints(), 128);
  ASSERT_EQ(torus->GetNumberOfPolys(), 256);
  vtkNew<vtkLKLatticeFitFilter> fit;
  fit->SetInputData(torus);
  fit->SetTargetNumberOfVertices(5);
  expectOneWarning(fit, "more than the target of 5");
  vtkPolyData* lattice = fit->GetOutput();
  EXPECT_GT(lattice->GetNumberOfPoints(), 5);
  // Still a torus: V - E + F = 0.
  const auto edges = latticeEdges(lattice);
  EXPECT_EQ(lattice->GetNumberOfPoints() - static_cast<vtkIdType>(edges.size()) + lattice->GetNumberOfPolys(), 0);

  // A target it reaches gives no warning.
  vtkNew<vtkLKLatticeFitFilter> reachable;
  reachable->SetInputData(torus);
  reachable->SetTargetNumberOfVertices(60);
  lktest::ErrorRecorder none(reachable);
  reachable->Update();
  EXPECT_EQ(none.errors + none.warnings, 0) << none.messages << none.warningMessages;
  EXPECT_EQ(reachable->GetOutput()->GetNumberOfPoints(), 60);
}

TEST(QuadPairingFilter, PairsAndKeepsLineCells)
{
  auto bone = lktest::tciaMandible();
  vtkNew<vtkLKLatticeFitFilter> fit;
  fit->SetInputData(bone);
  fit->SetTargetNumberOfVertices(1000);
  fit->ComputeErrorOff();
  std::vector<lk::EdgeKey> edges;
  fit->SetFeatureLinesData(lktest::mandibleLoop(bone, edges));
  fit->LockFeaturesOn();
  vtkNew<vtkLKQuadPairingFilter> pairs;
  pairs->SetInputConnection(fit->GetOutputPort());
  pairs->SetMaximumDihedralAngle(40);
  pairs->Update();
  vtkPolyData* out = pairs->GetOutput();
  const double quads = field(out, "Quads"), tris = field(out, "Triangles");
  EXPECT_GT(quads, 30.0);
  EXPECT_EQ(2 * quads + tris, static_cast<double>(fit->GetOutput()->GetNumberOfPolys()));
  EXPECT_EQ(out->GetNumberOfLines(), fit->GetOutput()->GetNumberOfLines());
  // Feature edges are still edges of the faces.
  const auto latt = latticeEdges(out);
  auto it = vtk::TakeSmartPointer(out->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    EXPECT_TRUE(latt.count(lk::edgeKey(ids[0], ids[1])));
  }
  vtkNew<vtkLKQuadPairingFilter> bad;
  bad->SetInputConnection(fit->GetOutputPort());
  bad->SetRightAngleTolerance(-1);
  lktest::ErrorRecorder errors(bad);
  bad->Update();
  EXPECT_EQ(errors.errors, 1);
  EXPECT_NE(errors.messages.find("S1"), std::string::npos);
}

#include <vtkSphereSource.h>

TEST(LatticeFitFilter, TheSurfaceMetroAndMapReportProgressAndStop)
{
  // After the refinement the filter builds the lattice surface, measures it
  // with Metro and maps the input's vertices: most of a minute on a
  // 600,000-triangle CT surface, which once showed no progress at all.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(60);
  sphere->SetPhiResolution(60);
  sphere->SetRadius(10.0);
  vtkNew<vtkLKLatticeFitFilter> fit;
  fit->SetInputConnection(sphere->GetOutputPort());
  fit->SetTargetNumberOfVertices(300);
  fit->SetRefinement(true);
  fit->SetRefinementIterations(2);
  lktest::ProgressRecorder seen(fit);
  fit->Update();
  ASSERT_EQ(fit->GetOutput()->GetNumberOfPoints(), 300);
  std::size_t late = 0;
  for (std::size_t i = 0; i < seen.progress.size(); ++i)
  {
    if (i > 0)
      ASSERT_GE(seen.progress[i], seen.progress[i - 1]) << "progress event " << i;
    late += seen.progress[i] > 0.9 && seen.progress[i] < 1.0;
  }
  EXPECT_GE(late, 10u) << "events between 90 % and 100 %";
  // A stop in that stage: empty outputs and the warning, as at any other.
  seen.progress.clear();
  seen.stopAt = 0.95;
  fit->Modified();
  lktest::ErrorRecorder messages(fit);
  fit->Update();
  EXPECT_EQ(messages.errors, 0) << messages.messages;
  EXPECT_NE(messages.warningMessages.find("Aborted."), std::string::npos);
  EXPECT_EQ(fit->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(fit->GetVertexMapOutput()->GetNumberOfPoints(), 0);
  ASSERT_FALSE(seen.progress.empty());
  EXPECT_LT(seen.progress.back(), 1.0);
}

TEST(LatticeFitFilter, ErrorBoundFindsAFewVerticesWithinIt)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(60);
  sphere->SetPhiResolution(60);
  sphere->SetRadius(10.0);
  sphere->Update();
  vtkNew<vtkLKLatticeFitFilter> fit;
  fit->SetInputConnection(sphere->GetOutputPort());
  fit->SetMaximumError(0.5);
  // The progress never runs back, however many fits the search takes.
  lktest::ProgressRecorder seen(fit);
  const std::vector<double>& progress = seen.progress;
  fit->Update();
  ASSERT_GT(progress.size(), 10u);
  for (std::size_t i = 1; i < progress.size(); ++i)
    ASSERT_GE(progress[i], progress[i - 1]) << "progress event " << i;
  vtkPolyData* lattice = fit->GetOutput();
  const double max = field(lattice, "Hausdorff_MaxPercent");
  std::printf("sphere of %lld vertices within 0.5 %%: %lld lattice vertices, max %.4f %%\n",
    static_cast<long long>(sphere->GetOutput()->GetNumberOfPoints()),
    static_cast<long long>(lattice->GetNumberOfPoints()), max);
  EXPECT_LE(max, 0.5);
  // Fewer fits than bisection over [4, 3481] (12).
  std::printf("%g fits measured\n", field(lattice, "ErrorBoundTrials"));
  EXPECT_GE(field(lattice, "ErrorBoundTrials"), 2.0);
  EXPECT_LT(field(lattice, "ErrorBoundTrials"), 12.0);
  // Each trial's count and error: the lattice's count is one measured within
  // the bound, with the error the output reports.
  vtkDataArray* trials = lattice->GetFieldData()->GetArray("ErrorBoundTrialCountAndError");
  ASSERT_NE(trials, nullptr);
  ASSERT_EQ(trials->GetNumberOfComponents(), 2);
  EXPECT_EQ(static_cast<double>(trials->GetNumberOfTuples()), field(lattice, "ErrorBoundTrials"));
  bool measured = false;
  for (vtkIdType i = 0; i < trials->GetNumberOfTuples(); ++i)
    if (trials->GetComponent(i, 0) == static_cast<double>(lattice->GetNumberOfPoints()))
    {
      measured = true;
      EXPECT_LE(trials->GetComponent(i, 1), 0.5);
      EXPECT_NEAR(trials->GetComponent(i, 1), max, 1e-9);
    }
  EXPECT_TRUE(measured);
  EXPECT_GT(lattice->GetNumberOfPoints(), 4);
  EXPECT_LT(lattice->GetNumberOfPoints(), sphere->GetOutput()->GetNumberOfPoints() / 4);
  // Not stopped early: with 20 % fewer vertices the bound no longer holds.
  vtkNew<vtkLKLatticeFitFilter> fewer;
  fewer->SetInputConnection(sphere->GetOutputPort());
  fewer->SetTargetNumberOfVertices(lattice->GetNumberOfPoints() * 4 / 5);
  fewer->Update();
  EXPECT_GT(field(fewer->GetOutput(), "Hausdorff_MaxPercent"), 0.5);
}

TEST(LatticeFitFilter, AHugeInputIsThinnedForTheRefinement)
{
  // A sphere of 180,000 triangles gives Metro's sampling about 1.4 million
  // samples; the refinement of a 200-vertex lattice keeps 500,000 of them
  // (150 per vertex would be 30,000; 500,000 is the floor of the cap). The
  // mandible stays below the cap and keeps all of its samples.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(300);
  sphere->SetPhiResolution(302);
  sphere->SetRadius(10.0);
  vtkNew<vtkLKLatticeFitFilter> fit;
  fit->SetInputConnection(sphere->GetOutputPort());
  fit->SetTargetNumberOfVertices(200);
  fit->SetRefinement(true);
  fit->SetRefinementIterations(2);
  fit->SetRefinementInsertions(0);
  fit->Update();
  ASSERT_GT(sphere->GetOutput()->GetNumberOfPolys(), 170000);
  EXPECT_EQ(field(fit->GetOutput(), "RefinementSamples"), 500000.0);
  EXPECT_LT(field(fit->GetOutput(), "RefinementFinalRMS"), field(fit->GetOutput(), "RefinementInitialRMS"));
  EXPECT_LT(field(fit->GetOutput(), "Hausdorff_MeanPercent"), 0.05);

  auto bone = lktest::tciaMandible();
  vtkNew<vtkLKLatticeFitFilter> small;
  small->SetInputData(bone);
  small->SetTargetNumberOfVertices(300);
  small->SetRefinement(true);
  small->SetRefinementIterations(1);
  small->SetRefinementInsertions(0);
  small->Update();
  // Every vertex, edge and face sample: more than the 4 face samples per triangle.
  EXPECT_GT(field(small->GetOutput(), "RefinementSamples"), 4.0 * bone->GetNumberOfPolys());
  EXPECT_LT(field(small->GetOutput(), "RefinementSamples"), 500000.0);
}

TEST(LatticeFitFilter, TheFitDoesNotDependOnTheUnitOfLength)
{
  // The same mandible in millimetres, in metres and in micrometres (a mesh
  // from a tool that writes metres): the same lattice up to the scale, so
  // the errors in % of the diagonal agree. An absolute tolerance in the
  // simplification or the refinement (a step, a damping, a convergence test
  // in mm) would break this.
  auto bone = lktest::tciaMandible();
  double mean[3] = { 0, 0, 0 }, maxError[3] = { 0, 0, 0 };
  const double scales[3] = { 1.0, 1e-3, 1e3 };
  for (int s = 0; s < 3; ++s)
  {
    vtkNew<vtkPolyData> scaled;
    scaled->DeepCopy(bone);
    for (vtkIdType i = 0; i < scaled->GetNumberOfPoints(); ++i)
    {
      double p[3];
      scaled->GetPoint(i, p);
      scaled->GetPoints()->SetPoint(i, p[0] * scales[s], p[1] * scales[s], p[2] * scales[s]);
    }
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(scaled);
    fit->SetTargetNumberOfVertices(500);
    fit->SetRefinement(true);
    fit->SetRefinementIterations(3);
    fit->Update();
    vtkFieldData* fd = fit->GetOutput()->GetFieldData();
    ASSERT_NE(fd->GetArray("Hausdorff_MeanPercent"), nullptr);
    mean[s] = fd->GetArray("Hausdorff_MeanPercent")->GetTuple1(0);
    maxError[s] = fd->GetArray("Hausdorff_MaxPercent")->GetTuple1(0);
  }
  for (int s = 1; s < 3; ++s)
  {
    EXPECT_NEAR(mean[s], mean[0], 0.01 * mean[0]) << "scale " << scales[s];
    EXPECT_NEAR(maxError[s], maxError[0], 0.05 * maxError[0]) << "scale " << scales[s];
  }
}
