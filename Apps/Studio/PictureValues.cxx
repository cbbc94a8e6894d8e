#include "PictureValues.h"

#include "PictureSchema.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkNew.h"

#include <cmath>

namespace riemann
{
namespace studio
{
namespace
{
bool IsCameraSetting(const PictureSetting& setting)
{
  return *setting.Core && setting.Type != PictureSetting::Choice;
}

PropertySpec SpecOf(const PictureSetting& setting)
{
  PropertySpec spec;
  spec.Key = setting.Property;
  spec.Label = setting.Label;
  spec.Help =
    QString::fromStdString(std::string(setting.Help) + ": " + DescribePictureValues(setting));
  switch (setting.Type)
  {
    case PictureSetting::Point:
      spec.Type = PropertySpec::Vector3;
      break;
    case PictureSetting::Direction:
      spec.Type = PropertySpec::Vector3;
      spec.NonZero = true;
      break;
    case PictureSetting::Choice:
      spec.Type = PropertySpec::Choice;
      for (const std::string& name : PictureChoices(setting))
      {
        spec.Choices << QString::fromStdString(name);
      }
      break;
    default:
      spec.Type = setting.Type == PictureSetting::Count ? PropertySpec::Integer : PropertySpec::Number;
      spec.Minimum = setting.Range.Minimum;
      spec.MinimumExclusive = setting.Range.MinimumExclusive;
      spec.Maximum = setting.Range.Maximum;
      spec.MaximumExclusive = setting.Range.MaximumExclusive;
      break;
  }
  return spec;
}
} // namespace

std::vector<PropertySpec> PicturePropertySpecs()
{
  std::vector<PropertySpec> specs;
  for (const PictureSetting& setting : PictureSchema)
  {
    if (*setting.Label)
    {
      specs.push_back(SpecOf(setting));
    }
  }
  return specs;
}

nlohmann::json CameraValues(vtkCamera* camera)
{
  const auto vector = [](const double* v) { return std::vector<double>{ v[0], v[1], v[2] }; };
  using Id = PictureSettingId;
  return { { PictureSettingOf(Id::Position).Property, vector(camera->GetPosition()) },
    { PictureSettingOf(Id::LookAt).Property, vector(camera->GetFocalPoint()) },
    { PictureSettingOf(Id::ViewUp).Property, vector(camera->GetViewUp()) },
    { PictureSettingOf(Id::ViewAngle).Property, camera->GetViewAngle() } };
}

bool IsCameraValue(const std::string& key)
{
  for (const PictureSetting& setting : PictureSchema)
  {
    if (IsCameraSetting(setting) && key == setting.Property)
    {
      return true;
    }
  }
  return false;
}

std::string CheckCameraView(
  const double position[3], const double focalPoint[3], const double viewUp[3])
{
  double forward[3];
  vtkMath::Subtract(focalPoint, position, forward);
  const double length = vtkMath::Norm(forward);
  if (!(length > 0) || !std::isfinite(length))
  {
    return "the camera is at the point it looks at";
  }
  double cross[3];
  vtkMath::Cross(forward, viewUp, cross);
  if (!(vtkMath::Norm(cross) > 1e-9 * length * vtkMath::Norm(viewUp)))
  {
    return "the view up is along the view direction";
  }
  return std::string();
}

std::string ApplyCameraValues(const nlohmann::json& values, vtkCamera* camera)
{
  // Tried on a copy first: a camera that defines no view is never applied.
  using Id = PictureSettingId;
  vtkNew<vtkCamera> trial;
  trial->DeepCopy(camera);
  const auto vector = [&values](Id id, double out[3])
  {
    const char* key = PictureSettingOf(id).Property;
    if (!values.contains(key))
    {
      return false;
    }
    for (int i = 0; i < 3; ++i)
    {
      out[i] = values.at(key).at(i).get<double>();
    }
    return true;
  };
  double v[3];
  if (vector(Id::Position, v))
  {
    trial->SetPosition(v);
  }
  if (vector(Id::LookAt, v))
  {
    trial->SetFocalPoint(v);
  }
  if (vector(Id::ViewUp, v))
  {
    trial->SetViewUp(v);
  }
  const char* angle = PictureSettingOf(Id::ViewAngle).Property;
  if (values.contains(angle))
  {
    trial->SetViewAngle(values.at(angle).get<double>());
  }
  // The view up as given (vtkCamera orthogonalises the one it keeps).
  double up[3];
  if (!vector(Id::ViewUp, up))
  {
    camera->GetViewUp(up);
  }
  const std::string why = CheckCameraView(trial->GetPosition(), trial->GetFocalPoint(), up);
  if (why.empty())
  {
    camera->DeepCopy(trial);
  }
  return why;
}
} // namespace studio
} // namespace riemann
