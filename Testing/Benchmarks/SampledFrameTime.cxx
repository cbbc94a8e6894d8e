// Frame time of vtkRiemannRayTracePass on a sampled metric (issue 17)
// against the analytic metric it samples: the showcase's Gaussian lens scene
// (Data/scenes/showcase-lens.json, RK4, its own steps), with the lens
// analytic (conformal), then sampled on 24^3, 48^3 and 96^3 points over
// [-4, 4]^3 (Euclidean outside). The ratio is what the tensor-volume spline
// costs over a closed-form metric, on the same renderer in the same run.
//
// Not a test: timings depend on the machine. Run under an X server, e.g.
//   xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" build/bin/RiemannSampledFrameBenchmark \
//     --width 480 --height 270
// Options: --width W --height H --repetitions R --data DIR.
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayTracePass.h"
#include "vtkRiemannScene.h"

#include "RenderBenchmarkOptions.h"
#include "SampledLensImage.h"

#include <cstdio>
#include <string>

namespace
{
/// Median seconds of `repetitions` frames, after one that compiles and uploads.
double MedianFrame(vtkRenderWindow* window, int repetitions)
{
  window->Render();
  return MedianFrameSeconds(window, repetitions);
}
} // namespace

int main(int argc, char** argv)
{
  RenderBenchmarkOptions options;
  if (!ParseRenderBenchmarkOptions(argc, argv, options, true))
  {
    return 2;
  }
  vtkNew<vtkRiemannScene> scene;
  if (!scene->SetDefinitionFile((options.Data + "/scenes/showcase-lens.json").c_str()))
  {
    std::fprintf(stderr, "%s\n", scene->GetLastError());
    return 1;
  }
  vtkNew<vtkRiemannMetric> metric;
  vtkNew<vtkRiemannRayTracePass> pass;
  pass->SetMetric(metric);
  pass->SetScene(scene);
  vtkNew<vtkRenderer> renderer;
  renderer->SetPass(pass);
  scene->ApplyCamera(renderer->GetActiveCamera());
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(options.Width, options.Height);

  if (!metric->SetDefinition(scene->GetMetricDefinition().c_str()))
  {
    std::fprintf(stderr, "%s\n", metric->GetLastError());
    return 1;
  }
  window->Render();
  std::printf("Sampled vs analytic lens, showcase-lens scene, %dx%d, median of %d (GL renderer: "
              "%s)\n\n| metric | frame (s) | ratio to analytic |\n|---|---|---|\n",
    options.Width, options.Height, options.Repetitions, RendererName(window).c_str());
  const double analytic = MedianFrame(window, options.Repetitions);
  std::printf("| analytic (conformal) | %.3f | 1.00 |\n", analytic);
  std::fflush(stdout);
  for (int n : { 24, 48, 96 })
  {
    if (!metric->SetTensorData(SampledLensImage(n, -4.0, 4.0), "Tensors"))
    {
      std::fprintf(stderr, "%s\n", metric->GetLastError());
      return 1;
    }
    const double sampled = MedianFrame(window, options.Repetitions);
    std::printf("| sampled %d^3 | %.3f | %.2f |\n", n, sampled, sampled / analytic);
    std::fflush(stdout);
  }
  if (!std::string(pass->GetLastError()).empty())
  {
    std::fprintf(stderr, "%s\n", pass->GetLastError());
    return 1;
  }
  return 0;
}
