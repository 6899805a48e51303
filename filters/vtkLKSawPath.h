// Whether a screw that fixes a guide lies in a saw's path: the rule both
// guide filters (vtkLKCuttingGuideFilter with its OtherCutPlanes,
// vtkLKGuideBarFilter for guides made without them) judge screws by.
//
// A screw is the segment from the guide's top to ScrewDepth into the bone
// along the guide's approach. The blade cuts a kerf half the slot's width
// each side of its plane; where the screw comes within its radius, that
// half-width and a 1 mm margin of the plane, the blade would meet it.
#ifndef vtkLKSawPath_h
#define vtkLKSawPath_h

#include <algorithm>
#include <array>
#include <cmath>

namespace lkvtk
{
/// How deep a screw that fixes a guide goes into the bone: mm (a
/// monocortical screw is 5 to 8 mm long).
constexpr double ScrewDepth = 10.0;

/// The room kept between a screw and a saw's kerf: mm.
constexpr double SawPathMargin = 1.0;

/// How far the segment from `a` to `b` stays from the plane through
/// `origin` with unit `normal`: 0 where it crosses the plane.
inline double segmentPlaneGap(const std::array<double, 3>& a, const std::array<double, 3>& b,
  const std::array<double, 3>& origin, const std::array<double, 3>& normal)
{
  double fa = 0.0, fb = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    fa += (a[i] - origin[i]) * normal[i];
    fb += (b[i] - origin[i]) * normal[i];
  }
  return fa * fb <= 0.0 ? 0.0 : std::min(std::abs(fa), std::abs(fb));
}

/// Whether a screw of `radius` from `top` to `deep` lies in the path of the
/// saw whose kerf reaches `halfWidth` each side of the plane through
/// `origin` with unit `normal`.
inline bool screwInSawPath(const std::array<double, 3>& top, const std::array<double, 3>& deep, double radius,
  const std::array<double, 3>& origin, const std::array<double, 3>& normal, double halfWidth)
{
  return segmentPlaneGap(top, deep, origin, normal) < radius + halfWidth + SawPathMargin;
}
} // namespace lkvtk

#endif
