// latticekit-planner: the osteotomy planner in a plain VTK render window.
// Draw strokes on the bone, turn them into feature lines, cut along closed
// lines, fit lattices to the pieces, see the Metro error, undo and redo,
// deform the pieces (bump, box, smoothing brush on adaptively refined
// patches), save and replay sessions (JSON), export the pieces.
#include "common/AppSupport.h"
#include "common/DistanceColourBar.h"
#include "common/JsonFields.h"
#include "planner/PlannerSession.h"

#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKClosedLineCutFilter.h"
#include "vtkLKLatticeFitFilter.h"
#include "vtkLKLatticeSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKMeshRepairFilter.h"
#include "vtkLKMetroFilter.h"
#include "vtkLKPatchDeformationFilter.h"
#include "vtkLKStrokeFeatureLineFilter.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCellPicker.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkExtractEdges.h>
#include <vtkFieldData.h>
#include <vtkGeometryFilter.h>
#include <vtkIdTypeArray.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLookupTable.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkThreshold.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkMatrix4x4.h>
#include <vtkWindowToImageFilter.h>
#include <vtk_jsoncpp.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numeric>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace lkplanner;

const char* kHelp = "d: draw on/off | 1 paint 2 nearest 3 snap 4 split | x: cut (capped) | l: lattice | m: Metro colours\n"
                    "n: pick the segment (smallest piece first) | g: move it (drag; shift+drag rotates) | r: reset its move\n"
                    "f: deform tool (bump, box, smooth, off: pick and drag up/down) | [ ]: tool radius\n"
                    "z: undo  y: redo | w: save session | e: export pieces | q: quit | mouse: rotate, pan, zoom";

bool isIdentity(const std::array<double, 16>& m)
{
  for (int i = 0; i < 16; ++i)
    if (m[static_cast<std::size_t>(i)] != (i % 5 == 0 ? 1.0 : 0.0))
      return false;
  return true;
}

std::string matrixText(const std::array<double, 16>& m)
{
  std::ostringstream os;
  os.precision(6);
  os << std::fixed;
  for (int r = 0; r < 4; ++r)
  {
    os << "  ";
    for (int c = 0; c < 4; ++c)
      os << (c ? " " : "") << m[static_cast<std::size_t>(4 * r + c)];
    os << "\n";
  }
  return os.str();
}

/// The planner's deformation tools, in the order `f` cycles through them.
enum Tool
{
  NO_TOOL,
  BUMP,
  BOX,
  SMOOTH,
  TOOL_COUNT
};

const char* toolName(int tool)
{
  return tool == BUMP ? "bump" : tool == BOX ? "box" : tool == SMOOTH ? "smooth" : "off";
}

/// `text` with every line broken at spaces to at most `width` characters
/// (a longer word stays whole).
std::string wrapped(const std::string& text, std::size_t width)
{
  std::string out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
  {
    std::string current;
    std::istringstream words(line);
    for (std::string word; words >> word;)
    {
      if (!current.empty() && current.size() + 1 + word.size() > width)
      {
        out += current + "\n";
        current = "  "; // continuation lines are indented
      }
      current += (current.empty() || current == "  " ? "" : " ") + word;
    }
    out += current + "\n";
  }
  if (!out.empty())
    out.pop_back();
  return out;
}

/// Appends `line` to a message of several lines.
void addLine(std::string& message, const std::string& line)
{
  message += (message.empty() ? "" : "\n") + line;
}

/// Each line of `text` as its own line of `message`, after `prefix`.
void addLines(std::string& message, const std::string& prefix, const std::string& text)
{
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty())
      addLine(message, prefix + line);
}

std::array<double, 3> pieceColour(std::size_t p)
{
  const double colours[4][3] = { { 0.93, 0.85, 0.65 }, { 0.6, 0.75, 0.93 }, { 0.7, 0.9, 0.7 }, { 0.95, 0.7, 0.7 } };
  return { colours[p % 4][0], colours[p % 4][1], colours[p % 4][2] };
}

class Planner
{
public:
  vtkSmartPointer<vtkPolyData> bone;
  Session session;
  int mode = vtkLKStrokeFeatureLineFilter::NEAREST_EDGES;
  bool drawing = false;
  std::vector<std::array<double, 3>> current;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkTextActor> help, status, messages;
  vtkNew<vtkScalarBarActor> scalarBar;
  vtkNew<vtkLookupTable> distanceColours; ///< the Metro colours of every piece
  vtkNew<vtkActor> strokeActor;
  vtkNew<vtkPolyData> strokePd;
  std::vector<vtkSmartPointer<vtkActor>> sceneActors;
  std::vector<vtkSmartPointer<vtkPolyData>> pieces;
  std::string message; ///< a problem: shown, and reported as "message:" in batch runs
  std::string notice;  ///< an outcome (saved, exported): shown only
  bool cutFailed = false;
  bool moving = false;                    ///< the mouse moves the segment
  int tool = NO_TOOL;                     ///< the deformation tool the mouse uses
  double radius = 1.0;                    ///< the tool's radius (set from the bone's size)
  vtkNew<vtkActor> preview;               ///< the piece being deformed, live
  std::vector<double> frameMs, updateMs;  ///< per mouse move: deformation plus render, deformation alone
  std::vector<Session> undoStack, redoStack; ///< whole-session snapshots
  std::vector<std::vector<vtkSmartPointer<vtkActor>>> pieceActors;
  /// Each piece's lattice and its surface, kept while the piece and the
  /// vertex count do not change: toggling Metro, a stroke that leaves the
  /// cut as it was or a deformation of another piece refits nothing.
  struct FittedLattice
  {
    std::uint64_t key = 0;
    vtkSmartPointer<vtkPolyData> lattice, surface; ///< empty surface: the fit failed
    std::string errors;
    /// The surface with its Metro distance to the piece, once asked for.
    vtkSmartPointer<vtkPolyData> metro;
    double colourMaximum = 0.0, hausdorff = 0.0;
  };
  std::vector<FittedLattice> lattices;
  std::size_t latticeFits = 0, latticesReused = 0;

  /// Call before a change: the session as it was goes on the undo stack.
  void remember() { remember(session); }
  /// After a drag that changed the session live: the session before it.
  void remember(const Session& before)
  {
    undoStack.push_back(before);
    redoStack.clear();
  }

  bool hasSegment() const { return session.segment >= 0 && session.segment < static_cast<int>(pieces.size()); }

  vtkSmartPointer<vtkMatrix4x4> segmentMatrix() const
  {
    auto m = vtkSmartPointer<vtkMatrix4x4>::New();
    m->DeepCopy(session.segmentMatrix.data());
    return m;
  }

  /// Shows the segment where its transform puts it.
  void placeSegment(const std::array<double, 16>& matrix)
  {
    for (std::size_t p = 0; p < pieceActors.size(); ++p)
      for (auto& a : pieceActors[p])
      {
        if (static_cast<int>(p) == session.segment)
        {
          vtkNew<vtkMatrix4x4> m;
          m->DeepCopy(matrix.data());
          a->SetUserMatrix(m);
        }
        else
          a->SetUserMatrix(nullptr);
      }
  }

