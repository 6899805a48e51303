#pragma once
/// \file PlannerStyle.h
/// latticekit-planner's mouse and keys: drawing strokes (picked onto the
/// bone), moving the cut segment (drag; shift+drag rotates), the deformation
/// tools (bump, box, smoothing brush: press and drag up or down), and the
/// key commands (kHelp); a saw line (p: a straight drag across the bone,
/// which cuts it in the plane that holds the line and the eye), naming a
/// piece (t: a click on it, then its name typed, Return). While the left button draws, moves or deforms, the
/// right button turns the view (a line around a bone is drawn in parts, the
/// view turned between them; Planner::addStroke). Each change goes to the Planner's session, with an
/// undo snapshot, and the Planner rebuilds what it changes.

#include "common/PickLocators.h"
#include "planner/Planner.h"

#include <vtkCellPicker.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace lkplanner
{

/// The interactor style of the planner's window (trackball camera otherwise).
class PlannerStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static PlannerStyle* New();
  vtkTypeMacro(PlannerStyle, vtkInteractorStyleTrackballCamera);
  Planner* planner = nullptr;
  std::string sessionPath = "planner_session.json", exportFolder = "planner-pieces";
  bool quitRequested = false; ///< 'q' or Escape was pressed
  /// The left button is down on a drag of the view's tools: a stroke or a
  /// saw line drawn, the segment moved, a deformation pulled. Keys wait for
  /// it to be let go (OnChar).
  bool pressed = false;
  vtkNew<vtkCellPicker> picker;
  /// Cell locators for the pickers on large surfaces (a whole skull).
  lkapp::PickLocators locators;
  // Moving the segment: where the drag started, the session then, the
  // segment's centre (moved) and the matrix being shown.
  int dragStart[2] = { 0, 0 };
  Session beforeMove;
  double centre[3] = { 0, 0, 0 };
  std::array<double, 16> dragMatrix{};

  /// World point at display (x, y) on the plane through `centre` facing the camera.
  void displayToWorld(double x, double y, double world[3]);

  void startMove();

  void drag();

  void endMove();

  void pick();

  /// The saw line: where it started on the screen, the line shown while the
  /// mouse moves, and on release the plane through it and the eye (the
  /// camera's view direction, for a parallel projection) handed to
  /// Planner::addSawStroke.
  int sawStart[2] = { 0, 0 };
  void showSawLine(int x, int y);
  void endSaw();
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
  int pickPiece(int x, int y, std::array<double, 3>& point, std::array<double, 3>& normal);

  /// The cutting guide (an index into planner->guides) under display (x,
  /// y): the one nearest the point picked on the guides shown, the bar of a
  /// resection guide counting for its nearest guide; -1 when none is there.
  int guideAt(int x, int y);

  /// Naming (t): a click picks the piece, then the keys type its name.
  void pickPieceToName();
  /// Measuring (u): a click's point on the bone, the first or the second of
  /// a distance; stopMeasuring ends it (another mode's key does too).
  void measureClick();
  /// Measuring on the CT view: the click's point on the view's plane (a
  /// point inside the bone, the canal's or a root's, that the bone's surface
  /// does not have).
  void measureOnScan();
  /// A measured point picked (on the bone or the view), of `piece` (-1: none).
  void addMeasuredPoint(const std::array<double, 3>& point, int piece);
  void stopMeasuring();
  /// No drawing, sawing, moving or deformation tool: before a mode that
  /// takes the mouse or the keys (naming, measuring, typing a move or a count).
  void putToolsDown();
  /// A key while naming: every key is the naming's (Escape stops it).
  void typeName(const std::string& key);
  /// A key while the segment's move is typed (v): digits, sign, point,
  /// spaces and commas; Return moves it, BackSpace, Escape.
  void typeMove(const std::string& key);
  /// Typing the lattice's vertices per piece (L): digits, Return sets the
  /// count (and shows the lattices), Escape stops.
  void typeLatticeVertices(const std::string& key);

  void startDeform();

  void dragDeform();

  void endDeform();

  /// The CT view (c) is dragged as radiology viewers are: to the right a
  /// wider window, up a lower level (brighter); the session takes the
  /// window when the button is let go. A press without a drag in a mode
  /// that picks says that the view is not the bone.
  bool windowing = false, windowDragged = false;
  int windowStart[2] = { 0, 0 };
  double windowFrom[2] = { 0, 0 }, windowTo[2] = { 0, 0 }; ///< width and level, at the press and now
  /// Whether a left press picks a point of the bone (naming, measuring,
  /// deforming, moving, sawing, drawing) rather than turning the view.
  bool picksOnTheBone() const;
  /// Whether display (x, y) is on the CT view.
  bool onScanView(int x, int y) const;
  void dragWindow();
  void endWindow();
  /// The mouse wheel over the CT view moves its plane along its normal,
  /// 1 mm a step (forward: toward the viewer); elsewhere it zooms.
  void moveScanPlane(double mm);
  /// Where the last wheel step left the undo stack and the offset: the next
  /// step, with nothing done between, is part of the same undo step.
  std::size_t wheelUndoSize = 0;
  double wheelOffset = std::numeric_limits<double>::quiet_NaN();

  void OnLeftButtonDown() override;
  void OnMouseMove() override;
  void OnLeftButtonUp() override;
  void OnMouseWheelForward() override;
  void OnMouseWheelBackward() override;
  /// The view turns with the right button while the left one has a tool
  /// (draw, move, deform); otherwise the trackball's (zoom).
  void OnRightButtonDown() override;
  void OnRightButtonUp() override;
  void OnChar() override;
};

} // namespace lkplanner
