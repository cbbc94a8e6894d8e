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
 * observed algorithm reports progress, when `show` is true. Commands pass
 * StderrIsTerminal() (plus their own rules, e.g. a long render), so scripts
 * and tests that read stderr from a pipe get clean logs.
 */
class ProgressBar : public vtkCommand
{
public:
  static ProgressBar* New() { return new ProgressBar; }
  /// Observe `object`'s ProgressEvent under `label`; draw only if `show`.
  void Observe(vtkObject* object, const std::string& label, bool show);
  /// Whether stderr is a terminal (someone watches).
  static bool StderrIsTerminal();
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