  /// The segment's transform as the surgery plan states it: which piece, the
  /// matrix, its translation and rotation angle.
  std::string segmentText() const
  {
    if (!hasSegment())
      return "";
    const auto& m = session.segmentMatrix;
    const double trace = m[0] + m[5] + m[10];
    const double angle = std::acos(std::clamp((trace - 1.0) / 2.0, -1.0, 1.0)) * 180.0 / 3.14159265358979;
    char line[200];
    std::snprintf(line, sizeof line, "segment: piece %d moved, translation %.2f %.2f %.2f mm, rotation %.2f deg\n",
      session.segment, m[3], m[7], m[11], angle);
    return line + matrixText(m);
  }

  void setup()
  {
    window->AddRenderer(renderer);
    window->SetSize(1000, 750);
    window->SetWindowName("latticekit planner");
    renderer->SetBackground(1, 1, 1);
    help->SetInput(kHelp);
    help->GetTextProperty()->SetFontSize(13);
    help->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
    help->SetDisplayPosition(8, 8);
    renderer->AddViewProp(help);
    status->GetTextProperty()->SetFontSize(15);
    status->GetTextProperty()->SetColor(0.1, 0.1, 0.4);
    status->SetDisplayPosition(8, 78);
    renderer->AddViewProp(status);
    // Problems and warnings, at the top where they are seen while drawing.
    messages->GetTextProperty()->SetFontSize(14);
    messages->GetTextProperty()->SetColor(0.6, 0.1, 0.0);
    messages->GetTextProperty()->SetVerticalJustificationToTop();
    messages->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    messages->GetPositionCoordinate()->SetValue(0.01, 0.985);
    renderer->AddViewProp(messages);
    scalarBar->SetVisibility(false);
    renderer->AddViewProp(scalarBar);
    vtkNew<vtkPolyDataMapper> sm;
    sm->SetInputData(strokePd);
    strokeActor->SetMapper(sm);
    strokeActor->GetProperty()->SetColor(0.9, 0.1, 0.1);
    strokeActor->GetProperty()->SetLineWidth(3);
    strokeActor->GetProperty()->SetPointSize(6);
    strokeActor->PickableOff(); // strokes are picked on the bone, never on themselves
    renderer->AddActor(strokeActor);
    preview->SetVisibility(false);
    preview->PickableOff();
    renderer->AddActor(preview);
    radius = 0.05 * bone->GetLength();
  }

  /// The strokes and the cut, kept while they do not change (the lattice,
  /// Metro, segment and deformation keys do not redo them).
  struct CutStage
  {
    std::string key;
    std::vector<std::pair<vtkSmartPointer<vtkPolyData>, double>> lines; ///< feature lines, shade
    std::vector<vtkSmartPointer<vtkPolyData>> pieces;
    std::string message;
    bool failed = false;
    int innerWallLines = 0; ///< lines the cut added on a hollow bone's inner walls
  } cut;
  /// One deformation filter per piece: it keeps the refined mesh between
  /// updates, so a drag or a brush dab costs one deformation.
  std::vector<vtkSmartPointer<vtkLKPatchDeformationFilter>> deformers;

  void computeCut()
  {
    const std::string key = cutKey(session);
    if (!cut.pieces.empty() && cut.key == key)
      return;
    cut = CutStage();
    cut.key = key;
    deformers.clear();
    vtkSmartPointer<vtkPolyData> surface = bone;
    std::vector<vtkSmartPointer<vtkPolyData>> closedLines;
    for (std::size_t i = 0; i < session.strokes.size(); ++i)
    {
      const Stroke& st = session.strokes[i];
      const std::string which = "stroke " + std::to_string(i + 1) + " (" + modeName(st.mode) + ")";
      vtkNew<vtkPoints> pts;
      for (const auto& p : st.points)
        pts->InsertNextPoint(p.data());
      vtkNew<vtkPolyData> stroke;
      stroke->SetPoints(pts);
      vtkNew<vtkLKStrokeFeatureLineFilter> f;
      f->SetInputData(facesOnly(surface));
      f->SetStrokeData(stroke);
      f->SetMode(st.mode);
      const int errorsBefore = lkapp::errorCount(), warningsBefore = lkapp::warningCount();
      f->Update();
      const std::string warned = lkapp::warningsSince(warningsBefore);
      if (!warned.empty())
        addLines(cut.message, which + ": ", warned);
      if (lkapp::errorCount() > errorsBefore || f->GetOutput()->GetNumberOfPoints() == 0)
      {
        const std::string why = lkapp::errorsSince(errorsBefore);
        addLine(cut.message, which + " failed: " + (why.empty() ? "no feature line" : why));
        continue; // the stroke stays in the session; the message says why
      }
      auto next = vtkSmartPointer<vtkPolyData>::New();
      next->ShallowCopy(f->GetOutput());
      surface = next;
      // The earlier lines onto the new surface: a split stroke that crosses
      // one cuts its edges (the cut needs its loops along the mesh's edges).
      for (auto& earlier : cut.lines)
      {
        vtkNew<vtkPolyData> carried;
        if (f->CarryLine(earlier.first, carried))
          earlier.first->DeepCopy(carried);
      }
      auto line = vtkSmartPointer<vtkPolyData>::New();
      line->DeepCopy(f->GetFeatureLineOutput());
      cut.lines.emplace_back(line, st.mode == vtkLKStrokeFeatureLineFilter::PAINT ? 0.2 : 0.0);
      if (line->GetFieldData()->GetArray("Closed")->GetComponent(0, 0) > 0.5 &&
        st.mode != vtkLKStrokeFeatureLineFilter::PAINT)
        closedLines.push_back(line);
    }
    vtkSmartPointer<vtkPolyData> faces = facesOnly(surface);
    if (session.cut && !closedLines.empty())
    {
      vtkNew<vtkPolyData> loops;
      vtkNew<vtkPoints> lp;
      vtkNew<vtkCellArray> lc;
      vtkNew<vtkIdTypeArray> ids;
      ids->SetName("MeshPointId");
      for (const auto& l : closedLines)
      {
        vtkDataArray* mid = l->GetPointData()->GetArray("MeshPointId");
        lc->InsertNextCell(l->GetNumberOfPoints());
        for (vtkIdType i = 0; i < l->GetNumberOfPoints(); ++i)
        {
          lc->InsertCellPoint(lp->InsertNextPoint(l->GetPoint(i)));
          ids->InsertNextValue(static_cast<vtkIdType>(mid->GetComponent(i, 0)));
        }
      }
      loops->SetPoints(lp);
      loops->SetLines(lc);
      loops->GetPointData()->AddArray(ids);
      vtkNew<vtkLKClosedLineCutFilter> cutter;
      cutter->SetInputData(faces);
      cutter->SetLinesData(loops);
      cutter->SetCapping(session.capping);
      const int before = lkapp::errorCount(), warningsBefore = lkapp::warningCount();
      cutter->Update();
      const std::string warned = lkapp::warningsSince(warningsBefore);
      if (!warned.empty())
        addLines(cut.message, "the cut: ", warned);
      if (lkapp::errorCount() == before)
      {
        for (int r = 0; r < cutter->GetNumberOfPieces(); ++r)
          cut.pieces.push_back(region(cutter->GetOutput(), r));
        cut.innerWallLines = cutter->GetNumberOfInnerWallLines();
      }
      else
      {
        addLine(cut.message, "the cut failed: " + lkapp::errorsSince(before));
        cut.failed = true;
      }
    }
    else if (session.cut)
      addLine(cut.message, "no closed line to cut along: draw a stroke whose ends meet");
    if (cut.pieces.empty())
    {
      auto whole = vtkSmartPointer<vtkPolyData>::New();
      whole->ShallowCopy(faces);
      cut.pieces.push_back(whole);
    }
  }

