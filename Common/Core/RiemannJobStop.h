/**
 * @class riemann::JobStop
 * @brief The one way long work is stopped: the command line's SIGINT and
 * SIGTERM and riemann-studio's Cancel both Request() a stop of the job's
 * algorithms, which the toolkit's filters honour at their next check.
 *
 * Watch() the algorithms of a job; Request() (from any thread: a signal
 * thread, the GUI thread) asks them to stop. A watched algorithm sets its
 * AbortExecute at its next progress report, on its own thread; the
 * toolkit's filters report after each batch and check it before the next
 * (vtkRiemannParallelBatches: at most 1/50 of the work after the request)
 * and return an empty output. The caller tells a stop from a failure by
 * Requested().
 *
 * The request sticks. VTK clears AbortExecute where an execution starts
 * (vtkDemandDrivenPipeline::ExecuteDataStart), so a flag set before a job
 * starts, or between two of its updates, was lost (a cancelled job ran to
 * its end). The watch sets AbortExecute again on the algorithm's own thread
 * at each of its progress reports, the first of which comes right after
 * that reset: an algorithm asked to stop before it starts stops at once.
 *
 * A private header of Riemann::CommonCore for the apps (not wrapped).
 */
#ifndef RiemannJobStop_h
#define RiemannJobStop_h

#include "RiemannCommonCoreModule.h" // For export macro

#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

class vtkAlgorithm;

namespace riemann
{
class RIEMANNCOMMONCORE_EXPORT JobStop
{
public:
  JobStop();
  /// Release()s.
  ~JobStop();
  JobStop(const JobStop&) = delete;
  JobStop& operator=(const JobStop&) = delete;

  /// Watch `algorithm` (thread-safe; null and repeated calls do nothing).
  void Watch(vtkAlgorithm* algorithm);

  /// Ask every watched algorithm to stop at its next check (thread-safe).
  void Request();

  /// Whether Request() was called.
  bool Requested() const { return this->Stop.load(); }

  /**
   * Stop watching: remove the observers from the algorithms still alive.
   * Call it when the job is over, before the same algorithms run another
   * job (a stop requested of this one must not stop that one).
   */
  void Release();

private:
  struct Watched;
  std::atomic<bool> Stop{ false };
  std::mutex Lock;
  std::vector<std::unique_ptr<Watched>> Algorithms;
};
} // namespace riemann

#endif
