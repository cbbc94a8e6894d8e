#include "DeclaredProperties.h"

#include "IntegrationValues.h"
#include "SettingValues.h"

#include "vtkNew.h"
#include "vtkRiemannIntegrationSettings.h"

#include <algorithm>

namespace riemann
{
namespace studio
{
PropertySpec DeclaredPropertySpec(const riemann::SettingDeclaration& setting)
{
  PropertySpec spec;
  spec.Key = setting.Name;
  spec.Label = QString::fromUtf8(setting.Label);
  spec.Minimum = setting.Minimum;
  spec.MinimumExclusive = setting.MinimumExclusive;
  spec.Maximum = setting.Maximum;
  spec.MaximumExclusive = setting.MaximumExclusive;
  std::string help = setting.Help;
  if (setting.Type != riemann::SettingDeclaration::Boolean)
  {
    help += ": " + riemann::DescribeSettingRange(setting);
  }
  spec.Help = QString::fromStdString(help);
  for (const QString& alias : QString::fromUtf8(setting.ProjectAliases).split(',', Qt::SkipEmptyParts))
  {
    spec.Aliases << alias;
  }
  switch (setting.Type)
  {
    case riemann::SettingDeclaration::Boolean:
      spec.Type = PropertySpec::Boolean;
      break;
    case riemann::SettingDeclaration::Integer:
      spec.Type = PropertySpec::Integer;
      break;
    case riemann::SettingDeclaration::Number:
      spec.Type = PropertySpec::Number;
      break;
    case riemann::SettingDeclaration::Point:
      spec.Type = PropertySpec::Vector3;
      break;
    case riemann::SettingDeclaration::Direction:
      spec.Type = PropertySpec::Vector3;
      spec.NonZero = true;
      break;
    case riemann::SettingDeclaration::Choice:
      spec.Type = PropertySpec::Choice;
      for (const std::string& name : riemann::ChoiceNames(setting))
      {
        spec.Choices << QString::fromStdString(name);
      }
      break;
    case riemann::SettingDeclaration::NumberList:
      spec.Type = PropertySpec::NumberList;
      break;
    case riemann::SettingDeclaration::Bounds:
      spec.Type = PropertySpec::Numbers6;
      break;
    case riemann::SettingDeclaration::Dimensions:
      spec.Type = PropertySpec::Integers3;
      break;
  }
  return spec;
}

namespace
{
bool IsDeclaredSettingLeftOut(const std::string& name, const std::vector<std::string>& leftOut)
{
  return std::find(leftOut.begin(), leftOut.end(), name) != leftOut.end();
}
}

std::vector<PropertySpec> DeclaredPropertySpecs(
  const riemann::SettingTable& table, const std::vector<std::string>& leftOut)
{
  std::vector<PropertySpec> specs;
  for (const riemann::SettingDeclaration& setting : table)
  {
    if (!IsDeclaredSettingLeftOut(setting.Name, leftOut))
    {
      specs.push_back(DeclaredPropertySpec(setting));
    }
  }
  return specs;
}

nlohmann::json DeclaredDefaults(
  nlohmann::json declared, const std::vector<std::string>& leftOut, const char* preset)
{
  for (const std::string& name : leftOut)
  {
    declared.erase(name);
  }
  if (preset)
  {
    declared.update(nlohmann::json::parse(preset));
  }
  return declared;
}

nlohmann::json FilterDefaults(nlohmann::json declared, vtkRiemannIntegrationSettings* integration,
  const nlohmann::json& own, const std::vector<std::string>& leftOut, const char* preset)
{
  declared = DeclaredDefaults(std::move(declared), leftOut, preset);
  declared.update(IntegrationValues(integration));
  if (own.is_object())
  {
    declared.update(own);
  }
  return declared;
}

} // namespace studio
} // namespace riemann
