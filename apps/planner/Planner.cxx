// latticekit-planner: the plan's scene: its set-up and rebuild, the segment's place and how it meets
// the other pieces, its move as typed, the status line, the plan's text and the report. The other
// parts are in Planner*.cxx beside it, one concern each.
#include "planner/Planner.h"
#include "planner/PlannerShared.h"

#include "common/AppSupport.h"
#include "common/AtomicFile.h"
#include "common/CutReport.h"
#include "common/DistanceColourBar.h"
#include "common/LabelPlacement.h"
#include "common/TextFont.h"
#include "common/WrappedText.h"

#include "vtkLKMetroFilter.h"
#include "vtkLKPolyDataConversion.h"

#include "vtkLKStrokeFeatureLineFilter.h"
#include "vtkLKText.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkExtractEdges.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInteractorObserver.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkPolyDataNormals.h>
#include <vtkSphereSource.h>
#include <vtkMath.h>
#include <vtkProperty.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>
#include <vtkMatrix4x4.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace lkplanner
{
namespace
{
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

} // namespace

bool isIdentity(const std::array<double, 16>& m)
{
  for (int i = 0; i < 16; ++i)
    if (m[static_cast<std::size_t>(i)] != (i % 5 == 0 ? 1.0 : 0.0))
      return false;
  return true;
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

const char* const kHelp = "d: draw on/off (right drag turns the view; drag on from an orange end) | 1 paint 2 nearest 3 snap 4 split | p: saw line | c: CT at a cut (C: its window)\n"
                    "x: cut (capped) | l: lattice, L: size | m: Metro colours | n: pick the segment (smallest first) | g: move it (shift: rotate) | v: by numbers | r: reset\n"
                    "f: deform (bump, box, smooth; drag up/down) | [ ]: tool radius | u: distance, a: angle | Delete: what is pointed at | o: mirror image, O: its plane\n"
                    "t: name a piece (click it, type, Return) | k: cutting guides (K: side, j: joined) | z: undo, y: redo | w: save | e: export | q: quit | mouse: turn, pan, zoom";

const char* toolName(int tool)
{
  return tool == BUMP ? "bump" : tool == BOX ? "box" : tool == SMOOTH ? "smooth" : "off";
}

/// A marker ball (an open line's end, a measurement's first point).
vtkSmartPointer<vtkPolyData> ballAt(const std::array<double, 3>& centre, double radius)
{
  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(centre.data());
  ball->SetRadius(radius);
  ball->SetThetaResolution(16);
  ball->SetPhiResolution(12);
  ball->Update();
  return ball->GetOutput();
}

/// A caption in the view: `text` with a leader to its attachment point,
/// `offset` pixels from it, bold in `colour` on a light background (readable
/// over the Metro colours), not pickable.
vtkSmartPointer<vtkCaptionActor2D> captionActor(
  const std::string& text, const std::array<double, 3>& colour, int fontSize, const std::array<double, 2>& offset)
{
  auto caption = vtkSmartPointer<vtkCaptionActor2D>::New();
  caption->SetCaption(text.c_str());
  caption->BorderOff();
  caption->LeaderOn();
  caption->ThreeDimensionalLeaderOff();
  caption->GetTextActor()->SetTextScaleModeToNone();
  vtkTextProperty* property = caption->GetCaptionTextProperty();
  property->SetFontSize(fontSize);
  property->SetColor(colour.data());
  property->BoldOn();
  property->ItalicOff();
  property->ShadowOff();
  property->SetJustificationToLeft();
  property->SetBackgroundColor(1.0, 1.0, 1.0);
  property->SetBackgroundOpacity(0.75);
  caption->GetProperty()->SetColor(colour.data()); // the leader
  // A name in a script VTK's compiled font lacks (Greek, Cyrillic, kanji)
  // is drawn with an installed font that has it; one that no font has is
  // said once.
  if (const std::string lacking = lkapp::useFontFor(property, text); !lacking.empty())
  {
    static std::set<std::string> said;
    if (said.insert(text).second)
      std::fprintf(stderr, "planner: no installed font draws '%s' of '%s'; the view leaves them out\n",
        lkvtk::shownText(lacking, 64).c_str(), lkvtk::shownText(text, 64).c_str());
  }
  caption->SetPosition(offset[0], offset[1]);
  std::vector<char32_t> characters;
  lkvtk::decodeUTF8(text, &characters);
  caption->SetWidth(0.01 * static_cast<double>(characters.size() + 2));
  caption->SetHeight(0.0027 * fontSize);
  caption->PickableOff();
  return caption;
}

/// A stroke's points as one polyline. A line cell needs two points: a
/// stroke of one point (a click) is a vertex cell, and an empty one has no
/// cell (a line of fewer points leaves the polydata's cell map unbuildable,
/// which crashed a pick).
vtkSmartPointer<vtkPolyData> polylineOf(const std::vector<std::array<double, 3>>& points)
{
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> lines, verts;
  vtkCellArray* cells = points.size() >= 2 ? lines.Get() : verts.Get();
  if (!points.empty())
    cells->InsertNextCell(static_cast<vtkIdType>(points.size()));
  for (const auto& p : points)
    cells->InsertCellPoint(pts->InsertNextPoint(p.data()));
  auto polyline = vtkSmartPointer<vtkPolyData>::New();
  polyline->SetPoints(pts);
  polyline->SetLines(lines);
  polyline->SetVerts(verts);
  return polyline;
}

/// A plane's square drawn by two actors: a faint sheet and its outline,
/// through its four corners in order around it.
void showSquare(vtkPoints* corners, vtkActor* sheetActor, vtkActor* outlineActor)
{
  const vtkIdType quad[4] = { 0, 1, 2, 3 }, loop[5] = { 0, 1, 2, 3, 0 };
  vtkNew<vtkPolyData> sheet, outline;
  sheet->SetPoints(corners);
  sheet->Allocate(1);
  sheet->InsertNextCell(VTK_QUAD, 4, quad);
  outline->SetPoints(corners);
  outline->Allocate(1);
  outline->InsertNextCell(VTK_POLY_LINE, 5, loop);
  vtkPolyDataMapper::SafeDownCast(sheetActor->GetMapper())->SetInputData(sheet);
  vtkPolyDataMapper::SafeDownCast(outlineActor->GetMapper())->SetInputData(outline);
}

std::array<double, 3> pieceColour(std::size_t p)
{
  const double colours[4][3] = { { 0.93, 0.85, 0.65 }, { 0.6, 0.75, 0.93 }, { 0.7, 0.9, 0.7 }, { 0.95, 0.7, 0.7 } };
  return { colours[p % 4][0], colours[p % 4][1], colours[p % 4][2] };
}

void Planner::remember(const Session& before)
{
  undoStack.push_back(before);
  redoStack.clear();
}

vtkSmartPointer<vtkMatrix4x4> Planner::segmentMatrix() const
{
  auto m = vtkSmartPointer<vtkMatrix4x4>::New();
  m->DeepCopy(session.segmentMatrix.data());
  return m;
}

void Planner::placeSegment(const std::array<double, 16>& matrix)
{
  for (const NameCaption& c : nameCaptions)
    c.actor->SetAttachmentPoint(shownPoint(c.at, c.piece, matrix).data());
  for (std::size_t p = 0; p < pieceActors.size(); ++p)
    for (auto& a : pieceActors[p])
    {
      if (static_cast<int>(p) == movedPiece())
      {
        vtkNew<vtkMatrix4x4> m;
        m->DeepCopy(matrix.data());
        a->SetUserMatrix(m);
      }
      else
        a->SetUserMatrix(nullptr);
    }
  shownMatrix = matrix;
  showMeasurements(); // an end on the segment moves with it
  updateContacts(matrix);
  updateMirrorFit(matrix);
  showScanMoved(matrix);
}

void Planner::updateContacts(const std::array<double, 16>& matrix)
{
  contacts.clear();
  overlapMarker->SetVisibility(false);
  if (!hasSegment() || isIdentity(matrix))
    return;
  std::vector<vtkPolyData*> shown;
  for (const auto& piece : pieces)
    shown.push_back(piece);
  if (shown != contactPieces)
  {
    contactSurfaces.clear();
    for (vtkPolyData* piece : shown)
      contactSurfaces.push_back(std::make_unique<lkapp::ContactSurface>(piece));
    contactPieces = shown;
  }
  // Closer than this the pieces touch (a cut's two caps lie on each other).
  const double touch = 1e-4 * bone->GetLength();
  const auto s = static_cast<std::size_t>(session.segment);
  vtkNew<vtkPoints> inside;
  for (std::size_t p = 0; p < pieces.size(); ++p)
    if (p != s)
      contacts.emplace_back(
        static_cast<int>(p), lkapp::contactOf(*contactSurfaces[s], matrix, *contactSurfaces[p], touch, inside));
  if (inside->GetNumberOfPoints() > 0)
  {
    vtkNew<vtkPolyData> points;
    points->SetPoints(inside);
    vtkNew<vtkCellArray> verts;
    for (vtkIdType i = 0; i < inside->GetNumberOfPoints(); ++i)
      verts->InsertNextCell(1, &i);
    points->SetVerts(verts);
    vtkPolyDataMapper::SafeDownCast(overlapMarker->GetMapper())->SetInputData(points);
    overlapMarker->SetVisibility(true);
  }
}

std::string Planner::contactStatus() const
{
  const std::pair<int, lkapp::Contact>* shown = nullptr;
  for (const auto& c : contacts)
  {
    const bool deeper = c.second.overlap && (!shown || !shown->second.overlap || c.second.depth > shown->second.depth);
    const bool nearer = !c.second.overlap && (!shown || (!shown->second.overlap && c.second.gap < shown->second.gap));
    if (deeper || nearer)
      shown = &c;
  }
  if (!shown)
    return "";
  char text[120];
  if (shown->second.overlap)
    std::snprintf(text, sizeof text, "OVERLAPS piece %d by %.2f mm", shown->first, shown->second.depth);
  else
    std::snprintf(text, sizeof text, "%.2f mm from piece %d", shown->second.gap, shown->first);
  return text;
}

std::string Planner::segmentText() const
{
  if (!hasSegment())
    return "";
  // The move as a surgeon states it (and types it with v): how far the
  // segment's centre goes, and its turn about the axes through the centre.
  // The matrix's own translation is the move of the coordinates' origin,
  // far from the bone, once the segment turns.
  const auto& m = session.segmentMatrix;
  const double trace = m[0] + m[5] + m[10];
  const double angle = std::acos(std::clamp((trace - 1.0) / 2.0, -1.0, 1.0)) * 180.0 / vtkMath::Pi();
  const std::array<double, 3> c = segmentCentre();
  const SegmentMove move = segmentMove();
  char line[400];
  std::snprintf(line, sizeof line, "segment: %s moved, translation %.2f %.2f %.2f mm (of its centre), rotation %.2f deg\n",
    pieceLabel(static_cast<std::size_t>(session.segment)).c_str(), move.translation[0], move.translation[1],
    move.translation[2], angle);
  std::string text = line;
  // How it meets the bone beside it where the plan puts it.
  for (const auto& [piece, contact] : contacts)
    text += "segment and " + pieceLabel(static_cast<std::size_t>(piece)) + ": " + lkapp::contactText(contact) + "\n";
  std::snprintf(line, sizeof line,
    "segment centre: (%.2f, %.2f, %.2f); the rotation is %.2f %.2f %.2f deg about x, y, z through it, in that order%s%s\n",
    c[0], c[1], c[2], move.angles[0], move.angles[1], move.angles[2], axesText.empty() ? "" : " (",
    axesText.empty() ? "" : (axesText + ")").c_str());
  return text + line + matrixText(m);
}

std::array<double, 3> Planner::segmentCentre() const
{
  std::array<double, 3> centre{ 0, 0, 0 };
  if (!hasSegment() || static_cast<std::size_t>(session.segment) >= cut.pieces.size())
    return centre;
  double b[6];
  cut.pieces[static_cast<std::size_t>(session.segment)]->GetBounds(b);
  return { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
}

Planner::SegmentMove Planner::segmentMove() const
{
  const auto& m = session.segmentMatrix;
  SegmentMove move;
  const std::array<double, 3> c = segmentCentre();
  const std::array<double, 3> moved = lkapp::placedPoint(m, c);
  for (std::size_t i = 0; i < 3; ++i)
    move.translation[i] = moved[i] - c[i];
  // R = Rz(c) Ry(b) Rx(a): m[8] = -sin b, m[9] = cos b sin a,
  // m[10] = cos b cos a, m[4] = cos b sin c, m[0] = cos b cos c.
  const double degrees = 180.0 / vtkMath::Pi();
  const double b = std::asin(std::clamp(-m[8], -1.0, 1.0));
  if (std::abs(m[8]) < 1.0 - 1e-12)
  {
    move.angles = { std::atan2(m[9], m[10]) * degrees, b * degrees, std::atan2(m[4], m[0]) * degrees };
  }
  else
    move.angles = { 0.0, b * degrees, std::atan2(-m[1], m[5]) * degrees }; // a and c turn about one axis
  for (auto* values : { &move.translation, &move.angles })
    for (double& v : *values)
      v = std::abs(v) < 1e-9 ? 0.0 : v; // rounding's dust, and no "-0.00"
  return move;
}

std::array<double, 16> Planner::moveMatrix(const std::array<double, 3>& centre, const SegmentMove& move)
{
  vtkNew<vtkTransform> t;
  t->PostMultiply(); // each step after the last, about the fixed axes
  t->Translate(-centre[0], -centre[1], -centre[2]);
  t->RotateX(move.angles[0]);
  t->RotateY(move.angles[1]);
  t->RotateZ(move.angles[2]);
  t->Translate(centre[0] + move.translation[0], centre[1] + move.translation[1], centre[2] + move.translation[2]);
  std::array<double, 16> m{};
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k)
      m[static_cast<std::size_t>(4 * r + k)] = t->GetMatrix()->GetElement(r, k);
  return m;
}

bool Planner::moveSegmentTo(const std::string& text, std::string& why)
{
  std::string spaced = text;
  std::replace(spaced.begin(), spaced.end(), ',', ' ');
  std::istringstream in(spaced);
  std::vector<double> values;
  for (std::string word; in >> word;)
  {
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (end != word.c_str() + word.size() || !std::isfinite(v))
    {
      why = "'" + word + "' is not a number: type x y z (mm), then rx ry rz (degrees) to turn it";
      return false;
    }
    values.push_back(v);
  }
  if (values.size() != 3 && values.size() != 6)
  {
    why = "type three numbers, x y z (mm), or six, x y z rx ry rz (mm, then degrees about x, y, z): " +
      std::to_string(values.size()) + " given";
    return false;
  }
  SegmentMove move;
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    const double most = i < 3 ? 1000.0 : 360.0;
    if (std::abs(values[i]) > most)
    {
      why = i < 3 ? "a move beyond 1000 mm is a slip" : "a turn beyond 360 degrees is a slip";
      return false;
    }
    (i < 3 ? move.translation[i] : move.angles[i - 3]) = values[i];
  }
  remember();
  session.segmentMatrix = moveMatrix(segmentCentre(), move);
  placeSegment(session.segmentMatrix);
  return true;
}

void Planner::setup()
{
  window->AddRenderer(renderer);
  overlay->SetLayer(1);
  overlay->InteractiveOff();
  overlay->SetActiveCamera(renderer->GetActiveCamera());
  window->SetNumberOfLayers(2);
  window->AddRenderer(overlay);
  // The scan on a cut line's plane: the lower left, above the status lines,
  // over the measurements' layer, opaque (a layer above the first keeps the
  // picture beneath it unless told otherwise).
  scanRenderer->SetLayer(1);
  scanRenderer->PreserveColorBufferOff();
  scanRenderer->PreserveDepthBufferOff();
  scanRenderer->SetViewport(0.005, 0.24, 0.375, 0.735);
  scanRenderer->InteractiveOff();
  scanRenderer->DrawOff();
  window->AddRenderer(scanRenderer);
  // While it is shown, the bone is drawn smaller, right of it (after the
  // projection: picks and drags go through the same transform; showScan
  // sets it).
  window->SetSize(1000, 750);
  window->SetWindowName("latticekit planner");
  renderer->SetBackground(1, 1, 1);
  renderer->AddObserver(vtkCommand::StartEvent, this, &Planner::placeCaptions);
  help->SetInput(kHelp);
  // The lines stand on a light band, readable where a zoomed bone (its
  // Metro colours) reaches under them.
  for (vtkTextActor* text : { help.Get(), status.Get(), messages.Get() })
  {
    text->GetTextProperty()->SetBackgroundColor(1.0, 1.0, 1.0);
    text->GetTextProperty()->SetBackgroundOpacity(0.7);
  }
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
  scalarBar->SetVisibility(false); // placed by showScan
  renderer->AddViewProp(scalarBar);
  vtkNew<vtkPolyDataMapper> sm;
  sm->SetInputData(strokePd);
  strokeActor->SetMapper(sm);
  strokeActor->GetProperty()->SetColor(0.9, 0.1, 0.1);
  strokeActor->GetProperty()->SetLineWidth(3);
  strokeActor->GetProperty()->SetPointSize(6);
  strokeActor->PickableOff(); // strokes are picked on the bone, never on themselves
  renderer->AddActor(strokeActor);
  vtkNew<vtkPolyDataMapper2D> sawMapper;
  sawMapper->SetInputData(sawPd);
  sawActor->SetMapper(sawMapper);
  sawActor->GetProperty()->SetColor(0.85, 0.1, 0.1);
  sawActor->GetProperty()->SetLineWidth(2);
  sawActor->SetVisibility(false);
  renderer->AddViewProp(sawActor);
  preview->SetVisibility(false);
  preview->PickableOff();
  renderer->AddActor(preview);
  // The first point of a distance being measured (u).
  vtkNew<vtkPolyDataMapper> markerMapper;
  measureMarker->SetMapper(markerMapper);
  measureMarker->GetProperty()->SetColor(0.55, 0.0, 0.45);
  measureMarker->SetVisibility(false);
  measureMarker->PickableOff();
  overlay->AddActor(measureMarker);
  vtkNew<vtkPolyDataMapper> overlapMapper;
  overlapMarker->SetMapper(overlapMapper);
  overlapMarker->GetProperty()->SetColor(0.9, 0.05, 0.05);
  overlapMarker->GetProperty()->SetPointSize(5);
  overlapMarker->GetProperty()->RenderPointsAsSpheresOn();
  overlapMarker->SetVisibility(false);
  overlapMarker->PickableOff();
  overlay->AddActor(overlapMarker);
  // The mirror image: translucent over the bone, so that the bone shows
  // through where the two agree and the mirror stands out where they do not.
  vtkNew<vtkPolyDataMapper> mirrorMapper;
  mirrorMapper->ScalarVisibilityOff();
  mirrorActor->SetMapper(mirrorMapper);
  mirrorActor->GetProperty()->SetColor(0.55, 0.35, 0.85);
  mirrorActor->GetProperty()->SetOpacity(0.35);
  mirrorActor->SetVisibility(false);
  mirrorActor->PickableOff(); // strokes and picks land on the bone
  renderer->AddActor(mirrorActor);
  for (vtkActor* actor : { mirrorPlaneActor.Get(), mirrorPlaneOutline.Get() })
  {
    vtkNew<vtkPolyDataMapper> mapper;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.45, 0.25, 0.75);
    actor->GetProperty()->LightingOff();
    actor->SetVisibility(false);
    actor->PickableOff();
    renderer->AddActor(actor);
  }
  mirrorPlaneActor->GetProperty()->SetOpacity(0.12);
  mirrorPlaneOutline->GetProperty()->SetLineWidth(2.0);
  // The cutting guides: teal, apart from the pieces, and not picked
  // (a stroke drawn where a guide lies lands on the bone under it).
  vtkNew<vtkPolyDataMapper> guideMapper;
  guideMapper->ScalarVisibilityOff();
  guideActor->SetMapper(guideMapper);
  guideActor->GetProperty()->SetColor(0.0, 0.55, 0.6);
  guideActor->SetVisibility(false);
  guideActor->PickableOff();
  renderer->AddActor(guideActor);
  for (vtkActor* actor : { scanPlaneSheet.Get(), scanPlaneOutline.Get() })
  {
    vtkNew<vtkPolyDataMapper> mapper;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(kScanPlaneColour[0], kScanPlaneColour[1], kScanPlaneColour[2]);
    actor->GetProperty()->LightingOff();
    actor->SetVisibility(false);
    actor->PickableOff(); // strokes and picks land on the bone
    renderer->AddActor(actor);
  }
  scanPlaneSheet->GetProperty()->SetOpacity(0.15);
  scanPlaneOutline->GetProperty()->SetLineWidth(2.0);
  // The patient's sides, as medical viewers show them: a mandible is nearly
  // symmetric, and a cut planned on the wrong side is the error to prevent.
  // Patient x, y, z point to the left, back and up in LPS; to the right,
  // front and up in RAS. Without a known system the cube would guess.
  if (const std::string space = lkapp::coordinateSpace(bone); !space.empty())
  {
    const bool lps = space == "LPS";
    axesText = lps ? "x to the left, y back, z up" : "x to the right, y to the front, z up";
    marker->SetXPlusFaceText(lps ? "L" : "R");
    marker->SetXMinusFaceText(lps ? "R" : "L");
    marker->SetYPlusFaceText(lps ? "P" : "A");
    marker->SetYMinusFaceText(lps ? "A" : "P");
    marker->SetZPlusFaceText("S");
    marker->SetZMinusFaceText("I");
    // The S face reads upright seen from above with the front up (the cube
    // turns with the view; VTK's default text on that face is a quarter turn
    // off).
    marker->SetZFaceTextRotation(lps ? 90.0 : -90.0);
    marker->SetFaceTextScale(0.6);
    marker->GetCubeProperty()->SetColor(0.92, 0.92, 0.95);
    marker->GetTextEdgesProperty()->SetColor(0.5, 0.5, 0.6);
    for (vtkProperty* face : { marker->GetXPlusFaceProperty(), marker->GetXMinusFaceProperty(),
           marker->GetYPlusFaceProperty(), marker->GetYMinusFaceProperty(), marker->GetZPlusFaceProperty(),
           marker->GetZMinusFaceProperty() })
      face->SetColor(0.1, 0.1, 0.4);
    marker->PickableOff();
    // Seen face-on the cube shows one letter; arrows to the patient's left,
    // back and top (the axes' positive ends) say which way the others lie.
    markerAxes->SetTotalLength(1.3, 1.3, 1.3);
    markerAxes->SetShaftTypeToCylinder();
    markerAxes->SetCylinderRadius(0.03);
    markerAxes->SetXAxisLabelText(lps ? "L" : "R");
    markerAxes->SetYAxisLabelText(lps ? "P" : "A");
    markerAxes->SetZAxisLabelText("S");
    for (vtkCaptionActor2D* label : { markerAxes->GetXAxisCaptionActor2D(), markerAxes->GetYAxisCaptionActor2D(),
           markerAxes->GetZAxisCaptionActor2D() })
    {
      label->GetCaptionTextProperty()->SetFontSize(12);
      label->GetCaptionTextProperty()->SetColor(0.1, 0.1, 0.4);
      label->GetCaptionTextProperty()->ShadowOff();
      label->GetCaptionTextProperty()->ItalicOff();
    }
    markerAxes->PickableOff();
    markerRenderer->AddViewProp(markerAxes);
    markerRenderer->AddViewProp(marker);
    markerRenderer->SetViewport(0.87, 0.85, 0.995, 0.995); // top right, above the distance colour bar
    markerRenderer->SetLayer(1);
    markerRenderer->InteractiveOff();
    window->AddRenderer(markerRenderer);
    renderer->AddObserver(vtkCommand::StartEvent, this, &Planner::followCamera);
  }
  radius = 0.05 * bone->GetLength();
  // The stroke filter's "ends meet" is also how near a drag continues a line.
  if (const double tolerance = vtkLKStrokeFeatureLineFilter::DefaultCloseTolerance(bone); tolerance > 0.0)
    joinTolerance = tolerance;
}

