#include "IntegrationValues.h"

#include "PipelineItem.h" // For PythonNumber

#include "IntegrationSchema.h"
#include "RungeKutta.h"

#include "vtkNew.h"
#include "vtkRiemannIntegrationSettings.h"

namespace riemann
{
namespace studio
{
namespace
{
/// The settings the app shows (a label in the schema), with their ids.
template <class Visit>
void ForEachShownSetting(Visit visit)
{
  for (std::size_t i = 0; i < IntegrationSchema.size(); ++i)
  {
    if (*IntegrationSchema[i].Label)
    {
      visit(static_cast<IntegrationSettingId>(i), IntegrationSchema[i]);
    }
  }
}
} // namespace

nlohmann::json IntegrationValues(vtkRiemannIntegrationSettings* settings)
{
  nlohmann::json values = nlohmann::json::object();
  ForEachShownSetting(
    [&](IntegrationSettingId id, const IntegrationSetting& setting)
    {
      if (setting.Type == IntegrationSetting::Choice)
      {
        values[setting.Property] = settings->GetIntegratorTypeAsString();
      }
      else if (setting.Type == IntegrationSetting::Count)
      {
        values[setting.Property] = static_cast<long long>(settings->GetValue(id));
      }
      else
      {
        values[setting.Property] = settings->GetValue(id);
      }
    });
  return values;
}

std::string CheckIntegrationValue(const std::string& key, const nlohmann::json& value)
{
  std::string problem = "unknown setting";
  ForEachShownSetting(
    [&](IntegrationSettingId, const IntegrationSetting& setting)
    {
      if (key != setting.Property)
      {
        return;
      }
      if (setting.Type == IntegrationSetting::Choice)
      {
        IntegratorType type;
        problem = value.is_string() && ParseIntegratorName(value.get<std::string>(), type)
          ? std::string()
          : "expected \"euler\", \"rk4\" or \"dp45\"";
        return;
      }
      const bool valid = value.is_number() &&
        riemann::CheckIntegrationValue(setting, value.get<double>(), key).empty();
      problem = valid ? std::string()
                      : "expected " + DescribeIntegrationRange(setting) + ", got " + value.dump();
    });
  return problem;
}

void ApplyIntegrationValues(const nlohmann::json& values, vtkRiemannIntegrationSettings* settings)
{
  ForEachShownSetting(
    [&](IntegrationSettingId id, const IntegrationSetting& setting)
    {
      if (!values.contains(setting.Property))
      {
        return;
      }
      const nlohmann::json& value = values.at(setting.Property);
      if (setting.Type == IntegrationSetting::Choice)
      {
        settings->SetIntegratorTypeFromName(value.get<std::string>().c_str());
      }
      else
      {
        settings->SetValue(id, value.get<double>());
      }
    });
}

std::vector<std::string> IntegrationPython(
  const std::string& target, vtkRiemannIntegrationSettings* settings)
{
  std::vector<std::string> lines;
  ForEachShownSetting(
    [&](IntegrationSettingId id, const IntegrationSetting& setting)
    {
      if (setting.Type == IntegrationSetting::Choice)
      {
        lines.push_back(target + ".SetIntegratorTypeFromName(\"" +
          settings->GetIntegratorTypeAsString() + "\")");
      }
      else if (setting.Type == IntegrationSetting::Count)
      {
        lines.push_back(target + ".Set" + setting.Property + "(" +
          std::to_string(static_cast<long long>(settings->GetValue(id))) + ")");
      }
      else
      {
        lines.push_back(
          target + ".Set" + setting.Property + "(" + PythonNumber(settings->GetValue(id)) + ")");
      }
    });
  return lines;
}
} // namespace studio
} // namespace riemann
