#include "IntegrationOptions.h"

#include "vtkRiemannIntegrationSettingsSettingAccess.h"

namespace riemann
{
namespace cli
{
std::unique_ptr<DeclaredOptions> AddIntegrationOptions(CLI::App* command,
  vtkRiemannIntegrationSettings* defaults, const std::string& leftOut,
  const std::string& defaultWords)
{
  return std::make_unique<DeclaredOptions>(command,
    riemann::declared::vtkRiemannIntegrationSettings::Settings, leftOut,
    riemann::settings::SettingValues(defaults), defaultWords);
}

void ApplyIntegrationOptions(const DeclaredOptions& options, vtkRiemannIntegrationSettings* settings)
{
  riemann::settings::ApplySettings(settings, options.Given());
}

} // namespace cli
} // namespace riemann