void Planner::placeCaptions()
{
  const int* size = renderer->GetSize();
  if (!size || size[0] <= 0)
    return;
  // Beside its point, right of it (left where the right edge is near),
  // right of the CT view, left of the distance colour bar, and between the
  // status lines and the messages (where they leave a fifth of the window;
  // else the whole height), not over the orientation cube nor a caption
  // placed before it: the names in the pieces' order, then the measured
  // values.
  std::array<double, 2> band = betweenTheTexts();
  if (band[1] - band[0] < 0.2 * size[1])
    band = { 4.0, size[1] - 4.0 };
  const double left = 4.0 + (scanRenderer->GetDraw() ? scanRenderer->GetViewport()[2] * size[0] : 0.0);
  const double right = (scalarBar->GetVisibility() ? scalarBar->GetPosition()[0] : 1.0) * size[0] - 4.0;
  const lkapp::LabelRoom room{ left, band[0], std::max(right, left + 0.25 * size[0]), band[1] };
  std::vector<vtkCaptionActor2D*> captions;
  std::vector<lkapp::Label> labels;
  const auto add = [&](vtkCaptionActor2D* caption, const std::array<double, 2>& offset) {
    const double* at = caption->GetAttachmentPoint();
    double shown[3];
    vtkInteractorObserver::ComputeWorldToDisplay(renderer, at[0], at[1], at[2], shown);
    // Its point out of the window (a view zoomed in): hidden, not cut off
    // at the window's edge.
    const bool inWindow = shown[0] >= 0.0 && shown[0] <= size[0] && shown[1] >= 0.0 && shown[1] <= size[1];
    caption->SetVisibility(inWindow);
    if (!inWindow)
      return;
    captions.push_back(caption);
    labels.push_back({ { shown[0], shown[1] }, lkapp::textSize(renderer, caption->GetTextActor()), offset });
  };
  for (const NameCaption& c : nameCaptions)
    add(c.actor, NameCaptionOffset);
  for (const auto& c : measureCaptions)
    add(c, MeasureCaptionOffset);
  std::vector<lkapp::LabelRoom> keepOut; // the orientation cube, where it is shown
  if (window->HasRenderer(markerRenderer))
  {
    const double* v = markerRenderer->GetViewport();
    keepOut.push_back({ v[0] * size[0], v[1] * size[1], v[2] * size[0], v[3] * size[1] });
  }
  const std::vector<std::array<double, 2>> offsets = lkapp::placeLabels(labels, room, keepOut);
  for (std::size_t i = 0; i < captions.size(); ++i)
    captions[i]->SetPosition(offsets[i][0], offsets[i][1]);
}

