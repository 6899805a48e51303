#pragma once
/// \file CutReport.h
/// What the command-line tools report about a cut (latticekit-cut, the
/// planner, the main job): its pieces (vtkLKExtractCutPieceFilter takes them
/// out of a vtkLKClosedLineCutFilter output), whether each is closed and its volume,
/// and where each cut line lies (length, centre, plane), with the distance
/// and angle between two lines.

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace lkapp
{

/// What a surgeon asks of a cut piece before printing it: its faces (and
/// how many are cap faces: cell data Cap), whether it is closed (no edge
/// with one face only), and then the volume it encloses.
struct PieceFacts
{
  vtkIdType faces = 0, capFaces = 0, openEdges = 0;
  double volume = 0.0; ///< closed pieces only (mesh units cubed)
};
PieceFacts pieceFacts(vtkPolyData* piece);
/// ", closed, volume V ml" or ", open: N border edges" (a surface in mm).
std::string pieceFactsText(const PieceFacts& facts);

/// The geometry of one cut line (a line cell): what places a saw cut. Its
/// vertices (the closing repeat not counted), length, centre (of the line
/// itself, weighted by length), the normal of its best-fitting plane
/// (vtkPlane::ComputeBestFittingPlane; its sign is arbitrary) and how far its
/// farthest vertex lies from that plane.
struct LineFacts
{
  vtkIdType vertices = 0;
  bool closed = false;
  double length = 0.0;
  double centre[3] = { 0, 0, 0 };
  double normal[3] = { 0, 0, 1 };
  double flatness = 0.0;
  /// A closed line's area, projected into its plane (for a line around a
  /// bone, the bone's section: what the saw crosses), and its extent there
  /// along the plane's up and right directions as lkapp::viewFrame shows the
  /// plane (up: the patient's head, or front for a plane nearest axial).
  double area = 0.0;
  double extentUp = 0.0, extentRight = 0.0;
  std::string upAxis, rightAxis; ///< "S-I", "R-L", ...: the patient axes those directions are nearest
};
/// How two cut lines stand to each other: the distance between their centres
/// and the angle between their planes (0-90 degrees).
struct LinesApart
{
  double distance = 0.0, degrees = 0.0;
};
LinesApart linesApart(const LineFacts& a, const LineFacts& b);
/// One per line cell of `lines`, in order.
std::vector<LineFacts> lineFacts(vtkPolyData* lines);
/// The report's lines for them: "cut line k: ..." for each closed line (with
/// the area it encloses and its extent in its plane, along the patient's
/// axes where `patientAxes`: the coordinates are a scan's known LPS), then
/// for each pair "cut lines j and k: centres D mm apart, planes A deg apart"
/// (the planes' angle in 0-90 degrees: the length and the wedge of a segment
/// cut out between two lines). Open lines are left out.
std::string lineFactsText(const std::vector<LineFacts>& facts, bool patientAxes = false);

} // namespace lkapp
