/**
 * @file JobRunner.h
 * @brief Runs the items' filters off the GUI thread, one job per item at a
 * time, with progress and cancel.
 *
 * Start(key, job) runs job->Update() on a worker thread (QtConcurrent). The
 * filters report vtkCommand::ProgressEvent and honour AbortExecute between
 * batches, so Cancel(key) stops a job within a batch; a cancelled or failed
 * job's output is dropped and the item keeps its last result. A new Start for
 * a key whose job is still running cancels that job and runs the new one when
 * it has stopped (the latest request wins: moving a slider re-runs once).
 *
 * While a job runs, the runner holds the only reference to its algorithm and
 * neither thread registers or unregisters it: VTK's garbage collector (which
 * runs on every UnRegister of an algorithm, data object or executive, and
 * walks the whole pipeline) is not thread-safe, and a reference dropped on
 * the GUI thread while the worker updates the pipeline let it free the
 * running algorithm. Start() therefore takes the algorithm by move, the
 * worker sees a plain pointer, and a finished job is freed on the GUI thread
 * after its callback.
 */
#ifndef RiemannStudio_JobRunner_h
#define RiemannStudio_JobRunner_h

#include <QObject>
#include <QString>

#include "vtkSmartPointer.h"

#include <functional>
#include <map>
#include <memory>

class vtkAlgorithm;

namespace riemann
{
namespace studio
{
class JobRunner : public QObject
{
  Q_OBJECT
public:
  /// Called on the GUI thread when the job has finished: `ok` false when it
  /// was cancelled or failed (`error` says why; empty for a cancel).
  using Finished = std::function<void(vtkAlgorithm* job, bool ok, const QString& error)>;

  explicit JobRunner(QObject* parent = nullptr);
  ~JobRunner() override;

  /// `job` is moved in: the caller keeps no reference (see above).
  void Start(const void* key, vtkSmartPointer<vtkAlgorithm>&& job, const QString& label,
    Finished finished);
  /// Cancel the job of `key` (and forget a queued one).
  void Cancel(const void* key);
  void CancelAll();
  /// Block until no job runs (closing the window, tests).
  void WaitForAll();
  /// Cancel and wait for every job, and start no job after: the owner is
  /// going away (a finished job's callback or a pending render must not
  /// start work on what is being destroyed).
  void Close();
  bool IsRunning(const void* key) const;
  int NumberOfRunningJobs() const;

Q_SIGNALS:
  /// Progress in [0, 1] of the job called `label`.
  void Progress(const QString& label, double fraction);
  /// A job started or stopped: `running` jobs remain.
  void RunningChanged(int running);
  void JobFailed(const QString& label, const QString& error);

private:
  struct Job;
  void Launch(const void* key, std::shared_ptr<Job> job);
  void Done(const void* key);

  std::map<const void*, std::shared_ptr<Job>> Running;
  std::map<const void*, std::shared_ptr<Job>> Queued;
  bool Closed = false;
};
}
}

#endif
