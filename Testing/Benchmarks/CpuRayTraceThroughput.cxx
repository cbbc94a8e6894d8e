// Throughput of vtkRiemannCPURayTracer (Embree, all cores) and its ratio to
// the GPU pass (vtkRiemannRayTracePass), in one run:
// - the paper's grid in the one-bump metric (Data/scenes/paper-one-bump.json,
//   RK4, step 0.02): CPU and GPU render the same picture with the same rays,
//   so the CPU's count of integration steps is the GPU's too, and
//   rays x steps / s = steps / seconds on both;
// - a 1-million-triangle mesh (a UV sphere of 1000 x 500 quads, radius 1.5)
//   in the same metric and camera, on the CPU with Embree ray streams and with
//   one query per segment (the GPU pass on meshes: RiemannMeshFrameBenchmark).
//
// Not a test: timings depend on the machine. Run under an X server, e.g.
//   xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" build/bin/RiemannCpuRayTraceBenchmark
// Options: --width W --height H --data DIR. On this project's machines the
// GPU is Mesa llvmpipe (OpenGL on the same CPU cores).
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRiemannCPURayTracer.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayTracePass.h"
#include "vtkRiemannScene.h"
#include "vtkSMPTools.h"

#include "RenderBenchmarkOptions.h"
#include "UVSphereMesh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

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
  vtkNew<vtkRiemannScene> scene;
  if (!scene->SetDefinitionFile((data + "/scenes/paper-one-bump.json").c_str()))
  {
    std::fprintf(stderr, "%s\n", scene->GetLastError());
    return 1;
  }
  vtkNew<vtkRiemannMetric> metric;
  metric->SetDefinition(scene->GetMetricDefinition().c_str());
  vtkNew<vtkCamera> camera;
  scene->ApplyCamera(camera);

  // ---- CPU: the grid ----
  vtkNew<vtkRiemannCPURayTracer> tracer;
  tracer->SetMetric(metric);
  tracer->SetScene(scene);
  tracer->SetCamera(camera);
  tracer->SetWidth(width);
  tracer->SetHeight(height);
  tracer->Update();
  const double gridSteps = static_cast<double>(tracer->GetNumberOfIntegrationSteps());
  const double cpuGrid = tracer->GetTraceTime();

  // ---- GPU pass: the same grid, the same rays ----
  vtkNew<vtkRiemannRayTracePass> pass;
  pass->SetMetric(metric);
  pass->SetScene(scene);
  vtkNew<vtkRenderer> renderer;
  renderer->SetPass(pass);
  renderer->GetActiveCamera()->DeepCopy(camera);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(64, 36);
  window->Render(); // compile the shader outside the timing, on a small image
  window->SetSize(width, height);
  const auto start = std::chrono::steady_clock::now();
  window->Render();
  window->WaitForCompletion();
  const double gpuGrid =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // ---- CPU: the 1-million-triangle mesh, streams and single queries ----
  vtkNew<vtkRiemannScene> meshScene;
  meshScene->SetDefinition(R"({"objects": [],
    "integrator": {"method": "rk4", "step": 0.02, "max_steps": 1500, "max_length": 30}})");
  vtkNew<vtkRiemannCPURayTracer> meshTracer;
  meshTracer->SetMetric(metric);
  meshTracer->SetScene(meshScene);
  meshTracer->SetCamera(camera);
  meshTracer->SetWidth(width);
  meshTracer->SetHeight(height);
  meshTracer->AddMesh(UVSphereMesh(1.5, 1000, 500));
  double meshTime[2] = { 0, 0 };
  double meshSteps = 0;
  for (int streams = 1; streams >= 0; --streams)
  {
    meshTracer->SetUseRayStreams(streams == 1);
    meshTracer->Update();
    meshTime[streams] = meshTracer->GetTraceTime();
    meshSteps = static_cast<double>(meshTracer->GetNumberOfIntegrationSteps());
  }

  std::printf("CPU ray tracer vs GPU pass, %dx%d, one ray per pixel, %d CPU threads (%s); "
              "GL renderer: %s\n\n",
    width, height, vtkSMPTools::GetEstimatedNumberOfThreads(), vtkSMPTools::GetBackend(),
    RendererName(window).c_str());
  std::printf("| scene | backend | triangles | steps | seconds | rays x steps / s |\n"
              "|---|---|---|---|---|---|\n");
  std::printf("| paper-one-bump grid | CPU (Embree tracer) | 0 | %.4g | %.2f | %.3g |\n", gridSteps,
    cpuGrid, gridSteps / cpuGrid);
  std::printf("| paper-one-bump grid | GPU pass (%s) | 0 | %.4g | %.2f | %.3g |\n",
    RendererName(window).c_str(), gridSteps, gpuGrid, gridSteps / gpuGrid);
  std::printf("| sphere mesh in the bump | CPU, Embree ray streams | %lld | %.4g | %.2f | %.3g |\n",
    static_cast<long long>(meshTracer->GetNumberOfTriangles()), meshSteps, meshTime[1],
    meshSteps / meshTime[1]);
  std::printf("| sphere mesh in the bump | CPU, one Embree query per segment | %lld | %.4g | %.2f | "
              "%.3g |\n",
    static_cast<long long>(meshTracer->GetNumberOfTriangles()), meshSteps, meshTime[0],
    meshSteps / meshTime[0]);
  std::printf("\nCPU / GPU throughput ratio on the grid: %.2f\n", gpuGrid / cpuGrid);
  return 0;
}
