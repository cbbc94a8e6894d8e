// Frame time of vtkRiemannRayTracePass: the inside view at 1920x1080 with
// Euler and RK4 at 100, 300 and 1000 steps per ray, on the paper's one-bump
// scene (rays stop at their first hit) and on an empty scene in the same
// metric (every ray runs all its steps, so rays x steps / s is exact).
//
// Not a test: timings depend on the machine. Run under an X server, e.g.
//   xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" build/bin/RiemannRayTraceBenchmark
// Options: --width W --height H --repetitions R --data DIR.
// On this project's machines that X server is Mesa llvmpipe (OpenGL on the
// CPU); with a GPU's GLX driver the same command measures the GPU.
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayTracePass.h"
#include "vtkRiemannScene.h"

#include "RenderBenchmarkOptions.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  RenderBenchmarkOptions options;
  if (!ParseRenderBenchmarkOptions(argc, argv, options, true))
  {
    return 2;
  }
  const int width = options.Width;
  const int height = options.Height;
  const int repetitions = options.Repetitions;
  const std::string& data = options.Data;

  vtkNew<vtkRiemannScene> gridScene;
  if (!gridScene->SetDefinitionFile((data + "/scenes/paper-one-bump.json").c_str()))
  {
    std::fprintf(stderr, "%s\n", gridScene->GetLastError());
    return 1;
  }
  vtkNew<vtkRiemannScene> emptyScene;
  emptyScene->SetDefinition(R"({"objects": [], "camera": {"position": [0.5, 0.5, 3.6],
      "look_at": [0, 0, 0], "view_up": [0, 1, 0], "fov": 60}})");
  vtkNew<vtkRiemannMetric> metric;
  metric->SetDefinition(gridScene->GetMetricDefinition().c_str());

  vtkNew<vtkRiemannRayTracePass> pass;
  pass->SetMetric(metric);
  pass->SetUseSceneSettings(false);
  pass->GetIntegrationSettings()->SetInitialIntegrationStep(0.02);
  pass->GetIntegrationSettings()->SetMaximumPropagation(1e9);
  vtkNew<vtkRenderer> renderer;
  renderer->SetPass(pass);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(width, height);

  std::printf("vtkRiemannRayTracePass frame time, %dx%d, median of %d (GL renderer: ", width,
    height, repetitions);
  std::fflush(stdout);
  struct Scene
  {
    const char* Name;
    vtkRiemannScene* Object;
  } scenes[] = { { "one-bump grid", gridScene }, { "empty", emptyScene } };
  bool first = true;
  for (const Scene& scene : scenes)
  {
    pass->SetScene(scene.Object);
    scene.Object->ApplyCamera(renderer->GetActiveCamera());
    for (int integrator :
      { vtkRiemannIntegrationSettings::EULER, vtkRiemannIntegrationSettings::RUNGE_KUTTA4 })
    {
      pass->GetIntegrationSettings()->SetIntegratorType(integrator);
      for (int steps : { 100, 300, 1000 })
      {
        pass->GetIntegrationSettings()->SetMaximumNumberOfSteps(steps);
        if (first)
        {
          window->Render(); // compile the shader outside the timings
          std::printf("%s)\n\n", RendererName(window).c_str());
          std::printf("| scene | integrator | steps | frame (s) | frames/s | rays x steps / s |\n"
                      "|---|---|---|---|---|---|\n");
          first = false;
        }
        const double median = MedianFrameSeconds(window, repetitions);
        char throughput[64] = "-";
        if (scene.Object == emptyScene.GetPointer())
        {
          std::snprintf(throughput, sizeof(throughput), "%.3g",
            static_cast<double>(width) * height * steps / median);
        }
        std::printf("| %s | %s | %d | %.3f | %.2f | %s |\n", scene.Name,
          integrator == vtkRiemannIntegrationSettings::EULER ? "euler" : "rk4", steps, median,
          1.0 / median, throughput);
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
