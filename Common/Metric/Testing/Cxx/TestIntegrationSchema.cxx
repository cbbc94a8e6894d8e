// The integration schema (IntegrationSchema.h) is the one description of the
// integration settings: its defaults are the core's, its ranges hold them,
// and its checks say what is wrong in its words.
#include "GeodesicTrace.h"
#include "IntegrationSchema.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

using namespace riemann;

TEST(IntegrationSchema, NamesAreUniqueOnEverySurface)
{
  std::set<std::string> core, property, json, flag, label;
  for (const IntegrationSetting& s : IntegrationSchema)
  {
    EXPECT_TRUE(core.insert(s.Core).second) << s.Core;
    EXPECT_TRUE(property.insert(s.Property).second) << s.Property;
    if (*s.JsonKey)
    {
      EXPECT_TRUE(json.insert(s.JsonKey).second) << s.JsonKey;
    }
    if (*s.Flag)
    {
      EXPECT_EQ(std::string(s.Flag).rfind("--", 0), 0u) << s.Flag;
      EXPECT_TRUE(flag.insert(s.Flag).second) << s.Flag;
    }
    if (*s.Label)
    {
      EXPECT_TRUE(label.insert(s.Label).second) << s.Label;
    }
    EXPECT_GT(std::string(s.Help).size(), 10u) << s.Core;
  }
  // What a user types: five options, five scene keys, five fields in the app.
  EXPECT_EQ(flag.size(), 5u);
  EXPECT_EQ(json.size(), 5u);
  EXPECT_EQ(label.size(), 5u);
}

TEST(IntegrationSchema, BothColumnsOfDefaultsAreValid)
{
  for (const IntegrationSetting& s : IntegrationSchema)
  {
    EXPECT_EQ(CheckIntegrationValue(s, s.CurveDefault, s.Core), "") << s.Core;
    EXPECT_EQ(CheckIntegrationValue(s, s.RayDefault, s.Core), "") << s.Core;
  }
}

TEST(IntegrationSchema, GeodesicOptionsAreTheCurvesColumn)
{
  const GeodesicOptions options;
  const auto curve = [](IntegrationSettingId id) { return IntegrationSettingOf(id).CurveDefault; };
  EXPECT_EQ(static_cast<double>(options.Integrator), curve(IntegrationSettingId::Integrator));
  EXPECT_EQ(options.Step, curve(IntegrationSettingId::Step));
  EXPECT_EQ(options.MinimumStep, curve(IntegrationSettingId::MinimumStep));
  EXPECT_EQ(options.MaximumStep, curve(IntegrationSettingId::MaximumStep));
  EXPECT_EQ(options.Tolerance, curve(IntegrationSettingId::Tolerance));
  EXPECT_EQ(options.MaximumLength, curve(IntegrationSettingId::Length));
  EXPECT_EQ(static_cast<double>(options.MaximumSteps), curve(IntegrationSettingId::MaximumSteps));
  // The values the docs state (MetricFormat.md, the CLI's help).
  EXPECT_EQ(options.Step, 0.01);
  EXPECT_EQ(options.Tolerance, 1e-8);
  EXPECT_EQ(options.MaximumLength, 10.0);
  EXPECT_EQ(options.MaximumSteps, 100000);
}

TEST(IntegrationSchema, ChecksNameTheSettingAndItsRange)
{
  const IntegrationSetting& step = IntegrationSettingOf(IntegrationSettingId::Step);
  EXPECT_EQ(CheckIntegrationValue(step, 0.0, "InitialIntegrationStep"),
    "InitialIntegrationStep is 0: expected a number from 1e-09 to 1e+06 (arc length)");
  EXPECT_EQ(CheckIntegrationValue(step, 1e-9, "s"), "");
  EXPECT_EQ(CheckIntegrationValue(step, 1e6, "s"), "");
  EXPECT_NE(CheckIntegrationValue(step, std::nan(""), "s"), "");
  EXPECT_NE(CheckIntegrationValue(step, std::numeric_limits<double>::infinity(), "s"), "");

  const IntegrationSetting& length = IntegrationSettingOf(IntegrationSettingId::Length);
  EXPECT_EQ(CheckIntegrationValue(length, 0.0, "MaximumPropagation"),
    "MaximumPropagation is 0: expected a number above 0 and at most 1e+09 (arc length)");
  EXPECT_EQ(CheckIntegrationValue(length, 1e-300, "l"), "");

  const IntegrationSetting& steps = IntegrationSettingOf(IntegrationSettingId::MaximumSteps);
  EXPECT_EQ(CheckIntegrationValue(steps, 2.5, "MaximumNumberOfSteps"),
    "MaximumNumberOfSteps is 2.5: expected a whole number from 1 to 1e+09 (steps)");
  EXPECT_EQ(CheckIntegrationValue(steps, 1e9, "n"), "");
  EXPECT_NE(CheckIntegrationValue(steps, 1e9 + 1, "n"), "");

  const IntegrationSetting& integrator = IntegrationSettingOf(IntegrationSettingId::Integrator);
  EXPECT_EQ(CheckIntegrationValue(integrator, 2, "IntegratorType"), "");
  EXPECT_EQ(CheckIntegrationValue(integrator, 3, "IntegratorType"),
    "IntegratorType is 3: expected euler, rk4 or dp45");
}