void Planner::followCamera()
{
  vtkCamera* view = renderer->GetActiveCamera();
  vtkCamera* cube = markerRenderer->GetActiveCamera();
  double d[3];
  view->GetDirectionOfProjection(d);
  cube->SetFocalPoint(0.0, 0.0, 0.0);
  cube->SetPosition(-5.0 * d[0], -5.0 * d[1], -5.0 * d[2]);
  cube->SetViewUp(view->GetViewUp());
  cube->SetParallelProjection(false);
  markerRenderer->ResetCamera(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0); // the cube, its arrows and room for their letters
}

void Planner::rebuild()
{
  if (showWork)
  {
    const char* shown = status->GetInput();
    status->SetInput((std::string(shown ? shown : "") + " | working ...").c_str());
    window->Render();
  }
  for (auto& a : sceneActors)
    renderer->RemoveActor(a);
  sceneActors.clear();
  // The last rebuild's surfaces, for this one to show with the same mappers.
  lastShownMappers.swap(shownMappers);
  shownMappers.clear();
  scalarBar->SetVisibility(false);
  computeCut();
  message = inputWarnings;
  if (!cut.message.empty())
    addLine(message, cut.message);
  cutFailed = cut.failed;
  for (const auto& [line, shade] : cut.lines)
    addLineActor(line, { 0.1 + shade, 0.5, 0.1 }, 3);
  // A stroke that made no line (its message says why) is drawn where it was
  // drawn, dark red as the messages are, for Delete to take it out there.
  for (std::size_t i = 0; i < session.strokes.size(); ++i)
    if (cut.madeNoLine(i))
    {
      // Its points as dots too: a click's two points are one pixel apart.
      vtkSmartPointer<vtkPolyData> drawn = polylineOf(session.strokes[i].points);
      vtkNew<vtkCellArray> dots;
      for (vtkIdType k = 0; k < drawn->GetNumberOfPoints(); ++k)
        dots->InsertNextCell(1, &k);
      drawn->SetVerts(dots);
      addLineActor(drawn, { 0.6, 0.1, 0.0 }, 2)->GetProperty()->SetPointSize(6);
    }
  // Where an open line can be continued: a drag that starts in a marker.
  for (const auto& end : openEnds())
  {
    auto marker = addActorData(ballAt(end, joinTolerance), { 0.95, 0.55, 0.1 }, false);
    marker->GetProperty()->SetOpacity(0.6);
    marker->PickableOff(); // a drag that starts in it picks the bone under it
  }
  applyDeformations();
  resolveNames();
  cutSummary = summaryOfCut();
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
  if (session.segment >= 0 && pieces.size() < 2)
    addLine(message, "the segment (piece " + std::to_string(session.segment) + ") is not moved: there is no cut");
  else if (session.segment >= static_cast<int>(pieces.size()))
    addLine(message, "the session's segment (piece " + std::to_string(session.segment) + ") does not exist: the plan has " +
      std::to_string(pieces.size()) + " piece(s)");
  // The mirror image, made once per bone.
  for (vtkActor* actor : { mirrorActor.Get(), mirrorPlaneActor.Get(), mirrorPlaneOutline.Get() })
    actor->SetVisibility(false);
  if (session.mirror)
  {
    if (mirrorImage().surface)
      for (vtkActor* actor : { mirrorActor.Get(), mirrorPlaneActor.Get(), mirrorPlaneOutline.Get() })
        actor->SetVisibility(true);
    else
      addLine(message, "no mirror image: " + mirror.error);
  }
  updateGuides();
  showNames();
  sceneMessage = message;
  showScan();
  placeSegment(session.segmentMatrix); // and the measurements and the fit to the mirror
  lastShownMappers.clear(); // what this rebuild no longer shows goes
  keepChanges();
  updateStatus();
}

