// Results a filter reports in its output's field data: one tuple of doubles
// under a name (Metro's distances, a fit's counts, a plane, a guide's slot).
#ifndef vtkLKFieldValues_h
#define vtkLKFieldValues_h

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>

namespace lkvtk
{
/// Adds to `fd` the array `name` of one tuple, `components` values long.
inline void addFieldValues(vtkFieldData* fd, const char* name, const double* values, int components)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->InsertNextTuple(values);
  fd->AddArray(a);
}

/// Adds to `fd` the array `name` of one value.
inline void addFieldValue(vtkFieldData* fd, const char* name, double value)
{
  addFieldValues(fd, name, &value, 1);
}
} // namespace lkvtk

#endif
