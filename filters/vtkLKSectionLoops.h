#pragma once
/// \file vtkLKSectionLoops.h
/// Private: where an implicit function (a plane, a sphere) cuts a surface,
/// as polylines of points (vtkCutter, vtkStripper). The cutting guide finds
/// its bone's section with it, and the apps their saw lines' and the main
/// job's (lkapp::sectionLoops).

#include <vtkImplicitFunction.h>
#include <vtkPolyData.h>

#include <array>
#include <vector>

namespace lkvtk
{

using Point3 = std::array<double, 3>;

/// The polylines in which the zero set of `function` cuts `surface`'s
/// polygons, each as its points; a closed one's last point repeats its first
/// (an open one ends at an open surface's border). The segments are joined
/// however many there are: vtkStripper's default of 1,000 cuts a skull's
/// section into open pieces.
std::vector<std::vector<Point3>> sectionPolylines(vtkPolyData* surface, vtkImplicitFunction* function);

/// The polyline with the point nearest p; -1 when there is none. `distance`,
/// if given, gets how far that point is from p.
int nearestPolyline(const std::vector<std::vector<Point3>>& lines, const Point3& p, double* distance = nullptr);

} // namespace lkvtk
