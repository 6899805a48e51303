// latticekit-demo: the main job. A mandible osteotomy planned on a CT:
// CT -> mandible surface -> a scripted closed pen stroke around one side of
// the mandible body (split mode) -> capped cut into two pieces -> a lattice
// for each piece (the cut line locked: its points that hold it within the
// plan's cutLineTolerance kept exactly) -> a Metro report like the
// paper's Table 2 (no cut / cut / cut with quads), exported pieces and
// lattices, and PNG pictures.
#include "common/AppSupport.h"
#include "common/AtomicFile.h"
#include "common/CutReport.h"
#include "common/PlaneSection.h"
#include "common/ScanPicture.h"
#include "common/JsonFields.h"
#include "common/DistanceColourBar.h"
#include "latticekit/FeatureChains.h"

#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKClosedLineCutFilter.h"
#include "vtkLKCuttingGuideFilter.h"
#include "vtkLKExtractCutPieceFilter.h"
#include "vtkLKLatticeFitFilter.h"
#include "vtkLKLatticeSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKMetroFilter.h"
#include "vtkLKPolyDataConversion.h"
#include "vtkLKStrokeFeatureLineFilter.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkExtractEdges.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkMath.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTubeFilter.h>
#include <vtk_jsoncpp.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#ifndef LATTICEKIT_SOURCE_DIR
#define LATTICEKIT_SOURCE_DIR "."
#endif

namespace
{
void usage(std::ostream& os)
{
  os << "usage: latticekit-demo [INPUT] [-o FOLDER] [--plan PLAN.json] [options]\n"
        "\n"
        "Runs the main job, a mandible osteotomy plan on a CT: the mandible surface, a scripted\n"
        "closed pen stroke around one side of the mandible body (split mode), the capped cut into\n"
        "two pieces, a lattice for each piece with the cut line locked (the points of the line\n"
        "that hold it within the plan's cutLineTolerance, 0.05 mm by default, kept exactly, the rim\n"
        "a crease of the smooth surface), and a\n"
        "Metro report like the paper's Table 2 (no cut / cut / cut with quads). Writes to FOLDER\n"
        "(default latticekit-output): mandible.vtp/.stl (with the cut line split in), cut_line.vtp\n"
        "(its MeshPointId name mandible.vtp's points), piece0/1 (.stl .vtp .obj), the lattices and\n"
        "their surfaces, report.md and plan.png, pieces.png, error.png, cut_line_ct.png and\n"
        "cut_line_across_ct.png (the CT on the cut line's plane and across it).\n"
        "INPUT defaults to the bundled CT head and PLAN to its plan\n"
        "(sample_data/cthead/mandible_plan.json: crop box, seed, iso value, smoothing, cut plane,\n"
        "lattice size, cut line tolerance, view; see that file). A plan without \"smoothing\"\n"
        "(windowed-sinc iterations, 0 to 1000) and \"imageSmoothing\" (a Gaussian on the volume,\n"
        "0 to 20 voxels) gets latticekit-surface's defaults: none on a CT; half a voxel and 20\n"
        "iterations on a label map (1 and 0 give the surface made before December 2026).\n"
        "\n"
        "  --plan FILE      the plan (JSON)\n"
        "  --vertices N     lattice control vertices in all (default: the plan's)\n"
        "  --no-render      skip the PNGs (they need an X display: run under xvfb-run)\n"
        "  -q, --quiet      no progress bars\n"
        "  -h, --help       this help\n";
}

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}


/// The plan of the osteotomy (see sample_data/cthead/mandible_plan.json).
struct Plan
{
  double iso = 300.0;
  /// Windowed-sinc iterations on the surface and the Gaussian on the volume
  /// (voxels); -1: the surface filter's automatic choice, none for a CT and
  /// half a voxel and 20 iterations for a label map, as latticekit-surface's
  /// and the planner's (the bundled plan asks for 10 iterations on its CT).
  int smoothing = -1;
  double imageSmoothing = -1.0;
  bool crop = false;
  std::array<double, 6> box{};      ///< patient coordinates (as the surface), mm
  bool seeded = false;
  std::array<double, 3> seed{};     ///< the mandible's component
  std::array<double, 3> origin{};   ///< the cut plane
  std::array<double, 3> normal{};
  double penOffset = 0.3;           ///< mm off the surface
  double penStep = 1.0;             ///< mm between stroke points
  long vertices = 1500;
  /// Each piece's lattice keeps the points of its cut line that hold the
  /// line within this distance (mm), exactly; 0: every vertex of the line
  /// (a split line has one at each mesh edge it crosses).
  double lineTolerance = 0.05;
  std::array<double, 3> viewFrom{ 0, 0, 1 }, viewUp{ 0, -1, 0 };
  /// The patient's head and front in the scan's coordinates, for a scan
  /// whose file gives no orientation: the CT pictures stand head up.
  bool patientGiven = false;
  lkapp::HeadAndFront patient;
};

