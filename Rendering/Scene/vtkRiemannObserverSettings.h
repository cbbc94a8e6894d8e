/**
 * @file vtkRiemannObserverSettings.h
 * @brief What every renderer of the inside view (vtkRiemannRayTracePass,
 * vtkRiemannCPURayTracer, vtkRiemannRayBundle) decides the same way, written
 * once: which integration settings and projection apply (the scene's or the
 * renderer's own), and the observer taken from a vtkCamera.
 *
 * Not wrapped for Python (core types in the signatures).
 */
#ifndef vtkRiemannObserverSettings_h
#define vtkRiemannObserverSettings_h

#include "RiemannRenderingSceneModule.h" // For export macro
#include "RiemannScene.h"                     // For RaySettings, CameraSettings

class vtkCamera;
class vtkRiemannIntegrationSettings;

/**
 * Give `settings` the renderers' defaults, those of riemann::RaySettings
 * (RUNGE_KUTTA4, step 0.02, MaximumPropagation 30, 1000 steps, MaximumError
 * 1e-4), so that the pass, the CPU tracer and the ray bundle agree.
 */
RIEMANNRENDERINGSCENE_EXPORT void vtkRiemannSetRayDefaults(
  vtkRiemannIntegrationSettings* settings);

/**
 * The integration of the rays: the scene's "integrator" block when
 * `useSceneSettings`, else `settings` (InitialIntegrationStep,
 * MaximumNumberOfSteps, MaximumPropagation, MaximumError and the integrator).
 */
RIEMANNRENDERINGSCENE_EXPORT riemann::RaySettings vtkRiemannResolveRaySettings(
  bool useSceneSettings, const riemann::Scene& scene, vtkRiemannIntegrationSettings* settings);

/// The scene camera's projection when `useSceneSettings` and it has a camera, else `projection`.
RIEMANNRENDERINGSCENE_EXPORT riemann::Projection vtkRiemannResolveProjection(
  bool useSceneSettings, const riemann::Scene& scene, int projection);

/**
 * The observer of `camera` (position, focal point, view up, and its view
 * angle as the vertical one of an image of aspect `width / height`: a
 * horizontal view angle is converted), with projection `mode`. Without a
 * camera, `fallback` with that projection.
 */
RIEMANNRENDERINGSCENE_EXPORT riemann::CameraSettings vtkRiemannCameraSettings(
  vtkCamera* camera, double aspect, const riemann::CameraSettings& fallback, riemann::Projection mode);

#endif
