#include "DeclaredJob.h"

#include "SettingValues.h"

#include "vtkRiemannIntegrationSettings.h"

namespace riemann
{
namespace studio
{
std::vector<std::string> DeclaredPythonLines(const std::string& className,
  const riemann::SettingTable& table, const std::string& var, const nlohmann::json& values,
  bool integrates)
{
  std::vector<std::string> lines{
    var + " = riemann." + className + "()",
    var + ".SetMetric(metric)",
  };
  for (const std::string& line : riemann::SettingPythonLines(table, var, values))
  {
    lines.push_back(line);
  }
  if (integrates)
  {
    vtkNew<vtkRiemannIntegrationSettings> integration;
    ApplyIntegrationValues(values, integration);
    for (const std::string& line : IntegrationPython(var + ".GetIntegrationSettings()", integration))
    {
      lines.push_back(line);
    }
  }
  return lines;
}
} // namespace studio
} // namespace riemann
