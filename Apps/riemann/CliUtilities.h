// Helpers shared by the `riemann` subcommands: argument parsing, loading a
// metric, catching VTK errors, and writing output files whole or not at all.
#ifndef RiemannCliUtilities_h
#define RiemannCliUtilities_h

#include "RungeKutta.h" // For IntegratorType

#include "vtkCommand.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

class vtkObject;
class vtkPolyData;
class vtkRiemannMetric;

namespace riemann
{
namespace cli
{
/// An error to report on stderr with exit status `Status` (1: runtime, 2: usage).
class Failure : public std::runtime_error
{
public:
  Failure(const std::string& message, int status = 1)
    : std::runtime_error(message)
    , Status(status)
  {
  }
  int Status;
};

/// "X,Y,Z" -> three finite numbers; throws Failure (status 2) naming `option`.
void ParseVector3(const std::string& text, const std::string& option, double out[3]);

/// Lower-case extension without the dot ("vtp", "csv"); "" if none.
std::string Extension(const std::string& path);

/// Load and validate a metric file; throws Failure with the parser's message.
vtkSmartPointer<vtkRiemannMetric> LoadMetric(const std::string& path);

/**
 * Write `path` whole or not at all: `write` fills a temporary file next to
 * it, which is renamed over `path` only if `write` returns true.
 * Throws Failure (and removes the temporary file) otherwise.
 */
void WriteAtomically(const std::string& path, const std::function<bool(const std::string&)>& write);

/// Write `data` as a .vtp file (appended binary); false on failure.
bool WritePolyDataFile(vtkPolyData* data, const std::string& path);

/// WritePolyDataFile through WriteAtomically: the file whole or not at all.
void WritePolyDataAtomically(vtkPolyData* data, const std::string& path);

/// "euler", "rk4" or "dp45"; throws Failure (status 2) naming --integrator.
IntegratorType ParseIntegratorOption(const std::string& name);

/**
 * Collects ErrorEvent messages of the observed VTK objects instead of
 * letting them print, so the tool can report them once and exit non-zero.
 */
class ErrorCollector : public vtkCommand
{
public:
  static ErrorCollector* New() { return new ErrorCollector; }
  void Execute(vtkObject* caller, unsigned long event, void* data) override;
  void Observe(vtkObject* object);
  /// Throws Failure with the collected messages, if any.
  void ThrowIfAny(const std::string& context) const;

private:
  std::vector<std::string> Messages;
};
} // namespace cli
} // namespace riemann

#endif
