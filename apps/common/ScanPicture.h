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
  /// Where the scan ends (scanBorder; blue): beyond it the picture is black
  /// for want of a scan, not for air.
  std::vector<std::array<double, 3>> border;
  std::string title;
  bool directions = false; ///< the patient's directions are known: letters on the edges
};

/// The scan on the plane of `line` (a closed polyline, patient coordinates,
/// with its best-fitting plane's normal), over a square 1.5 times the line's
/// extent and at least 40 mm across, in pixels of half the scan's finest
/// spacing (at most 512 across); the bone surface's section by that plane.
/// False, with `why`, when the scan cannot be resliced.
/// A CT is shown in the bone window, or with `softTissue` the soft-tissue
/// window (greyWindowOf).
bool makeScanPicture(vtkImageData* scan, vtkMatrix4x4* scanToPatient, bool labelMap, bool softTissue, vtkPolyData* bone,
  const std::vector<std::array<double, 3>>& line, const std::array<double, 3>& centre,
  const std::array<double, 3>& normal, ScanPicture& picture, std::string& why);

/// Puts the picture into `renderer` (whose props it replaces) with its own
/// camera; `fontSize` for the title, the letters and the bar's label.
void showScanPicture(vtkRenderer* renderer, const ScanPicture& picture, int fontSize);

/// The picture alone, `pixels` square, as a PNG file (whole or not at all),
/// rendered off screen on the X connection `display` (openDisplay's).
bool writeScanPicture(const ScanPicture& picture, int pixels, const std::string& path, std::string& error,
  void* display);

} // namespace lkapp
