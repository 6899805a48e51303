#pragma once
/// \file ScanOnPlane.h
/// The scan a bone surface was made from, resliced on a plane (a cut line's):
/// what the saw passes through, a tooth root or the mandibular canal, seen
/// in the CT itself. The plane is shown as radiologists show the nearest of
/// the three standard planes: an axial plane from the feet with the front
/// up, a coronal one from the front, a sagittal one from the patient's left
/// with the front to the left; the patient's right is on the screen's left
/// in the first two (LPS coordinates, as vtkLKMedicalImageReader gives them).

#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

namespace lkapp
{

/// A plane as the screen shows it: its centre, and unit vectors to the
/// screen's right, up, and out of the screen toward the viewer (right x up).
struct ViewFrame
{
  std::array<double, 3> centre{ 0, 0, 0 };
  std::array<double, 3> right{ 1, 0, 0 }, up{ 0, 1, 0 }, towardViewer{ 0, 0, 1 };
};

/// The frame of the plane through `centre` with `normal` (either sign; not
/// zero): towardViewer is the normal turned to the patient's feet, front or
/// left, whichever axis it is nearest; up is the head's direction (the
/// front's for a plane nearest axial) within the plane.
ViewFrame viewFrame(const std::array<double, 3>& centre, const std::array<double, 3>& normal);

/// Where a scan's file gives no orientation (a NIfTI without qform or
/// sform), the patient's head and face directions in its coordinates, as a
/// plan states them. The patient's left is taken as an LPS scan would have
/// it (left = back x head), which such a file cannot confirm.
struct HeadAndFront
{
  std::array<double, 3> head{ 0, 0, 1 }, front{ 0, -1, 0 };
};
/// Whether both are non-zero, finite and not parallel (10 degrees apart at
/// least).
bool isValid(const HeadAndFront& patient);

/// viewFrame in a scan whose patient directions are `patient`'s: the plane
/// shown as the nearest standard one of that patient, head (or front) up.
/// The frame is in the scan's coordinates. Not valid: viewFrame's.
ViewFrame viewFrame(const std::array<double, 3>& centre, const std::array<double, 3>& normal,
  const HeadAndFront& patient);

/// A point in the frame: {mm to the right of the centre, mm up, mm toward the viewer}.
std::array<double, 3> inFrame(const ViewFrame& frame, const std::array<double, 3>& point);

/// The patient direction a vector points to most, in LPS: "L", "R", "P",
/// "A", "S" or "I".
const char* directionLetter(const std::array<double, 3>& v);
/// The same in words: "the patient's left", "the patient's right", "the
/// front", "the back", "the head" or "the feet".
const char* directionWord(const std::array<double, 3>& v);

/// The volume on the frame's plane: a square of `side` mm centred on the
/// frame's centre, `pixels` by `pixels` (pixel (i, j) at
/// centre + x right + y up, x and y from -side/2 + side/pixels/2), values
/// interpolated trilinearly, `background` outside the volume. The volume is
/// in data coordinates (its origin and spacing), which `dataToPatient` takes
/// to the frame's (patient) coordinates; the image is in the frame's 2D
/// coordinates (origin (-side/2 + pixel/2, ..., 0), spacing side/pixels).
/// Null for an empty volume, a singular matrix, side <= 0 or pixels < 2.
vtkSmartPointer<vtkImageData> scanOnPlane(vtkImageData* volume, vtkMatrix4x4* dataToPatient, const ViewFrame& frame,
  double side, int pixels, double background);

/// Where the frame's plane meets the volume's box (from its first to its
/// last voxel centres, taken to patient coordinates): the corners of that
/// polygon in order around it, the first repeated at the end; empty where
/// the plane misses the box. Beyond it the picture shows no scan.
std::vector<std::array<double, 3>> scanBorder(vtkImageData* volume, vtkMatrix4x4* dataToPatient, const ViewFrame& frame);

/// The window and level a volume is shown with: a CT's bone window (width
/// 2000, level 500 HU: the cortex white, marrow and soft tissue grey) or
/// soft-tissue window (width 400, level 40 HU: muscle, fat and a tumour's
/// mass told apart, bone white), or a label map's values from its lowest to
/// its highest (no name).
struct GreyWindow
{
  double width = 2000.0, level = 500.0;
  std::string name = "bone window";
};
GreyWindow greyWindowOf(vtkImageData* volume, bool labelMap, bool softTissue = false);
/// "bone window: W 2000, L 500"; empty for a label map's.
std::string greyWindowLabel(const GreyWindow& window);
/// " (bone window: W 2000, L 500)"; empty for a label map's.
std::string greyWindowText(const GreyWindow& window);

} // namespace lkapp
