// A progress bar on stderr for long filters (ProgressEvent observer).
#ifndef RiemannProgressBar_h
#define RiemannProgressBar_h

#include "vtkCommand.h"

#include <string>

namespace riemann
{
namespace cli
{
/**
 * Prints "label [#####     ]  45%" on stderr, redrawn in place, while the
 * observed algorithm reports progress. Only on a terminal: when stderr is a
 * file or a pipe (scripts, tests) it prints nothing, so logs stay clean.
 */
class ProgressBar : public vtkCommand
{
public:
  static ProgressBar* New() { return new ProgressBar; }
  /// Observe `object`'s ProgressEvent under `label`.
  void Observe(vtkObject* object, const std::string& label);
  void Execute(vtkObject* caller, unsigned long event, void* data) override;
  /// End the line (call after the work, even if it failed).
  void Finish();

private:
  std::string Label;
  int Shown = -1;
  bool Enabled = false;
};
} // namespace cli
} // namespace riemann

#endif
