// Frame time of the GPU pass drawing a 1-million-triangle mesh, in one run
// against the grid scene on the GPU and against the CPU tracer:
// - the metric and camera of the paper's two bumps
//   (Data/scenes/paper-two-bumps.json, RK4, step 0.02);
// - "grid": that scene's grid of bars (analytic, uniforms);
// - "mesh": a UV sphere of 1000 x 500 quads (1,000,000 triangles, radius
//   1.2, behind the bumps) added to the renderer as a vtkActor and drawn with
//   UseRendererProps (its hierarchy built by Embree and uploaded once: the
//   first frame, on a small window, pays for it and for the shader);
// - the CPU tracer on the same mesh (AddActor, Embree ray streams, all cores).
// The GPU and CPU pictures of the mesh are compared pixel by pixel.
//
// Not a test: timings depend on the machine. Run under an X server, e.g.
//   xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" build/bin/RiemannMeshFrameBenchmark
// Options: --width W --height H --data DIR. On this project's machines the
// GPU is Mesa llvmpipe (OpenGL on the same CPU cores); with a GPU's GLX
// driver the same command measures the GPU.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRiemannCPURayTracer.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayTracePass.h"
#include "vtkRiemannScene.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include "ImageComparison.h"
#include "RenderBenchmarkOptions.h"
#include "UVSphereMesh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
double Seconds(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The GPU pass's frame time for `scene` (and the renderer's actors) at the
/// full size, after a first frame on a small window (shader, hierarchy).
struct GpuFrame
{
  double FirstFrame = 0.0;
  double Frame = 0.0;
  std::vector<unsigned char> Pixels;
};

GpuFrame RenderOnGpu(vtkRiemannMetric* metric, vtkRiemannScene* scene, vtkCamera* camera,
  vtkActor* actor, int width, int height, std::string& rendererName)
{
  vtkNew<vtkRiemannRayTracePass> pass;
  pass->SetMetric(metric);
  pass->SetScene(scene);
  pass->SetUseRendererProps(actor != nullptr);
  vtkNew<vtkRenderer> renderer;
  renderer->SetPass(pass);
  if (actor)
  {
    renderer->AddActor(actor);
  }
  renderer->GetActiveCamera()->DeepCopy(camera);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  window->SetSize(64, 36);
  GpuFrame result;
  auto start = std::chrono::steady_clock::now();
  window->Render();
  window->WaitForCompletion();
  result.FirstFrame = Seconds(start);
  window->SetSize(width, height);
  start = std::chrono::steady_clock::now();
  window->Render();
  window->WaitForCompletion();
  result.Frame = Seconds(start);
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, width - 1, height - 1, 0, pixels);
  result.Pixels.assign(pixels->GetPointer(0), pixels->GetPointer(0) + 3 * width * height);
  rendererName = RendererName(window);
  return result;
}

} // namespace

int main(int argc, char** argv)
{
  RenderBenchmarkOptions options;
  if (!ParseRenderBenchmarkOptions(argc, argv, options))
  {
    return 2;
  }
  const int width = options.Width;
  const int height = options.Height;
  const std::string& data = options.Data;
  vtkNew<vtkRiemannScene> grid;
  if (!grid->SetDefinitionFile((data + "/scenes/paper-two-bumps.json").c_str()))
  {
    std::fprintf(stderr, "%s\n", grid->GetLastError());
    return 1;
  }
  vtkNew<vtkRiemannMetric> metric;
  metric->SetDefinition(grid->GetMetricDefinition().c_str());
  vtkNew<vtkCamera> camera;
  grid->ApplyCamera(camera);
  vtkNew<vtkRiemannScene> empty; // the mesh alone, same rays and background
  empty->SetDefinition(R"({"objects": [], "background": [0.05, 0.05, 0.08],
    "integrator": {"method": "rk4", "step": 0.02, "max_steps": 1000, "max_length": 20},
    "lighting": "observer"})");

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(UVSphereMesh(1.2, 1000, 500, 0.0, 0.0, -2.5));
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.6, 0.3);

  std::string rendererName;
  const GpuFrame gpuGrid = RenderOnGpu(metric, grid, camera, nullptr, width, height, rendererName);
  const GpuFrame gpuMesh = RenderOnGpu(metric, empty, camera, actor, width, height, rendererName);

  vtkNew<vtkRiemannCPURayTracer> tracer;
  tracer->SetMetric(metric);
  tracer->SetScene(empty);
  tracer->SetCamera(camera);
  tracer->SetWidth(width);
  tracer->SetHeight(height);
  tracer->AddActor(actor);
  const auto start = std::chrono::steady_clock::now();
  tracer->Update();
  const double cpuMeshTotal = Seconds(start);
  const double cpuMesh = tracer->GetTraceTime();
  const riemann::testing::DifferenceStatistics difference =
    riemann::testing::Compare(gpuMesh.Pixels, riemann::testing::CpuPixels(tracer->GetOutput()), 24);

  std::printf("GPU pass on a 1,000,000-triangle mesh, %dx%d, two-bump metric, one ray per "
              "pixel; GL renderer: %s; CPU: %d threads (%s)\n\n",
    width, height, rendererName.c_str(), vtkSMPTools::GetEstimatedNumberOfThreads(),
    vtkSMPTools::GetBackend());
  std::printf("| scene | backend | first frame, 64x36 (s) | frame (s) |\n|---|---|---|---|\n");
  std::printf(
    "| paper-two-bumps grid | GPU pass | %.2f | %.2f |\n", gpuGrid.FirstFrame, gpuGrid.Frame);
  std::printf(
    "| 1 M-triangle sphere | GPU pass | %.2f | %.2f |\n", gpuMesh.FirstFrame, gpuMesh.Frame);
  std::printf("| 1 M-triangle sphere | CPU tracer (Embree streams) | - | %.2f (%.2f with the "
              "mesh's conversion and Embree's build) |\n",
    cpuMesh, cpuMeshTotal);
  std::printf("\nmesh / grid frame time on the GPU: %.2f\n", gpuMesh.Frame / gpuGrid.Frame);
  std::printf("GPU / CPU throughput on the mesh: %.2f\n", cpuMesh / gpuMesh.Frame);
  std::printf("GPU vs CPU pictures of the mesh: mean difference %.4f of 255, %.4f%% of the "
              "pixels above 24\n",
    difference.Mean, 100.0 * difference.FractionAbove);
  return 0;
}