  /// The filter call for one deformation.
  static void addTo(vtkLKPatchDeformationFilter* f, const Deformation& d)
  {
    const auto& c = d.centre;
    const double r = d.radius;
    if (d.tool == "bump")
      f->AddFunctionalDeformation(c[0], c[1], c[2], d.amount, d.falloff, r);
    else if (d.tool == "box")
      f->AddRangeDeformation(c[0] - r, c[0] + r, c[1] - r, c[1] + r, c[2] - r, c[2] + r, d.amount * d.normal[0],
        d.amount * d.normal[1], d.amount * d.normal[2]);
    else
      f->AddSmoothingDeformation(c[0], c[1], c[2], r, d.iterations);
  }

  /// The deformation filter of piece p (made on first use).
  vtkLKPatchDeformationFilter* deformer(std::size_t p)
  {
    deformers.resize(cut.pieces.size());
    if (!deformers[p])
    {
      deformers[p] = vtkSmartPointer<vtkLKPatchDeformationFilter>::New();
      deformers[p]->SetInputData(cut.pieces[p]);
    }
    return deformers[p];
  }

  /// The session's deformations applied to the cut pieces, in order.
  void applyDeformations()
  {
    pieces = cut.pieces;
    std::vector<std::vector<const Deformation*>> perPiece(pieces.size());
    for (std::size_t i = 0; i < session.deformations.size(); ++i)
    {
      const Deformation& d = session.deformations[i];
      if (d.piece < static_cast<int>(pieces.size()))
        perPiece[static_cast<std::size_t>(d.piece)].push_back(&d);
      else
        addLine(message, "deformation " + std::to_string(i) + " is on piece " + std::to_string(d.piece) +
          ", which does not exist: the plan has " + std::to_string(pieces.size()) + " piece(s)");
    }
    for (std::size_t p = 0; p < pieces.size(); ++p)
    {
      if (perPiece[p].empty())
      {
        if (p < deformers.size() && deformers[p])
          deformers[p]->RemoveAllDeformations(); // undone: the next drag starts from the cut piece
        continue;
      }
      vtkLKPatchDeformationFilter* f = deformer(p);
      f->RemoveAllDeformations();
      for (const Deformation* d : perPiece[p])
        addTo(f, *d);
      const int before = lkapp::errorCount();
      f->Update(); // only what changed is redone (the filter keeps its state)
      if (lkapp::errorCount() > before)
      {
        addLine(message, "cannot deform piece " + std::to_string(p) + ": " + lkapp::errorsSince(before));
        continue;
      }
      auto deformed = vtkSmartPointer<vtkPolyData>::New();
      deformed->ShallowCopy(f->GetOutput());
      pieces[p] = deformed;
    }
  }

  /// Re-runs the plan from the bone: strokes, cut (kept while unchanged),
  /// deformations, lattices, colours.
  void rebuild()
  {
    for (auto& a : sceneActors)
      renderer->RemoveActor(a);
    sceneActors.clear();
    scalarBar->SetVisibility(false);
    computeCut();
    message = cut.message;
    cutFailed = cut.failed;
    for (const auto& [line, shade] : cut.lines)
      addLineActor(line, shade);
    applyDeformations();
    if (lattices.size() > pieces.size())
      lattices.resize(pieces.size()); // pieces the cut no longer makes
    pieceActors.assign(pieces.size(), {});
    // Every piece's Metro colours share one scale: the largest of their colour maxima.
    double colourTop = 0.0, largest = 0.0;
    for (std::size_t p = 0; p < pieces.size(); ++p)
    {
      const std::size_t firstActor = sceneActors.size();
      vtkSmartPointer<vtkPolyData> shown = pieces[p];
      FittedLattice* fitted = session.lattice ? &latticeOf(p) : nullptr;
      if (fitted && !fitted->errors.empty())
        addLine(message, "no lattice for piece " + std::to_string(p) + ": " + fitted->errors);
      const bool latticeShown = fitted && fitted->surface->GetNumberOfPoints() > 0;
      if (latticeShown)
      {
        shown = fitted->surface;
        vtkNew<vtkExtractEdges> cage;
        cage->SetInputData(fitted->lattice);
        addActor(cage->GetOutputPort(), nullptr, { 0.2, 0.2, 0.2 }, false)->PickableOff();
      }
      if (session.metro && latticeShown)
      {
        if (!fitted->metro)
        {
          vtkNew<vtkLKMetroFilter> metro;
          metro->SetInputData(fitted->surface);
          metro->SetTargetData(pieces[p]);
          metro->Update();
          fitted->metro = vtkSmartPointer<vtkPolyData>::New();
          fitted->metro->ShallowCopy(metro->GetOutput());
          fitted->metro->GetPointData()->SetActiveScalars("Distance");
          fitted->colourMaximum = metro->GetEffectiveColorMaximum();
          fitted->hausdorff = metro->GetHausdorffDistance();
        }
        auto actor = addActorData(fitted->metro, { 1, 1, 1 }, true);
        actor->GetMapper()->SetLookupTable(distanceColours);
        actor->GetMapper()->UseLookupTableScalarRangeOn();
        colourTop = std::max(colourTop, fitted->colourMaximum);
        largest = std::max(largest, fitted->hausdorff);
        scalarBar->SetVisibility(true);
      }
      else
        addActorData(shown, pieceColour(p), false);
      pieceActors[p].assign(sceneActors.begin() + static_cast<std::ptrdiff_t>(firstActor), sceneActors.end());
    }
    lkapp::distanceColourBar(colourTop, largest, distanceColours, scalarBar);
    if (session.segment >= static_cast<int>(pieces.size()))
      addLine(message, "the session's segment (piece " + std::to_string(session.segment) + ") does not exist: the plan has " +
        std::to_string(pieces.size()) + " piece(s)");
    placeSegment(session.segmentMatrix);
    updateStatus();
  }

  /// Piece p's lattice (600 vertices or the session's, at most half the
  /// piece's) and its smooth surface: fitted again only when the piece's
  /// points or faces, or the count, changed since the last fit.
  FittedLattice& latticeOf(std::size_t p)
  {
    vtkPolyData* piece = pieces[p];
    const vtkIdType vertices = std::min<vtkIdType>(session.latticeVertices, piece->GetNumberOfPoints() / 2);
    const std::uint64_t key = geometryKey(piece, vertices);
    if (lattices.size() <= p)
      lattices.resize(p + 1);
    FittedLattice& fitted = lattices[p];
    if (fitted.lattice && fitted.key == key)
    {
      ++latticesReused;
      return fitted;
    }
    ++latticeFits;
    vtkNew<vtkLKLatticeFitFilter> fit;
    fit->SetInputData(piece);
    fit->SetTargetNumberOfVertices(vertices);
    fit->QuadPairingOn();
    fit->ComputeErrorOff();
    vtkNew<vtkLKLatticeSurfaceFilter> smooth;
    smooth->SetInputConnection(fit->GetOutputPort());
    smooth->SetResolution(4);
    const int before = lkapp::errorCount();
    smooth->Update();
    fitted.key = key;
    fitted.errors = lkapp::errorCount() > before ? lkapp::errorsSince(before) : "";
    fitted.lattice = vtkSmartPointer<vtkPolyData>::New();
    fitted.lattice->ShallowCopy(fit->GetOutput());
    fitted.surface = vtkSmartPointer<vtkPolyData>::New();
    fitted.surface->ShallowCopy(smooth->GetOutput());
    fitted.metro = nullptr;
    return fitted;
  }

