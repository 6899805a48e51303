#include "planner/PlannerStyle.h"

#include "common/AppSupport.h"
#include "common/KeyCharacter.h"

#include "vtkLKPatchDeformationFilter.h"
#include "vtkLKText.h"

#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkStaticCellLocator.h>
#include <vtkTransform.h>
#include <vtkMatrix4x4.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstring>
#include <numeric>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace lkplanner
{
vtkStandardNewMacro(PlannerStyle);

void PlannerStyle::displayToWorld(double x, double y, double world[3])
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

void PlannerStyle::startMove()
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

void PlannerStyle::drag()
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

void PlannerStyle::endMove()
{
  pressed = false;
  planner->remember(beforeMove);
  planner->session.segmentMatrix = dragMatrix;
  std::printf("%s", planner->segmentText().c_str());
  std::fflush(stdout);
  planner->keepChanges();
  planner->updateStatus();
  this->Interactor->Render();
}

void PlannerStyle::pick()
{
  int* pos = this->Interactor->GetEventPosition();
  picker->SetTolerance(0.0005);
  locators.update(planner->renderer, picker);
  if (picker->Pick(pos[0], pos[1], 0, planner->renderer) && picker->GetCellId() >= 0)
  {
    double p[3];
    picker->GetPickPosition(p);
    planner->current.push_back({ p[0], p[1], p[2] });
    planner->showStroke();
    this->Interactor->Render();
  }
}

int PlannerStyle::guideAt(int x, int y)
{
  if (!planner->guideActor->GetVisibility())
    return -1;
  // The guides and the bone (a guide behind the bone is not under the
  // mouse), with the pieces' picker and its locators (a skull's surface);
  // the guides are not pickable otherwise (strokes are drawn through them
  // onto the bone).
  vtkCellPicker* picker = piecePicker;
  picker->InitializePickList();
  picker->PickFromListOn();
  picker->SetTolerance(0.0005);
  picker->AddPickList(planner->guideActor);
  for (auto& actors : planner->pieceActors)
    for (auto& a : actors)
      picker->AddPickList(a);
  planner->guideActor->PickableOn();
  locators.update(planner->renderer, picker);
  const bool picked = picker->Pick(x, y, 0, planner->renderer) && picker->GetCellId() >= 0 &&
    picker->GetProp3D() == planner->guideActor.GetPointer();
  planner->guideActor->PickableOff();
  if (!picked)
    return -1;
  double at[3];
  picker->GetPickPosition(at);
  int nearest = -1;
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < planner->guides.size(); ++i)
  {
    vtkPolyData* surface = planner->guides[i].surface;
    if (!surface)
      continue;
    vtkNew<vtkStaticCellLocator> locator;
    locator->SetDataSet(surface);
    locator->BuildLocator();
    double closest[3], d2 = 0.0;
    vtkIdType cell = -1;
    int subId = 0;
    locator->FindClosestPoint(at, closest, cell, subId, d2);
    if (cell >= 0 && d2 < least)
    {
      least = d2;
      nearest = static_cast<int>(i);
    }
  }
  return nearest;
}

int PlannerStyle::pickPiece(int x, int y, std::array<double, 3>& point, std::array<double, 3>& normal)
{
  piecePicker->InitializePickList();
  piecePicker->PickFromListOn();
  piecePicker->SetTolerance(0.0005);
  for (auto& actors : planner->pieceActors)
    for (auto& a : actors)
      piecePicker->AddPickList(a);
  if (planner->preview->GetVisibility())
    piecePicker->AddPickList(planner->preview);
  locators.update(planner->renderer, piecePicker);
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
  if (piece == planner->movedPiece())
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

void PlannerStyle::startDeform()
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
  if (planner->tool == SMOOTH)
  {
    // A new brush stroke: its dabs share the number after the session's last.
    int last = 0;
    for (const Deformation& d : planner->session.deformations)
      last = std::max(last, d.stroke);
    dragged.stroke = last + 1;
  }
  dabs.assign(1, dragged);
  vtkLKPatchDeformationFilter* f = planner->deformer(static_cast<std::size_t>(piece));
  f->CheckCrossingsOff(); // while dragging; the release's rebuild looks (Planner::applyDeformations)
  Planner::addTo(f, dragged); // a bump or box of amount 0 until the mouse moves
  // The live piece: the filter's output, shown in place of the piece's actors.
  vtkNew<vtkPolyDataMapper> m;
  m->SetInputConnection(f->GetOutputPort());
  m->ScalarVisibilityOff();
  planner->preview->SetMapper(m);
  planner->preview->GetProperty()->SetColor(pieceColour(static_cast<std::size_t>(piece)).data());
  planner->preview->SetUserMatrix(piece == planner->movedPiece() ? planner->segmentMatrix().GetPointer() : nullptr);
  planner->preview->SetVisibility(true);
  planner->preview->PickableOn();
  for (auto& actor : planner->pieceActors[static_cast<std::size_t>(piece)])
    actor->SetVisibility(false);
  this->Interactor->Render();
}

