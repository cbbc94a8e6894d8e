#include "vtkRiemannObserverSettings.h"

#include "RiemannIntegrationSettingsDeclaration.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkRiemannIntegrationSettings.h"

#include <algorithm>
#include <climits>
#include <cmath>

void vtkRiemannSetRayDefaults(vtkRiemannIntegrationSettings* settings)
{
  // The declared "Rays" preset (vtkRiemannIntegrationSettings.settings.json).
  namespace rays = riemann::declared::vtkRiemannIntegrationSettings::Rays;
  settings->SetIntegratorType(rays::IntegratorType);
  settings->SetInitialIntegrationStep(rays::InitialIntegrationStep);
  settings->SetMaximumNumberOfSteps(static_cast<vtkIdType>(rays::MaximumNumberOfSteps));
  settings->SetMaximumPropagation(rays::MaximumPropagation);
  settings->SetMaximumError(rays::MaximumError);
}

riemann::RaySettings vtkRiemannResolveRaySettings(
  bool useSceneSettings, const riemann::Scene& scene, vtkRiemannIntegrationSettings* settings)
{
  if (useSceneSettings || !settings)
  {
    return scene.Rays;
  }
  riemann::RaySettings rays;
  rays.Integrator = static_cast<riemann::IntegratorType>(settings->GetIntegratorType());
  rays.Step = settings->GetInitialIntegrationStep();
  // The GPU counts steps in an int.
  rays.MaximumSteps = static_cast<int>(
    std::min<vtkIdType>(settings->GetMaximumNumberOfSteps(), static_cast<vtkIdType>(INT_MAX)));
  rays.MaximumLength = settings->GetMaximumPropagation();
  rays.Tolerance = settings->GetMaximumError();
  return rays;
}

riemann::Projection vtkRiemannResolveProjection(
  bool useSceneSettings, const riemann::Scene& scene, int projection)
{
  if (useSceneSettings && scene.HasCamera)
  {
    return scene.Camera.Mode;
  }
  return projection == static_cast<int>(riemann::Projection::Equirectangular)
    ? riemann::Projection::Equirectangular
    : riemann::Projection::Perspective;
}

riemann::CameraSettings vtkRiemannCameraSettings(
  vtkCamera* camera, double aspect, const riemann::CameraSettings& fallback, riemann::Projection mode)
{
  riemann::CameraSettings settings = fallback;
  settings.Mode = mode;
  if (!camera)
  {
    return settings;
  }
  settings.Position = riemann::Vec3(camera->GetPosition());
  settings.LookAt = riemann::Vec3(camera->GetFocalPoint());
  settings.ViewUp = riemann::Vec3(camera->GetViewUp());
  double angle = camera->GetViewAngle();
  if (camera->GetUseHorizontalViewAngle())
  {
    // The observer's angle is the vertical one: convert for this aspect.
    angle = vtkMath::DegreesFromRadians(
      2.0 * std::atan(std::tan(0.5 * vtkMath::RadiansFromDegrees(angle)) / aspect));
  }
  settings.ViewAngle = angle;
  return settings;
}
