/**
 * @file IntegrationSchema.h
 * @brief Every setting of how curves are integrated, described once: its
 * name on each surface, its type, its defaults, its valid range, its unit
 * and its help (as F3D makes all its options from one options.json).
 *
 * What is made from this table, and nowhere else decided:
 * - the defaults of the core structs: GeodesicOptions (GeodesicTrace.h) for
 *   curves (geodesics, exponential maps, conjugate loci) and RaySettings
 *   (Rendering/Core) for the rays of a picture;
 * - vtkRiemannIntegrationSettings: its properties' defaults and
 *   CheckSettings();
 * - the options of every `riemann` command that integrates
 *   (AddIntegrationOptions: flag, help, unit, range);
 * - riemann-studio's integration forms (label, help, range);
 * - the keys and ranges of a scene's "integrator" block (SceneFormat.md).
 *
 * Two columns of defaults, on purpose: a curve the user asked for is
 * integrated finely (step 0.01, tolerance 1e-8, up to 100000 steps), while a
 * picture traces a ray per pixel, millions of them, within a frame (step
 * 0.02, tolerance 1e-4, 1000 steps). Each setting has one default per use,
 * and every surface of that use takes it from here.
 */
#ifndef RiemannIntegrationSchema_h
#define RiemannIntegrationSchema_h

#include "RiemannCommonMetricExport.h"

#include <array>
#include <string>

namespace riemann
{
/// One integration setting.
struct IntegrationSetting
{
  enum Kind
  {
    Choice, ///< the integrator: IntegratorName() / ParseIntegratorName() (Integrators.h)
    Number, ///< a real number in the range
    Count   ///< a whole number in the range
  };
  /// Member of GeodesicOptions and RaySettings ("" where only the VTK object has it).
  const char* Core;
  /// Property of vtkRiemannIntegrationSettings (Set<Property>, Get<Property>).
  const char* Property;
  /// Key in a scene's "integrator" block ("" where a scene does not set it).
  const char* JsonKey;
  /// Option of the `riemann` commands that integrate ("" where none).
  const char* Flag;
  /// riemann-studio's label ("" where the app has no field for it).
  const char* Label;
  Kind Type;
  /// Defaults for curves and for the rays of a picture (a Choice: the IntegratorType).
  double CurveDefault;
  double RayDefault;
  /// The valid range: Minimum < value (MinimumExclusive) or Minimum <= value, value <= Maximum.
  double Minimum;
  bool MinimumExclusive;
  double Maximum;
  /// What a value is measured in ("" for a choice or a pure number).
  const char* Unit;
  /// One line, without the unit or range (every surface shows those from the fields above).
  const char* Help;
};

/// The settings, in the order every surface lists them.
enum class IntegrationSettingId
{
  Integrator,
  Step,
  MinimumStep,
  MaximumStep,
  Tolerance,
  Length,
  MaximumSteps
};

constexpr std::array<IntegrationSetting, 7> IntegrationSchema{ {
  { "Integrator", "IntegratorType", "method", "--integrator", "Integrator",
    IntegrationSetting::Choice, 1, 1, 0, false, 2, "",
    "euler (the paper's), rk4 (fixed step) or dp45 (adaptive Dormand-Prince 5(4))" },
  { "Step", "InitialIntegrationStep", "step", "--step", "Step", IntegrationSetting::Number, 0.01,
    0.02, 1e-9, false, 1e6, "arc length", "The step (the first one for dp45)" },
  { "MinimumStep", "MinimumIntegrationStep", "", "", "", IntegrationSetting::Number, 1e-7, 2e-8,
    0.0, true, 1e6, "arc length", "Smallest step of dp45" },
  { "MaximumStep", "MaximumIntegrationStep", "", "", "", IntegrationSetting::Number, 0.5, 0.08,
    0.0, true, 1e6, "arc length", "Largest step of dp45" },
  { "Tolerance", "MaximumError", "tolerance", "--tolerance", "Tolerance",
    IntegrationSetting::Number, 1e-8, 1e-4, 1e-15, false, 1.0, "",
    "Per-step error tolerance of dp45" },
  { "MaximumLength", "MaximumPropagation", "max_length", "--length", "Length",
    IntegrationSetting::Number, 10.0, 30.0, 0.0, true, 1e9, "arc length",
    "Arc length at which a curve stops" },
  { "MaximumSteps", "MaximumNumberOfSteps", "max_steps", "--max-steps", "Maximum steps",
    IntegrationSetting::Count, 100000, 1000, 1, false, 1e9, "steps",
    "Steps of a curve at most" },
} };

constexpr const IntegrationSetting& IntegrationSettingOf(IntegrationSettingId id)
{
  return IntegrationSchema[static_cast<std::size_t>(id)];
}

/// The default of a setting for curves (GeodesicOptions) and for rays (RaySettings).
constexpr double CurveDefault(IntegrationSettingId id)
{
  return IntegrationSettingOf(id).CurveDefault;
}
constexpr double RayDefault(IntegrationSettingId id)
{
  return IntegrationSettingOf(id).RayDefault;
}

/**
 * "" when `value` is valid for `setting` (finite, in range, whole for a
 * Count, an integrator index for a Choice); else why not, naming it `name`
 * ("InitialIntegrationStep is 0: expected a number above 0 and at most 1e+06
 * (arc length)").
 */
RIEMANNCOMMONMETRIC_EXPORT std::string CheckIntegrationValue(
  const IntegrationSetting& setting, double value, const std::string& name);

/// The range as words: "a number above 0 and at most 1e+09 (arc length)".
RIEMANNCOMMONMETRIC_EXPORT std::string DescribeIntegrationRange(const IntegrationSetting& setting);

/// The range as an interval: "[1e-09, 1e+06]", "(0, 1e+09]" (a choice: "euler|rk4|dp45").
RIEMANNCOMMONMETRIC_EXPORT std::string IntegrationInterval(const IntegrationSetting& setting);
} // namespace riemann

#endif
