#pragma once
/// \file vtkLKRaisedLabel.h
/// Private: text raised on a surface, a printed part's label (a cutting
/// guide's stroke number), so that parts printed for one plan are told
/// apart on the instrument table. The text's outline comes from
/// vtkVectorText, drawn into a fine raster and traced (its strokes overlap,
/// and a solid needs one outline), then laid onto the surface along a
/// direction and lifted off it into a closed solid to join to the part.

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>

namespace lkvtk
{

/// The outline of `text` as flat triangles in the plane z = 0, in mm,
/// counter-clockwise seen from +z: its digits and capitals `height` tall,
/// the baseline on y = 0, the text starting at x = 0; strokes thickened to
/// `stroke` mm at least (a printer's finest wall). The triangles are split
/// until no edge is longer than `edge`, so that the outline can follow a
/// curved surface. Null for a text without a printable character (a space
/// or a character outside ASCII draws nothing).
vtkSmartPointer<vtkPolyData> textOutline(const std::string& text, double height, double stroke, double edge);

/// A closed solid of `outline` (textOutline) on `surface`: each outline
/// point x, y goes to origin + x xAxis + y yAxis (unit, square to each
/// other), then along -up (up = xAxis x yAxis) onto the first face of
/// `surface` a ray from above meets; the solid reaches from `depth` below
/// that face to `relief` above it, oriented outward. Null with `why` when a
/// ray misses the surface or meets a face turned more than 60 degrees from
/// up (a slot's wall, a hole's, an edge): the text has no room there.
vtkSmartPointer<vtkPolyData> raisedLabel(vtkPolyData* surface, vtkPolyData* outline, const double origin[3],
  const double xAxis[3], const double yAxis[3], double relief, double depth, std::string& why);

} // namespace lkvtk
