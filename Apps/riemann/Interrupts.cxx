#include "Interrupts.h"

#include "Distributed.h"

#include "RiemannJobStop.h"

#include <atomic>
#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <set>
#include <thread>

#include <pthread.h>
#include <unistd.h>

namespace riemann
{
namespace cli
{
namespace
{
namespace fs = std::filesystem;

struct Outputs
{
  std::mutex Lock;
  std::set<fs::path> Folders;
};

Outputs& RegisteredOutputs()
{
  static Outputs outputs;
  return outputs;
}

/// Remove this process's partial files next to the registered outputs; how many.
int RemovePartialFiles()
{
  const std::string tag = ".partial-" + InterruptHandling::PartialTag();
  Outputs& outputs = RegisteredOutputs();
  std::lock_guard<std::mutex> guard(outputs.Lock);
  int removed = 0;
  for (const fs::path& folder : outputs.Folders)
  {
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
    {
      const std::string name = entry.path().filename().string();
      const std::size_t at = name.find(tag);
      // The tag whole: ".partial-12" must not match the files of process 123.
      const std::size_t end = at + tag.size();
      if (at != std::string::npos &&
        (end == name.size() || !std::isdigit(static_cast<unsigned char>(name[end]))))
      {
        std::error_code ignored;
        removed += fs::remove_all(entry.path(), ignored) > 0 ? 1 : 0;
      }
    }
  }
  return removed;
}

/// The signal that came (0: none yet).
std::atomic<int> ReceivedSignal{ 0 };

/// The stop every watched algorithm honours (riemann-studio's Cancel's too).
JobStop& Stop()
{
  static JobStop stop;
  return stop;
}

/// Whoever concludes first (the command at its end, or the waiting thread
/// after GraceSeconds) does it; the other does nothing.
std::mutex ConcludeLock;
bool Concluded = false;

/// Partial files removed, the line printed; the exit status.
int ConcludeLocked()
{
  Concluded = true;
  const int signal = ReceivedSignal.load();
  const int removed = RemovePartialFiles();
  if (Rank() == 0)
  {
    std::cerr << "riemann: interrupted by " << (signal == SIGINT ? "SIGINT" : "SIGTERM")
              << "; stopped"
              << (removed == 0 ? std::string()
                               : ", removed " + std::to_string(removed) +
                   (removed == 1 ? " partial file" : " partial files"))
              << " (earlier outputs are kept)" << std::endl;
  }
  return 128 + signal;
}

void WaitForInterrupts(sigset_t signals)
{
  int signal = 0;
  while (sigwait(&signals, &signal) != 0)
  {
  }
  ReceivedSignal.store(signal);
  Stop().Request();
  // The command stops at its next check and concludes; wait for that.
  const auto deadline =
    std::chrono::steady_clock::now() + std::chrono::seconds(InterruptHandling::GraceSeconds);
  while (std::chrono::steady_clock::now() < deadline)
  {
    {
      std::lock_guard<std::mutex> guard(ConcludeLock);
      if (Concluded)
      {
        return;
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  std::lock_guard<std::mutex> guard(ConcludeLock);
  if (!Concluded)
  {
    std::_Exit(ConcludeLocked());
  }
}
} // namespace

InterruptHandling::InterruptHandling()
{
  // Once per process: under MPI before MPI_Init (whose threads must inherit
  // the mask), then again in RunCommandLine.
  static std::once_flag started;
  std::call_once(started, []() { Start(); });
}

void InterruptHandling::Start()
{
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  if (pthread_sigmask(SIG_BLOCK, &signals, nullptr) != 0)
  {
    return; // the default handlers stay: interrupts then end the tool as before
  }
  std::thread(WaitForInterrupts, signals).detach();
}

void InterruptHandling::AddOutput(const std::string& path)
{
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty())
  {
    folder = ".";
  }
  Outputs& outputs = RegisteredOutputs();
  std::lock_guard<std::mutex> guard(outputs.Lock);
  outputs.Folders.insert(folder);
}

std::string InterruptHandling::PartialTag()
{
  return std::to_string(::getpid());
}

void InterruptHandling::Watch(vtkAlgorithm* algorithm)
{
  Stop().Watch(algorithm);
}

bool InterruptHandling::Interrupted()
{
  return ReceivedSignal.load() != 0;
}

int InterruptHandling::Conclude()
{
  std::lock_guard<std::mutex> guard(ConcludeLock);
  return Concluded ? 128 + ReceivedSignal.load() : ConcludeLocked();
}
} // namespace cli
} // namespace riemann
