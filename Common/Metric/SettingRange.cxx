#include "SettingRange.h"

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

std::string DescribeSettingRange(const SettingRange& range)
{
  const std::string kind = range.Whole ? "a whole number" : "a number";
  const std::string lower = range.MinimumExclusive ? "above " + Number(range.Minimum)
                                                   : "from " + Number(range.Minimum);
  const std::string upper =
    (range.MinimumExclusive ? " and at most " : " to ") + Number(range.Maximum);
  const std::string unit = *range.Unit ? std::string(" (") + range.Unit + ")" : std::string();
  return kind + " " + lower + upper + unit;
}

std::string SettingInterval(const SettingRange& range)
{
  return (range.MinimumExclusive ? "(" : "[") + Number(range.Minimum) + ", " +
    Number(range.Maximum) + "]";
}

std::string CheckSettingValue(const SettingRange& range, double value, const std::string& name)
{
  const bool inRange = std::isfinite(value) &&
    (range.MinimumExclusive ? value > range.Minimum : value >= range.Minimum) &&
    value <= range.Maximum;
  const bool whole = !range.Whole || value == std::floor(value);
  if (inRange && whole)
  {
    return std::string();
  }
  return name + " is " + Number(value) + ": expected " + DescribeSettingRange(range);
}
} // namespace riemann
