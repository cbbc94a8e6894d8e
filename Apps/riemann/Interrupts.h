// SIGINT and SIGTERM for the command-line tools: the command stops, its
// partial files are removed, earlier outputs are kept, one line is printed
// and the tool exits with 130 (SIGINT) or 143 (SIGTERM), as shells expect.
//
// Why a thread: a signal handler may only call async-signal-safe functions,
// and removing a folder of pieces is not one. So both signals are blocked in
// every thread (the mask is set before any other thread starts and is
// inherited), and one thread waits for them with sigwait(), where removing
// files is ordinary code. It then ends the process with _Exit(): the
// command's own threads are mid-work and must not run static destructors.
#ifndef RiemannCliInterrupts_h
#define RiemannCliInterrupts_h

#include <string>

namespace riemann
{
namespace cli
{
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

private:
  static void Start();
};
} // namespace cli
} // namespace riemann

#endif
