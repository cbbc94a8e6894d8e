/**
 * @file IntegrationValues.h
 * @brief The integration settings as the app stores them (an item's
 * properties, a project's "inside.integration"), read, checked, applied and
 * exported to Python through their declaration
 * (vtkRiemannIntegrationSettings.settings.json) rather than property by
 * property.
 *
 * The keys are vtkRiemannIntegrationSettings's property names (a project
 * stores the VTK objects' properties, as ParaView's state files do), every
 * declared setting; the integrator is stored by its name ("rk4").
 */
#ifndef RiemannStudioIntegrationValues_h
#define RiemannStudioIntegrationValues_h

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

class vtkRiemannIntegrationSettings;

namespace riemann
{
namespace studio
{
/// The app's settings of `settings`, keyed by property.
nlohmann::json IntegrationValues(vtkRiemannIntegrationSettings* settings);

/// "" when `key` names one of the app's settings and `value` is valid for it
/// (type and the declared range); else why not.
std::string CheckIntegrationValue(const std::string& key, const nlohmann::json& value);

/// Set the settings `values` names (checked before: CheckIntegrationValue).
void ApplyIntegrationValues(const nlohmann::json& values, vtkRiemannIntegrationSettings* settings);

/// Python that sets them on `target` (an expression giving a
/// vtkRiemannIntegrationSettings): one `target.SetX(v)` line each.
std::vector<std::string> IntegrationPython(
  const std::string& target, vtkRiemannIntegrationSettings* settings);
} // namespace studio
} // namespace riemann

#endif
