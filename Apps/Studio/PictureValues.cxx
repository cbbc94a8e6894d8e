#include "PictureValues.h"

#include "DeclaredProperties.h"
#include "RiemannPictureSettingsDeclaration.h"
#include "SettingValues.h"

#include "vtkRiemannPictureSettings.h"
#include "vtkRiemannPictureSettingsSettingAccess.h"

#include "vtkCamera.h"
#include "vtkNew.h"

#include <sstream>

namespace riemann
{
namespace studio
{
namespace
{
const riemann::SettingTable& PictureTable()
{
  return riemann::declared::vtkRiemannPictureSettings::Settings;
}

/// The camera settings of `values` (the others dropped).
nlohmann::json CameraPart(const nlohmann::json& values)
{
  nlohmann::json camera = nlohmann::json::object();
  for (const auto& entry : values.items())
  {
    if (vtkRiemannPictureSettings::IsCameraSetting(entry.key()))
    {
      camera[entry.key()] = entry.value();
    }
  }
  return camera;
}

/// The key `object` gives `setting` under: its name, else a project alias ("" when none).
std::string KeyOf(const nlohmann::json& object, const riemann::SettingDeclaration& setting)
{
  if (object.contains(setting.Name))
  {
    return setting.Name;
  }
  std::stringstream aliases(setting.ProjectAliases);
  for (std::string alias; std::getline(aliases, alias, ',');)
  {
    if (object.contains(alias))
    {
      return alias;
    }
  }
  return std::string();
}
} // namespace

std::vector<PropertySpec> PicturePropertySpecs()
{
  // The projection, size and shader path are the window's, not the form's.
  return DeclaredPropertySpecs(PictureTable(), { "Projection", "Width", "Height", "GPUPath" });
}

nlohmann::json CameraValues(vtkCamera* camera)
{
  vtkNew<vtkRiemannPictureSettings> picture;
  picture->SetFromCamera(camera);
  return CameraPart(riemann::settings::SettingValues(picture));
}

std::string CheckCameraValues(const nlohmann::json& values)
{
  vtkNew<vtkRiemannPictureSettings> picture;
  riemann::settings::ApplySettings(picture, CameraPart(values));
  return picture->CheckSettings();
}

std::string ApplyCameraValues(const nlohmann::json& values, vtkCamera* camera)
{
  // Tried on the settings first: a camera that defines no view is never
  // applied. The view up is checked as given (vtkCamera orthogonalises the
  // one it keeps).
  vtkNew<vtkRiemannPictureSettings> picture;
  picture->SetFromCamera(camera);
  riemann::settings::ApplySettings(picture, CameraPart(values));
  const std::string why = picture->CheckSettings();
  if (why.empty())
  {
    picture->ApplyTo(camera);
  }
  return why;
}

nlohmann::json ReadPictureValues(const nlohmann::json& object,
  const std::vector<std::string>& names, const std::string& where, std::string& error)
{
  error.clear();
  if (!object.is_object())
  {
    error = where + ": expected an object";
    return nullptr;
  }
  nlohmann::json values = nlohmann::json::object();
  for (const std::string& name : names)
  {
    const riemann::SettingDeclaration& setting = *PictureTable().Find(name);
    const std::string key = KeyOf(object, setting);
    const nlohmann::json value = key.empty() ? riemann::DefaultValue(setting) : object.at(key);
    error = riemann::CheckSettingValue(setting, value, where + "." + (key.empty() ? name : key));
    if (!error.empty())
    {
      return nullptr;
    }
    values[name] = value;
  }
  return values;
}
} // namespace studio
} // namespace riemann
