/**
 * @file DeclaredProperties.h
 * @brief The properties panel's fields made from a VTK class's declared
 * settings (`<Class>.settings.json`, SettingDeclaration.h): key, label,
 * type, range and help as the declaration states them, so the app's forms
 * say what the CLI's help and ParaView's panels say.
 */
#ifndef RiemannStudioDeclaredProperties_h
#define RiemannStudioDeclaredProperties_h

#include "PipelineItem.h" // For PropertySpec

#include "SettingDeclaration.h"

class vtkRiemannIntegrationSettings;


#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace riemann
{
namespace studio
{
/// The field of one declared setting.
PropertySpec DeclaredPropertySpec(const riemann::SettingDeclaration& setting);

/// The fields of every setting of `table`, in its order, but those `leftOut`
/// names (settings of inputs the item cannot give: the tracer's mask seeds).
std::vector<PropertySpec> DeclaredPropertySpecs(
  const riemann::SettingTable& table, const std::vector<std::string>& leftOut = {});

/**
 * A new filter's declared settings (`declared`: its SettingValues) but the
 * `leftOut` ones, with the declared `preset`'s values (its JSON text) when
 * the item starts from one.
 */
nlohmann::json DeclaredDefaults(nlohmann::json declared,
  const std::vector<std::string>& leftOut = {}, const char* preset = nullptr);

/**
 * The settings of an item, as a new filter has them: its declared settings
 * (`declared`: riemann::settings::SettingValues of a new filter, from its
 * `<Class>SettingAccess.h`) and its integration settings (`integration`,
 * the new filter's), then the item's `own` (display settings). One default
 * per setting: the filter's, as the CLI and Python have it, or the declared
 * `preset`'s (its JSON text, `<Preset>::Json` of the declaration) where the
 * item starts from one. The `leftOut` settings are not the item's.
 */
nlohmann::json FilterDefaults(nlohmann::json declared, vtkRiemannIntegrationSettings* integration,
  const nlohmann::json& own, const std::vector<std::string>& leftOut = {},
  const char* preset = nullptr);

} // namespace studio
} // namespace riemann

#endif
