#include "SettingRange.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
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

std::string ShortestNumberText(double value)
{
  // A whole number below a million as it is ("180", not "1.8e+02", which %g
  // would take as the shortest); larger ones may take the exponent ("1e+06").
  if (value == std::floor(value) && std::abs(value) < 1e6)
  {
    char whole[32];
    std::snprintf(whole, sizeof(whole), "%.0f", value);
    return whole;
  }
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", value);
  // The shortest text that reads back the same.
  for (int digits = 1; digits <= 17; ++digits)
  {
    char shorter[32];
    std::snprintf(shorter, sizeof(shorter), "%.*g", digits, value);
    if (std::strtod(shorter, nullptr) == value)
    {
      return shorter;
    }
  }
  return text;
}

std::string DescribeSettingRange(const SettingRange& range)
{
  const std::string kind = range.Whole ? "a whole number" : "a number";
  const std::string lower = range.MinimumExclusive ? "above " + Number(range.Minimum)
                                                   : "from " + Number(range.Minimum);
  // "from 1 to 4", "above 0 and at most 1e+09", "above 0 and below 180".
  const std::string upper = (range.MaximumExclusive ? " and below "
                                : range.MinimumExclusive ? " and at most "
                                                         : " to ") +
    Number(range.Maximum);
  const std::string unit = *range.Unit ? std::string(" (") + range.Unit + ")" : std::string();
  return kind + " " + lower + upper + unit;
}

std::string SettingInterval(const SettingRange& range)
{
  return (range.MinimumExclusive ? "(" : "[") + Number(range.Minimum) + ", " +
    Number(range.Maximum) + (range.MaximumExclusive ? ")" : "]");
}

std::string CheckSettingValue(const SettingRange& range, double value, const std::string& name)
{
  const bool inRange = std::isfinite(value) &&
    (range.MinimumExclusive ? value > range.Minimum : value >= range.Minimum) &&
    (range.MaximumExclusive ? value < range.Maximum : value <= range.Maximum);
  const bool whole = !range.Whole || value == std::floor(value);
  if (inRange && whole)
  {
    return std::string();
  }
  // The value exactly as given (1000001, not 1e+06); the range as written.
  return name + " is " + ShortestNumberText(value) + ": expected " + DescribeSettingRange(range);
}
} // namespace riemann
