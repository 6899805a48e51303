#pragma once
/// \file PlannerShared.h
/// What the planner's source files share: the lines of a message, markers
/// and captions in the view, a plane's square (Planner.cxx), a piece's
/// edges (PlannerCut.cxx). Not part of the Planner's interface.

#include <vtkCaptionActor2D.h>
#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <array>
#include <string>
#include <vector>

class vtkActor;
class vtkPoints;
class vtkPolyData;

namespace lkplanner
{

/// Whether a 4 x 4 matrix (row by row) is the identity, exactly.
bool isIdentity(const std::array<double, 16>& m);

/// Appends `line` to a message of several lines.
void addLine(std::string& message, const std::string& line);

/// Each line of `text` as its own line of `message`, after `prefix`.
void addLines(std::string& message, const std::string& prefix, const std::string& text);

/// A marker ball (an open line's end, a measurement's first point).
vtkSmartPointer<vtkPolyData> ballAt(const std::array<double, 3>& centre, double radius);

/// A caption in the view: `text` with a leader to its attachment point,
/// `offset` pixels from it, bold in `colour` on a light background (readable
/// over the Metro colours), not pickable.
vtkSmartPointer<vtkCaptionActor2D> captionActor(
  const std::string& text, const std::array<double, 3>& colour, int fontSize, const std::array<double, 2>& offset);

/// How closely a piece's lattice keeps its cut and stroke lines (mm): the
/// points of a line that hold it this close stay exactly, as lattice
/// vertices (vtkLKLatticeFitFilter::FeatureTolerance), as in the main job.
constexpr double kLineTolerance = 0.05;

/// Where a piece's name and a measured value stand from their points when
/// nothing is in the way (Planner::placeCaptions), in pixels.
constexpr std::array<double, 2> NameCaptionOffset{ 20.0, 20.0 };
constexpr std::array<double, 2> MeasureCaptionOffset{ 15.0, -30.0 };

/// A plane's square drawn by two actors: a faint sheet and its outline,
/// through its four corners in order around it.
void showSquare(vtkPoints* corners, vtkActor* sheetActor, vtkActor* outlineActor);

/// Edges as point-id pairs, the smaller id first.
using FeatureEdges = std::vector<std::array<vtkIdType, 2>>;

/// The edges of `piece`'s faces (smaller id first), sorted; with `only`
/// (a flag per point), only those whose two points it flags.
FeatureEdges faceEdgesOf(vtkPolyData* piece, const std::vector<char>* only = nullptr);

} // namespace lkplanner