void Planner::keepChanges()
{
  if (std::string error; !keepUnsaved(error))
    addLine(message, "the changes not saved could not be kept (--session sets where): " + error);
}

void Planner::markSaved()
{
  savedSession = sessionText(session);
  std::string error;
  keepUnsaved(error); // only removes the kept copy
}

bool Planner::keepUnsaved(std::string& error)
{
  if (unsavedPath.empty())
    return true;
  const std::string text = sessionText(session);
  if (text == savedSession)
  {
    if (!keptSession.empty())
      std::remove(unsavedPath.c_str()); // only the saved session is left to keep
    keptSession.clear();
    lkapp::setCrashNote("");
    return true;
  }
  if (text == keptSession)
    return true;
  if (!lkapp::writeFileAtomically(unsavedPath, text, error))
    return false;
  keptSession = text;
  // A crash in a later step loses that step only: say where the rest is.
  lkapp::setCrashNote("the plan, as it was after its last finished step, is kept in " + unsavedPath +
    ": open it again with --replay " + unsavedPath);
  return true;
}

vtkSmartPointer<vtkActor> Planner::addActorData(vtkPolyData* pd, std::array<double, 3> colour, bool scalars)
{
  const auto key = std::make_pair(pd, scalars);
  vtkSmartPointer<vtkPolyDataMapper> m;
  for (const auto* kept : { &shownMappers, &lastShownMappers })
    if (const auto it = kept->find(key); !m && it != kept->end())
      m = it->second.mapper;
  if (!m)
  {
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(pd);
    m = vtkSmartPointer<vtkPolyDataMapper>::New();
    m->SetInputConnection(normals->GetOutputPort());
    m->SetScalarVisibility(scalars);
  }
  shownMappers[key] = { pd, m };
  return addActorOf(m, colour);
}