  /// A 64-bit digest of a mesh's points and polygons and a count: FNV-1a
  /// over 8-byte words, each scrambled first (splitmix64's finaliser, so that
  /// every bit of a word reaches every bit of the digest); the skull's 40 MB
  /// in a few milliseconds.
  static std::uint64_t geometryKey(vtkPolyData* pd, vtkIdType count)
  {
    std::uint64_t h = 1469598103934665603ULL;
    auto mix = [&h](const void* data, std::size_t bytes) {
      const auto* c = static_cast<const unsigned char*>(data);
      for (std::size_t i = 0; i < bytes; i += 8)
      {
        std::uint64_t word = 0;
        std::memcpy(&word, c + i, std::min<std::size_t>(8, bytes - i));
        word = (word ^ (word >> 30)) * 0xbf58476d1ce4e5b9ULL;
        word = (word ^ (word >> 27)) * 0x94d049bb133111ebULL;
        word ^= word >> 31;
        h = (h ^ word) * 1099511628211ULL;
      }
    };
    mix(&count, sizeof count);
    const vtkIdType n = pd->GetNumberOfPoints();
    mix(&n, sizeof n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      pd->GetPoint(i, x);
      mix(x, sizeof x);
    }
    auto it = vtk::TakeSmartPointer(pd->GetPolys()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      it->GetCurrentCell(size, ids);
      mix(&size, sizeof size);
      mix(ids, sizeof(vtkIdType) * static_cast<std::size_t>(size));
    }
    return h;
  }

  /// The surface without its line cells (the feature lines a stroke left on it).
  static vtkSmartPointer<vtkPolyData> facesOnly(vtkPolyData* surface)
  {
    auto faces = vtkSmartPointer<vtkPolyData>::New();
    faces->ShallowCopy(surface);
    vtkNew<vtkCellArray> none;
    faces->SetLines(none);
    return faces;
  }

  vtkSmartPointer<vtkPolyData> region(vtkPolyData* cut, int r)
  {
    vtkNew<vtkThreshold> t;
    t->SetInputData(cut);
    t->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "RegionId");
    t->SetLowerThreshold(r - 0.5);
    t->SetUpperThreshold(r + 0.5);
    vtkNew<vtkGeometryFilter> g;
    g->SetInputConnection(t->GetOutputPort());
    g->Update();
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->ShallowCopy(g->GetOutput());
    out->GetPointData()->Initialize();
    out->GetCellData()->Initialize();
    return out;
  }

  vtkSmartPointer<vtkActor> addActorData(vtkPolyData* pd, std::array<double, 3> colour, bool scalars)
  {
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(pd);
    return addActor(normals->GetOutputPort(), pd, colour, scalars);
  }

  vtkSmartPointer<vtkActor> addActor(vtkAlgorithmOutput* port, vtkPolyData*, std::array<double, 3> colour, bool scalars)
  {
    vtkNew<vtkPolyDataMapper> m;
    m->SetInputConnection(port);
    m->SetScalarVisibility(scalars);
    auto a = vtkSmartPointer<vtkActor>::New();
    a->SetMapper(m);
    a->GetProperty()->SetColor(colour.data());
    renderer->AddActor(a);
    sceneActors.push_back(a);
    return a;
  }

  void addLineActor(vtkPolyData* line, double shade)
  {
    vtkNew<vtkPolyDataMapper> m;
    m->SetInputData(line);
    m->ScalarVisibilityOff();
    auto a = vtkSmartPointer<vtkActor>::New();
    a->SetMapper(m);
    a->GetProperty()->SetColor(0.1 + shade, 0.5, 0.1);
    a->GetProperty()->SetLineWidth(3);
    a->PickableOff(); // the lines lie on the bone; strokes and presses pick the bone
    renderer->AddActor(a);
    sceneActors.push_back(a);
  }

  void updateStatus()
  {
    std::ostringstream s;
    s << (drawing ? "DRAW" : "view") << " | mode: " << modeName(mode) << " | strokes: " << session.strokes.size()
      << " | pieces: " << pieces.size() << (cut.innerWallLines > 0 ? " (cut through the marrow cavity too)" : "")
      << (session.lattice ? " | lattice" : "")
      << (session.metro ? (session.lattice ? " | Metro colours" : " | Metro colours (on the lattice: press l)") : "");
    if (tool != NO_TOOL)
    {
      char r[32];
      std::snprintf(r, sizeof r, "%.1f", radius);
      s << " | DEFORM " << toolName(tool) << ", radius " << r
        << (tool == SMOOTH ? " (drag to brush)" : " (drag up/down)");
    }
    if (!session.deformations.empty())
      s << " | deformations: " << session.deformations.size();
    if (moving)
      s << " | MOVE segment " << session.segment << " (drag; shift+drag rotates)";
    else if (hasSegment())
      s << " | segment: piece " << session.segment << (isIdentity(session.segmentMatrix) ? "" : " (moved)");
    if (!notice.empty())
      s << " | " << notice;
    status->SetInput(s.str().c_str());
    messages->SetInput(wrapped(message, 120).c_str());
  }

  void showStroke()
  {
    // A line cell needs two points: a stroke of one point (a click) is a
    // vertex cell, and an empty one has no cell (a line of fewer points
    // leaves the polydata's cell map unbuildable, which crashed a pick).
    vtkNew<vtkPoints> pts;
    vtkNew<vtkCellArray> lines, verts;
    vtkCellArray* cells = current.size() >= 2 ? lines.Get() : verts.Get();
    if (!current.empty())
      cells->InsertNextCell(static_cast<vtkIdType>(current.size()));
    for (const auto& p : current)
      cells->InsertCellPoint(pts->InsertNextPoint(p.data()));
    strokePd->SetPoints(pts);
    strokePd->SetLines(lines);
    strokePd->SetVerts(verts);
    strokePd->Modified();
  }

  void report()
  {
    std::printf("strokes: %zu\npieces: %zu\n", session.strokes.size(), pieces.size());
    if (cut.innerWallLines > 0)
      std::printf("inner wall lines: %d (the cut went through the marrow cavity too)\n", cut.innerWallLines);
    for (std::size_t p = 0; p < pieces.size(); ++p)
    {
      std::printf("piece %zu: %lld points, %lld faces", p, static_cast<long long>(pieces[p]->GetNumberOfPoints()),
        static_cast<long long>(pieces[p]->GetNumberOfPolys()));
      if (vtkDataArray* d = pieces[p]->GetPointData()->GetArray("Displacement"))
      {
        std::printf(", deformed: largest displacement %.3f, refinement levels 0-%d", d->GetMaxNorm(),
          static_cast<int>(pieces[p]->GetCellData()->GetArray("Level")->GetRange()[1]));
      }
      std::printf("\n");
    }
    for (std::size_t i = 0; i < session.deformations.size(); ++i)
    {
      const Deformation& d = session.deformations[i];
      std::printf("deformation %zu: %s on piece %d at (%.2f, %.2f, %.2f), radius %.2f", i, d.tool.c_str(), d.piece,
        d.centre[0], d.centre[1], d.centre[2], d.radius);
      if (d.tool == "smooth")
        std::printf(", %d iterations\n", d.iterations);
      else
        std::printf(", amount %.3f\n", d.amount);
    }
    if (!frameMs.empty())
    {
      // What a user waits for per mouse move (printed, never asserted).
      std::vector<double> t = frameMs, u = updateMs;
      std::sort(t.begin(), t.end());
      std::sort(u.begin(), u.end());
      std::printf("deformation frames: %zu; deformation median %.1f ms, slowest %.1f ms; with render median %.1f ms, "
                  "slowest %.1f ms\n",
        t.size(), u[u.size() / 2], u.back(), t[t.size() / 2], t.back());
    }
    if (latticeFits + latticesReused > 0)
      std::printf("lattice fits: %zu (%zu kept from an earlier fit of the same piece)\n", latticeFits, latticesReused);
    std::printf("%s", segmentText().c_str());
    std::istringstream lines(message);
    for (std::string line; std::getline(lines, line);)
      std::printf("message: %s\n", line.c_str());
  }

  bool exportPieces(const std::string& folder, std::string& error)
  {
    vtksys::SystemTools::MakeDirectory(folder);
    for (std::size_t p = 0; p < pieces.size(); ++p)
    {
      // The segment goes where the plan moves it.
      vtkSmartPointer<vtkPolyData> piece = pieces[p];
      if (static_cast<int>(p) == session.segment && !isIdentity(session.segmentMatrix))
      {
        vtkNew<vtkTransform> t;
        t->SetMatrix(session.segmentMatrix.data());
        vtkNew<vtkTransformPolyDataFilter> move;
        move->SetInputData(pieces[p]);
        move->SetTransform(t);
        move->Update();
        piece = move->GetOutput();
      }
      for (const char* ext : { ".stl", ".vtp", ".obj" })
      {
        const std::string path = folder + "/piece" + std::to_string(p) + ext;
        if (!lkapp::writeMesh(piece, path, error))
          return false;
      }
    }
    if (hasSegment())
    {
      std::ofstream out(folder + "/segment_transform.txt");
      out << segmentText();
      if (!out)
      {
        error = "cannot write '" + folder + "/segment_transform.txt'";
        return false;
      }
    }
    return true;
  }

  bool screenshot(const std::string& path)
  {
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    vtkNew<vtkPNGWriter> w;
    w->SetInputConnection(grab->GetOutputPort());
    w->SetFileName(path.c_str());
    w->Write();
    return vtksys::SystemTools::FileExists(path);
  }
};

class PlannerStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static PlannerStyle* New();
  vtkTypeMacro(PlannerStyle, vtkInteractorStyleTrackballCamera);
  Planner* planner = nullptr;
  std::string sessionPath = "planner_session.json", exportFolder = "planner-pieces";
  bool pressed = false;
  vtkNew<vtkCellPicker> picker;
  // Moving the segment: where the drag started, the session then, the
  // segment's centre (moved) and the matrix being shown.
  int dragStart[2] = { 0, 0 };
  Session beforeMove;
  double centre[3] = { 0, 0, 0 };
  std::array<double, 16> dragMatrix{};

  /// World point at display (x, y) on the plane through `centre` facing the camera.
  void displayToWorld(double x, double y, double world[3])
  {
    vtkRenderer* ren = planner->renderer;
    ren->SetWorldPoint(centre[0], centre[1], centre[2], 1.0);
    ren->WorldToDisplay();
    const double depth = ren->GetDisplayPoint()[2];
    ren->SetDisplayPoint(x, y, depth);
    ren->DisplayToWorld();
    const double* w = ren->GetWorldPoint();
    for (int i = 0; i < 3; ++i)
      world[i] = w[i] / w[3];
  }

  void startMove()
  {
    pressed = true;
    beforeMove = planner->session;
    const int* pos = this->Interactor->GetEventPosition();
    dragStart[0] = pos[0];
    dragStart[1] = pos[1];
    double b[6];
    planner->pieces[static_cast<std::size_t>(planner->session.segment)]->GetBounds(b);
    const double c[4] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]), 1.0 };
    double moved[4];
    planner->segmentMatrix()->MultiplyPoint(c, moved);
    std::copy(moved, moved + 3, centre);
    dragMatrix = planner->session.segmentMatrix;
  }

  void drag()
  {
    const int* pos = this->Interactor->GetEventPosition();
    vtkNew<vtkTransform> t;
    t->PostMultiply();
    t->SetMatrix(beforeMove.segmentMatrix.data());
    if (this->Interactor->GetShiftKey())
    {
      // Rotate about the view direction through the segment's centre.
      double axis[3];
      planner->renderer->GetActiveCamera()->GetDirectionOfProjection(axis);
      t->Translate(-centre[0], -centre[1], -centre[2]);
      t->RotateWXYZ(0.5 * (pos[0] - dragStart[0]), axis);
      t->Translate(centre);
    }
    else
    {
      double a[3], b[3];
      displayToWorld(dragStart[0], dragStart[1], a);
      displayToWorld(pos[0], pos[1], b);
      t->Translate(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    }
    vtkMatrix4x4* m = t->GetMatrix();
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        dragMatrix[static_cast<std::size_t>(4 * r + c)] = m->GetElement(r, c);
    planner->placeSegment(dragMatrix);
    this->Interactor->Render();
  }

  void endMove()
  {
    pressed = false;
    planner->remember(beforeMove);
    planner->session.segmentMatrix = dragMatrix;
    std::printf("%s", planner->segmentText().c_str());
    std::fflush(stdout);
    planner->updateStatus();
    this->Interactor->Render();
  }

  void pick()
  {
    int* pos = this->Interactor->GetEventPosition();
    picker->SetTolerance(0.0005);
    if (picker->Pick(pos[0], pos[1], 0, planner->renderer) && picker->GetCellId() >= 0)
    {
      double p[3];
      picker->GetPickPosition(p);
      planner->current.push_back({ p[0], p[1], p[2] });
      planner->showStroke();
      this->Interactor->Render();
    }
  }
  // Deforming (seed 002's tools): the piece under the press, the
  // deformation being dragged (or the brush's dabs), the session before it
  // (for undo), and the world length of one pixel at the picked point.
  int deformPiece = -1;
  Deformation dragged;
  std::vector<Deformation> dabs;
  Session beforeDeform;
  double worldPerPixel = 0.0;
  int deformStart[2] = { 0, 0 };
  vtkNew<vtkCellPicker> piecePicker;

  /// The piece under display (x, y), with the picked point and the surface
  /// normal there in the piece's own frame (before the segment's move); -1
  /// when no piece is there.
  int pickPiece(int x, int y, std::array<double, 3>& point, std::array<double, 3>& normal)
  {
    piecePicker->InitializePickList();
    piecePicker->PickFromListOn();
    piecePicker->SetTolerance(0.0005);
    for (auto& actors : planner->pieceActors)
      for (auto& a : actors)
        piecePicker->AddPickList(a);
    if (planner->preview->GetVisibility())
      piecePicker->AddPickList(planner->preview);
    if (!piecePicker->Pick(x, y, 0, planner->renderer) || piecePicker->GetCellId() < 0)
      return -1;
    vtkProp3D* hit = piecePicker->GetProp3D();
    int piece = hit == planner->preview.GetPointer() ? deformPiece : -1;
    for (std::size_t p = 0; p < planner->pieceActors.size() && piece < 0; ++p)
      for (auto& a : planner->pieceActors[p])
        if (a.GetPointer() == hit)
          piece = static_cast<int>(p);
    if (piece < 0)
      return -1;
    double w[4] = { 0, 0, 0, 1 }, n[4] = { 0, 0, 0, 0 };
    piecePicker->GetPickPosition(w);
    piecePicker->GetPickNormal(n);
    if (piece == planner->session.segment)
    {
      vtkNew<vtkMatrix4x4> inverse;
      vtkMatrix4x4::Invert(planner->segmentMatrix(), inverse);
      inverse->MultiplyPoint(w, w);
      inverse->MultiplyPoint(n, n);
    }
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int i = 0; i < 3; ++i)
    {
      point[static_cast<std::size_t>(i)] = w[i];
      normal[static_cast<std::size_t>(i)] = length > 0.0 ? n[i] / length : (i == 2 ? 1.0 : 0.0);
    }
    return piece;
  }

  void startDeform()
  {
    const int* pos = this->Interactor->GetEventPosition();
    std::array<double, 3> c, n;
    deformPiece = -1;
    const int piece = pickPiece(pos[0], pos[1], c, n);
    if (piece < 0)
    {
      planner->message = "the deformation tools need a press on the bone";
      planner->updateStatus();
      this->Interactor->Render();
      return;
    }
    pressed = true;
    deformPiece = piece;
    beforeDeform = planner->session;
    deformStart[0] = pos[0];
    deformStart[1] = pos[1];
    // One pixel, in world units, on the plane through the picked point.
    piecePicker->GetPickPosition(centre);
    double a[3], b[3];
    displayToWorld(pos[0], pos[1], a);
    displayToWorld(pos[0], pos[1] + 100, b);
    worldPerPixel = std::sqrt(vtkMath::Distance2BetweenPoints(a, b)) / 100.0;
    const double r = planner->radius;
    dragged = Deformation();
    dragged.tool = toolName(planner->tool);
    dragged.piece = piece;
    dragged.centre = c;
    dragged.normal = n;
    dragged.radius = r;
    dragged.falloff = planner->tool == BUMP ? bumpFalloff(r) : 0.0;
    dabs.assign(1, dragged);
    vtkLKPatchDeformationFilter* f = planner->deformer(static_cast<std::size_t>(piece));
    Planner::addTo(f, dragged); // a bump or box of amount 0 until the mouse moves
    // The live piece: the filter's output, shown in place of the piece's actors.
    vtkNew<vtkPolyDataMapper> m;
    m->SetInputConnection(f->GetOutputPort());
    m->ScalarVisibilityOff();
    planner->preview->SetMapper(m);
    planner->preview->GetProperty()->SetColor(pieceColour(static_cast<std::size_t>(piece)).data());
    planner->preview->SetUserMatrix(piece == planner->session.segment ? planner->segmentMatrix().GetPointer() : nullptr);
    planner->preview->SetVisibility(true);
    planner->preview->PickableOn();
    for (auto& actor : planner->pieceActors[static_cast<std::size_t>(piece)])
      actor->SetVisibility(false);
    this->Interactor->Render();
  }

  void dragDeform()
  {
    const auto t0 = std::chrono::steady_clock::now();
    const int* pos = this->Interactor->GetEventPosition();
    vtkLKPatchDeformationFilter* f = planner->deformer(static_cast<std::size_t>(deformPiece));
    if (planner->tool == SMOOTH)
    {
      // The brush: a new dab once the pointer has moved a third of the radius.
      std::array<double, 3> c, n;
      if (pickPiece(pos[0], pos[1], c, n) != deformPiece)
        return;
      const auto& last = dabs.back().centre;
      const double step = std::sqrt(vtkMath::Distance2BetweenPoints(c.data(), last.data()));
      if (step < dabs.back().radius / 3.0)
        return;
      Deformation dab = dabs.back();
      dab.centre = c;
      dab.normal = n;
      dabs.push_back(dab);
      Planner::addTo(f, dab);
    }
    else
    {
      // Up raises along the normal at the press, down lowers.
      dragged.amount = (pos[1] - deformStart[1]) * worldPerPixel;
      f->RemoveLastDeformation();
      Planner::addTo(f, dragged);
    }
    f->Update();
    const auto t1 = std::chrono::steady_clock::now();
    this->Interactor->Render();
    using ms = std::chrono::duration<double, std::milli>;
    planner->updateMs.push_back(ms(t1 - t0).count());
    planner->frameMs.push_back(ms(std::chrono::steady_clock::now() - t0).count());
  }

  void endDeform()
  {
    pressed = false;
    planner->preview->SetVisibility(false);
    planner->preview->PickableOff();
    planner->preview->SetMapper(nullptr);
    if (planner->tool == SMOOTH)
      planner->session.deformations.insert(planner->session.deformations.end(), dabs.begin(), dabs.end());
    else if (dragged.amount != 0.0)
      planner->session.deformations.push_back(dragged);
    if (planner->session.deformations.size() == beforeDeform.deformations.size())
    {
      // A click without a drag: nothing to remember.
      planner->deformer(static_cast<std::size_t>(deformPiece))->RemoveLastDeformation();
      for (auto& actor : planner->pieceActors[static_cast<std::size_t>(deformPiece)])
        actor->SetVisibility(true);
      this->Interactor->Render();
      return;
    }
    planner->remember(beforeDeform);
    planner->rebuild(); // the same list: the filter keeps its result; lattices are refitted
    this->Interactor->Render();
  }

  void OnLeftButtonDown() override
  {
    if (planner->tool != NO_TOOL)
      return startDeform();
    if (planner->moving && planner->hasSegment())
      return startMove();
    if (!planner->drawing)
      return vtkInteractorStyleTrackballCamera::OnLeftButtonDown();
    pressed = true;
    planner->current.clear();
    pick();
  }
  void OnMouseMove() override
  {
    if (planner->tool != NO_TOOL && pressed)
      return dragDeform();
    if (planner->moving && pressed)
      return drag();
    if (planner->drawing && pressed)
      return pick();
    vtkInteractorStyleTrackballCamera::OnMouseMove();
  }
  void OnLeftButtonUp() override
  {
    if (planner->tool != NO_TOOL && pressed)
      return endDeform();
    if (planner->moving && pressed)
      return endMove();
    if (!planner->drawing || !pressed)
      return vtkInteractorStyleTrackballCamera::OnLeftButtonUp();
    pressed = false;
    if (planner->current.size() >= 2)
    {
      planner->remember();
      planner->session.strokes.push_back({ planner->mode, planner->current });
      planner->rebuild();
    }
    planner->current.clear();
    planner->showStroke();
    this->Interactor->Render();
  }
  void OnChar() override
  {
    const std::string key = this->Interactor->GetKeySym() ? this->Interactor->GetKeySym() : "";
    Session& s = planner->session;
    std::string error;
    bool rebuild = true;
    planner->notice.clear();
    if (key == "d")
    {
      planner->drawing = !planner->drawing;
      planner->moving = false;
      planner->tool = NO_TOOL;
      rebuild = false;
    }
    else if (key == "f")
    {
      planner->tool = (planner->tool + 1) % TOOL_COUNT; // bump, box, smooth, off
      planner->drawing = false;
      planner->moving = false;
      rebuild = false;
    }
    else if (key == "bracketleft" || key == "bracketright")
    {
      planner->radius *= key == "bracketleft" ? 0.8 : 1.25;
      rebuild = false;
    }
    else if (key == "1" || key == "2" || key == "3" || key == "4")
    {
      planner->mode = key[0] - '1';
      rebuild = false;
    }
    else if (key == "x" || key == "l" || key == "m")
    {
      planner->remember();
      bool& flag = key == "x" ? s.cut : key == "l" ? s.lattice : s.metro;
      flag = !flag;
    }
    else if (key == "n")
    {
      // The next segment, smallest piece first (the part a surgeon moves).
      rebuild = false;
      if (planner->pieces.size() < 2)
        planner->message = "no segment to pick: cut first (x)";
      else
      {
        std::vector<int> bySize(planner->pieces.size());
        std::iota(bySize.begin(), bySize.end(), 0);
        std::stable_sort(bySize.begin(), bySize.end(), [&](int a, int b) {
          return planner->pieces[static_cast<std::size_t>(a)]->GetNumberOfPolys() <
            planner->pieces[static_cast<std::size_t>(b)]->GetNumberOfPolys();
        });
        const auto at = std::find(bySize.begin(), bySize.end(), s.segment);
        planner->remember();
        s.segment = at == bySize.end() || at + 1 == bySize.end() ? bySize.front() : *(at + 1);
        s.segmentMatrix = Session().segmentMatrix;
        planner->placeSegment(s.segmentMatrix);
        planner->message.clear();
      }
    }
    else if (key == "g")
    {
      rebuild = false;
      if (!planner->hasSegment())
        planner->message = "pick a segment first (n)";
      else
      {
        planner->moving = !planner->moving;
        planner->drawing = false;
        planner->tool = NO_TOOL;
      }
    }
    else if (key == "r")
    {
      rebuild = false;
      if (planner->hasSegment())
      {
        planner->remember();
        s.segmentMatrix = Session().segmentMatrix;
        planner->placeSegment(s.segmentMatrix);
      }
    }
    else if (key == "z" && !planner->undoStack.empty())
    {
      planner->redoStack.push_back(s);
      s = planner->undoStack.back();
      planner->undoStack.pop_back();
    }
    else if (key == "y" && !planner->redoStack.empty())
    {
      planner->undoStack.push_back(s);
      s = planner->redoStack.back();
      planner->redoStack.pop_back();
    }
    else if (key == "w")
    {
      if (saveSession(s, sessionPath, error))
        planner->notice = "saved " + vtksys::SystemTools::GetFilenameName(sessionPath);
      else
        planner->message = error;
      rebuild = false;
    }
    else if (key == "e")
    {
      if (planner->exportPieces(exportFolder, error))
        planner->notice = "exported to " + exportFolder;
      else
        planner->message = error;
      rebuild = false;
    }
    else if (key == "q" || key == "Escape")
    {
      this->Interactor->TerminateApp();
      return;
    }
    else
      return; // no VTK default keys: 'e' and 'w' mean other things here
    if (rebuild)
      planner->rebuild();
    planner->updateStatus();
    this->Interactor->Render();
  }
};
vtkStandardNewMacro(PlannerStyle);

