// The two GPU paths of vtkRiemannRayTracePass side by side (issue 28):
// frame time, frames per second and nanoseconds per ray step of the fragment
// and the compute path, and their ratio, measured in one run on one renderer.
//
// Cases (rays stop at their first hit, at 1e9 of arc length never):
// - the empty scene in the paper's one-bump metric, RK4, 1000 steps: every
//   ray takes every step;
// - the paper's one-bump grid, RK4 and Euler at 100, 300 and 1000 steps;
// - a 1,000,000-triangle sphere (the renderer's actor, UseRendererProps) in
//   the two-bump metric, RK4, 1000 steps;
// - the showcase lens in its scene, analytic, then sampled on 48^3 points
//   and read at the voxels ("christoffel": "voxels"); read by the exact
//   spline ("spline") last, as the slowest;
// - the metric families on the empty scene, RK4, 300 steps: built-in
//   Gaussians (graph), the same bump as a typed expression, and a
//   diffeomorphism (the twist).
// Ray steps are counted from the hit capture of the same view (untimed):
// a ray that hits at arc length s took floor(s / h) + 1 steps, one without
// a hit all of its steps (an upper bound where a ray leaves a sampled
// metric's data early, which the cases here do not), a failed one none.
//
// Not a test: timings depend on the machine. Run under an X server, e.g.
//   xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" build/bin/RiemannGpuPathsBenchmark \
//     --width 320 --height 180
// Options: --width W --height H (default 1920x1080) --repetitions R --data DIR.
// On this project's machines the X server is Mesa llvmpipe (OpenGL on the
// CPU); with a GPU's GLX driver (Testing/Benchmarks/gpu_device) the same
// command measures the GPU.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayTracePass.h"
#include "vtkRiemannScene.h"

#include "RenderBenchmarkOptions.h"
#include "SampledLensImage.h"
#include "UVSphereMesh.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace
{
constexpr const char* EmptySceneJson = R"({"objects": [], "camera": {"position": [0.5, 0.5, 3.6],
  "look_at": [0, 0, 0], "view_up": [0, 1, 0], "fov": 60}})";
constexpr const char* TwistJson = R"({"type": "diffeo", "preset": "twist", "rate": 1})";

/// One row of the table: a view set up on the pass, then measured on both paths.
struct Case
{
  std::string Name;
  std::string Integrator;
  int Steps = 0;
};

struct PathFrame
{
  double Seconds = 0.0;
  double RaySteps = 0.0;
};

/// Ray steps of the last render's hit capture (see the top of this file).
double CountRaySteps(vtkRiemannRayTracePass* pass, double step, int maximumSteps)
{
  vtkFloatArray* hits = pass->GetHitImage();
  double steps = 0.0;
  for (vtkIdType i = 0; i < hits->GetNumberOfTuples(); ++i)
  {
    const double length = hits->GetComponent(i, 3);
    if (length >= 0.0)
    {
      steps += std::min<double>(maximumSteps, std::floor(length / step) + 1.0);
    }
    else if (length == -1.0)
    {
      steps += maximumSteps;
    }
  }
  return steps;
}

/// Median frame of one path (after a frame that compiles), and its ray steps.
PathFrame MeasurePath(
  vtkRenderWindow* window, vtkRiemannRayTracePass* pass, int path, int repetitions)
{
  pass->SetGPUPath(path);
  pass->CaptureHitsOn();
  window->Render(); // compiles; its hits count the steps
  vtkRiemannIntegrationSettings* settings = pass->GetIntegrationSettings();
  PathFrame frame;
  frame.RaySteps = CountRaySteps(
    pass, settings->GetInitialIntegrationStep(), settings->GetMaximumNumberOfSteps());
  pass->CaptureHitsOff();
  window->Render();
  frame.Seconds = MedianFrameSeconds(window, repetitions);
  return frame;
}