vtkSmartPointer<vtkActor> Planner::addActor(vtkAlgorithmOutput* port, vtkPolyData*, std::array<double, 3> colour, bool scalars)
{
  vtkNew<vtkPolyDataMapper> m;
  m->SetInputConnection(port);
  m->SetScalarVisibility(scalars);
  return addActorOf(m, colour);
}

vtkSmartPointer<vtkActor> Planner::addActorOf(vtkPolyDataMapper* mapper, std::array<double, 3> colour)
{
  auto a = vtkSmartPointer<vtkActor>::New();
  a->SetMapper(mapper);
  a->GetProperty()->SetColor(colour.data());
  renderer->AddActor(a);
  sceneActors.push_back(a);
  return a;
}

vtkSmartPointer<vtkActor> Planner::addLineActor(vtkPolyData* line, const std::array<double, 3>& colour, double width)
{
  vtkNew<vtkPolyDataMapper> m;
  m->SetInputData(line);
  m->ScalarVisibilityOff();
  auto a = vtkSmartPointer<vtkActor>::New();
  a->SetMapper(m);
  a->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  a->GetProperty()->SetLineWidth(width);
  a->PickableOff(); // the lines lie on the bone; strokes and presses pick the bone
  renderer->AddActor(a);
  sceneActors.push_back(a);
  return a;
}