void PlannerStyle::dragDeform()
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

void PlannerStyle::endDeform()
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

void PlannerStyle::showSawLine(int x, int y)
{
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(sawStart[0], sawStart[1], 0.0);
  pts->InsertNextPoint(x, y, 0.0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType ends[2] = { 0, 1 };
  lines->InsertNextCell(2, ends);
  planner->sawPd->SetPoints(pts);
  planner->sawPd->SetLines(lines);
  planner->sawPd->Modified();
  planner->sawActor->SetVisibility(true);
  this->Interactor->Render();
}

void PlannerStyle::endSaw()
{
  const int* end = this->Interactor->GetEventPosition();
  planner->sawActor->SetVisibility(false);
  const double dx = end[0] - sawStart[0], dy = end[1] - sawStart[1];
  const double pixels = std::sqrt(dx * dx + dy * dy);
  if (pixels < 5.0)
  {
    this->Interactor->Render(); // a click: no line
    return;
  }
  // The line's ends at the depth of the focal point, and the plane through
  // them that holds the eye (or the view direction).
  vtkCamera* camera = planner->renderer->GetActiveCamera();
  double focal[4], display[3], a[4], b[4];
  camera->GetFocalPoint(focal);
  vtkInteractorObserver::ComputeWorldToDisplay(planner->renderer, focal[0], focal[1], focal[2], display);
  vtkInteractorObserver::ComputeDisplayToWorld(planner->renderer, sawStart[0], sawStart[1], display[2], a);
  vtkInteractorObserver::ComputeDisplayToWorld(planner->renderer, end[0], end[1], display[2], b);
  double along[3], towards[3], normal[3];
  for (int c = 0; c < 3; ++c)
    along[c] = b[c] - a[c];
  if (camera->GetParallelProjection())
    camera->GetDirectionOfProjection(towards);
  else
  {
    const double* eye = camera->GetPosition();
    for (int c = 0; c < 3; ++c)
      towards[c] = a[c] - eye[c];
  }
  vtkMath::Cross(along, towards, normal);
  // A point of the bone under the line, from its middle outwards.
  std::array<double, 3> onBone{};
  bool hit = false;
  locators.update(planner->renderer, picker);
  const int steps = static_cast<int>(pixels), middle = steps / 2;
  for (int k = 0; k <= steps && !hit; ++k)
  {
    const int i = middle + (k % 2 ? (k + 1) / 2 : -(k / 2)); // middle, +1, -1, +2, -2, ...
    if (i < 0 || i > steps)
      continue;
    const double t = static_cast<double>(i) / steps;
    const int x = static_cast<int>(std::lround(sawStart[0] + t * dx)), y = static_cast<int>(std::lround(sawStart[1] + t * dy));
    if (picker->Pick(x, y, 0, planner->renderer) && picker->GetCellId() >= 0)
    {
      picker->GetPickPosition(onBone.data());
      hit = true;
    }
  }
  std::string why;
  if (!hit || vtkMath::Norm(normal) == 0.0)
    why = "the saw line does not cross the bone: drag it across the bone";
  else
  {
    const Session before = planner->session;
    if (planner->addSawStroke({ a[0], a[1], a[2] }, { normal[0], normal[1], normal[2] }, onBone, why))
    {
      planner->remember(before);
      planner->notice = "saw line: stroke " + std::to_string(planner->session.strokes.size());
      planner->rebuild();
    }
  }
  if (!why.empty())
  {
    planner->message = why;
    planner->updateStatus();
  }
  this->Interactor->Render();
}

void PlannerStyle::putToolsDown()
{
  planner->drawing = false;
  planner->sawing = false;
  planner->moving = false;
  planner->tool = NO_TOOL;
}

void PlannerStyle::stopMeasuring()
{
  planner->measuring = 0;
  planner->settingPlane = false;
  if (!planner->measurePicked.empty())
  {
    planner->measurePicked.clear();
    planner->measurePickedPieces.clear();
    planner->showMeasurements();
  }
}

void PlannerStyle::measureClick()
{
  // A point of a piece, in the piece's own frame (a point on the moved
  // segment moves with it), as names and deformations are picked.
  Planner& p = *planner;
  const int* pos = this->Interactor->GetEventPosition();
  std::array<double, 3> point, normal;
  const int piece = pickPiece(pos[0], pos[1], point, normal);
  const bool angle = p.measuring == 3 && !p.settingPlane;
  if (piece < 0)
  {
    p.message = p.settingPlane ? "no bone there: click three points of the bone's midline (O: stop)"
      : angle ? "no bone there: click the bone for an arm's end, the vertex and the other arm's end (a: stop)"
              : "no bone there: click the bone to measure from and to (u: stop measuring)";
    p.updateStatus();
    this->Interactor->Render();
    return;
  }
  addMeasuredPoint(point, piece);
}

void PlannerStyle::measureOnScan()
{
  // The point of the CT view's plane under the click, in the scan's (the
  // bone's unmoved) coordinates; it goes with the piece nearest it (a point
  // of the mandibular canal, inside the bone, with the bone around it), or,
  // in the soft tissue away from the bone, with none: the plan moves bone
  // only.
  Planner& p = *planner;
  const int* pos = this->Interactor->GetEventPosition();
  vtkRenderer* view = p.scanRenderer;
  view->SetDisplayPoint(pos[0], pos[1], 0.0);
  view->DisplayToWorld();
  double world[4];
  view->GetWorldPoint(world);
  const double half = 0.5 * p.scanPicture.side;
  const double x = world[3] != 0.0 ? world[0] / world[3] : world[0], y = world[3] != 0.0 ? world[1] / world[3] : world[1];
  if (!(std::abs(x) <= half && std::abs(y) <= half))
  {
    p.message = "that is beside the CT's picture: click in it (or on the bone)";
    p.updateStatus();
    this->Interactor->Render();
    return;
  }
  const lkapp::ViewFrame& f = p.scanPicture.frame;
  std::array<double, 3> point;
  for (std::size_t i = 0; i < 3; ++i)
    point[i] = f.centre[i] + x * f.right[i] + y * f.up[i];
  double away = 0.0;
  const int piece = p.pieceOnScan(point, away);
  const std::size_t picked = p.measurePicked.size(), measured = p.session.measurements.size();
  addMeasuredPoint(point, piece);
  const bool taken = p.measurePicked.size() > picked || p.session.measurements.size() > measured;
  if (taken && piece < 0 && away < VTK_DOUBLE_MAX)
  {
    char text[160];
    std::snprintf(text, sizeof text,
      "that point lies in the soft tissue, %.1f mm from the bone: it stays where it is when the segment moves", away);
    // After the measurement's last point, beside what it measured.
    p.notice = p.measurePicked.empty() ? p.notice + "; " + text : std::string(text);
    p.updateStatus();
    this->Interactor->Render();
  }
}

void PlannerStyle::addMeasuredPoint(const std::array<double, 3>& point, int piece)
{
  Planner& p = *planner;
  const bool angle = p.measuring == 3 && !p.settingPlane;
  p.message.clear();
  // An angle's arm needs a length: its end apart from the vertex, as shown
  // (and a plane three points apart).
  if (p.measuring == 3 && !p.measurePicked.empty() &&
    p.shownPoint(point, piece, p.shownMatrix) ==
      p.shownPoint(p.measurePicked.back(), p.measurePickedPieces.back(), p.shownMatrix))
    p.message = "click a point apart from the last: an angle's arm needs a length";
  else
  {
    p.measurePicked.push_back(point);
    p.measurePickedPieces.push_back(piece);
  }
  if (static_cast<int>(p.measurePicked.size()) < p.measuring)
    p.showMeasurements();
  else if (p.settingPlane)
  {
    // The plane through the three points (midline landmarks) replaces the
    // fitted one, and the mirror is shown across it.
    std::array<double, 3> origin, normal;
    std::string why;
    if (!planeThrough(p.measurePicked, origin, normal, why))
    {
      p.message = why + ": click three points again (O: stop)";
      p.measurePicked.clear();
      p.measurePickedPieces.clear();
      p.showMeasurements();
    }
    else
    {
      p.remember();
      p.session.mirrorPlane = p.measurePicked;
      p.session.mirror = true;
      stopMeasuring();
      p.notice = "mirror plane set through three points";
      p.rebuild(); // (which says anew what the plan warns)
      // A mid-sagittal plane is within a few degrees of the left-right
      // axis; far from it, the clicks were likely not on the midline.
      const double tilt = Planner::degreesFromX(normal);
      if (tilt > 30.0)
      {
        char text[200];
        std::snprintf(text, sizeof text,
          "the plane set is %.0f deg from x, the patient's left-right axis: were the clicks on the midline? (O: "
          "set it again)",
          tilt);
        p.message += (p.message.empty() ? "" : "\n") + std::string(text);
      }
    }
  }
  else
  {
    p.remember();
    Measurement m;
    m.from = p.measurePicked[0];
    m.pieces[Measurement::FROM] = p.measurePickedPieces[0];
    const std::size_t last = p.measurePicked.size() - 1;
    m.to = p.measurePicked[last];
    m.pieces[Measurement::TO] = p.measurePickedPieces[last];
    if (angle)
    {
      m.angle = true;
      m.at = p.measurePicked[1];
      m.pieces[Measurement::AT] = p.measurePickedPieces[1];
    }
    p.session.measurements.push_back(m);
    p.measurePicked.clear();
    p.measurePickedPieces.clear();
    p.notice = "measured " + p.measuredText(m);
    p.rebuild();
  }
  planner->updateStatus();
  this->Interactor->Render();
}

bool PlannerStyle::picksOnTheBone() const
{
  return planner->naming == 1 || planner->measuring || planner->tool != NO_TOOL || planner->moving ||
    planner->sawing || planner->drawing;
}

bool PlannerStyle::onScanView(int x, int y) const
{
  return planner->onScanView(x, y);
}

void PlannerStyle::dragWindow()
{
  const int* at = this->Interactor->GetEventPosition();
  const int* size = planner->scanRenderer->GetSize();
  const double dx = at[0] - windowStart[0], dy = at[1] - windowStart[1];
  if (std::abs(dx) + std::abs(dy) < 3 && !windowDragged)
    return; // a click's tremor
  windowDragged = true;
  // The view's width to the right: four times the window; its height up:
  // the level one window lower.
  windowTo[0] = windowFrom[0] * std::pow(4.0, dx / std::max(1, size[0]));
  windowTo[1] = windowFrom[1] - windowFrom[0] * dy / std::max(1, size[1]);
  planner->previewScanWindow(windowTo[0], windowTo[1]);
  this->Interactor->Render();
}

void PlannerStyle::endWindow()
{
  windowing = false;
  if (!windowDragged)
  {
    // A click on the view: in a mode that picks, it is not the bone.
    if (picksOnTheBone())
      planner->message = "that is the CT view, not the bone: press on the bone (c hides the view)";
    planner->updateStatus();
    this->Interactor->Render();
    return;
  }
  planner->remember();
  const lkapp::GreyWindow grey = lkapp::handWindow(windowTo[0], windowTo[1]);
  planner->session.scanWindowWidth = grey.width;
  planner->session.scanWindowLevel = grey.level;
  planner->notice = "the CT view's " + lkapp::greyWindowLabel(grey) + " (C: back to the preset)";
  planner->refreshScan();
  this->Interactor->Render();
}

void PlannerStyle::moveScanPlane(double mm)
{
  Session& s = planner->session;
  const double offset = std::clamp(s.scanOffset + mm, -200.0, 200.0);
  if (offset == s.scanOffset)
    return;
  // The notches of one turn of the wheel are one undo step: a step right
  // after the last one (nothing done between) adds none.
  if (!(planner->undoStack.size() == wheelUndoSize && planner->redoStack.empty() && s.scanOffset == wheelOffset))
    planner->remember();
  s.scanOffset = std::abs(offset) < 1e-9 ? 0.0 : offset;
  wheelUndoSize = planner->undoStack.size();
  wheelOffset = s.scanOffset;
  planner->notice.clear();
  planner->refreshScan();
  this->Interactor->Render();
}

void PlannerStyle::OnMouseWheelForward()
{
  const int* at = this->Interactor->GetEventPosition();
  if (onScanView(at[0], at[1]))
    return moveScanPlane(1.0);
  vtkInteractorStyleTrackballCamera::OnMouseWheelForward();
}

void PlannerStyle::OnMouseWheelBackward()
{
  const int* at = this->Interactor->GetEventPosition();
  if (onScanView(at[0], at[1]))
    return moveScanPlane(-1.0);
  vtkInteractorStyleTrackballCamera::OnMouseWheelBackward();
}

void PlannerStyle::OnLeftButtonDown()
{
  // The CT view hides the bone behind it: a press there sets the view's
  // window (a CT's), a click picks nothing.
  const int* at = this->Interactor->GetEventPosition();
  if (onScanView(at[0], at[1]))
  {
    // A distance or an angle measured on the CT: what the surface does not
    // have (from the cut to the canal, a root's length).
    if (planner->measuring && !planner->settingPlane && planner->scanPicture.image)
      return measureOnScan();
    if (planner->scanIsLabelMap || !planner->scanPicture.image)
    {
      planner->message = picksOnTheBone() ? "that is the CT view, not the bone: press on the bone (c hides the view)" :
                                 "the view shows a label map, which has no window to drag (the wheel moves its plane)";
      planner->updateStatus();
      this->Interactor->Render();
      return;
    }
    windowing = true;
    windowDragged = false;
    windowStart[0] = at[0];
    windowStart[1] = at[1];
    windowFrom[0] = windowTo[0] = planner->scanPicture.grey.width;
    windowFrom[1] = windowTo[1] = planner->scanPicture.grey.level;
    return;
  }
  if (planner->naming == 1)
    return pickPieceToName();
  if (planner->measuring)
    return measureClick();
  if (planner->tool != NO_TOOL)
    return startDeform();
  if (planner->moving && planner->hasSegment())
    return startMove();
  if (planner->sawing)
  {
    pressed = true;
    const int* pos = this->Interactor->GetEventPosition();
    sawStart[0] = pos[0];
    sawStart[1] = pos[1];
    return;
  }
  if (!planner->drawing)
    return vtkInteractorStyleTrackballCamera::OnLeftButtonDown();
  pressed = true;
  planner->current.clear();
  pick();
}

void PlannerStyle::OnMouseMove()
{
  if (windowing)
    return dragWindow();
  if (planner->tool != NO_TOOL && pressed)
    return dragDeform();
  if (planner->moving && pressed)
    return drag();
  if (planner->sawing && pressed)
    return showSawLine(this->Interactor->GetEventPosition()[0], this->Interactor->GetEventPosition()[1]);
  if (planner->drawing && pressed)
    return pick();
  vtkInteractorStyleTrackballCamera::OnMouseMove();
}

void PlannerStyle::OnLeftButtonUp()
{
  if (windowing)
    return endWindow();
  if (planner->tool != NO_TOOL && pressed)
    return endDeform();
  if (planner->moving && pressed)
    return endMove();
  if (planner->sawing && pressed)
  {
    pressed = false;
    return endSaw();
  }
  if (!planner->drawing || !pressed)
    return vtkInteractorStyleTrackballCamera::OnLeftButtonUp();
  pressed = false;
  if (planner->current.size() >= 2)
  {
    planner->remember();
    const bool continued = planner->addStroke(planner->current);
    planner->notice = continued ? "stroke " + std::to_string(planner->session.strokes.size()) + " continued" : "";
    planner->rebuild();
  }
  planner->current.clear();
  planner->showStroke();
  this->Interactor->Render();
}

void PlannerStyle::OnRightButtonDown()
{
  if (!planner->drawing && !planner->sawing && !planner->moving && planner->tool == NO_TOOL)
    return vtkInteractorStyleTrackballCamera::OnRightButtonDown();
  if (pressed)
    return; // the left button's drag first
  const int* pos = this->Interactor->GetEventPosition();
  this->FindPokedRenderer(pos[0], pos[1]);
  if (!this->CurrentRenderer)
    return;
  this->GrabFocus(this->EventCallbackCommand);
  this->StartRotate();
}

void PlannerStyle::OnRightButtonUp()
{
  if (this->State != VTKIS_ROTATE)
    return vtkInteractorStyleTrackballCamera::OnRightButtonUp();
  this->EndRotate();
  if (this->Interactor)
    this->ReleaseFocus();
}

void PlannerStyle::pickPieceToName()
{
  const int* pos = this->Interactor->GetEventPosition();
  std::array<double, 3> point{}, normal{};
  const int piece = pickPiece(pos[0], pos[1], point, normal);
  if (piece < 0)
    planner->message = "no piece there: click a piece to name it (Escape: stop naming)";
  else
  {
    planner->naming = 2;
    planner->namingPiece = piece;
    planner->namingAt = point;
    planner->namingText = planner->pieceName(static_cast<std::size_t>(piece));
    planner->composer.reset();
    planner->message.clear();
  }
  planner->updateStatus();
  this->Interactor->Render();
}

void PlannerStyle::typeName(const std::string& key)
{
  Planner& p = *planner;
  // Escape and BackSpace drop a dead accent that waits for its letter, as
  // X's input methods do; Return drops it and keeps the name.
  if (p.naming == 2 && p.composer.composing() && (key == "Escape" || key == "BackSpace"))
    p.composer.reset();
  else if (key == "Escape" || (p.naming == 1 && key == "t"))
    p.naming = 0;
  else if (p.naming == 1)
    // A click that missed leaves the keys of the name to come: none of them
    // is a command (e exports, q quits).
    p.message = "click the piece to name first (Escape: stop naming)";
  else if (key == "Return" || key == "KP_Enter")
  {
    p.composer.reset();
    // Spaces around the name are a slip of the thumb, not part of it.
    const auto first = p.namingText.find_first_not_of(' ');
    p.namingText = first == std::string::npos ? std::string()
                                              : p.namingText.substr(first, p.namingText.find_last_not_of(' ') - first + 1);
    std::string why;
    if (p.namePiece(static_cast<std::size_t>(p.namingPiece), p.namingAt, p.namingText, why))
    {
      p.notice = p.namingText.empty() ? "piece " + std::to_string(p.namingPiece) + " has no name"
                                      : "named piece " + std::to_string(p.namingPiece) + " '" + p.namingText + "'";
      p.naming = 0;
      p.rebuild();
    }
    else
      p.message = why;
  }
  else if (key == "BackSpace")
  {
    // A whole character, however many bytes it takes in UTF-8.
    while (!p.namingText.empty() && (static_cast<unsigned char>(p.namingText.back()) & 0xC0) == 0x80)
      p.namingText.pop_back();
    if (!p.namingText.empty())
      p.namingText.pop_back();
    p.message.clear();
  }
  else
  {
    // The typed letters go into the name as UTF-8: a key's own, or what a
    // dead accent (or the Compose key) and the next key compose ("é"). A
    // key that gives no letter (Shift, an arrow, a control key) is passed
    // over; a backslash, a name grown to its longest and an accent that
    // goes on no such letter are said. A no-break space (U+00A0) is not a
    // letter: it looks like a space and is not one.
    const std::string accent = p.composer.pending();
    const std::u32string typed =
      p.composer.type(key, this->Interactor->GetKeyCode(), this->Interactor->GetControlKey() != 0);
    std::vector<char32_t> characters;
    lkvtk::decodeUTF8(p.namingText, &characters);
    if (p.composer.cancelled())
    {
      const char32_t plain = lkapp::keyCharacter(key, this->Interactor->GetKeyCode(), false);
      const std::string what = plain != 0 && !lkvtk::isControl(plain) ? lkvtk::encodeUTF8(plain) : key;
      p.message =
        (accent.empty() ? "Compose" : "'" + accent + "'") + " and '" + what + "' make no letter: both are dropped";
    }
    else if (p.composer.composing())
      p.message.clear();
    for (const char32_t code : typed)
    {
      const bool letter =
        code != U'\\' && code != 0xA0 && !lkvtk::isControl(code) && lkvtk::isScalarValue(code);
      if (letter && characters.size() < kPieceNameLength)
      {
        p.namingText += lkvtk::encodeUTF8(code);
        characters.push_back(code);
        p.message.clear();
      }
      else if (letter)
        p.message = "a name holds at most " + std::to_string(kPieceNameLength) + " characters";
      else if (code == U'\\')
        p.message = "a name cannot hold a backslash: DICOM reads it as a separator";
    }
  }
  p.updateStatus();
  this->Interactor->Render();
}

void PlannerStyle::typeMove(const std::string& key)
{
  Planner& p = *planner;
  if (key == "Escape")
    p.typingMove = false;
  else if (key == "Return" || key == "KP_Enter")
  {
    std::string why;
    if (p.moveSegmentTo(p.moveText, why))
    {
      p.typingMove = false;
      p.message.clear();
      p.notice = "segment moved by numbers";
      std::printf("%s", p.segmentText().c_str());
      std::fflush(stdout);
      p.keepChanges();
    }
    else
      p.message = why;
  }
  else if (key == "BackSpace")
  {
    if (!p.moveText.empty())
      p.moveText.pop_back();
    p.message.clear();
  }
  else
  {
    // Numbers: digits, a sign, a point, spaces or commas between them, from
    // the keypad too.
    const char32_t typed =
      lkapp::keyCharacter(key, this->Interactor->GetKeyCode(), this->Interactor->GetControlKey() != 0);
    const bool number = typed != 0 && typed < 0x80 && std::strchr("0123456789+-., ", static_cast<char>(typed)) != nullptr;
    if (number && p.moveText.size() < 80)
    {
      p.moveText += static_cast<char>(typed);
      p.message.clear();
    }
    else if (!number && typed != 0 && !lkvtk::isControl(typed))
      p.message = "'" + lkvtk::encodeUTF8(typed) + "' is not part of a number: type x y z (mm), then rx ry rz (degrees)";
  }
  p.updateStatus();
  this->Interactor->Render();
}

void PlannerStyle::typeLatticeVertices(const std::string& key)
{
  Planner& p = *planner;
  if (key == "Escape")
  {
    p.typingLattice = false;
    p.message.clear();
  }
  else if (key == "Return" || key == "KP_Enter")
  {
    const long count = p.latticeText.empty() ? 0 : std::stol(p.latticeText);
    if (count < kFewestLatticeVertices || count > kMostLatticeVertices)
      p.message = std::string("type the lattice's vertices per piece, ") + kLatticeVerticesRange;
    else
    {
      p.typingLattice = false;
      p.message.clear();
      if (count != p.session.latticeVertices || !p.session.lattice)
      {
        p.remember();
        p.session.latticeVertices = count;
        p.session.lattice = true;
        p.notice = "lattices of " + std::to_string(count) + " vertices per piece";
        p.rebuild();
      }
    }
  }
  else if (key == "BackSpace")
  {
    if (!p.latticeText.empty())
      p.latticeText.pop_back();
    p.message.clear();
  }
  else
  {
    const char32_t typed =
      lkapp::keyCharacter(key, this->Interactor->GetKeyCode(), this->Interactor->GetControlKey() != 0);
    if (typed >= U'0' && typed <= U'9')
    {
      if (p.latticeText.size() < 9)
        p.latticeText += static_cast<char>(typed);
      p.message.clear();
    }
    else if (typed != 0 && !lkvtk::isControl(typed))
      p.message = "'" + lkvtk::encodeUTF8(typed) + "' is not a digit: type the lattice's vertices per piece";
  }
  p.updateStatus();
  this->Interactor->Render();
}

void PlannerStyle::OnChar()
{
  const std::string key = this->Interactor->GetKeySym() ? this->Interactor->GetKeySym() : "";
  // While a name is typed every key is a letter of it (q does not quit).
  if (planner->naming != 0)
    return typeName(key);
  if (planner->typingMove)
    return typeMove(key);
  if (planner->typingLattice)
    return typeLatticeVertices(key);
  if (pressed)
  {
    // A key in the middle of a drag would change the tool, the cut or the
    // session under it (z undoing what the drag started from, d turning a
    // bump's pull into a stroke): it is not taken. Shift and the other
    // modifiers say nothing (shift turns a move into a rotation).
    static const char* const modifiers[] = { "Shift", "Control", "Alt", "Meta", "Super", "Caps_Lock", "ISO_" };
    const bool modifier = key.empty() ||
      std::any_of(std::begin(modifiers), std::end(modifiers),
        [&key](const char* m) { return key.compare(0, std::strlen(m), m) == 0; });
    if (!modifier)
    {
      planner->message = key + " not taken: let go of the mouse button first (a drag is under way)";
      planner->updateStatus();
      this->Interactor->Render();
    }
    return;
  }
  Session& s = planner->session;
  std::string error;
  bool rebuild = true;
  planner->notice.clear();
  if (key == "t")
  {
    rebuild = false;
    if (planner->pieces.empty())
      planner->message = "no piece to name";
    else
    {
      planner->naming = 1;
      putToolsDown();
      stopMeasuring();
    }
  }
  else if (key == "O")
  {
    // O: the mirror plane through three clicked points; O again before the
    // third click takes the bone's fitted plane back.
    rebuild = false;
    const bool on = !planner->settingPlane;
    stopMeasuring();
    if (on)
    {
      planner->measuring = 3;
      planner->settingPlane = true;
      putToolsDown();
    }
    else if (!s.mirrorPlane.empty())
    {
      planner->remember();
      s.mirrorPlane.clear();
      planner->notice = "mirror plane: the bone's own plane of symmetry again";
      rebuild = true;
    }
  }
  else if (key == "u" || key == "a")
  {
    // u: a distance (two clicks), a: an angle (three); the same key again stops.
    rebuild = false;
    const int clicks = key == "u" ? 2 : 3;
    const bool on = planner->measuring != clicks;
    stopMeasuring();
    planner->measuring = on ? clicks : 0;
    if (on)
    {
      putToolsDown();
    }
  }
  else if (key == "d" || key == "p")
  {
    bool& on = key == "d" ? planner->drawing : planner->sawing;
    on = !on;
    (key == "d" ? planner->sawing : planner->drawing) = false;
    planner->moving = false;
    planner->tool = NO_TOOL;
    rebuild = false;
    stopMeasuring();
  }
  else if (key == "f")
  {
    planner->tool = (planner->tool + 1) % TOOL_COUNT; // bump, box, smooth, off
    planner->drawing = false;
    planner->sawing = false;
    planner->moving = false;
    rebuild = false;
    stopMeasuring();
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
  else if (key == "K")
  {
    // With the mouse on a guide, that guide alone to the bone's other side
    // (and back); elsewhere all of them; shown, if they were not.
    planner->remember();
    const int* pos = this->Interactor->GetEventPosition();
    const int guide = s.guides ? guideAt(pos[0], pos[1]) : -1;
    if (guide >= 0)
    {
      const std::size_t stroke = planner->guides[static_cast<std::size_t>(guide)].stroke;
      Stroke& st = s.strokes[stroke];
      st.guideOtherSide = !st.guideOtherSide;
      planner->notice = "the cutting guide of stroke " + std::to_string(stroke + 1) +
        (st.guideOtherSide ? ": on the other side from the rest (K on it: back)"
                           : ": on the same side as the rest (K on it: the other)");
    }
    else
    {
      s.guidesOtherSide = !s.guidesOtherSide;
      planner->notice = s.guidesOtherSide ? "cutting guides: on the bone's other side (K: back; K on one: that one)"
                                          : "cutting guides: on the side chosen for them (K: the other; K on one: that one)";
    }
    s.guides = true;
  }
  else if (key == "j")
  {
    // The guides joined along the bone by bars (and apart again); shown, if
    // they were not.
    planner->remember();
    s.guidesJoined = !s.guidesJoined;
    s.guides = true;
    planner->notice = s.guidesJoined ? "cutting guides: joined along the bone by bars (j: apart)"
                                     : "cutting guides: apart (j: joined)";
  }
  else if (key == "x" || key == "l" || key == "m" || key == "o" || key == "k")
  {
    planner->remember();
    bool& flag = key == "x" ? s.cut : key == "l" ? s.lattice : key == "m" ? s.metro : key == "o" ? s.mirror : s.guides;
    flag = !flag;
  }
  else if (key == "c")
  {
    // c: the CT on the first cut line's plane, across it, on the next
    // line's, ... none.
    const std::vector<int> lines = planner->closedCutLines();
    if (!planner->hasScan())
    {
      rebuild = false;
      planner->message = "c shows the CT on a cut line's plane: this plan is on a mesh file, which has no CT";
    }
    else if (lines.empty() && s.scanOnLine == 0)
    {
      rebuild = false;
      planner->message = "c shows the CT on a cut line's plane: there is no closed cut line yet (draw one, then x)";
    }
    else
    {
      // On a line's plane, across it, the next line's plane, ..., none: the
      // view alone is drawn anew.
      planner->remember();
      s.scanOffset = 0.0; // another plane: the cut's own
      if (s.scanOnLine > 0 && !s.scanAcross && std::find(lines.begin(), lines.end(), s.scanOnLine) != lines.end())
        s.scanAcross = true;
      else
      {
        const auto next = std::upper_bound(lines.begin(), lines.end(), s.scanOnLine);
        s.scanOnLine = next == lines.end() ? 0 : *next;
        s.scanAcross = false;
      }
      rebuild = false;
      planner->refreshScan();
    }
  }
  else if (key == "C")
  {
    // C: the CT view's window, bone or soft tissue.
    if (!planner->scanRenderer->GetDraw())
    {
      rebuild = false;
      planner->message = "C turns the CT view from the bone window to the soft-tissue one and back: show it first (c)";
    }
    else if (planner->scanIsLabelMap)
    {
      rebuild = false;
      planner->message = "C: the view shows a label map, which has no soft tissue to window";
    }
    else
    {
      // The window set by hand goes (the preset it was set from), or the
      // other preset comes: the view alone is drawn anew.
      planner->remember();
      if (s.scanWindowWidth > 0.0)
        s.scanWindowWidth = s.scanWindowLevel = 0.0;
      else
        s.softTissueWindow = !s.softTissueWindow;
      rebuild = false;
      planner->refreshScan();
    }
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
      s.segmentAnchored = true;
      s.segmentAnchor = planner->anchorOf(static_cast<std::size_t>(s.segment));
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
      planner->sawing = false;
      planner->tool = NO_TOOL;
      stopMeasuring();
    }
  }
  else if (key == "L")
  {
    rebuild = false;
    planner->typingLattice = true;
    planner->latticeText.clear();
    putToolsDown();
    stopMeasuring();
  }
  else if (key == "v")
  {
    rebuild = false;
    if (!planner->hasSegment())
      planner->message = "pick a segment first (n)";
    else
    {
      planner->typingMove = true;
      planner->moveText.clear();
      putToolsDown();
      stopMeasuring();
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
    {
      planner->notice = "saved " + vtksys::SystemTools::GetFilenameName(sessionPath);
      planner->markSaved();
    }
    else
      planner->message = error;
    rebuild = false;
  }
  else if (key == "e")
  {
    if (planner->exportPieces(exportFolder, error))
    {
      planner->notice = "exported to " + exportFolder +
        (planner->exportedStructureSet ? " (with pieces.dcm, an RT structure set on the CT)" : "");
      planner->markSaved(); // the export holds session.json
    }
    else
      planner->message = error;
    rebuild = false;
  }
  else if (key == "Delete" || key == "BackSpace")
  {
    // While measuring, the last point clicked goes; otherwise the
    // measurement or the stroke whose line is under the mouse, or else the
    // deformation of the bone there (undone with z).
    Planner& p = *planner;
    rebuild = false;
    const int* pos = this->Interactor->GetEventPosition();
    double toMeasurement = 0.0, toStroke = 0.0;
    const int measurement = p.measurementAt(pos[0], pos[1], 12.0, toMeasurement);
    const int stroke = p.strokeAt(pos[0], pos[1], 12.0, toStroke);
    // The deformation under the mouse, looked for only where no line is.
    const auto deformationHere = [&]() {
      std::array<double, 3> at, normal;
      const int piece = p.session.deformations.empty() || p.onScanView(pos[0], pos[1])
        ? -1
        : pickPiece(pos[0], pos[1], at, normal);
      return piece >= 0 ? p.deformationAt(piece, at) : -1;
    };
    if (p.measuring && !p.measurePicked.empty())
    {
      p.measurePicked.pop_back();
      p.measurePickedPieces.pop_back();
      p.notice = "the last point clicked is taken back";
      p.showMeasurements();
    }
    else if (measurement >= 0 && (stroke < 0 || toMeasurement <= toStroke))
    {
      p.remember();
      const std::string what = p.measuredText(p.session.measurements[static_cast<std::size_t>(measurement)]);
      p.session.measurements.erase(p.session.measurements.begin() + measurement);
      p.notice = "measurement " + std::to_string(measurement + 1) + " (" + what + ") removed (z: back)";
      rebuild = true;
    }
    else if (stroke >= 0)
    {
      p.remember();
      p.session.strokes.erase(p.session.strokes.begin() + stroke);
      p.notice = "stroke " + std::to_string(stroke + 1) + " removed (z: back)";
      rebuild = true;
    }
    else if (const int deformation = deformationHere(); deformation >= 0)
    {
      p.removeDeformation(static_cast<std::size_t>(deformation));
      rebuild = true;
    }
    else if (p.session.measurements.empty() && p.session.strokes.empty() && p.session.deformations.empty())
      p.message = key + ": nothing to remove (no stroke, no measurement, no deformation)";
    else
      p.message = key +
        " removes what is under the mouse in the bone's view: a stroke's or a measurement's line, or a deformation";
  }
  else if (key == "Escape" && planner->measuring)
  {
    rebuild = false; // Escape ends measuring, as it ends naming; it quits only from the view
    stopMeasuring();
  }
  else if (key == "q" || key == "Escape")
  {
    quitRequested = true;
    this->Interactor->TerminateApp();
    return;
  }
  else
    return; // no VTK default keys: 'e' and 'w' mean other things here
  if (rebuild)
    planner->rebuild();
  else
    planner->keepChanges(); // a step without a rebuild (n, r) changes the session too
  planner->updateStatus();
  this->Interactor->Render();
}

} // namespace lkplanner
