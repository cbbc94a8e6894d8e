#include "IntegrationSchema.h"

#include "SettingRange.h"

namespace riemann
{
namespace
{
SettingRange RangeOf(const IntegrationSetting& setting)
{
  return { setting.Minimum, setting.MinimumExclusive, setting.Maximum,
    setting.Type == IntegrationSetting::Count, setting.Unit };
}
} // namespace

std::string DescribeIntegrationRange(const IntegrationSetting& setting)
{
  if (setting.Type == IntegrationSetting::Choice)
  {
    return "euler, rk4 or dp45";
  }
  return DescribeSettingRange(RangeOf(setting));
}

std::string IntegrationInterval(const IntegrationSetting& setting)
{
  if (setting.Type == IntegrationSetting::Choice)
  {
    return "euler|rk4|dp45";
  }
  return SettingInterval(RangeOf(setting));
}

std::string CheckIntegrationValue(
  const IntegrationSetting& setting, double value, const std::string& name)
{
  // A choice is checked as the index of an integrator (0, 1 or 2).
  SettingRange range = RangeOf(setting);
  range.Whole = range.Whole || setting.Type == IntegrationSetting::Choice;
  const std::string why = CheckSettingValue(range, value, name);
  if (why.empty() || setting.Type != IntegrationSetting::Choice)
  {
    return why;
  }
  // Its words name the integrators, not the indices.
  return why.substr(0, why.find(": expected ")) + ": expected " + DescribeIntegrationRange(setting);
}
} // namespace riemann