void Planner::updateStatus()
{
  std::ostringstream s;
  s << (sawing ? "SAW (drag across the bone)" : drawing ? "DRAW" : "view") << " | mode: " << modeName(mode) << " | strokes: " << session.strokes.size()
    << " | pieces: " << pieces.size() << (cut.innerWallLines > 0 ? " (cut through the marrow cavity too)" : "")
    << (session.lattice ? " | lattice" : "")
    << (session.metro ? (session.lattice ? " | Metro colours" : " | Metro colours (on the lattice: press l)") : "")
    << (scanRenderer->GetDraw() ? " | " + scanShown() : "");
  if (session.mirror && mirror.surface)
  {
    char text[120];
    if (segmentToMirror.valid)
      std::snprintf(text, sizeof text, " | mirror image: the segment %.2f mm from it", segmentToMirror.mean);
    else
      std::snprintf(text, sizeof text, " | mirror image: the bone %.2f mm from it", mirror.mean);
    s << text;
  }
  if (session.guides)
  {
    std::size_t shown = 0;
    for (const CuttingGuide& g : guides)
      shown += g.surface ? 1 : 0;
    s << " | cutting guides: " << shown;
    std::size_t joined = 0;
    int bars = 0, merges = 0;
    for (const JoinedGuide& j : joinedGuides)
      if (j.surface)
      {
        joined += j.members.size();
        bars += j.filter->GetNumberOfBars();
        merges += j.filter->GetNumberOfMerges();
      }
    if (joined > 0)
    {
      s << " (" << joined << " joined";
      if (bars > 0)
        s << " by " << (bars == 1 ? "a bar" : std::to_string(bars) + " bars");
      if (merges > 0)
        s << ", " << merges << (merges == 1 ? " pair" : " pairs") << " merged";
      s << ")";
    }
  }
  if (tool != NO_TOOL)
  {
    char r[32];
    std::snprintf(r, sizeof r, "%.1f", radius);
    s << " | DEFORM " << toolName(tool) << ", radius " << r
      << (tool == SMOOTH ? " (drag to brush)" : " (drag up/down)");
  }
  if (!session.deformations.empty())
  {
    // As the surgeon made them: a brush stroke is one, however many dabs.
    std::size_t made = 0;
    for (std::size_t i = 0; i < session.deformations.size(); i = deformationGroup(i).second + 1)
      ++made;
    s << " | deformations: " << made;
  }
  if (naming == 1)
    s << " | NAME: click a piece (Escape: stop)";
  else if (naming == 2)
    s << " | NAME " << pieceLabel(static_cast<std::size_t>(namingPiece)) << ": " << namingText << composer.pending()
      << "_ (Return keeps it, an empty name takes it away; Escape: stop)";
  // With the CT view shown, its plane's points can be measured too.
  const std::string where = scanRenderer->GetDraw() && measuring && !settingPlane ? " on the bone or the CT" : "";
  if (measuring == 2)
    s << " | MEASURE: click the " << (measurePicked.empty() ? "first" : "second") << " point" << where << " (u: stop)";
  else if (measuring == 3 && settingPlane)
    s << " | MIRROR PLANE: click a point of the bone's midline, " << measurePicked.size() + 1
      << " of 3 (O again: the fitted plane; Escape: stop)";
  else if (measuring == 3)
    s << (measurePicked.empty()       ? " | ANGLE: click an arm's end"
            : measurePicked.size() == 1 ? " | ANGLE: click the vertex"
                                        : " | ANGLE: click the other arm's end")
      << where << " (a: stop)";
  else if (!session.measurements.empty())
    s << " | measured: " << measuredText(session.measurements.back())
      << (session.measurements.size() > 1 ? " (last of " + std::to_string(session.measurements.size()) + ")" : "");
  if (typingLattice)
    s << " | LATTICE: " << latticeText << "_ vertices per piece (now " << session.latticeVertices
      << "; Escape: stop)";
  else if (typingMove)
    s << " | MOVE segment " << session.segment << " BY: " << moveText << "_ (x y z mm, then rx ry rz deg to turn"
      << (axesText.empty() ? "" : "; " + axesText) << "; Return; Escape: stop)";
  else if (moving)
    s << " | MOVE segment " << session.segment << " (drag; shift+drag rotates)";
  else if (hasSegment())
    s << " | segment: " << pieceLabel(static_cast<std::size_t>(session.segment))
      << (isIdentity(session.segmentMatrix) ? "" : " (moved)");
  if (const std::string contact = contactStatus(); !contact.empty() && !typingMove)
    s << ", " << contact;
  if (!notice.empty())
    s << " | " << notice;
  if (!cutSummary.empty())
    s << "\n" << cutSummary;
  const std::string statusText = lkapp::wrapped(s.str(), 130); // the window is 1000 pixels wide
  const std::string messageText = lkapp::wrapped(message, 120);
  lkapp::useFontFor(status->GetTextProperty(), statusText); // names in any script
  lkapp::useFontFor(messages->GetTextProperty(), messageText);
  status->SetInput(statusText.c_str());
  messages->SetInput(messageText.c_str());
  placeScanView();
}