/// Reads the plan, every field's kind checked (a wrong one is refused with a
/// message naming it, not an exception).
bool readPlan(const Json::Value& root, Plan& plan, std::string& error)
{
  using namespace lkapp;
  const std::string where = "the plan";
  // A misspelt field would be dropped without a word, and the plan run with
  // the default in its place.
  const auto warnUnknown = [](const Json::Value& object, std::initializer_list<const char*> known, const char* name) {
    if (const std::string unknown = unknownMembers(object, known); !unknown.empty())
      std::cerr << "warning: " << name << " has fields latticekit-demo does not know, ignored: " << unknown << "\n";
  };
  warnUnknown(root,
    { "description", "iso", "smoothing", "imageSmoothing", "crop", "seed", "cut", "latticeVertices",
      "cutLineTolerance", "view", "patient" },
    "the plan");
  warnUnknown(root["cut"], { "origin", "normal", "penOffset", "penStep" }, "the plan's cut");
  warnUnknown(root["view"], { "from", "up" }, "the plan's view");
  warnUnknown(root["patient"], { "head", "front" }, "the plan's patient");
  long long smoothing = plan.smoothing, vertices = plan.vertices;
  // The surface filter's limits (it would clamp more iterations without a word).
  const auto iterations = [](const Json::Value& v, long long& out) { return jsonInteger(v, 0, 1000, out); };
  const auto gaussian = [](const Json::Value& v, double& out) { return jsonNumber(v, out) && out >= 0.0 && out <= 20.0; };
  const auto count = [](const Json::Value& v, long long& out) { return jsonInteger(v, 8, 100000000, out); };
  if (!jsonMember(root, "iso", plan.iso, jsonNumber, where, "a number", error) ||
    !jsonMember(root, "smoothing", smoothing, iterations, where, "a whole number from 0 to 1000", error) ||
    !jsonMember(root, "imageSmoothing", plan.imageSmoothing, gaussian, where,
      "a standard deviation from 0 to 20 voxels", error) ||
    !jsonMember(root, "latticeVertices", vertices, count, where, "a whole number from 8 to 100,000,000", error) ||
    !jsonMember(root, "cutLineTolerance", plan.lineTolerance,
      [](const Json::Value& v, double& out) { return jsonNumber(v, out) && out >= 0.0 && out <= 10.0; }, where,
      "a distance from 0 to 10 mm", error))
    return false;
  plan.smoothing = static_cast<int>(smoothing);
  plan.vertices = static_cast<long>(vertices);
  if (root.isMember("crop"))
  {
    if (!jsonNumbers(root["crop"], plan.box))
    {
      error = "the plan's crop must be [xmin, xmax, ymin, ymax, zmin, zmax]";
      return false;
    }
    if (!lkapp::isOrderedBox(plan.box.data()))
    {
      error = "the plan's crop must be [xmin, xmax, ymin, ymax, zmin, zmax], each min below its max";
      return false;
    }
    plan.crop = true;
  }
  if (root.isMember("seed"))
  {
    if (!jsonNumbers(root["seed"], plan.seed))
    {
      error = "the plan's seed must be [x, y, z]";
      return false;
    }
    plan.seeded = true;
  }
  const Json::Value& cut = root["cut"];
  if (!cut.isObject() || !jsonNumbers(cut["origin"], plan.origin) || !jsonNumbers(cut["normal"], plan.normal))
  {
    error = "the plan needs a cut plane: \"cut\": {\"origin\": [x, y, z], \"normal\": [x, y, z]}";
    return false;
  }
  if (!jsonMember(cut, "penOffset", plan.penOffset, jsonNumber, "the plan's cut", "a number", error) ||
    !jsonMember(cut, "penStep", plan.penStep, jsonNumber, "the plan's cut", "a number", error))
    return false;
  if (root.isMember("view") &&
    (!root["view"].isObject() || !jsonNumbers(root["view"]["from"], plan.viewFrom) ||
      !jsonNumbers(root["view"]["up"], plan.viewUp)))
  {
    error = "the plan's view needs \"from\" and \"up\" as [x, y, z]";
    return false;
  }
  if (root.isMember("patient"))
  {
    if (!lkapp::jsonHeadAndFront(root["patient"], plan.patient))
    {
      error = "the plan's patient needs \"head\" and \"front\" as [x, y, z]: non-zero and not parallel";
      return false;
    }
    plan.patientGiven = true;
  }
  const double n = std::sqrt(plan.normal[0] * plan.normal[0] + plan.normal[1] * plan.normal[1] + plan.normal[2] * plan.normal[2]);
  if (!(n > 0) || !(plan.penStep > 0) || plan.penOffset < 0)
  {
    error = "the plan's cut normal must be non-zero, penStep above 0 and penOffset 0 or more";
    return false;
  }
  return true;
}

/// Where the cut line lies against the plan's cut plane: its length, the
/// plane it lies in (the angle between that plane and the plan's, and the
/// distance of its centre from the plan's plane), how flat it is.
std::string lineAgainstPlan(vtkPolyData* line, const Plan& plan)
{
  const std::vector<lkapp::LineFacts> facts = lkapp::lineFacts(line);
  if (facts.empty())
    return "";
  const lkapp::LineFacts& f = facts.front();
  double n[3] = { plan.normal[0], plan.normal[1], plan.normal[2] };
  vtkMath::Normalize(n);
  const double angle = vtkMath::DegreesFromRadians(std::acos(std::min(1.0, std::abs(vtkMath::Dot(n, f.normal)))));
  const double offset = std::abs(vtkMath::Dot(n, f.centre) - vtkMath::Dot(n, plan.origin.data()));
  char text[500];
  std::snprintf(text, sizeof text,
    "The line is %.1f mm long; its best-fitting plane is %.2f deg from the plan's cut plane, its centre %.2f mm "
    "from it, and every vertex within %.2f mm of its own plane. It encloses %.1f mm^2 of bone (what the saw crosses), "
    "%.2f by %.2f mm across in that plane.",
    f.length, angle, offset, f.flatness, f.area, f.extentUp, f.extentRight);
  return text;
}

