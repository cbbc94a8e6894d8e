#include "IntegrationSchema.h"

#include <cmath>
#include <sstream>

namespace riemann
{
namespace
{
std::string Number(double value)
{
  std::ostringstream s;
  s << value;
  return s.str();
}
} // namespace

std::string DescribeIntegrationRange(const IntegrationSetting& setting)
{
  if (setting.Type == IntegrationSetting::Choice)
  {
    return "euler, rk4 or dp45";
  }
  const std::string kind = setting.Type == IntegrationSetting::Count ? "a whole number" : "a number";
  const std::string lower = setting.MinimumExclusive ? "above " + Number(setting.Minimum)
                                                     : "from " + Number(setting.Minimum);
  const std::string upper =
    (setting.MinimumExclusive ? " and at most " : " to ") + Number(setting.Maximum);
  const std::string unit = *setting.Unit ? std::string(" (") + setting.Unit + ")" : std::string();
  return kind + " " + lower + upper + unit;
}

std::string IntegrationInterval(const IntegrationSetting& setting)
{
  if (setting.Type == IntegrationSetting::Choice)
  {
    return "euler|rk4|dp45";
  }
  return (setting.MinimumExclusive ? "(" : "[") + Number(setting.Minimum) + ", " +
    Number(setting.Maximum) + "]";
}

std::string CheckIntegrationValue(
  const IntegrationSetting& setting, double value, const std::string& name)
{
  const bool inRange = std::isfinite(value) &&
    (setting.MinimumExclusive ? value > setting.Minimum : value >= setting.Minimum) &&
    value <= setting.Maximum;
  const bool whole = setting.Type == IntegrationSetting::Number || value == std::floor(value);
  if (inRange && whole)
  {
    return std::string();
  }
  return name + " is " + Number(value) + ": expected " + DescribeIntegrationRange(setting);
}
} // namespace riemann
