/**
 * @file InsideViewRays.h
 * @brief One place that gives a CPU renderer of the inside view's rays
 * (vtkRiemannRayBundle, vtkRiemannCPURayTracer: the same property names)
 * what the inside view has, so a picked ray, a ray bundle and the CPU picture
 * are exactly the pass's rays: metric, scene, observer camera, image size,
 * ray settings and whether the scene's "integrator" block applies.
 */
#ifndef RiemannStudio_InsideViewRays_h
#define RiemannStudio_InsideViewRays_h

#include "PipelineItem.h"

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannScene.h"

namespace riemann
{
namespace studio
{
/**
 * With `privateCopies` the renderer gets its own metric, scene and camera
 * (vtkRiemannMetric/vtkRiemannScene::ShallowCopy share the parsed data), so
 * it may run on a worker thread while the document changes; without, the
 * document's own (a synchronous pick).
 */
template <class RayRenderer>
void SetUpInsideViewRays(
  RayRenderer* renderer, const JobInputs& inputs, int width, int height, bool privateCopies)
{
  if (privateCopies)
  {
    vtkNew<vtkRiemannMetric> metric;
    metric->ShallowCopy(inputs.Metric);
    vtkNew<vtkRiemannScene> scene;
    scene->ShallowCopy(inputs.Scene);
    vtkNew<vtkCamera> camera;
    camera->DeepCopy(inputs.Observer);
    renderer->SetMetric(metric);
    renderer->SetScene(scene);
    renderer->SetCamera(camera);
  }
  else
  {
    renderer->SetMetric(inputs.Metric);
    renderer->SetScene(inputs.Scene);
    renderer->SetCamera(inputs.Observer);
  }
  renderer->SetWidth(width);
  renderer->SetHeight(height);
  renderer->SetUseSceneSettings(inputs.UseSceneSettings);
  renderer->GetIntegrationSettings()->DeepCopy(inputs.RaySettings);
}
}
}

#endif
