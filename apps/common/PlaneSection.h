#pragma once
/// \file PlaneSection.h
/// Where a plane (or another implicit function) cuts a surface: the closed
/// loops of the section (vtkCutter, vtkStripper). The main job traces a
/// plane's as its scripted pen stroke, the planner's saw line turns one into
/// a stroke (a flat osteotomy), and the osteotomy benchmark takes a sphere's
/// as its craniotomy outline.

#include <vtkImplicitFunction.h>
#include <vtkPolyData.h>

#include <array>
#include <vector>

namespace lkapp
{

using Point3 = std::array<double, 3>;

/// The closed loops in which the zero set of `function` (a plane, a sphere)
/// cuts the surface's polygons, each as its points, the last repeating the
/// first. Open sections and loops of fewer than 7 points are left out.
std::vector<std::vector<Point3>> sectionLoops(vtkPolyData* surface, vtkImplicitFunction* function);

/// sectionLoops for the plane (origin, normal), moved `beside` along the
/// normal: a plane through a flat cap's corners has no defined section
/// there, and a cut along a drawn line leaves its cap flat only to a few
/// hundredths of a millimetre, so a plane that can lie in a piece's cap
/// needs `beside` 0.05 mm. A plane leaves an open surface's section open at
/// its border: such sections are not loops.
std::vector<std::vector<Point3>> planeSectionLoops(
  vtkPolyData* surface, const Point3& origin, const Point3& normal, double beside = 0.0);

/// The loop with the point nearest p; -1 when there is none. `distance`, if
/// given, gets how far that point is from p.
int nearestLoop(const std::vector<std::vector<Point3>>& loops, const Point3& p, double* distance = nullptr);

/// Whether a loop of a plane's section (its points in that plane, the last
/// repeating the first) encloses p, a point of the same plane (its normal
/// `normal`): the even-odd rule in the plane's coordinates.
bool loopEncloses(const std::vector<Point3>& loop, const Point3& p, const Point3& normal);

/// A stroke along a loop (its last point repeating the first): a point at
/// least `step` from the one before, each moved `offset` away from the
/// loop's centre (a pen held just above the bone; 0 keeps the points on it),
/// and back to where it started.
std::vector<Point3> strokeAlongLoop(const std::vector<Point3>& loop, double step, double offset);

} // namespace lkapp
