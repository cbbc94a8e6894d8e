#include "MetricParameters.h"

#include "MetricDefinition.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace riemann
{
namespace
{
/// The definition as ordered JSON (the parameters keep the user's order), or null.
nlohmann::ordered_json ParsedObject(const std::string& json)
{
  auto parsed = nlohmann::ordered_json::parse(json, nullptr, /*allow_exceptions=*/false);
  return parsed.is_object() ? parsed : nlohmann::ordered_json();
}

std::string NameList(const nlohmann::ordered_json& parameters)
{
  std::string names;
  for (const auto& item : parameters.items())
  {
    names += (names.empty() ? "" : ", ") + item.key();
  }
  return names.empty() ? "none" : names;
}
}

std::vector<std::string> ParameterNames(const std::string& json)
{
  std::vector<std::string> names;
  const nlohmann::ordered_json definition = ParsedObject(json);
  if (definition.is_object() && definition.contains("parameters") &&
    definition["parameters"].is_object())
  {
    for (const auto& item : definition["parameters"].items())
    {
      names.push_back(item.key());
    }
  }
  return names;
}

std::string WithParameterValues(const std::string& json, const std::vector<ParameterValue>& values)
{
  if (values.empty())
  {
    return json;
  }
  nlohmann::ordered_json definition = ParsedObject(json);
  if (!definition.is_object())
  {
    return json;
  }
  const bool hasParameters =
    definition.contains("parameters") && definition["parameters"].is_object();
  for (const ParameterValue& value : values)
  {
    if (!hasParameters || !definition["parameters"].contains(value.Name))
    {
      throw MetricDefinitionError("metric.parameters: no parameter \"" + value.Name +
        "\" to set; the definition's parameters: " +
        (hasParameters ? NameList(definition["parameters"]) : std::string("none")));
    }
    if (!std::isfinite(value.Value))
    {
      throw MetricDefinitionError("metric.parameters." + value.Name + ": the value given (" +
        std::to_string(value.Value) + ") is not a finite number");
    }
    definition["parameters"][value.Name] = value.Value;
  }
  return definition.dump(2);
}
} // namespace riemann