/// A number as a stream writes it (6 significant digits).
std::string number(double x)
{
  std::ostringstream text;
  text << x;
  return text.str();
}

/// The mean distance between a stroke's consecutive points, to 3 digits.
std::string penSpacing(vtkPolyData* stroke)
{
  double length = 0.0;
  for (vtkIdType i = 0; i + 1 < stroke->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    stroke->GetPoint(i, a);
    stroke->GetPoint(i + 1, b);
    length += std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", stroke->GetNumberOfPoints() > 1 ? length / (stroke->GetNumberOfPoints() - 1) : 0.0);
  return text;
}

bool loadPlan(const std::string& path, Plan& plan, std::string& error)
{
  return lkapp::loadJsonObject(
    path, "plan", [&](const Json::Value& root, std::string& message) { return readPlan(root, plan, message); }, error);
}

/// The scripted pen stroke: the section of the surface by the cut plane (the
/// closed loop nearest the plane's origin), traced every penStep mm and
/// penOffset mm off the surface, as a pen held just above the bone.
vtkSmartPointer<vtkPolyData> scriptedStroke(vtkPolyData* surface, const Plan& plan, std::string& error)
{
  const auto loops = lkapp::planeSectionLoops(surface, plan.origin, plan.normal);
  const int nearest = lkapp::nearestLoop(loops, plan.origin);
  if (nearest < 0)
  {
    error = "the plan's cut plane does not cross the mandible in a closed loop";
    return nullptr;
  }
  vtkNew<vtkPoints> pts;
  for (const auto& p : lkapp::strokeAlongLoop(loops[static_cast<std::size_t>(nearest)], plan.penStep, plan.penOffset))
    pts->InsertNextPoint(p.data());
  auto stroke = vtkSmartPointer<vtkPolyData>::New();
  stroke->SetPoints(pts);
  return stroke;
}

/// The edges of a piece's cut lines (vtkLKExtractCutPieceFilter's count).
vtkIdType cutLineEdges(vtkPolyData* border)
{
  vtkDataArray* count = border ? border->GetFieldData()->GetArray("CutLineEdges") : nullptr;
  return count ? static_cast<vtkIdType>(count->GetTuple1(0)) : 0;
}

/// The vertices of a piece's cut lines that its lattice keeps: every one
/// (closed lines: as many as edges), or with a tolerance those that hold each
/// line within it, as the fit chooses them (the fit filter's own reading of
/// the lines, lkvtk::lineEdges, and lk::chainVerticesToKeep).
vtkIdType keptLineVertices(vtkPolyData* border, vtkPolyData* piece, double tolerance)
{
  std::vector<lk::EdgeKey> edges;
  lk::TriangleMesh mesh;
  if (!(tolerance > 0.0) || !border || !lkvtk::lineEdges(border, piece, edges).empty() ||
    !lkvtk::toTriangleMesh(piece, mesh).empty())
    return cutLineEdges(border); // a piece the fit refuses says why there
  return static_cast<vtkIdType>(lk::featureVerticesToKeep(mesh.points, edges, tolerance));
}

struct Row
{
  std::string name;
  double vertices = 0, triangles = 0, quads = 0, polygons = 0;
  double featureEdges = 0, creaseEdges = 0; ///< the lattices' edges on the cut lines, and the creases among them
  long long bytes = 0;
  double max = 0, mean = 0, rms = 0;
  double colourTop = 0; ///< the distance (mm) the error picture maps to red
  double seconds = 0;
};

/// Lattices for each mesh (each keeps its locked border's vertices, and the
/// rest of the vertices are shared in proportion to the faces), their
/// surfaces appended, Metro against the meshes appended.
Row fitRow(const std::string& name, const std::vector<vtkSmartPointer<vtkPolyData>>& meshes,
  const std::vector<vtkSmartPointer<vtkPolyData>>& borders, double lineTolerance, long vertices, bool quads,
  const std::string& folder,
  const std::string& stem, bool quiet, vtkSmartPointer<vtkPolyData>& surfaceOut,
  std::vector<vtkSmartPointer<vtkPolyData>>& latticesOut)
{
  Row row;
  row.name = name;
  const auto start = Clock::now();
  // Locked border vertices first: a hollow bone's piece has the inner line
  // too, and a share by faces alone could leave it little else.
  double faces = 0;
  std::vector<vtkIdType> locked(meshes.size(), 0), shares(meshes.size(), 0);
  vtkIdType allLocked = 0;
  for (std::size_t i = 0; i < meshes.size(); ++i)
  {
    faces += static_cast<double>(meshes[i]->GetNumberOfPolys());
    if (i < borders.size())
      locked[i] = keptLineVertices(borders[i], meshes[i], lineTolerance);
    allLocked += locked[i];
  }
  const vtkIdType free = std::max<vtkIdType>(0, static_cast<vtkIdType>(vertices) - allLocked);
  vtkIdType given = 0;
  for (std::size_t i = 0; i < meshes.size(); ++i)
  {
    shares[i] = i + 1 < meshes.size()
      ? locked[i] + static_cast<vtkIdType>(std::llround(static_cast<double>(free) *
                      static_cast<double>(meshes[i]->GetNumberOfPolys()) / faces))
      : std::max<vtkIdType>(locked[i], static_cast<vtkIdType>(vertices) - given);
    given += shares[i];
  }
  vtkNew<vtkAppendPolyData> surfaces, dense;
  latticesOut.clear();
  for (std::size_t i = 0; i < meshes.size(); ++i)
  {
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(meshes[i]);
    if (i < borders.size() && borders[i] && borders[i]->GetNumberOfLines() > 0)
    {
      fit->SetFeatureLinesData(borders[i]);
      fit->LockFeaturesOn();
      fit->SetFeatureTolerance(lineTolerance);
    }
    fit->SetTargetNumberOfVertices(std::max<vtkIdType>(8, shares[i]));
    fit->SetQuadPairing(quads);
    fit->SetRefinement(quads); // the paper's open problem: refine after pairing
    fit->ComputeErrorOff();
    {
      lkapp::ProgressBar bar(fit, name + " lattice " + std::to_string(i), !quiet);
      fit->Update();
    }
    if (lkapp::errorCount() > 0)
      return row;
    vtkPolyData* lattice = fit->GetOutput();
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->DeepCopy(lattice);
    latticesOut.push_back(copy);
    row.vertices += lkapp::fieldValue(lattice, "ControlVertices");
    row.triangles += lkapp::fieldValue(lattice, "Triangles");
    row.quads += lkapp::fieldValue(lattice, "Quads");
    row.polygons += lkapp::fieldValue(lattice, "DisplayPolygons");
    row.featureEdges += lkapp::fieldValue(lattice, "FeatureEdges");
    row.creaseEdges += lkapp::fieldValue(lattice, "CreaseEdges");
    const std::string path = folder + "/" + stem + (meshes.size() > 1 ? std::to_string(i) : "") + ".vtp";
    std::string error;
    if (!lkapp::writeMesh(lattice, path, error, lkapp::coordinateSpace(meshes[i])))
    {
      std::cerr << "error: " << error << "\n";
      return row;
    }
    row.bytes += lkapp::fileBytes(path);
    vtkNew<vtkLKLatticeSurfaceFilter> surface;
    surface->SetInputData(lattice);
    surface->SetResolution(6);
    surface->Update();
    surfaces->AddInputData(surface->GetOutput());
    dense->AddInputData(meshes[i]);
  }
  surfaces->Update();
  dense->Update();
  vtkNew<vtkLKMetroFilter> metro;
  metro->SetInputData(surfaces->GetOutput());
  metro->SetTargetData(dense->GetOutput());
  metro->Update();
  vtkPolyData* m = metro->GetOutput();
  row.max = lkapp::fieldValue(m, "Hausdorff_MaxPercent");
  row.mean = lkapp::fieldValue(m, "Hausdorff_MeanPercent");
  row.rms = lkapp::fieldValue(m, "Hausdorff_RMSPercent");
  row.colourTop = metro->GetEffectiveColorMaximum();
  surfaceOut = vtkSmartPointer<vtkPolyData>::New();
  surfaceOut->ShallowCopy(m);
  row.seconds = since(start);
  return row;
}

vtkSmartPointer<vtkActor> surfaceActor(vtkPolyData* pd, const double colour[3])
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(pd);
  normals->SplittingOff();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetSpecular(0.2);
  return actor;
}

