// Casting a ray through a cell locator: the first face a segment meets.
//
// The tolerance matters. VTK's cells accept a hit when its distance to the
// face is within the tolerance (vtkTriangle compares the squares), and that
// distance is round-off, not 0, inside a face: at a tolerance of 0 a ray
// goes through a surface now and then without a hit, or the first face it
// meets is missed and a farther one returned, depending on where the ray
// starts (seen on raised labels: 1 to 3 % of the rays). A billionth of the
// ray's length keeps every hit, whatever the unit of length, and takes no
// face the ray misses by more.
#ifndef vtkLKRayCast_h
#define vtkLKRayCast_h

#include <vtkAbstractCellLocator.h>
#include <vtkGenericCell.h>
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

/// Whether the segment from `from` to `to` meets a face of `locator`'s data
/// set; if so, `hit` is where it first does, `cell` holds that face and
/// `cellId` (when given) its id.
inline bool firstHit(vtkAbstractCellLocator* locator, const double from[3], const double to[3],
  vtkGenericCell* cell, double hit[3], vtkIdType* cellId = nullptr)
{
  double t = 0.0, pcoords[3];
  int subId = 0;
  vtkIdType id = -1;
  const bool found =
    locator->IntersectWithLine(from, to, rayTolerance(from, to), t, hit, pcoords, subId, id, cell) != 0;
  if (cellId)
    *cellId = id;
  return found;
}
} // namespace lkvtk

#endif