void usage(std::ostream& os)
{
  os << "usage: latticekit-planner INPUT [options]\n"
        "\n"
        "The osteotomy planner: a VTK window on the bone surface of INPUT (a CT or label map:\n"
        "DICOM folder or file, .nrrd, .mha, .nii; or a mesh: .vtp .vtk .stl .ply .obj).\n"
        "Keys: "
     << kHelp
     << "\n"
        "\n"
        "  --iso V              a CT's bone threshold (default 300 HU; a 0/1 label map is found\n"
        "                       and taken at 0.5)\n"
        "  --seed X,Y,Z         keep the bone component nearest this patient-space point (mm)\n"
        "                       instead of the largest (the mandible, where the skull is larger)\n"
        "  --crop X0,X1,Y0,Y1,Z0,Z1\n"
        "                       only the CT inside this patient-space box (mm), padded with air\n"
        "                       so that the surface closes where the box cuts bone\n"
        "  --series I           DICOM: series I of the folder (0 = largest, the default)\n"
        "  --smooth N           windowed-sinc smoothing of the surface, N iterations (default 0;\n"
        "                       20 takes a label map's slice staircase out, moving the surface\n"
        "                       by about 0.07 mm on average, up to about 1 mm)\n"
        "  --replay SESSION     apply a saved session (JSON: strokes, cut, lattice, metro, moved segment,\n"
        "                       deformations)\n"
        "  --screenshot PNG     render once to PNG and exit (no window needed: use xvfb-run)\n"
        "  --export FOLDER      write every piece as STL, VTP and OBJ and exit\n"
        "  --session OUT        where 'w' saves the session (default planner_session.json)\n"
        "  --events LOG         play an event stream (vtkInteractorEventRecorder's format: mouse\n"
        "                       strokes, keys) through the window, then report (and\n"
        "                       --screenshot, --export) and exit\n"
        "  -h, --help           this help\n";
}
} // namespace

