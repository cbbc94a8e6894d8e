// Shared by the rendering benchmarks (RayTraceFrameTime, CpuRayTraceThroughput,
// MeshFrameTime): their command-line options and the GL renderer's name.
#ifndef RiemannRenderBenchmarkOptions_h
#define RiemannRenderBenchmarkOptions_h

#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderWindow.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#ifndef RIEMANN_SOURCE_DIR
#define RIEMANN_SOURCE_DIR "."
#endif

struct RenderBenchmarkOptions
{
  int Width = 1920;
  int Height = 1080;
  /// Frames per measurement (only where the benchmark takes --repetitions).
  int Repetitions = 2;
  /// The project's Data folder (scenes and metrics).
  std::string Data = std::string(RIEMANN_SOURCE_DIR) + "/Data";
};

/**
 * Read --width W, --height H, --data DIR and, when `withRepetitions`,
 * --repetitions R. False, after saying which, on an unknown option.
 */
inline bool ParseRenderBenchmarkOptions(
  int argc, char** argv, RenderBenchmarkOptions& options, bool withRepetitions = false)
{
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i];
    if (option == "--width")
      options.Width = std::max(1, std::atoi(argv[i + 1]));
    else if (option == "--height")
      options.Height = std::max(1, std::atoi(argv[i + 1]));
    else if (option == "--repetitions" && withRepetitions)
      options.Repetitions = std::max(1, std::atoi(argv[i + 1]));
    else if (option == "--data")
      options.Data = argv[i + 1];
    else
    {
      std::fprintf(stderr, "unknown option %s\n", argv[i]);
      return false;
    }
  }
  return true;
}

/// The median wall time of `repetitions` frames of `window` (each waits
/// for the GPU to finish).
inline double MedianFrameSeconds(vtkRenderWindow* window, int repetitions)
{
  std::vector<double> seconds;
  for (int r = 0; r < repetitions; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    window->WaitForCompletion();
    seconds.push_back(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

/// Only the "OpenGL renderer string" line of VTK's long capability report.
inline std::string RendererName(vtkRenderWindow* window)
{
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  const std::string report = gl ? gl->ReportCapabilities() : "";
  const std::string key = "OpenGL renderer string:";
  const size_t at = report.find(key);
  return at == std::string::npos
    ? std::string("unknown")
    : report.substr(at + key.size(), report.find('\n', at) - at - key.size());
}

#endif
