#pragma once
/// \file ScanView.h
/// The planner's view of the scan on a cut line's plane (c): the CT
/// resliced there (lkapp::scanOnPlane), the cut line and the bone surface's
/// section over it, the patient's directions on its edges and a 10 mm bar.
/// Drawn in a corner of the window, and by the export as a picture of its
/// own for each cut line (cut_line1_ct.png, ...).

#include "common/ScanOnPlane.h"

#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

namespace lkplanner
{

/// What the view shows.
struct ScanPicture
{
  vtkSmartPointer<vtkImageData> image; ///< lkapp::scanOnPlane's, in the frame's 2D coordinates
  lkapp::ViewFrame frame;
  double side = 0.0; ///< mm across
  lkapp::GreyWindow grey;
  /// Polylines in patient coordinates, drawn over the image: the cut line
  /// (orange) and the bone surface's section by the plane (yellow).
  std::vector<std::vector<std::array<double, 3>>> line, section;
  std::string title;
  bool directions = false; ///< the patient's directions are known: letters on the edges
};

/// The scan on the plane of `line` (a closed polyline, patient coordinates,
/// with its best-fitting plane's normal), over a square 1.5 times the line's
/// extent and at least 40 mm across, in pixels of half the scan's finest
/// spacing (at most 512 across); the bone surface's section by that plane.
/// False, with `why`, when the scan cannot be resliced.
bool makeScanPicture(vtkImageData* scan, vtkMatrix4x4* scanToPatient, bool labelMap, vtkPolyData* bone,
  const std::vector<std::array<double, 3>>& line, const std::array<double, 3>& centre,
  const std::array<double, 3>& normal, ScanPicture& picture, std::string& why);

/// Puts the picture into `renderer` (whose props it replaces) with its own
/// camera; `fontSize` for the title, the letters and the bar's label.
void showScanPicture(vtkRenderer* renderer, const ScanPicture& picture, int fontSize);

/// The picture alone, `pixels` square, as a PNG file (whole or not at all),
/// rendered off screen on the X connection of `like` (the planner's window).
bool writeScanPicture(const ScanPicture& picture, int pixels, const std::string& path, std::string& error,
  vtkRenderWindow* like);

} // namespace lkplanner
