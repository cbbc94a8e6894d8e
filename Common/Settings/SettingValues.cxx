#include "SettingValues.h"

#include "SettingRange.h"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace riemann
{
namespace
{
SettingRange RangeOf(const SettingDeclaration& setting)
{
  return { setting.Minimum, setting.MinimumExclusive, setting.Maximum,
    setting.Type == SettingDeclaration::Integer || setting.Type == SettingDeclaration::Dimensions,
    setting.Unit, setting.MaximumExclusive };
}

bool IsFiniteNumbers(const nlohmann::json& value, std::size_t count)
{
  if (!value.is_array() || value.size() != count)
  {
    return false;
  }
  for (const nlohmann::json& x : value)
  {
    if (!x.is_number() || !std::isfinite(x.get<double>()))
    {
      return false;
    }
  }
  return true;
}

/// Numbers separated by commas (and spaces): "0,0,1", "1, 2.5".
bool ParseNumbers(const std::string& text, std::vector<double>& numbers)
{
  numbers.clear();
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    const char* begin = item.c_str();
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    while (end && (*end == ' ' || *end == '\t'))
    {
      ++end;
    }
    if (end == begin || !end || *end != '\0' || !std::isfinite(value))
    {
      return false;
    }
    numbers.push_back(value);
  }
  return text.empty() || text.back() != ',';
}
} // namespace

nlohmann::json DefaultValue(const SettingDeclaration& setting)
{
  return nlohmann::json::parse(setting.Default);
}

nlohmann::json DefaultValues(const SettingTable& table)
{
  nlohmann::json values = nlohmann::json::object();
  for (const SettingDeclaration& setting : table)
  {
    values[setting.Name] = DefaultValue(setting);
  }
  return values;
}

std::vector<std::string> ChoiceNames(const SettingDeclaration& setting)
{
  std::vector<std::string> names;
  std::stringstream stream(setting.Choices);
  std::string name;
  while (std::getline(stream, name, '|'))
  {
    names.push_back(name);
  }
  return names;
}

namespace
{
/// The choice an old name stands for ("adaptive" -> "dp45"), or the name itself.
std::string CurrentChoiceName(const SettingDeclaration& setting, const std::string& name)
{
  std::stringstream stream(setting.ChoiceAliases);
  std::string pair;
  while (std::getline(stream, pair, ','))
  {
    const std::size_t equals = pair.find('=');
    if (equals != std::string::npos && pair.substr(0, equals) == name)
    {
      return pair.substr(equals + 1);
    }
  }
  return name;
}
} // namespace

int ChoiceIndex(const SettingDeclaration& setting, const std::string& name)
{
  const std::vector<std::string> names = ChoiceNames(setting);
  const std::string current = CurrentChoiceName(setting, name);
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    if (names[i] == current)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}

std::string DirectionProblem(const double v[3])
{
  if (v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0)
  {
    return "is the zero vector: a direction must not be zero";
  }
  // Normalised later (in g): its squared length must be a normal double.
  const double squared = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  if (!(squared >= DBL_MIN && squared <= DBL_MAX))
  {
    return std::string("is too ") + (squared < 1.0 ? "short" : "long") + " to normalise (scale it)";
  }
  return std::string();
}

std::string BoundsProblem(const double b[6])
{
  const char* axes = "xyz";
  for (int a = 0; a < 3; ++a)
  {
    if (!(b[2 * a] < b[2 * a + 1]))
    {
      const char axis = axes[a];
      return std::string("the ") + axis + " range needs " + axis + "0 < " + axis + "1, got " +
        ShortestNumberText(b[2 * a]) + " >= " + ShortestNumberText(b[2 * a + 1]);
    }
  }
  return std::string();
}

std::string CheckSettingValue(
  const SettingDeclaration& setting, const nlohmann::json& value, const std::string& name)
{
  const std::string expected = name + ": expected " + DescribeSettingRange(setting);
  switch (setting.Type)
  {
    case SettingDeclaration::Boolean:
      return value.is_boolean() ? std::string() : expected;
    case SettingDeclaration::Choice:
      return value.is_string() && ChoiceIndex(setting, value.get<std::string>()) >= 0
        ? std::string()
        : expected;
    case SettingDeclaration::Point:
      return IsFiniteNumbers(value, 3) ? std::string() : expected;
    case SettingDeclaration::Direction:
    {
      if (!IsFiniteNumbers(value, 3))
      {
        return expected;
      }
      const double v[3] = { value[0].get<double>(), value[1].get<double>(), value[2].get<double>() };
      const std::string why = DirectionProblem(v);
      return why.empty() ? std::string() : name + " " + why;
    }
    case SettingDeclaration::Bounds:
    {
      if (!IsFiniteNumbers(value, 6))
      {
        return expected;
      }
      double b[6];
      for (int i = 0; i < 6; ++i)
      {
        b[i] = value[i].get<double>();
      }
      const std::string why = BoundsProblem(b);
      return why.empty() ? std::string() : name + ": " + why;
    }
    case SettingDeclaration::Dimensions:
      if (!IsFiniteNumbers(value, 3))
      {
        return expected;
      }
      for (const nlohmann::json& x : value)
      {
        const std::string why = riemann::CheckSettingValue(RangeOf(setting), x.get<double>(), name);
        if (!why.empty())
        {
          return why;
        }
      }
      return std::string();
    case SettingDeclaration::NumberList:
    {
      if (!value.is_array())
      {
        return expected;
      }
      for (const nlohmann::json& x : value)
      {
        const std::string why = x.is_number()
          ? riemann::CheckSettingValue(RangeOf(setting), x.get<double>(), name)
          : expected;
        if (!why.empty())
        {
          return why;
        }
      }
      return std::string();
    }
    case SettingDeclaration::Integer:
    case SettingDeclaration::Number:
      break;
  }
  if (!value.is_number())
  {
    return expected;
  }
  return riemann::CheckSettingValue(RangeOf(setting), value.get<double>(), name);
}