void PrintRow(const Case& row, const PathFrame& fragment, const PathFrame& compute)
{
  std::printf("| %s | %s | %d | %.4f | %.4f | %.3f | %.2f | %.2f | %.3g | %.3g |\n",
    row.Name.c_str(), row.Integrator.c_str(), row.Steps, fragment.Seconds, compute.Seconds,
    compute.Seconds / fragment.Seconds, 1.0 / fragment.Seconds, 1.0 / compute.Seconds,
    1e9 * fragment.Seconds / fragment.RaySteps, 1e9 * compute.Seconds / compute.RaySteps);
  std::fflush(stdout);
}
} // namespace

int main(int argc, char** argv)
{
  RenderBenchmarkOptions options;
  if (!ParseRenderBenchmarkOptions(argc, argv, options, true))
  {
    return 2;
  }
  const std::string& data = options.Data;
  vtkNew<vtkRiemannScene> grid;
  vtkNew<vtkRiemannScene> twoBumps;
  vtkNew<vtkRiemannScene> lens;
  vtkNew<vtkRiemannScene> empty;
  for (auto& [scene, file] : { std::pair<vtkRiemannScene*, const char*>{ grid, "paper-one-bump" },
         { twoBumps, "paper-two-bumps" }, { lens, "showcase-lens" } })
  {
    if (!scene->SetDefinitionFile((data + "/scenes/" + file + ".json").c_str()))
    {
      std::fprintf(stderr, "%s\n", scene->GetLastError());
      return 1;
    }
  }
  empty->SetDefinition(EmptySceneJson);
  const std::string bump = grid->GetMetricDefinition();
  vtkNew<vtkRiemannMetric> metric;

  vtkNew<vtkRiemannRayTracePass> pass;
  pass->SetMetric(metric);
  pass->SetUseSceneSettings(false);
  pass->SetAutoAdjustSampleDistances(false);
  vtkRiemannIntegrationSettings* settings = pass->GetIntegrationSettings();
  settings->SetInitialIntegrationStep(0.02);
  settings->SetMaximumPropagation(1e9);
  vtkNew<vtkRenderer> renderer;
  renderer->SetPass(pass);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  window->SetSize(options.Width, options.Height);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(UVSphereMesh(1.2, 1000, 500, 0.0, 0.0, -2.5));
  vtkNew<vtkActor> sphere;
  sphere->SetMapper(mapper);
  sphere->GetProperty()->SetColor(0.9, 0.6, 0.3);

  bool first = true;
  auto measure = [&](const Case& row, vtkRiemannScene* scene, int integrator)
  {
    pass->SetScene(scene);
    scene->ApplyCamera(renderer->GetActiveCamera());
    settings->SetIntegratorType(integrator);
    settings->SetMaximumNumberOfSteps(row.Steps);
    if (first)
    {
      window->Render();
      std::printf("vtkRiemannRayTracePass, fragment vs compute path, %dx%d, median of %d frames "
                  "(GL renderer: %s; compute workgroup %d x %d)\n\n",
        options.Width, options.Height, options.Repetitions, RendererName(window).c_str(),
        pass->GetComputeWorkgroupSize()[0], pass->GetComputeWorkgroupSize()[1]);
      std::printf("| case | integrator | steps | fragment (s) | compute (s) | compute / fragment | "
                  "fragment frames/s | compute frames/s | fragment ns per ray step | compute ns "
                  "per ray step |\n|---|---|---|---|---|---|---|---|---|---|\n");
      first = false;
    }
    const PathFrame fragment =
      MeasurePath(window, pass, vtkRiemannRayTracePass::FRAGMENT, options.Repetitions);
    const PathFrame compute =
      MeasurePath(window, pass, vtkRiemannRayTracePass::COMPUTE, options.Repetitions);
    PrintRow(row, fragment, compute);
  };
  const int rk4 = vtkRiemannIntegrationSettings::RUNGE_KUTTA4;
  const int euler = vtkRiemannIntegrationSettings::EULER;

  // The empty scene and the one-bump grid.
  metric->SetDefinition(bump.c_str());
  measure({ "empty, one bump", "rk4", 1000 }, empty, rk4);
  for (int integrator : { rk4, euler })
  {
    for (int steps : { 100, 300, 1000 })
    {
      measure({ "one-bump grid", integrator == rk4 ? "rk4" : "euler", steps }, grid, integrator);
    }
  }

  // The showcase lens in its scene: analytic, then sampled on 48^3 and
  // read at the voxels ("christoffel": "voxels", the default), early: these
  // are the figures the sampled metrics' issue asks for.
  const auto sampledLens = [&](const char* reading)
  {
    if (metric->SetTensorData(
          SampledLensImage(48, -4.0, 4.0), "Tensors", false, 1.0, false, "euclidean", reading))
    {
      measure({ std::string("showcase lens sampled on 48^3, \"") + reading + "\"", "rk4", 1000 },
        lens, rk4);
    }
    else
    {
      std::fprintf(stderr, "sampled lens: %s\n", metric->GetLastError());
    }
  };
  if (metric->SetDefinition(lens->GetMetricDefinition().c_str()))
  {
    measure({ "showcase lens, analytic (conformal)", "rk4", 1000 }, lens, rk4);
  }
  sampledLens("voxels");

  // The metric families, every ray all its steps.
  metric->SetDefinition(bump.c_str());
  measure({ "empty, built-in Gaussian (graph)", "rk4", 300 }, empty, rk4);
  if (metric->SetDefinitionFile((data + "/metrics/gaussian-bump-typed.json").c_str()))
  {
    measure({ "empty, typed expression (graph)", "rk4", 300 }, empty, rk4);
  }
  else
  {
    std::fprintf(stderr, "typed bump: %s\n", metric->GetLastError());
  }
  metric->SetDefinition(TwistJson);
  measure({ "empty, diffeomorphism (twist)", "rk4", 300 }, empty, rk4);

  // The compute path's workgroup (the tile of pixels it traces together).
  metric->SetDefinition(bump.c_str());
  pass->SetScene(grid);
  grid->ApplyCamera(renderer->GetActiveCamera());
  settings->SetIntegratorType(rk4);
  settings->SetMaximumNumberOfSteps(300);
  std::printf("\nCompute workgroups, one-bump grid, rk4, 300 steps\n\n"
              "| workgroup | compute (s) | ratio to 8 x 8 |\n|---|---|---|\n");
  double reference = 0.0;
  for (const auto& size : { std::pair<int, int>{ 8, 8 }, { 4, 4 }, { 8, 4 }, { 16, 8 },
         { 16, 16 }, { 32, 8 }, { 32, 32 } })
  {
    pass->SetComputeWorkgroupSize(size.first, size.second);
    const PathFrame frame =
      MeasurePath(window, pass, vtkRiemannRayTracePass::COMPUTE, options.Repetitions);
    reference = reference > 0.0 ? reference : frame.Seconds;
    std::printf("| %d x %d | %.4f | %.3f |\n", size.first, size.second, frame.Seconds,
      frame.Seconds / reference);
    std::fflush(stdout);
  }
  pass->SetComputeWorkgroupSize(8, 8);

  // The 1 M-triangle mesh, the renderer's actor.
  metric->SetDefinition(twoBumps->GetMetricDefinition().c_str());
  renderer->AddActor(sphere);
  pass->UseRendererPropsOn();
  measure({ "1 M-triangle sphere, two bumps", "rk4", 1000 }, empty, rk4);
  renderer->RemoveActor(sphere);
  pass->UseRendererPropsOff();

  // The exact spline ("christoffel": "spline") last: at 1080p on an H200
  // its frames took 20 s.
  sampledLens("spline");

  return 0;
}
