#include "RiemannJobStop.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkWeakPointer.h"

namespace riemann
{
struct JobStop::Watched
{
  vtkWeakPointer<vtkAlgorithm> Algorithm;
  unsigned long Tag = 0;
};

namespace
{
/// ProgressEvent, on the algorithm's own thread: a requested stop is set
/// again after VTK's reset at the start of the execution.
void StopIfRequested(vtkObject* caller, unsigned long, void* clientData, void*)
{
  const auto* stop = static_cast<const std::atomic<bool>*>(clientData);
  auto* algorithm = static_cast<vtkAlgorithm*>(caller);
  if (stop->load() && !algorithm->GetAbortExecute())
  {
    algorithm->SetAbortExecute(1);
  }
}
} // namespace

JobStop::JobStop() = default;

JobStop::~JobStop()
{
  this->Release();
}

void JobStop::Release()
{
  std::lock_guard<std::mutex> guard(this->Lock);
  for (const std::unique_ptr<Watched>& watched : this->Algorithms)
  {
    if (watched->Algorithm)
    {
      watched->Algorithm->RemoveObserver(watched->Tag);
    }
  }
  this->Algorithms.clear();
}

void JobStop::Watch(vtkAlgorithm* algorithm)
{
  if (!algorithm)
  {
    return;
  }
  std::lock_guard<std::mutex> guard(this->Lock);
  for (const std::unique_ptr<Watched>& watched : this->Algorithms)
  {
    if (watched->Algorithm == algorithm)
    {
      return;
    }
  }
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(StopIfRequested);
  callback->SetClientData(&this->Stop);
  auto watched = std::make_unique<Watched>();
  watched->Algorithm = algorithm;
  // Before other observers (a progress bar): the stop is seen first.
  watched->Tag = algorithm->AddObserver(vtkCommand::ProgressEvent, callback, 1.0f);
  this->Algorithms.push_back(std::move(watched));
}

void JobStop::Request()
{
  // Only the flag: AbortExecute is set by the algorithm's own thread, at its
  // next progress report (not from this thread while it runs: its members
  // are not atomic).
  this->Stop.store(true);
}
} // namespace riemann