void Planner::placeScanView()
{
  // From 6 pixels above the status lines' top to 6 below the messages, at
  // most [0.24, 0.735] of the height and 0.37 of the width (370 pixels
  // square in the 1000 x 750 window), a quarter of the height at the least
  // (a very long status and message list then reach under it).
  const int* size = window->GetSize();
  if (!size || size[0] <= 0 || size[1] <= 0)
    return;
  const std::array<double, 2> band = betweenTheTexts();
  const double statusTop = band[0] / size[1], messagesBottom = band[1] / size[1];
  const double bottom = std::max(0.24, statusTop);
  const double top = std::max(bottom + 0.25, std::min(0.735, messagesBottom));
  const double width = 0.37 * (top - bottom) / 0.495; // its shape at full size
  double now[4];
  scanRenderer->GetViewport(now);
  const double wanted[4] = { 0.005, bottom, 0.005 + width, top };
  bool changed = false;
  for (int k = 0; k < 4; ++k)
    changed = changed || std::abs(now[k] - wanted[k]) > 1e-6;
  if (!changed)
    return;
  scanRenderer->SetViewport(0.005, bottom, 0.005 + width, top);
  if (scanRenderer->GetDraw() && scanPicture.image)
    lkapp::showScanPicture(scanRenderer, scanPicture, 12); // its title fitted to the new width
}

std::array<double, 2> Planner::betweenTheTexts() const
{
  const int* size = window->GetSize();
  return { status->GetPosition()[1] + lkapp::textSize(renderer, status)[1] + 6.0,
    0.985 * size[1] - lkapp::textSize(renderer, messages)[1] - 6.0 };
}

void Planner::showStroke()
{
  strokePd->ShallowCopy(polylineOf(current));
  strokePd->Modified();
}

void Planner::checkReplayedInput(bool replayed)
{
  const std::string file = vtksys::SystemTools::GetFilenameName(input);
  std::array<double, 6> b{};
  bone->GetBounds(b.data());
  if (replayed)
  {
    const double diagonal = std::hypot(b[1] - b[0], b[3] - b[2], b[5] - b[4]);
    double shift = 0.0;
    for (std::size_t i = 0; session.inputBoundsKnown && i < 6; ++i)
      shift = std::max(shift, std::abs(b[i] - session.inputBounds[i]));
    const bool otherFile = !session.inputFile.empty() && session.inputFile != file;
    // The same file and settings give the same bone to the last digit; 1 %
    // of its size is another scan (or another surface of it).
    const bool otherBone = session.inputBoundsKnown && shift > 0.01 * diagonal;
    inputWarnings.clear();
    if (otherFile || otherBone)
    {
      char mm[64];
      std::snprintf(mm, sizeof mm, "%.1f", shift);
      inputWarnings = "the session was drawn on " +
        (otherFile ? "'" + session.inputFile + "', not on '" + file + "'" : std::string("another surface")) +
        (otherBone ? std::string(" (the bones' bounds differ by up to ") + mm + " mm)" : "") +
        ": check that this is the same patient's scan before using the plan";
    }
  }
  session.inputFile = file;
  session.inputBounds = b;
  session.inputBoundsKnown = true;
}

