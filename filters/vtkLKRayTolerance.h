// The tolerance for a cell locator's IntersectWithLine. VTK's cells accept a
// hit when its distance to the face is within the tolerance (vtkTriangle
// compares the squares), and that distance is round-off, not 0, inside a
// face: at a tolerance of 0 a ray goes through a surface now and then
// without a hit, or the first face it meets is missed and a farther one
// returned, depending on where the ray starts (seen on raised labels: 1 to 3
// % of the rays). A billionth of the ray's length keeps every hit, whatever
// the unit of length, and takes no face the ray misses by more.
#ifndef vtkLKRayTolerance_h
#define vtkLKRayTolerance_h

#include <vtkMath.h>

#include <cmath>

namespace lkvtk
{
/// The tolerance to give IntersectWithLine for the segment from `from` to
/// `to`.
inline double rayTolerance(const double from[3], const double to[3])
{
  return 1e-9 * std::sqrt(vtkMath::Distance2BetweenPoints(from, to));
}
} // namespace lkvtk

#endif
