#include "vtkRiemannPictureSettings.h"

#include "ObserverCamera.h"
#include "vtkRiemannPictureSettingsSettingAccess.h"

#include "vtkCamera.h"
#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(vtkRiemannPictureSettings);

namespace
{
namespace PictureDefault = riemann::declared::vtkRiemannPictureSettings::Default;
}

vtkRiemannPictureSettings::vtkRiemannPictureSettings()
  : ViewAngle(PictureDefault::ViewAngle)
  , Projection(PictureDefault::Projection)
  , Width(static_cast<int>(PictureDefault::Width))
  , Height(static_cast<int>(PictureDefault::Height))
  , SamplesPerPixel(static_cast<int>(PictureDefault::SamplesPerPixel))
  , Backend(PictureDefault::Backend)
  , GPUPath(PictureDefault::GPUPath)
{
  std::copy(PictureDefault::Position, PictureDefault::Position + 3, this->Position);
  std::copy(PictureDefault::LookAt, PictureDefault::LookAt + 3, this->LookAt);
  std::copy(PictureDefault::ViewUp, PictureDefault::ViewUp + 3, this->ViewUp);
}

std::string vtkRiemannPictureSettings::CheckSettings() const
{
  // Each property in its declared range, in the declaration's order, named as the property.
  std::string error = riemann::CheckSettingValues(riemann::declared::vtkRiemannPictureSettings::Settings,
    riemann::settings::SettingValues(const_cast<vtkRiemannPictureSettings*>(this)));
  if (!error.empty())
  {
    return error;
  }
  const riemann::CameraSettings camera = this->GetCameraSettings();
  return riemann::CheckCameraView(camera.Position, camera.LookAt, camera.ViewUp);
}

void vtkRiemannPictureSettings::ApplyTo(vtkCamera* camera) const
{
  if (!camera)
  {
    return;
  }
  camera->SetPosition(this->Position);
  camera->SetFocalPoint(this->LookAt);
  camera->SetViewUp(this->ViewUp);
  camera->SetViewAngle(this->ViewAngle);
}

void vtkRiemannPictureSettings::SetFromCamera(vtkCamera* camera)
{
  if (!camera)
  {
    return;
  }
  this->SetPosition(camera->GetPosition());
  this->SetLookAt(camera->GetFocalPoint());
  this->SetViewUp(camera->GetViewUp());
  this->SetViewAngle(camera->GetViewAngle());
}

bool vtkRiemannPictureSettings::IsCameraSetting(const std::string& name)
{
  return name == "Position" || name == "LookAt" || name == "ViewUp" || name == "ViewAngle";
}

riemann::CameraSettings vtkRiemannPictureSettings::GetCameraSettings() const
{
  riemann::CameraSettings camera;
  camera.Position = riemann::Vec3(this->Position[0], this->Position[1], this->Position[2]);
  camera.LookAt = riemann::Vec3(this->LookAt[0], this->LookAt[1], this->LookAt[2]);
  camera.ViewUp = riemann::Vec3(this->ViewUp[0], this->ViewUp[1], this->ViewUp[2]);
  camera.ViewAngle = this->ViewAngle;
  camera.Mode = static_cast<riemann::Projection>(this->Projection);
  return camera;
}

void vtkRiemannPictureSettings::DeepCopy(vtkRiemannPictureSettings* other)
{
  if (!other || other == this)
  {
    return;
  }
  riemann::settings::ApplySettings(this, riemann::settings::SettingValues(other));
}

void vtkRiemannPictureSettings::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Position: (" << this->Position[0] << ", " << this->Position[1] << ", "
     << this->Position[2] << ")\n";
  os << indent << "LookAt: (" << this->LookAt[0] << ", " << this->LookAt[1] << ", "
     << this->LookAt[2] << ")\n";
  os << indent << "ViewUp: (" << this->ViewUp[0] << ", " << this->ViewUp[1] << ", "
     << this->ViewUp[2] << ")\n";
  os << indent << "ViewAngle: " << this->ViewAngle << "\n";
  os << indent << "Projection: " << this->Projection << "\n";
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "SamplesPerPixel: " << this->SamplesPerPixel << "\n";
  os << indent << "Backend: " << this->Backend << "\n";
  os << indent << "GPUPath: " << this->GPUPath << "\n";
}
