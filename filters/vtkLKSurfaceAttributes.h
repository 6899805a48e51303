#pragma once
/// \file vtkLKSurfaceAttributes.h
/// Private: carries a surface's point and cell data to a surface a filter
/// made from it without moving it (the repair's, a stroke split into it), as
/// VTK's own filters carry attributes.
#include <vtkType.h>

#include <vector>

class vtkDataSetAttributes;
class vtkIdTypeArray;
class vtkPolyData;

namespace lkvtk
{
/// Carries `input`'s point and cell data to `output`:
/// - output point j takes the data of input point pointSource[j]; where that
///   is -1 (a point the filter made), the data interpolated at it in the input
///   triangle nearest it (then, as vtkDataSetAttributes::InterpolateAllocate
///   decides, id arrays are not carried);
/// - an output triangle takes the data of the input cell whose triangle has the
///   same three corners (either orientation), the corners named by `corner`
///   (input point id -> the id standing for its position; empty: each its
///   own); otherwise, a face the filter made, of the input triangle nearest
///   its centre;
/// - other output cells (lines) take each array's null value.
/// `triangles` is `input`'s surface as triangles on `input`'s points, and
/// cellOf[t] the input cell its triangle t comes from. Normals are left out
/// unless `keepNormals` (a filter that neither moves points nor turns faces
/// over). Nothing is done when `input` has no point or cell data.
void carrySurfaceAttributes(vtkPolyData* input, vtkPolyData* triangles, const std::vector<vtkIdType>& cellOf,
  const std::vector<vtkIdType>& pointSource, const std::vector<vtkIdType>& corner, vtkPolyData* output,
  bool keepNormals = false);

/// Fills `out` (point or cell data) from `in` by origin: element i takes
/// element origin[i] of `in`, or each array's null value where origin[i] is
/// -1 (a point or face with no input counterpart, such as a cut's cap).
/// Normals are left out (a null normal would shade black).
void carryByOrigin(vtkDataSetAttributes* in, vtkDataSetAttributes* out, vtkIdTypeArray* origin);
} // namespace lkvtk
