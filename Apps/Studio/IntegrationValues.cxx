#include "IntegrationValues.h"

#include "SettingValues.h"
#include "vtkRiemannIntegrationSettingsSettingAccess.h"

namespace riemann
{
namespace studio
{
namespace
{
const riemann::SettingTable& Declared()
{
  return riemann::declared::vtkRiemannIntegrationSettings::Settings;
}
} // namespace

nlohmann::json IntegrationValues(vtkRiemannIntegrationSettings* settings)
{
  return riemann::settings::SettingValues(settings);
}

std::string CheckIntegrationValue(const std::string& key, const nlohmann::json& value)
{
  const riemann::SettingDeclaration* setting = Declared().Find(key);
  if (!setting)
  {
    return "unknown setting";
  }
  return riemann::CheckSettingValue(*setting, value, key).empty()
    ? std::string()
    : "expected " + riemann::DescribeSettingRange(*setting) + ", got " + value.dump();
}

void ApplyIntegrationValues(const nlohmann::json& values, vtkRiemannIntegrationSettings* settings)
{
  nlohmann::json declared = nlohmann::json::object();
  for (const riemann::SettingDeclaration& setting : Declared())
  {
    if (values.contains(setting.Name))
    {
      declared[setting.Name] = values.at(setting.Name);
    }
  }
  riemann::settings::ApplySettings(settings, declared);
}

std::vector<std::string> IntegrationPython(
  const std::string& target, vtkRiemannIntegrationSettings* settings)
{
  return riemann::SettingPythonLines(Declared(), target, IntegrationValues(settings));
}
} // namespace studio
} // namespace riemann
