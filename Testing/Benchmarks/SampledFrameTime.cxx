// Frame time of vtkRiemannRayTracePass on a sampled metric (issue 17)
// against the analytic metric it samples: the showcase's Gaussian lens scene
// (Data/scenes/showcase-lens.json, RK4, its own steps), with the lens
// analytic (conformal), then sampled on 24^3, 48^3 and 96^3 points over
// [-4, 4]^3 (Euclidean outside), read both ways ("christoffel": "voxels",
// the default: g and dg at the voxels by six trilinear reads; "spline": the
// exact 64-texel spline), and the 96^3 spline read by the texture unit's
// trilinear filtering (FilteredTextureReads). The ratio is what a tensor
// volume costs over a closed-form metric, on the same renderer in the same
// run.
//
// Then what interaction costs on the 48^3 volume: frames traced at image
// sample distances 2, 4 and 8 (one ray per d x d pixels), and the frames a
// user gets while moving the camera (the window's DesiredUpdateRate at the
// interactor's 15 frames/s, AutoAdjustSampleDistances on): the distance the
// pass settles at and the frame time there.
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

#include <algorithm>
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
/// Frame times of the 48^3 volume with fewer rays, and while interacting.
bool PrintInteractiveFrames(
  vtkRenderWindow* window, vtkRiemannRayTracePass* pass, vtkRiemannMetric* metric, int repetitions)
{
  if (!metric->SetTensorData(SampledLensImage(48, -4.0, 4.0), "Tensors"))
  {
    std::fprintf(stderr, "%s\n", metric->GetLastError());
    return false;
  }
  std::printf("\nSampled 48^3 with fewer rays (ImageSampleDistance d: one ray per d x d pixels)\n\n"
              "| d | frame (s) | frames/s | ratio to d = 1 |\n|---|---|---|---|\n");
  double full = 0.0;
  for (double distance : { 1.0, 2.0, 4.0, 8.0 })
  {
    pass->SetImageSampleDistance(distance);
    const double seconds = MedianFrame(window, repetitions);
    full = distance == 1.0 ? seconds : full;
    std::printf(
      "| %.0f | %.3f | %.2f | %.3f |\n", distance, seconds, 1.0 / seconds, seconds / full);
    std::fflush(stdout);
  }
  pass->SetImageSampleDistance(1.0);

  // Interacting: the rate vtkRenderWindowInteractor asks for while the
  // mouse moves; a few frames to settle, then the median.
  window->Render(); // a still frame: the measurement the first interactive frame starts from
  window->SetDesiredUpdateRate(15.0);
  for (int settle = 0; settle < 4; ++settle)
  {
    window->Render();
  }
  const double interactive = MedianFrameSeconds(window, std::max(3, repetitions));
  std::printf(
    "\nInteracting at 15 frames/s asked (AutoAdjustSampleDistances, distances 1 to %.0f): "
    "d = %.2f, frame %.3f s (%.1f frames/s)\n",
    pass->GetMaximumImageSampleDistance(), pass->GetLastImageSampleDistance(), interactive,
    1.0 / interactive);
  window->SetDesiredUpdateRate(0.0001);
  return true;
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
  // Both readings of the "christoffel" key: the voxels' g and dg (six
  // trilinear reads an evaluation, the default) and the exact spline (64
  // texels of two textures).
  for (const char* reading : { "voxels", "spline" })
  {
    for (int n : { 24, 48, 96 })
    {
      if (!metric->SetTensorData(
            SampledLensImage(n, -4.0, 4.0), "Tensors", false, 1.0, false, "euclidean", reading))
      {
        std::fprintf(stderr, "%s\n", metric->GetLastError());
        return 1;
      }
      const double sampled = MedianFrame(window, options.Repetitions);
      std::printf(
        "| sampled %d^3, \"%s\" | %.3f | %.2f |\n", n, reading, sampled, sampled / analytic);
      std::fflush(stdout);
    }
  }
  // The spline read with the texture unit's trilinear filtering.
  pass->FilteredTextureReadsOn();
  const double filtered = MedianFrame(window, options.Repetitions);
  std::printf(
    "| sampled 96^3, \"spline\", FilteredTextureReads | %.3f | %.2f |\n", filtered, filtered / analytic);
  std::fflush(stdout);
  pass->FilteredTextureReadsOff();
  if (!PrintInteractiveFrames(window, pass, metric, options.Repetitions))
  {
    return 1;
  }
  if (!std::string(pass->GetLastError()).empty())
  {
    std::fprintf(stderr, "%s\n", pass->GetLastError());
    return 1;
  }
  return 0;
}
