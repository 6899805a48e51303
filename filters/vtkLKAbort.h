// Stopping on request: a progress observer (or another thread) sets the
// filter's AbortExecute, and the filter stops at its next stage boundary or
// loop check. Every latticekit filter answers it the same way: an empty
// output and the warning "Aborted." (VTK 9.1 keeps an aborted output as up
// to date: call Modified() before the next Update to run again).
#ifndef vtkLKAbort_h
#define vtkLKAbort_h

#include <vtkAlgorithm.h>
#include <vtkDataObject.h>

#include <initializer_list>

namespace lkvtk
{
/// True when `filter` was asked to stop; its `outputs` are then emptied and
/// a warning says so.
inline bool stopRequested(vtkAlgorithm* filter, std::initializer_list<vtkDataObject*> outputs)
{
  if (!filter->GetAbortExecute())
  {
    return false;
  }
  for (vtkDataObject* output : outputs)
  {
    if (output)
    {
      output->Initialize();
    }
  }
  vtkWarningWithObjectMacro(filter, "Aborted.");
  return true;
}
} // namespace lkvtk

#endif