std::string CheckSettingValues(const SettingTable& table, const nlohmann::json& values)
{
  for (const SettingDeclaration& setting : table)
  {
    const nlohmann::json missing;
    const nlohmann::json& value = values.contains(setting.Name) ? values.at(setting.Name) : missing;
    std::string error = CheckSettingValue(setting, value, setting.Name);
    if (!error.empty())
    {
      return error;
    }
  }
  return std::string();
}

nlohmann::json ParseSettingText(
  const SettingDeclaration& setting, const std::string& text, std::string& error)
{
  error.clear();
  std::vector<double> numbers;
  switch (setting.Type)
  {
    case SettingDeclaration::Boolean:
      if (text == "true" || text == "on" || text == "1")
      {
        return true;
      }
      if (text == "false" || text == "off" || text == "0")
      {
        return false;
      }
      break;
    case SettingDeclaration::Choice:
      if (ChoiceIndex(setting, text) >= 0)
      {
        return CurrentChoiceName(setting, text); // an old name reads as the current one
      }
      break;
    case SettingDeclaration::Point:
    case SettingDeclaration::Direction:
      if (ParseNumbers(text, numbers) && numbers.size() == 3)
      {
        return numbers;
      }
      error = "expected three finite comma-separated numbers X,Y,Z";
      return nullptr;
    case SettingDeclaration::Bounds:
      if (ParseNumbers(text, numbers) && numbers.size() == 6)
      {
        return numbers;
      }
      error = "expected six finite comma-separated numbers X0,X1,Y0,Y1,Z0,Z1";
      return nullptr;
    case SettingDeclaration::Dimensions:
      if (ParseNumbers(text, numbers) && numbers.size() == 3)
      {
        nlohmann::json counts = nlohmann::json::array();
        for (double x : numbers)
        {
          if (x == std::floor(x) && std::abs(x) < 9e15)
          {
            counts.push_back(static_cast<long long>(x));
          }
          else
          {
            counts.push_back(x); // refused by CheckSettingValue, naming the range
          }
        }
        return counts;
      }
      error = "expected three comma-separated whole numbers NX,NY,NZ";
      return nullptr;
    case SettingDeclaration::NumberList:
      if (ParseNumbers(text, numbers))
      {
        return numbers;
      }
      error = "expected finite numbers separated by commas";
      return nullptr;
    case SettingDeclaration::Integer:
    case SettingDeclaration::Number:
      if (ParseNumbers(text, numbers) && numbers.size() == 1)
      {
        if (setting.Type == SettingDeclaration::Integer && numbers[0] == std::floor(numbers[0]) &&
          std::abs(numbers[0]) < 9e15)
        {
          return static_cast<long long>(numbers[0]);
        }
        return numbers[0];
      }
      break;
  }
  error = "expected " + DescribeSettingRange(setting);
  return nullptr;
}

std::string SettingText(const SettingDeclaration& setting, const nlohmann::json& value)
{
  if (value.is_string())
  {
    return value.get<std::string>();
  }
  if (value.is_boolean())
  {
    return value.get<bool>() ? "true" : "false";
  }
  if (value.is_array())
  {
    const char* separator = setting.Type == SettingDeclaration::NumberList ? ", " : ",";
    std::string text;
    for (std::size_t i = 0; i < value.size(); ++i)
    {
      text += (i ? separator : "") + SettingText(setting, value[i]);
    }
    return text;
  }
  if (value.is_number_integer())
  {
    return std::to_string(value.get<long long>());
  }
  return value.is_number() ? ShortestNumberText(value.get<double>()) : value.dump();
}

std::vector<std::string> SettingPythonLines(
  const SettingTable& table, const std::string& variable, const nlohmann::json& values)
{
  const auto python = [](const nlohmann::json& x)
  {
    return x.is_number_integer() ? std::to_string(x.get<long long>())
                                 : ShortestNumberText(x.get<double>());
  };
  std::vector<std::string> lines;
  for (const SettingDeclaration& setting : table)
  {
    const auto found = values.find(setting.Name);
    if (found == values.end())
    {
      continue;
    }
    const nlohmann::json& value = *found;
    const std::string set = variable + ".Set" + setting.Name + "(";
    switch (setting.Type)
    {
      case SettingDeclaration::Boolean:
        lines.push_back(set + (value.get<bool>() ? "True" : "False") + ")");
        break;
      case SettingDeclaration::Choice:
        lines.push_back(set + std::to_string(ChoiceIndex(setting, value.get<std::string>())) +
          ")  # " + value.get<std::string>());
        break;
      case SettingDeclaration::Point:
      case SettingDeclaration::Direction:
        lines.push_back(set + python(value[0]) + ", " + python(value[1]) + ", " +
          python(value[2]) + ")");
        break;
      case SettingDeclaration::Bounds:
      case SettingDeclaration::Dimensions:
      {
        std::string arguments;
        for (std::size_t i = 0; i < value.size(); ++i)
        {
          arguments += (i ? ", " : "") + python(value[i]);
        }
        lines.push_back(set + arguments + ")");
        break;
      }
      case SettingDeclaration::NumberList:
        lines.push_back(variable + "." + setting.ClearCommand + "()");
        for (const nlohmann::json& x : value)
        {
          lines.push_back(variable + "." + setting.AddCommand + "(" + python(x) + ")");
        }
        break;
      case SettingDeclaration::Integer:
      case SettingDeclaration::Number:
        lines.push_back(set + python(value) + ")");
        break;
    }
  }
  return lines;
}
} // namespace riemann
