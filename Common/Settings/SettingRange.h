/**
 * @file SettingRange.h
 * @brief The valid range of a numeric setting, and the words every surface
 * uses for it (the CLI's help and errors, the scene and project parsers,
 * the app's fields, the VTK objects' checks).
 *
 * Used by every declared setting (SettingValues.h), so that a range is
 * written the same way wherever a user meets it.
 */
#ifndef RiemannSettingRange_h
#define RiemannSettingRange_h

#include "RiemannCommonSettingsExport.h"

#include <string>

namespace riemann
{
struct SettingRange
{
  /// Minimum < value (MinimumExclusive) or Minimum <= value.
  double Minimum;
  bool MinimumExclusive;
  /// value <= Maximum, or value < Maximum (MaximumExclusive).
  double Maximum;
  /// A whole number (a count of steps, pixels or samples).
  bool Whole;
  /// What a value is measured in ("" for a pure number).
  const char* Unit;
  /// value < Maximum (an angle below 180 degrees).
  bool MaximumExclusive = false;
};

/// The shortest text of `value` that reads back the same ("0.1", "1e-08", "1000001"),
/// a whole number below a million without an exponent ("180").
RIEMANNCOMMONSETTINGS_EXPORT std::string ShortestNumberText(double value);

/// The range as words: "a number above 0 and at most 1e+09 (arc length)".
RIEMANNCOMMONSETTINGS_EXPORT std::string DescribeSettingRange(const SettingRange& range);

/// The range as an interval: "[1e-09, 1e+06]", "(0, 179]", "(0, 180)".
RIEMANNCOMMONSETTINGS_EXPORT std::string SettingInterval(const SettingRange& range);

/// "" when `value` is finite, in the range and whole where it must be; else
/// why not, naming it `name` ("--fov is 180: expected a number above 0 and
/// at most 179 (degrees)").
RIEMANNCOMMONSETTINGS_EXPORT std::string CheckSettingValue(
  const SettingRange& range, double value, const std::string& name);
} // namespace riemann

#endif
