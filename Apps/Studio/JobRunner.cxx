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

namespace riemann
{
namespace studio
{
struct JobRunner::Job
{
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

void JobRunner::Start(
  const void* key, vtkSmartPointer<vtkAlgorithm> algorithm, const QString& label, Finished finished)
{
  if (this->Closed)
  {
    return;
  }
  auto job = std::make_shared<Job>();
  job->Algorithm = std::move(algorithm);
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

void JobRunner::Launch(const void* key, std::shared_ptr<Job> job)
{
  this->Running[key] = job;
  Q_EMIT this->RunningChanged(static_cast<int>(this->Running.size()));
  QObject::connect(&job->Watcher, &QFutureWatcher<void>::finished, this,
    [this, key, job]() { this->Done(key, job); });
  QPointer<JobRunner> runner(this);
  job->Watcher.setFuture(QtConcurrent::run([job, runner]() {
    ProgressContext context{ runner, job->Label };
    vtkNew<vtkCallbackCommand> progress;
    progress->SetCallback(ForwardProgress);
    progress->SetClientData(&context);
    vtkNew<vtkCallbackCommand> errors;
    errors->SetClientData(job.get());
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
    job->Stop.Watch(job->Algorithm);
    job->Algorithm->AddObserver(vtkCommand::ProgressEvent, progress);
    job->Algorithm->AddObserver(vtkCommand::ErrorEvent, errors);
    job->Algorithm->Update();
    job->Algorithm->RemoveObservers(vtkCommand::ProgressEvent);
    job->Algorithm->RemoveObservers(vtkCommand::ErrorEvent);
  }));
}

void JobRunner::Done(const void* key, std::shared_ptr<Job> job)
{
  this->Running.erase(key);
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
  if (job->WhenFinished)
  {
    job->WhenFinished(job->Algorithm, ok, cancelled ? QString() : error);
  }
  auto queued = this->Queued.find(key);
  if (queued != this->Queued.end())
  {
    auto next = queued->second;
    this->Queued.erase(queued);
    this->Launch(key, next);
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
