// Progress of a filter that runs other filters inside its RequestData: each
// inner filter's progress is forwarded into its share of the owner's, and a
// stop asked of the owner is passed on to the inner filter (VTK's filters
// check their own AbortExecute in their loops). Without it the owner's bar
// stands still while the inner filter works.
#ifndef vtkLKProgressRelay_h
#define vtkLKProgressRelay_h

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>

namespace lkvtk
{
/// Forwards `inner`'s progress into [lo, hi] of `owner`'s for as long as the
/// relay lives; the observer is removed with it.
class ProgressRelay
{
public:
  ProgressRelay(vtkAlgorithm* owner, vtkAlgorithm* inner, double lo, double hi)
    : Owner(owner)
    , Inner(inner)
    , Lo(lo)
    , Hi(hi)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject* caller, unsigned long, void* cd, void*) {
      auto* self = static_cast<ProgressRelay*>(cd);
      const double p = static_cast<vtkAlgorithm*>(caller)->GetProgress();
      self->Owner->UpdateProgress(self->Lo + (self->Hi - self->Lo) * p);
      if (self->Owner->GetAbortExecute())
        static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    });
    this->Tag = inner->AddObserver(vtkCommand::ProgressEvent, this->Command);
  }
  ~ProgressRelay() { this->Inner->RemoveObserver(this->Tag); }
  ProgressRelay(const ProgressRelay&) = delete;
  ProgressRelay& operator=(const ProgressRelay&) = delete;
  /// The share of the owner's progress the inner filter's next run fills.
  void SetRange(double lo, double hi)
  {
    this->Lo = lo;
    this->Hi = hi;
  }

private:
  vtkAlgorithm* Owner;
  vtkAlgorithm* Inner;
  double Lo, Hi;
  unsigned long Tag = 0;
  vtkNew<vtkCallbackCommand> Command;
};
} // namespace lkvtk

#endif
