#pragma once
/// \file ScanPicture.h
/// The picture of the scan on a cut line's plane: the CT resliced there
/// (scanOnPlane), the cut line and the bone surface's section over it, the
/// patient's directions on its edges and a 10 mm bar. The planner draws it
/// in a corner of its window (c) and its export writes one per cut line
/// (cut_line1_ct.png, ...); the main job writes its cut's (cut_line_ct.png).

#include "common/ScanOnPlane.h"

#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace lkapp
{

/// What the view shows.
struct ScanPicture
{
  vtkSmartPointer<vtkImageData> image; ///< lkapp::scanOnPlane's, in the frame's 2D coordinates
  ViewFrame frame;
  double side = 0.0; ///< mm across
  GreyWindow grey;
  /// Polylines in patient coordinates, drawn over the image: the cut line
  /// (orange) and the bone surface's section by the plane (yellow).
  std::vector<std::vector<std::array<double, 3>>> line, section;
  /// Across a cut: where its plane (orange) and the other cuts' planes
  /// (light orange) cross the picture, as segments in patient coordinates.
  std::vector<std::vector<std::array<double, 3>>> cutTrace, otherTraces;
  /// Where the scan ends (scanBorder; blue): beyond it the picture is black
  /// for want of a scan, not for air.
  std::vector<std::array<double, 3>> border;
  /// The moved segment's section by the picture's plane, where the plan
  /// moves it (cyan): the CT is the scan before the move.
  std::vector<std::vector<std::array<double, 3>>> moved;
  /// Measurements on the picture's plane (magenta): their lines (a point
  /// still waiting for its other end as a small cross) and their values at
  /// the points given, in patient coordinates.
  std::vector<std::vector<std::array<double, 3>>> measured;
  std::vector<std::pair<std::array<double, 3>, std::string>> measuredValues;
  /// A value drawn is the one before the segment's move (the picture is the
  /// scan, unmoved; the bone's view shows the moved value): the legend says so.
  bool measuredBeforeMove = false;
  /// The top line; the window (greyWindowLabel) is written at the bottom
  /// right, as radiology viewers write it.
  std::string title;
  /// A last line of the legend (the planner's: what the mouse does there);
  /// none in the exported pictures.
  std::string hint;
  bool directions = false; ///< the patient's directions are known: letters on the edges
};

/// The measurements' colour in the picture (magenta).
constexpr std::array<double, 3> kMeasuredColour{ 0.95, 0.35, 0.85 };

/// A plane: a point of it and its normal.
using Plane = std::pair<std::array<double, 3>, std::array<double, 3>>;

/// What to picture: a cut line and its plane, seen on that plane or across
/// it.
struct ScanPictureRequest
{
  std::vector<std::array<double, 3>> line; ///< closed, in patient coordinates
  std::array<double, 3> centre{ 0, 0, 0 }, normal{ 0, 0, 1 }; ///< its plane (best-fitting)
  /// Across the cut: the plane through its centre that holds its normal
  /// and its plane's up direction (viewFrame's: the head, or the front), so
  /// the bone runs along the picture and the cut crosses it as a line, with
  /// the other cuts' planes (a segment between two cuts, and what lies
  /// between them). Else on the cut's plane: the bone's section.
  bool across = false;
  std::vector<Plane> otherPlanes;
  bool softTissue = false; ///< a CT in the soft-tissue window, not the bone window (greyWindowOf)
  /// The picture's plane moved along its normal, in mm toward the viewer:
  /// the planes beside the cut (the saw's kerf, a root or the canal a few mm
  /// off it). The cut line and the cut planes' traces stay where they are.
  double offset = 0.0;
  /// A window set by hand (width > 0: the view dragged), in place of the
  /// preset's; a label map keeps its own.
  double windowWidth = 0.0, windowLevel = 0.0;
  /// For a scan whose file gives no orientation: the patient's head and
  /// front as a plan states them, so that the picture stands as a
  /// patient's would (viewFrame's); not given: the scan's own axes.
  bool patientGiven = false;
  HeadAndFront patient;
};

/// Where the picture's plane lies against the cut's: "" at 0, else
/// ", 2 mm toward the feet" (the patient's direction when `directions`,
/// else toward or away from the viewer). `offset` as ScanPictureRequest's.
std::string planeOffsetText(const ViewFrame& frame, double offset, bool directions);

/// A window set by hand: its name and values rounded as the text gives them,
/// the width from 1 to kLargestHandWindow, the level within
/// +-kLargestHandWindow.
GreyWindow handWindow(double width, double level);
constexpr double kLargestHandWindow = 100000.0;

/// The scan as the request asks, over a square three times the line's reach
/// from its centre (on an across view, the other cuts' within 100 mm too),
/// at least 40 and at most 400 mm across, in pixels of half the scan's
/// finest spacing (at most 512 across); the bone surface's section by the
/// picture's plane. False, with `why`, when the scan cannot be resliced.
bool makeScanPicture(vtkImageData* scan, vtkMatrix4x4* scanToPatient, bool labelMap, vtkPolyData* bone,
  const ScanPictureRequest& request, ScanPicture& picture, std::string& why);

/// Where the plane crosses the frame's square of `side` mm: its segment
/// (two points in patient coordinates), or nothing when it misses the square
/// or is parallel to the frame's plane.
std::vector<std::array<double, 3>> planeTrace(const ViewFrame& frame, double side, const Plane& plane);

/// Puts the picture into `renderer` (whose props it replaces) with its own
/// camera; `fontSize` for the title, the letters and the bar's label.
void showScanPicture(vtkRenderer* renderer, const ScanPicture& picture, int fontSize);

/// The picture alone, `pixels` square, as a PNG file (whole or not at all),
/// rendered off screen on the X connection `display` (openDisplay's).
bool writeScanPicture(const ScanPicture& picture, int pixels, const std::string& path, std::string& error,
  void* display);

} // namespace lkapp