vtkSmartPointer<vtkActor> lineActor(vtkPolyData* pd, const double colour[3], double width)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(pd);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  actor->GetProperty()->LightingOff();
  return actor;
}

/// `display`: the X connection opened at the start (lkapp::openDisplay),
/// which every picture's window uses instead of opening its own.
bool renderPng(const std::vector<vtkSmartPointer<vtkActor>>& actors, vtkScalarBarActor* bar, const std::string& title,
  const Plan& plan, const std::string& png, void* display, std::string& error)
{
  vtkNew<vtkRenderer> renderer;
  for (const auto& a : actors)
    renderer->AddActor(a);
  // The colour bar gets a column of its own, so that the bone never runs under it.
  vtkNew<vtkRenderer> barRenderer;
  if (bar)
  {
    renderer->SetViewport(0.0, 0.0, 0.82, 1.0);
    barRenderer->SetViewport(0.82, 0.0, 1.0, 1.0);
    barRenderer->SetBackground(1.0, 1.0, 1.0);
    bar->SetPosition(0.47, 0.1); // room on the left for the above-range note
    bar->SetPosition2(0.5, 0.8);
    barRenderer->AddViewProp(bar);
  }
  vtkNew<vtkTextActor> text;
  text->SetInput(title.c_str());
  text->GetTextProperty()->SetFontSize(16);
  text->GetTextProperty()->SetColor(0, 0, 0);
  text->SetDisplayPosition(10, 10);
  renderer->AddViewProp(text);
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(plan.viewFrom.data());
  camera->SetViewUp(plan.viewUp.data());
  renderer->ResetCamera();
  camera->Zoom(1.3);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkRenderWindow> window;
  window->SetDisplayId(display);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  if (bar)
    window->AddRenderer(barRenderer);
  window->SetSize(1000, 800);
  return lkapp::writeScreenshot(window, png, error);
}
} // namespace

