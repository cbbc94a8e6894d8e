#include "JobRunner.h"

#include "RiemannJobStop.h"

#include "RiemannVtkMessages.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QFutureWatcher>
#include <QPointer>
#include <QtConcurrent/QtConcurrentRun>

#include <atomic>
#include <mutex>
#include <sstream>
#include <utility>

namespace riemann
{
namespace studio
{
struct JobRunner::Job
{
  // Constructed from the moved handle: VTK 9.1's vtkSmartPointer has a move
  // constructor but no move assignment (assigning registers a second
  // reference and leaves the caller's).
  explicit Job(vtkSmartPointer<vtkAlgorithm>&& algorithm)
    : Algorithm(std::move(algorithm))
  {
  }
  vtkSmartPointer<vtkAlgorithm> Algorithm;
  QString Label;
  Finished WhenFinished;
  /// Cancel: the command line's mechanism for SIGINT (RiemannJobStop.h). The
  /// request sticks, so a job cancelled before its thread starts stops at once.
  riemann::JobStop Stop;
  /// Errors the filter raised (vtkErrorMacro), collected on the worker.
  std::mutex ErrorLock;
  std::string Errors;
  QFutureWatcher<void> Watcher;
};

namespace
{
struct ProgressContext
{
  QPointer<JobRunner> Runner;
  QString Label;
};

void ForwardProgress(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* context = static_cast<ProgressContext*>(clientData);
  const double fraction = callData ? *static_cast<double*>(callData) : 0.0;
  if (context->Runner)
  {
    // Queued: the signal is emitted on the GUI thread.
    QMetaObject::invokeMethod(context->Runner.data(), "Progress", Qt::QueuedConnection,
      Q_ARG(QString, context->Label), Q_ARG(double, fraction));
  }
}
}

JobRunner::JobRunner(QObject* parent)
  : QObject(parent)
{
}

JobRunner::~JobRunner()
{
  this->Close();
}

void JobRunner::Close()
{
  this->Closed = true;
  this->CancelAll();
  this->WaitForAll();
}

void JobRunner::Start(const void* key, vtkSmartPointer<vtkAlgorithm>&& algorithm,
  const QString& label, Finished finished)
{
  if (this->Closed)
  {
    return;
  }
  auto job = std::make_shared<Job>(std::move(algorithm));
  job->Label = label;
  job->WhenFinished = std::move(finished);
  auto running = this->Running.find(key);
  if (running != this->Running.end())
  {
    // The latest request wins: stop the running job, start this one after.
    running->second->Stop.Request();
    this->Queued[key] = job;
    return;
  }
  this->Launch(key, job);
}

void JobRunner::Launch(const void* key, std::shared_ptr<Job> owned)
{
  // The Running entry owns the job until Done(); the worker and the signal
  // see it through plain pointers, so nothing on either thread registers or
  // unregisters the algorithm while it runs (JobRunner.h).
  Job* job = owned.get();
  this->Running[key] = std::move(owned);
  Q_EMIT this->RunningChanged(static_cast<int>(this->Running.size()));
  QObject::connect(
    &job->Watcher, &QFutureWatcher<void>::finished, this, [this, key]() { this->Done(key); });
  QPointer<JobRunner> runner(this);
  job->Watcher.setFuture(QtConcurrent::run([job, runner]() {
    ProgressContext context{ runner, job->Label };
    vtkNew<vtkCallbackCommand> progress;
    progress->SetCallback(ForwardProgress);
    progress->SetClientData(&context);
    vtkNew<vtkCallbackCommand> errors;
    errors->SetClientData(job);
    errors->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void* callData) {
      auto* owner = static_cast<Job*>(clientData);
      std::lock_guard<std::mutex> lock(owner->ErrorLock);
      if (callData && owner->Errors.empty())
      {
        owner->Errors =
          riemann::PlainVtkMessage(static_cast<const char*>(callData), caller->GetClassName());
      }
    });
    // Observers are added here, on the job's thread: the algorithm may still
    // be running the job this one replaces when Start() queues it. A Cancel
    // requested before this point is kept by JobStop and honoured at once.
    vtkAlgorithm* algorithm = job->Algorithm.Get();
    job->Stop.Watch(algorithm);
    algorithm->AddObserver(vtkCommand::ProgressEvent, progress);
    algorithm->AddObserver(vtkCommand::ErrorEvent, errors);
    algorithm->Update();
    algorithm->RemoveObservers(vtkCommand::ProgressEvent);
    algorithm->RemoveObservers(vtkCommand::ErrorEvent);
  }));
}

void JobRunner::Done(const void* key)
{
  auto found = this->Running.find(key);
  if (found == this->Running.end())
  {
    return;
  }
  std::shared_ptr<Job> job = std::move(found->second);
  this->Running.erase(found);
  // The job is over: its stop must not stop the next job of this algorithm.
  job->Stop.Release();
  const bool cancelled = job->Stop.Requested() || job->Algorithm->GetAbortExecute();
  QString error;
  {
    std::lock_guard<std::mutex> lock(job->ErrorLock);
    error = QString::fromStdString(job->Errors).trimmed();
  }
  const bool ok = !cancelled && error.isEmpty();
  if (!ok && !cancelled)
  {
    Q_EMIT this->JobFailed(job->Label, error);
  }
  // The job queued behind this one, taken before the callback: a Start for
  // this key from inside the callback is newer, and wins over it.
  std::shared_ptr<Job> next;
  auto queued = this->Queued.find(key);
  if (queued != this->Queued.end())
  {
    next = std::move(queued->second);
    this->Queued.erase(queued);
  }
  if (job->WhenFinished)
  {
    job->WhenFinished(job->Algorithm, ok, cancelled ? QString() : error);
  }
  // This runs inside the job's watcher's signal: free the job (its
  // algorithm, output and watcher) once that signal has returned, on this
  // thread.
  QObject::disconnect(&job->Watcher, nullptr, this, nullptr);
  QMetaObject::invokeMethod(this, [job]() {}, Qt::QueuedConnection);
  if (next && !this->Closed && this->Running.count(key) == 0 && this->Queued.count(key) == 0)
  {
    this->Launch(key, std::move(next));
    return;
  }
  Q_EMIT this->RunningChanged(static_cast<int>(this->Running.size()));
}

void JobRunner::Cancel(const void* key)
{
  this->Queued.erase(key);
  auto running = this->Running.find(key);
  if (running != this->Running.end())
  {
    running->second->Stop.Request();
  }
}

void JobRunner::CancelAll()
{
  this->Queued.clear();
  for (auto& entry : this->Running)
  {
    entry.second->Stop.Request();
  }
}

void JobRunner::WaitForAll()
{
  while (!this->Running.empty())
  {
    auto job = this->Running.begin()->second;
    job->Watcher.waitForFinished();
    // Done() runs from the watcher's signal; deliver it now.
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
  }
}

bool JobRunner::IsRunning(const void* key) const
{
  return this->Running.count(key) != 0 || this->Queued.count(key) != 0;
}

int JobRunner::NumberOfRunningJobs() const
{
  return static_cast<int>(this->Running.size() + this->Queued.size());
}
}
}