int main(int argc, char* argv[])
{
  std::string input, replay, shot, exportFolder, events, sessionOut = "planner_session.json";
  double iso = 300.0, seed[3] = { 0, 0, 0 }, crop[6] = { 0, 0, 0, 0, 0, 0 };
  bool isoGiven = false, seeded = false, cropped = false;
  long series = -1, smoothing = -1;
  lkapp::Arguments args(argc, argv, usage);
  std::string a;
  while (args.next(a))
  {
    if (a == "--iso")
    {
      iso = args.number(a, -std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), "a number");
      isoGiven = true;
    }
    else if (a == "--seed")
    {
      args.triple(a, seed);
      seeded = true;
    }
    else if (a == "--crop")
    {
      args.box(a, crop);
      cropped = true;
    }
    else if (a == "--series")
      series = args.integer(a, 0, std::numeric_limits<int>::max(), "an integer >= 0");
    else if (a == "--smooth")
      smoothing = args.integer(a, 0, 1000, "an integer from 0 to 1000");
    else if (a == "--replay")
      replay = args.value(a);
    else if (a == "--screenshot")
      shot = args.value(a);
    else if (a == "--export")
      exportFolder = args.value(a);
    else if (a == "--events")
      events = args.value(a);
    else if (a == "--session")
      sessionOut = args.value(a);
    else if (lkapp::Arguments::isOption(a))
      args.unknown(a);
    else
      args.positional(a, input, "input");
  }
  if (input.empty())
  {
    std::cerr << "error: an INPUT is required\n";
    usage(std::cerr);
    return 2;
  }
  lkapp::installMessageHandler(true);
  Planner planner;
  std::string error;
  const std::string ext = vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(input));
  if (!replay.empty() && !loadSession(replay, planner.session, error))
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  // The surface: a mesh file through the same repair as the CT's surface
  // gets (polygons triangulated, a triangle soup such as an STL from
  // elsewhere merged, non-manifold vertices split, the orientation made
  // consistent; split mode, the cut and the lattice need that, and refused
  // such a mesh one step at a time without it), or a volume's bone surface.
  vtkNew<vtkLKMeshRepairFilter> repair;
  vtkNew<vtkLKMedicalImageReader> reader;
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  vtkSmartPointer<vtkPolyData> mesh;
  vtkPolyDataAlgorithm* surface = bone;
  if (ext == ".vtp" || ext == ".vtk" || ext == ".stl" || ext == ".ply" || ext == ".obj")
  {
    if (isoGiven || seeded || cropped || series >= 0 || smoothing >= 0)
    {
      std::cerr << "error: --iso, --seed, --crop, --series and --smooth are for a CT or label map; '" << input
                << "' is a mesh\n";
      return 2;
    }
    mesh = lkapp::readMesh(input, error);
    if (!mesh)
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
    repair->SetInputData(mesh);
    surface = repair;
  }
  else
  {
    // The command line's settings, else the replayed session's, else the
    // defaults; the session saved later records what was used.
    Session::Surface& used = planner.session.surface;
    if (isoGiven)
      used.iso = iso;
    if (seeded)
    {
      used.seeded = true;
      used.seed = { seed[0], seed[1], seed[2] };
    }
    if (cropped)
    {
      used.cropped = true;
      std::copy(crop, crop + 6, used.crop.begin());
    }
    if (series >= 0)
      used.series = series;
    if (smoothing >= 0)
      used.smoothing = smoothing;
    used.given = true;
    reader->SetFileName(input.c_str());
    reader->SetSeriesIndex(static_cast<int>(used.series));
    bone->SetInputConnection(reader->GetOutputPort());
    bone->SetIsoValue(used.iso);
    if (used.seeded)
    {
      bone->SetExtractionModeToSeededComponent();
      bone->SetSeedPoint(used.seed.data());
    }
    bone->SetCropping(used.cropped);
    bone->SetCropBox(used.crop.data());
    bone->SetSmoothingIterations(static_cast<int>(used.smoothing));
  }
  surface->Update();
  if (lkapp::errorCount() > 0 || surface->GetOutput()->GetNumberOfPolys() == 0)
  {
    std::cerr << "error: " << (lkapp::errorCount() ? lkapp::errors() : "no surface in " + input) << "\n";
    return 1;
  }
  planner.bone = vtkSmartPointer<vtkPolyData>::New();
  planner.bone->ShallowCopy(surface->GetOutput());
  if (!mesh)
  {
    const Session::Surface& used = planner.session.surface;
    std::cout << "surface: " << planner.bone->GetNumberOfPoints() << " points, "
              << planner.bone->GetNumberOfPolys() << " triangles ("
              << (bone->GetTreatedAsLabelMap() ? "label map at level " : "CT at ") << bone->GetEffectiveIsoValue()
              << (bone->GetTreatedAsLabelMap() ? "" : " HU") << ", ";
    if (used.cropped)
      std::cout << "inside the box x " << used.crop[0] << " to " << used.crop[1] << ", y " << used.crop[2] << " to "
                << used.crop[3] << ", z " << used.crop[4] << " to " << used.crop[5] << ", ";
    if (used.seeded)
      std::cout << "the component nearest (" << used.seed[0] << ", " << used.seed[1] << ", " << used.seed[2] << ")";
    else
      std::cout << "the largest component";
    if (reader->GetNumberOfSeries() > 0)
      std::cout << ", series " << std::max<long>(0, used.series) << " of " << reader->GetNumberOfSeries();
    if (used.smoothing > 0)
      std::cout << ", smoothed (" << used.smoothing << " windowed-sinc iterations)";
    std::cout << ")\n";
  }
  else
  {
    const double merged = lkapp::fieldValue(planner.bone, "MergedPoints"),
                 degenerate = lkapp::fieldValue(planner.bone, "RemovedDegenerateFaces"),
                 split = lkapp::fieldValue(planner.bone, "SplitNonManifoldVertices");
    std::cout << "mesh: " << planner.bone->GetNumberOfPoints() << " points, " << planner.bone->GetNumberOfPolys()
              << " triangles";
    if (mesh->GetNumberOfPolys() != planner.bone->GetNumberOfPolys() || merged > 0 || degenerate > 0 || split > 0)
      std::cout << " (repaired from " << mesh->GetNumberOfPolys() << " faces: " << merged << " points merged, "
                << degenerate << " degenerate faces removed, " << split << " non-manifold vertices split)";
    std::cout << "\n";
  }
  // After the input and the session are read, so that their problems are
  // named first.
  if (!lkapp::hasDisplay())
  {
    std::cerr << "error: the planner needs an X display (DISPLAY is not set, or names no running server); headless, "
                 "run it under xvfb-run -a "
                 "with --screenshot, --export or --events\n";
    return 1;
  }
  planner.setup();
  planner.rebuild();
  planner.renderer->ResetCamera();
  const bool batch = !shot.empty() || !exportFolder.empty() || !events.empty();
  if (!events.empty())
  {
    // Headless interaction: the recorded events go through the real style.
    if (!vtksys::SystemTools::FileExists(events))
    {
      std::cerr << "error: cannot open '" << events << "'\n";
      return 1;
    }
    planner.window->SetOffScreenRendering(1);
    vtkNew<vtkRenderWindowInteractor> interactor;
    vtkNew<PlannerStyle> style;
    style->planner = &planner;
    style->sessionPath = sessionOut;
    interactor->SetInteractorStyle(style);
    interactor->SetRenderWindow(planner.window);
    interactor->Initialize();
    planner.window->Render();
    // The event stream in vtkInteractorEventRecorder's documented format
    // (EventName X Y ctrl shift keycode repeatCount keySym, '#' comments),
    // invoked on the interactor one by one.
    std::ifstream in(events);
    std::string line;
    int played = 0;
    int lineNumber = 0;
    // A line as it can be printed: control and non-ASCII bytes as '?', at most 80 characters.
    auto printable = [](const std::string& text) {
      std::string shown = text.substr(0, 80);
      for (char& ch : shown)
        if (static_cast<unsigned char>(ch) < 32 || static_cast<unsigned char>(ch) > 126)
          ch = '?';
      return text.size() > 80 ? shown + "..." : shown;
    };
    while (std::getline(in, line))
    {
      ++lineNumber;
      if (line.empty() || line[0] == '#')
        continue;
      std::istringstream fields(line);
      std::string name, keyCode, keySym;
      int x = 0, y = 0, ctrl = 0, shift = 0, repeat = 0;
      if (!(fields >> name >> x >> y >> ctrl >> shift >> keyCode >> repeat >> keySym))
      {
        std::cerr << "error: cannot read event line " << lineNumber << " of '" << events << "' (EventName X Y ctrl shift keycode repeat keysym): '" << printable(line) << "'\n";
        return 1;
      }
      const unsigned long id = vtkCommand::GetEventIdFromString(name.c_str());
      if (id == vtkCommand::NoEvent)
      {
        std::cerr << "error: unknown event '" << name << "'\n";
        return 1;
      }
      const char code = keyCode.size() == 1 ? keyCode[0] : static_cast<char>(std::atoi(keyCode.c_str()));
      interactor->SetEventInformation(x, y, ctrl, shift, code, repeat, keySym == "0" ? nullptr : keySym.c_str());
      interactor->InvokeEvent(id, nullptr);
      ++played;
    }
    std::printf("events: %d\n", played);
  }
  if (batch)
  {
    planner.report();
    if (!exportFolder.empty() && !planner.exportPieces(exportFolder, error))
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
    if (!shot.empty())
    {
      planner.window->SetOffScreenRendering(1);
      if (!planner.screenshot(shot))
      {
        std::cerr << "error: cannot write '" << shot << "'\n";
        return 1;
      }
      std::printf("screenshot: %s\n", shot.c_str());
    }
    return planner.cutFailed ? 1 : 0;
  }
  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkNew<PlannerStyle> style;
  style->planner = &planner;
  style->sessionPath = sessionOut;
  interactor->SetInteractorStyle(style);
  interactor->SetRenderWindow(planner.window);
  planner.window->Render();
  interactor->Start();
  return 0;
}