int main(int argc, char* argv[])
{
  lkapp::installCrashReport("latticekit-demo");
  std::string input = std::string(LATTICEKIT_SOURCE_DIR) + "/sample_data/cthead/cthead_hu_approx.nii.gz";
  std::string planPath, folder = "latticekit-output";
  long vertices = 0;
  bool render = true, quiet = false, inputGiven = false;
  lkapp::Arguments args(argc, argv, usage);
  std::string a;
  while (args.next(a))
  {
    if (a == "-o" || a == "--output")
      folder = args.value(a);
    else if (a == "--plan")
      planPath = args.value(a);
    else if (a == "--vertices")
      vertices = args.integer(a, 8, 10000000L, "an integer of at least 8");
    else if (a == "--no-render")
      render = false;
    else if (a == "-q" || a == "--quiet")
      quiet = true;
    else if (lkapp::Arguments::isOption(a))
      args.unknown(a);
    else
    {
      std::string slot = inputGiven ? "x" : "";
      args.positional(a, slot, "INPUT");
      input = a;
      inputGiven = true;
    }
  }
  if (planPath.empty())
  {
    if (inputGiven)
    {
      std::cerr << "error: an INPUT other than the bundled CT needs its --plan (see "
                   "sample_data/cthead/mandible_plan.json)\n";
      return 2;
    }
    planPath = std::string(LATTICEKIT_SOURCE_DIR) + "/sample_data/cthead/mandible_plan.json";
  }
  lkapp::installMessageHandler(quiet);
  Plan plan;
  std::string error;
  if (!loadPlan(planPath, plan, error))
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  if (vertices > 0)
    plan.vertices = vertices;
  // The pictures' windows share one connection, opened now (see openDisplay).
  void* display = render ? lkapp::openDisplay() : nullptr;
  if (render && !display)
  {
    std::cerr << "error: the pictures need an X display (DISPLAY is not set, or names no running server): run under "
                 "xvfb-run -a, or pass "
                 "--no-render\n";
    return 1;
  }
  // The report is written first as a stub that says the run did not finish:
  // it proves the folder writable, and a run that stops with an error does
  // not leave an earlier run's report beside its own files. The finished
  // report replaces it.
  if (!vtksys::SystemTools::MakeDirectory(folder))
  {
    std::cerr << "error: cannot make the folder '" << folder << "'\n";
    return 1;
  }
  if (!lkapp::writeFileAtomically(folder + "/report.md",
      "# latticekit main job: did not finish\n\nThe run on `" + vtksys::SystemTools::GetFilenameName(input) +
        "` with the plan `" + vtksys::SystemTools::GetFilenameName(planPath) +
        "` stopped with an error (printed on the terminal). Other files in this folder may be from an "
        "earlier run.\n",
      error))
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  const auto start = Clock::now();

  // 1. The mandible: the plan's box of the CT, padded with air so that the
  //    surface closes where the box cuts bone, the component at the seed.
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(input.c_str());
  {
    lkapp::ProgressBar bar(reader, "read CT", !quiet); // a DICOM folder of hundreds of slices takes a while
    reader->Update();
  }
  if (lkapp::errorCount() > 0)
    return 1;
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  bone->SetInputConnection(reader->GetOutputPort());
  if (plan.crop)
  {
    bone->CroppingOn();
    bone->SetCropBox(plan.box.data());
  }
  bone->SetIsoValue(plan.iso);
  bone->SetLabelMapMode(vtkLKBoneSurfaceFilter::LABEL_MAP_AUTO);
  bone->SetSmoothingIterations(plan.smoothing);
  bone->SetImageSmoothing(plan.imageSmoothing);
  if (plan.seeded)
  {
    bone->SetExtractionModeToSeededComponent();
    bone->SetSeedPoint(plan.seed.data());
  }
  {
    lkapp::ProgressBar bar(bone, "mandible surface", !quiet);
    bone->Update();
  }
  if (lkapp::errorCount() > 0)
    return 1;
  auto mandible = vtkSmartPointer<vtkPolyData>::New();
  mandible->ShallowCopy(bone->GetOutput());
  // "LPS" when the CT gives its orientation (the bundled NIfTI does not):
  // every file written below names it, as 3D Slicer's do.
  const std::string space = lkapp::coordinateSpace(mandible);

  // 2. The scripted pen stroke, split into the mesh.
  auto stroke = scriptedStroke(mandible, plan, error);
  if (!stroke)
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  vtkNew<vtkLKStrokeFeatureLineFilter> feature;
  feature->SetInputData(mandible);
  feature->SetStrokeData(stroke);
  feature->SetModeToSplit();
  feature->Update();
  if (lkapp::errorCount() > 0)
    return 1;
  vtkPolyData* line = feature->GetFeatureLineOutput();
  if (line->GetFieldData()->GetArray("Closed")->GetTuple1(0) < 0.5)
  {
    std::cerr << "error: the scripted stroke did not close\n";
    return 1;
  }
  vtkNew<vtkPolyData> marked;
  marked->ShallowCopy(feature->GetOutput());
  vtkNew<vtkCellArray> noLines;
  marked->SetLines(noLines);
  marked->GetCellData()->Initialize();

  // 3. The capped cut.
  vtkNew<vtkLKClosedLineCutFilter> cut;
  cut->SetInputData(marked);
  cut->SetLinesData(line);
  cut->CappingOn();
  cut->Update();
  if (lkapp::errorCount() > 0)
    return 1;
  // Each piece, and its cut line as the feature lines its lattice keeps.
  std::vector<vtkSmartPointer<vtkPolyData>> pieces, borders;
  vtkNew<vtkLKExtractCutPieceFilter> extract;
  extract->SetInputConnection(cut->GetOutputPort());
  extract->PassAttributesOff();
  for (int r = 0; r < cut->GetNumberOfPieces(); ++r)
  {
    extract->SetPiece(r);
    extract->Update();
    auto piece = vtkSmartPointer<vtkPolyData>::New();
    auto border = vtkSmartPointer<vtkPolyData>::New();
    piece->ShallowCopy(extract->GetOutput());
    border->ShallowCopy(extract->GetCutLinesOutput());
    piece->GetFieldData()->Initialize(); // the cut's counts are not the piece's, nor its lattice's
    lkapp::setCoordinateSpace(piece, space);
    pieces.push_back(piece);
    borders.push_back(border);
  }

  // 4. Files of the plan. The mandible is written with the cut line split
  // in (the same surface, with the line's vertices and edges), because the
  // line's MeshPointId names those points: the two files cut again, or fit
  // with the line kept, as they are.
  for (const auto& [mesh, stem] : std::vector<std::pair<vtkPolyData*, std::string>>{
         { marked, "mandible.vtp" }, { marked, "mandible.stl" }, { line, "cut_line.vtp" }, { stroke, "stroke.vtp" } })
    if (!lkapp::writeMesh(mesh, folder + "/" + stem, error, space))
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
  for (std::size_t p = 0; p < pieces.size(); ++p)
    for (const char* ext : lkapp::pieceExtensions)
      if (!lkapp::writeMesh(pieces[p], folder + "/" + lkapp::pieceFileStem(p) + ext, error, space))
      {
        std::cerr << "error: " << error << "\n";
        return 1;
      }

  // The cutting guide: the plan's cut is a plane cut, so a printed guide
  // with a slot in that plane takes it to the patient.
  vtkNew<vtkLKCuttingGuideFilter> guide;
  guide->SetInputData(mandible);
  guide->SetPlaneOrigin(plan.origin.data());
  guide->SetPlaneNormal(plan.normal.data());
  std::string guideError;
  {
    // The plan goes on without it; the report says why.
    lkapp::ProgressBar bar(guide, "cutting guide", !quiet);
    guideError = lkapp::updateKeepingErrors(guide);
    if (guideError.empty() && guide->GetOutput()->GetNumberOfPolys() == 0)
      guideError = "no guide was made";
  }
  for (const char* name : { "guide.stl", "guide.vtp" })
    if (guideError.empty() && !lkapp::writeMesh(guide->GetOutput(), folder + "/" + name, error, space))
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }

  // 5. Table 2: no cut / cut / cut with quads (and refinement). Each piece
  //    keeps its locked lines' vertices; with fewer free vertices than
  //    locked ones the pieces' lattices are fans of slivers off the line
  //    (or cannot reach their share at all), so such a plan is refused.
  vtkIdType lockedVertices = 0, lineVertices = 0;
  for (std::size_t i = 0; i < borders.size(); ++i)
  {
    lockedVertices += keptLineVertices(borders[i], pieces[i], plan.lineTolerance);
    lineVertices += cutLineEdges(borders[i]); // closed lines: as many vertices as edges
  }
  if (plan.vertices < 2 * lockedVertices)
  {
    std::cerr << "error: the plan's latticeVertices (" << plan.vertices << ") is too few for the cut: the "
              << pieces.size() << " pieces keep " << lockedVertices
              << " vertices of their cut lines, and need at least as many more; give latticeVertices "
              << 2 * lockedVertices << " or more (in the plan, or --vertices " << 2 * lockedVertices
              << "; the pieces are written to " << folder << ")\n";
    return 1;
  }
  vtkSmartPointer<vtkPolyData> surfaceWhole, surfaceCut, surfaceQuads;
  std::vector<vtkSmartPointer<vtkPolyData>> latticesWhole, latticesCut, latticesQuads;
  std::vector<Row> rows;
  rows.push_back(fitRow("no cut", { mandible }, {}, 0.0, plan.vertices, false, folder, "lattice_whole", quiet, surfaceWhole,
    latticesWhole));
  rows.push_back(fitRow("cut", pieces, borders, plan.lineTolerance, plan.vertices, false, folder, "lattice_piece", quiet, surfaceCut,
    latticesCut));
  rows.push_back(fitRow("cut, quads, refined", pieces, borders, plan.lineTolerance, plan.vertices, true, folder, "lattice_quads_piece",
    quiet, surfaceQuads, latticesQuads));
  if (lkapp::errorCount() > 0)
    return 1;
  for (const auto& [pd, stem] : std::vector<std::pair<vtkPolyData*, std::string>>{
         { surfaceCut, "lattice_surface_cut.vtp" }, { surfaceQuads, "lattice_surface_quads.vtp" } })
    if (!lkapp::writeMesh(pd, folder + "/" + stem, error, space))
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }

  // 6. The report.
  std::ostringstream report;
  report << "# latticekit main job: a mandible osteotomy plan\n\n"
         << (bone->GetTreatedAsLabelMap() ? "Label map" : "CT") << ": `" << vtksys::SystemTools::GetFilenameName(input)
         << "`; plan: `" << vtksys::SystemTools::GetFilenameName(planPath) << "`.\n\n"
         << "- Mandible surface ("
         << (bone->GetTreatedAsLabelMap() ? "label map, level " + number(bone->GetEffectiveIsoValue())
                                          : number(plan.iso) + " HU")
         << (plan.crop ? ", the plan's box, padded with air" : "")
         << (plan.seeded ? ", the component at the seed" : "") << "; "
         << lkapp::smoothingWords(bone->GetEffectiveImageSmoothing(), bone->GetEffectiveSmoothingIterations()) << "): "
         << mandible->GetNumberOfPoints() << " vertices, " << mandible->GetNumberOfPolys() << " triangles.\n"
         << "- Scripted pen stroke: the section by the cut plane around one side of the body, "
         << stroke->GetNumberOfPoints() << " points " << penSpacing(stroke) << " mm apart on average (every "
         << plan.penStep << " mm or more along the section's own points), " << plan.penOffset
         << " mm off the surface; split mode: a closed cut line of " << line->GetNumberOfPoints() - 1
         << " vertices whose edges follow the stroke, split into the surface ("
         << marked->GetNumberOfPoints() - mandible->GetNumberOfPoints()
         << " new vertices; `mandible.vtp` is the surface with them, and `cut_line.vtp` names its points by "
            "MeshPointId). "
         << lineAgainstPlan(line, plan) << "\n"
         << "- Capped cut: " << pieces.size() << " pieces, each closed by the same flat cap"
         << (cut->GetNumberOfInnerWallLines() > 0
                ? " (the bone is hollow there: the cut also takes the plane's section of the marrow cavity, " +
                  std::to_string(cut->GetNumberOfInnerWallLines()) + " inner line(s), and the cap is an annulus)"
                : std::string())
         << ":";
  for (std::size_t p = 0; p < pieces.size(); ++p)
    report << " piece " << p << " " << pieces[p]->GetNumberOfPolys() << " triangles" << (p + 1 < pieces.size() ? ";" : ".");
  if (guideError.empty())
  {
    const std::array<double, 3> along = lkapp::guideDirection(guide->GetApproachUsed());
    char text[400];
    std::snprintf(text, sizeof text,
      "\n- Cutting guide (`guide.stl`): a shell %.1f mm thick on %.0f mm^2 of the bone within %.0f mm of the cut "
      "plane, on the outer side (along the section's short axis, away from the bone round the cut; put on along "
      "(%.3f, %.3f, %.3f)), with a slot %.1f mm wide and %.1f mm long in the plane for the saw and %d screw "
      "hole(s) of %.1f mm beside it to hold it; %.0f mm^3.",
      guide->GetThickness(), guide->GetContactArea(), guide->GetReach(), along[0], along[1], along[2],
      guide->GetSlotWidth(), guide->GetSlotLength(),
      guide->GetNumberOfScrewHoles(), guide->GetScrewHoleDiameter(), guide->GetVolume());
    report << text;
  }
  else
    report << "\n- No cutting guide: " << guideError;
  report << "\n\n## Table 2 (as in the paper): lattices at " << plan.vertices
         << " control vertices in all\n\n"
         << "Metro: symmetric Hausdorff distance between the lattice surfaces (one Doo-Sabin step, Gregory "
            "patches) and the dense surfaces (the mandible; the capped pieces), in % of the bounding-box "
            "diagonal. With the cut, the cut line is locked: "
         << (plan.lineTolerance > 0.0
                ? "each piece keeps the vertices of its cut line that hold the line within " +
                  number(plan.lineTolerance) +
                  " mm (the plan's cutLineTolerance), exactly where they are, as lattice vertices (" +
                  std::to_string(lockedVertices) + " of the " + std::to_string(lineVertices) +
                  " line vertices of the two pieces), and gets the rest"
                : std::string("each piece keeps every vertex of its cut line as a lattice vertex (the plan's "
                              "cutLineTolerance is 0) and gets the rest"))
         << " of the vertices in proportion to its faces."
         << (rows.size() > 1 && rows[1].featureEdges > 0
                ? " Where the surface bends across the line by more than " +
                  number(vtkSmartPointer<vtkLKLatticeFitFilter>::New()->GetCreaseAngle()) +
                  " degrees on average (the rim, where the flat cap meets the bone), its lattice edges are creases "
                  "of the smooth surface, which keeps the rim's edge: " +
                  number(rows[1].creaseEdges) + " of the pieces' " + number(rows[1].featureEdges) + " line edges."
                : std::string())
         << "\n\n"
         << "| model | control vertices | triangles | quads | display polygons | lattice bytes | max % | mean % | RMS % | time s |\n"
         << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    char text[400];
    std::snprintf(text, sizeof text, "| %s | %.0f | %.0f | %.0f | %.0f | %lld | %.4f | %.4f | %.4f | %.1f |\n",
      r.name.c_str(), r.vertices, r.triangles, r.quads, r.polygons, r.bytes, r.max, r.mean, r.rms, r.seconds);
    report << text;
  }
  report << "\nFiles: `mandible.vtp`/`.stl`, `stroke.vtp`, `cut_line.vtp`, " << (guideError.empty() ? "`guide.stl`/`.vtp`, " : "")
         << "`piece0`/`piece1` (`.stl` for "
            "printing, `.vtp`, `.obj`), `lattice_whole.vtp`, `lattice_piece*.vtp`, `lattice_quads_piece*.vtp`, "
            "`lattice_surface_cut.vtp`, `lattice_surface_quads.vtp` (with the Metro distance)";

  // 7. Pictures.
  if (render)
  {
    const double boneColour[3] = { 0.93, 0.87, 0.72 }, red[3] = { 0.85, 0.1, 0.1 };
    const double pieceColour[2][3] = { { 0.93, 0.85, 0.65 }, { 0.55, 0.72, 0.95 } }, cage[3] = { 0.15, 0.15, 0.15 };
    vtkNew<vtkTubeFilter> tube; // the line as a tube, visible from any side
    tube->SetInputData(line);
    tube->SetRadius(0.5);
    tube->SetNumberOfSides(8);
    tube->Update();
    auto tubePd = vtkSmartPointer<vtkPolyData>::New();
    tubePd->ShallowCopy(tube->GetOutput());
    const double teal[3] = { 0.0, 0.55, 0.6 };
    std::vector<vtkSmartPointer<vtkActor>> planActors{ surfaceActor(mandible, boneColour), surfaceActor(tubePd, red) };
    if (guideError.empty())
      planActors.push_back(surfaceActor(guide->GetOutput(), teal));
    bool ok = renderPng(planActors, nullptr,
      guideError.empty() ? "the plan: the osteotomy line (red) from the scripted stroke, its cutting guide (teal)"
                         : "the plan: the osteotomy line (red) from the scripted stroke",
      plan, folder + "/plan.png", display, error);
    std::vector<vtkSmartPointer<vtkActor>> actors;
    for (std::size_t p = 0; p < pieces.size(); ++p)
    {
      vtkNew<vtkLKLatticeSurfaceFilter> surface;
      surface->SetInputData(latticesQuads[p]);
      surface->SetResolution(6);
      surface->Update();
      auto s = vtkSmartPointer<vtkPolyData>::New();
      s->ShallowCopy(surface->GetOutput());
      actors.push_back(surfaceActor(s, pieceColour[p % 2]));
      vtkNew<vtkExtractEdges> edges;
      edges->SetInputData(latticesQuads[p]);
      edges->Update();
      auto e = vtkSmartPointer<vtkPolyData>::New();
      e->ShallowCopy(edges->GetOutput());
      actors.push_back(lineActor(e, cage, 1.0));
    }
    ok = ok && renderPng(actors, nullptr, "the two pieces: lattice cages and their smooth surfaces", plan,
                 folder + "/pieces.png", display, error);
    surfaceQuads->GetPointData()->SetActiveScalars("Distance");
    double range[2];
    surfaceQuads->GetPointData()->GetArray("Distance")->GetRange(range);
    vtkNew<vtkLookupTable> lut;
    vtkNew<vtkScalarBarActor> bar;
    lkapp::distanceColourBar(rows.back().colourTop, range[1], lut, bar);
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(surfaceQuads);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(normals->GetOutputPort());
    mapper->SetLookupTable(lut);
    mapper->UseLookupTableScalarRangeOn();
    mapper->SetScalarModeToUsePointFieldData();
    mapper->SelectColorArray("Distance");
    vtkNew<vtkActor> coloured;
    coloured->SetMapper(mapper);
    ok = ok && renderPng({ coloured }, bar, "Metro distance of the quad lattices to the pieces", plan, folder + "/error.png", display, error);
    // The CT on the cut line's plane (what the saw passes through) and
    // across it (the bone along its length, the cut as a line).
    const std::vector<lkapp::LineFacts> facts = lkapp::lineFacts(line);
    const bool oriented = lkapp::coordinateSpace(mandible) == "LPS";
    // A scan without orientation stands as the plan says its patient lies.
    const bool headUpAsPlanned = plan.patientGiven && !oriented;
    if (ok && !facts.empty())
    {
      lkapp::ScanPictureRequest request;
      vtkNew<vtkIdList> ids;
      line->GetCellPoints(0, ids);
      request.line.resize(static_cast<std::size_t>(ids->GetNumberOfIds()));
      for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
        line->GetPoint(ids->GetId(i), request.line[static_cast<std::size_t>(i)].data());
      const lkapp::LineFacts& f = facts.front();
      request.centre = { f.centre[0], f.centre[1], f.centre[2] };
      request.normal = { f.normal[0], f.normal[1], f.normal[2] };
      const bool labelMap = bone->GetTreatedAsLabelMap();
      request.patientGiven = headUpAsPlanned;
      request.patient = plan.patient;
      for (const bool across : { false, true })
      {
        request.across = across;
        lkapp::ScanPicture scanPicture;
        std::string why;
        if (!lkapp::makeScanPicture(reader->GetOutput(), reader->GetPatientMatrix(), labelMap, mandible, request,
              scanPicture, why))
        {
          std::cerr << "error: the CT " << (across ? "across" : "on") << " the cut line: " << why << "\n";
          return 1;
        }
        scanPicture.title = std::string(labelMap ? "label map" : "CT") +
          (across ? " across the cut line" : " on the cut line's plane") +
          (request.patientGiven ? ", head up as the plan states" : "");
        scanPicture.directions = oriented;
        ok = ok &&
          lkapp::writeScanPicture(scanPicture, 600,
            folder + (across ? "/cut_line_across_ct.png" : "/cut_line_ct.png"), error, display);
      }
    }
    if (!ok)
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
    report << ", `plan.png`, `pieces.png`, `error.png`, `cut_line_ct.png` and `cut_line_across_ct.png` (the CT on the "
              "cut line's plane and across it"
           << (headUpAsPlanned ? ", head up as the plan's \"patient\" states: the scan gives no orientation" : "")
           << ")";
  }
  report << ".\n\nTotal time: " << std::fixed;
  report.precision(1);
  report << since(start) << " s.\n";
  if (!lkapp::writeFileAtomically(folder + "/report.md", report.str(), error))
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  std::cout << report.str();
  return 0;
}
