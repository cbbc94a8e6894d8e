// SIGINT and SIGTERM for the command-line tools: the command stops at its
// next check, its partial files are removed, earlier outputs are kept, one
// line is printed and the tool exits with 130 (SIGINT) or 143 (SIGTERM), as
// shells expect.
//
// How it stops: as riemann-studio's Cancel, through riemann::JobStop
// (Common/Core/RiemannJobStop.h). Every algorithm a command observes for
// errors is watched; the signal requests the stop, the running filter stops
// at its next batch, ErrorCollector::ThrowIfAny and WriteAtomically then
// throw Interrupted instead of going on to write, and RunCommandLine ends
// with Conclude(): partial files removed, the line, the status.
//
// Why a thread: a signal handler may only call async-signal-safe functions.
// So both signals are blocked in every thread (the mask is set before any
// other thread starts and is inherited), and one thread waits for them with
// sigwait(), where ordinary code may run. Should the command not reach its
// end within GraceSeconds (a step that has no check: a long write, a
// collective call of a job whose other ranks were not signalled), that
// thread concludes itself and ends the process with _Exit(): the command's
// threads are mid-work and must not run static destructors.
#ifndef RiemannCliInterrupts_h
#define RiemannCliInterrupts_h

#include <exception>
#include <string>

class vtkAlgorithm;

namespace riemann
{
namespace cli
{
/// Thrown where a command notices an interrupt (ErrorCollector::ThrowIfAny,
/// WriteAtomically): it unwinds to RunCommandLine, which concludes.
class Interrupted : public std::exception
{
public:
  const char* what() const noexcept override { return "interrupted"; }
};

class InterruptHandling
{
public:
  /// Block SIGINT and SIGTERM and start the waiting thread (in main, before
  /// any other thread; once per process, later calls do nothing).
  InterruptHandling();
  /// The thread stays (detached) until the process ends.
  ~InterruptHandling() = default;
  InterruptHandling(const InterruptHandling&) = delete;
  InterruptHandling& operator=(const InterruptHandling&) = delete;

  /**
   * An output of this run: on an interrupt, every file or folder next to it
   * whose name has ".partial-<this process's id>" in it is removed (the
   * temporary names of WriteAtomically, WriteImage and the piece writers).
   * The output itself, written earlier or not, is left as it is.
   */
  static void AddOutput(const std::string& path);

  /// The text after ".partial-" in this process's temporary names.
  static std::string PartialTag();

  /// Stop `algorithm` at its next check when a signal comes (riemann::JobStop).
  static void Watch(vtkAlgorithm* algorithm);

  /// Whether SIGINT or SIGTERM came.
  static bool Interrupted();

  /**
   * After an interrupt, at the command's end: remove this run's partial
   * files, print the line (rank 0) and return the exit status, 128 + the
   * signal's number. Once; the waiting thread then does nothing more.
   */
  static int Conclude();

  /// How long the command has to reach its end after a signal, in seconds.
  static constexpr int GraceSeconds = 10;

private:
  static void Start();
};
} // namespace cli
} // namespace riemann

#endif