std::string Planner::planText()
{
  std::string text;
  char line[400];
  std::snprintf(line, sizeof line, "strokes: %zu\npieces: %zu\n", session.strokes.size(), pieces.size());
  text += line;
  if (cut.innerWallLines > 0)
  {
    std::snprintf(line, sizeof line, "inner wall lines: %d (the cut went through the marrow cavity too)\n",
      cut.innerWallLines);
    text += line;
  }
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    std::snprintf(line, sizeof line, "%s: %lld points, %lld faces%s", pieceLabel(p).c_str(),
      static_cast<long long>(pieces[p]->GetNumberOfPoints()), static_cast<long long>(pieces[p]->GetNumberOfPolys()),
      lkapp::pieceFactsText(factsOf(p)).c_str());
    text += line;
    if (vtkDataArray* d = pieces[p]->GetPointData()->GetArray("Displacement"))
    {
      std::snprintf(line, sizeof line, ", deformed: largest displacement %.3f, refinement levels 0-%d", d->GetMaxNorm(),
        static_cast<int>(pieces[p]->GetCellData()->GetArray("Level")->GetRange()[1]));
      text += line;
      if (const vtkIdType crossings = static_cast<vtkIdType>(lkapp::fieldValue(pieces[p], "SelfCrossings")))
      {
        std::snprintf(line, sizeof line, ", passes through itself: %lld pairs of faces cross",
          static_cast<long long>(crossings));
        text += line;
        if (const vtkIdType before = static_cast<vtkIdType>(lkapp::fieldValue(pieces[p], "SelfCrossingsBefore")))
        {
          std::snprintf(line, sizeof line, " (%lld before its deformations)", static_cast<long long>(before));
          text += line;
        }
      }
    }
    text += "\n";
  }
  if (cut.loops)
    text += lkapp::lineFactsText(lkapp::lineFacts(cut.loops), lkapp::coordinateSpace(bone) == "LPS");
  for (std::size_t i = 0; i < session.strokes.size(); ++i)
  {
    const Stroke& st = session.strokes[i];
    if (!st.saw)
      continue;
    const double length = std::hypot(st.sawNormal[0], st.sawNormal[1], st.sawNormal[2]);
    std::snprintf(line, sizeof line, "saw plane of stroke %zu: through (%.2f, %.2f, %.2f), normal (%.3f, %.3f, %.3f)\n",
      i + 1, st.sawOrigin[0], st.sawOrigin[1], st.sawOrigin[2], st.sawNormal[0] / length, st.sawNormal[1] / length,
      st.sawNormal[2] / length);
    text += line;
  }
  for (std::size_t i = 0; i < session.deformations.size(); ++i)
  {
    const Deformation& d = session.deformations[i];
    const auto group = deformationGroup(i);
    if (group.second > i)
    {
      // A smoothing brush stroke (a dab every third of a radius): one line,
      // not one per dab.
      const Deformation& last = session.deformations[group.second];
      double smallest = d.radius, largest = d.radius;
      int fewest = d.iterations, most = d.iterations;
      for (std::size_t k = i; k <= group.second; ++k)
      {
        const Deformation& dab = session.deformations[k];
        smallest = std::min(smallest, dab.radius);
        largest = std::max(largest, dab.radius);
        fewest = std::min(fewest, dab.iterations);
        most = std::max(most, dab.iterations);
      }
      std::snprintf(line, sizeof line,
        "deformations %zu to %zu: smoothing brush stroke on piece %d, %zu dabs from (%.2f, %.2f, %.2f) to (%.2f, "
        "%.2f, %.2f), radius %.2f",
        i, group.second, d.piece, group.second - i + 1, d.centre[0], d.centre[1], d.centre[2], last.centre[0],
        last.centre[1], last.centre[2], smallest);
      text += line;
      if (largest > smallest)
      {
        std::snprintf(line, sizeof line, " to %.2f", largest);
        text += line;
      }
      text += ", " + std::to_string(fewest) + (most > fewest ? " to " + std::to_string(most) : std::string()) +
        " iterations each\n";
      i = group.second;
      continue;
    }
    std::snprintf(line, sizeof line, "deformation %zu: %s on piece %d at (%.2f, %.2f, %.2f), radius %.2f", i,
      d.tool.c_str(), d.piece, d.centre[0], d.centre[1], d.centre[2], d.radius);
    text += line;
    if (d.tool == "smooth")
      std::snprintf(line, sizeof line, ", %d iterations\n", d.iterations);
    else
      std::snprintf(line, sizeof line, ", amount %.3f\n", d.amount);
    text += line;
  }
  // The lattices shown (l): their size, what they keep exactly, how close.
  for (std::size_t p = 0; session.lattice && p < pieces.size() && p < lattices.size(); ++p)
  {
    const FittedLattice& fitted = lattices[p];
    if (!fitted.lattice || !fitted.surface || fitted.surface->GetNumberOfPoints() == 0)
      continue; // a failed fit: its message says why
    std::snprintf(line, sizeof line, "lattice of %s: %.0f control vertices", pieceLabel(p).c_str(),
      lkapp::fieldValue(fitted.lattice, "ControlVertices"));
    text += line;
    if (fitted.raised)
    {
      std::snprintf(line, sizeof line, " (above the session's %ld: its lines take %zu, and the rest of the bone as many)",
        session.latticeVertices, fitted.neededLineVertices);
      text += line;
    }
    std::snprintf(line, sizeof line, ", %.0f triangles, %.0f quads", lkapp::fieldValue(fitted.lattice, "Triangles"),
      lkapp::fieldValue(fitted.lattice, "Quads"));
    text += line;
    if (fitted.featureEdges > 0)
    {
      std::snprintf(line, sizeof line,
        "; its cut and stroke lines kept as lattice edges (%zu edge%s) within %g mm, through %zu of their %zu "
        "vertices, each where it was",
        fitted.featureEdges, fitted.featureEdges == 1 ? "" : "s", kLineTolerance, fitted.keptLineVertices,
        fitted.lineVertices);
      text += line;
      if (fitted.creaseEdges > 0)
      {
        std::snprintf(line, sizeof line, "; %zu of those edges sharp, where the bone bends across the line (a cut's rim)",
          fitted.creaseEdges);
        text += line;
      }
    }
    if (fitted.featureEdgesRefined > 0)
    {
      std::snprintf(line, sizeof line, "; %zu edge%s of those lines that a deformation changed %s not kept",
        fitted.featureEdgesRefined, fitted.featureEdgesRefined == 1 ? "" : "s",
        fitted.featureEdgesRefined == 1 ? "is" : "are");
      text += line;
    }
    if (fitted.metro)
    {
      std::snprintf(line, sizeof line, "; Metro distance to the piece: %.3f mm at most, %.3f mm on average",
        lkapp::fieldValue(fitted.metro, "Hausdorff_Max"), lkapp::fieldValue(fitted.metro, "Hausdorff_Mean"));
      text += line;
    }
    text += "\n";
  }
  for (std::size_t i = 0; i < session.measurements.size(); ++i)
  {
    const Measurement& m = session.measurements[i];
    const Measurement shown = placed(m, session.segmentMatrix);
    const std::string value = valueText(shown);
    if (m.angle)
      std::snprintf(line, sizeof line, "measurement %zu: angle %s at (%.2f, %.2f, %.2f) between (%.2f, %.2f, %.2f) and (%.2f, %.2f, %.2f)",
        i + 1, value.c_str(), shown.at[0], shown.at[1], shown.at[2], shown.from[0], shown.from[1], shown.from[2],
        shown.to[0], shown.to[1], shown.to[2]);
    else
      std::snprintf(line, sizeof line, "measurement %zu: %s from (%.2f, %.2f, %.2f) to (%.2f, %.2f, %.2f)", i + 1,
        value.c_str(), shown.from[0], shown.from[1], shown.from[2], shown.to[0], shown.to[1], shown.to[2]);
    text += line;
    // A point on the moved segment moved with it: the value as picked too,
    // where the move changed it.
    const std::string picked = valueText(m);
    if (picked != value)
      text += ", " + picked + " before the segment's move";
    // Points of the soft tissue, measured on the CT: the plan moves bone only.
    const char* ends[2][3] = { { "its first point", "its second point", "" },
      { "arm 1's end", "arm 2's end", "the vertex" } };
    std::string outside;
    for (std::size_t k = 0; k < m.points().size(); ++k)
      if (m.pieces[k] == Measurement::kSoftTissue)
        outside += (outside.empty() ? "" : " and ") + std::string(ends[m.angle ? 1 : 0][k]);
    if (!outside.empty())
      text += ", " + outside + " in the soft tissue (not moved)";
    text += "\n";
  }
  text += segmentText();
  text += mirrorText();
  text += guidesText();
  // What the cut said (why it failed, a failed stroke) belongs to the plan
  // even when a later key's answer took its place in the window's message.
  std::vector<std::string> said;
  for (const std::string* from : { &inputWarnings, &cut.message, &message })
  {
    std::istringstream lines(*from);
    for (std::string m; std::getline(lines, m);)
      if (!m.empty() && std::find(said.begin(), said.end(), m) == said.end())
        said.push_back(m);
  }
  for (const std::string& m : said)
    text += "message: " + m + "\n";
  return text;
}

void Planner::report()
{
  std::printf("%s", planText().c_str());
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
  if (scanRenderer->GetDraw())
    std::printf("view: %s\n", scanShown().c_str());
  if (strokesMade + strokesReused > 0)
    std::printf("stroke lines made: %zu (%zu kept from an earlier rebuild with the same strokes before them)\n",
      strokesMade, strokesReused);
}

} // namespace lkplanner
