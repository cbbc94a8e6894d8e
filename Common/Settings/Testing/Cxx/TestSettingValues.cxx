// The declared settings' runtime (SettingDeclaration.h, SettingValues.h):
// option names, range words, checks, typed text and Python, on a table
// written here (the generated ones are walked by Python.TestSettingSurfaces).
#include "SettingDeclaration.h"
#include "SettingValues.h"
#include "RiemannCutLocusDeclaration.h"
#include "RiemannExponentialMapDeclaration.h"

#include <gtest/gtest.h>

#include <vector>

namespace
{
using riemann::SettingDeclaration;

// One setting of each kind, as a generated table states them.
constexpr SettingDeclaration Example[] = {
  { "NumberOfDirections", SettingDeclaration::Integer, "400", 1.0, false, 1e6, "", "", "Directions",
    "Directions of the grid", "--directions,-n", "", "", "", "" },
  { "ConeAngle", SettingDeclaration::Number, "180", 0.0, false, 180.0, "", "degrees", "Cone angle",
    "Half-angle", "", "", "", "", "" },
  { "InitialIntegrationStep", SettingDeclaration::Number, "0.01", 0.0, true, 1e6, "", "arc length",
    "Step", "The step", "--step", "", "", "", "" },
  { "ConeAxis", SettingDeclaration::Direction, "[0, 0, 1]", -1e300, false, 1e300, "", "", "Cone axis",
    "Axis", "", "", "", "", "" },
  { "Observer", SettingDeclaration::Point, "[0, 0, 0]", -1e300, false, 1e300, "", "", "Observer",
    "Where", "--seed", "", "", "", "" },
  { "IntegratorType", SettingDeclaration::Choice, "\"rk4\"", -1e300, false, 1e300, "euler|rk4|dp45",
    "", "Integrator", "The integrator", "", "", "", "", "" },
  { "Radii", SettingDeclaration::NumberList, "[]", 0.0, true, 1e9, "", "arc length", "Radii",
    "Wavefronts", "", "AddRadius", "RemoveAllRadii", "GetNumberOfRadii", "GetRadius" },
  { "ScalarBar", SettingDeclaration::Boolean, "false", -1e300, false, 1e300, "", "", "Legend",
    "Show the legend", "", "", "", "", "" },
  { "MinimumFA", SettingDeclaration::Number, "0.2", 0.0, false, 1.0, "", "", "Minimum FA",
    "Stop below", "", "", "", "", "" },
};
constexpr riemann::SettingTable Table{ "vtkExample", "Example", Example,
  sizeof(Example) / sizeof(Example[0]) };

const SettingDeclaration& Setting(const char* name)
{
  const SettingDeclaration* setting = Table.Find(name);
  EXPECT_NE(setting, nullptr) << name;
  return *setting;
}
} // namespace

TEST(SettingDeclaration, CommandLineNamesAreThePropertysWordsAndTheOldSpellings)
{
  EXPECT_EQ(riemann::CommandLineName(Setting("NumberOfDirections")), "--number-of-directions");
  EXPECT_EQ(riemann::CommandLineNames(Setting("NumberOfDirections")),
    "--number-of-directions,--directions,-n");
  EXPECT_EQ(riemann::CommandLineName(Setting("MinimumFA")), "--minimum-fa");
  SettingDeclaration acronym = Setting("MinimumFA");
  acronym.Name = "GPUPath";
  EXPECT_EQ(riemann::CommandLineName(acronym), "--gpu-path");
  EXPECT_EQ(riemann::CommandLineNames(Setting("ConeAngle")), "--cone-angle");
  EXPECT_EQ(Table.Find("Nothing"), nullptr);
}

TEST(SettingDeclaration, RangesInWords)
{
  EXPECT_EQ(riemann::DescribeSettingRange(Setting("NumberOfDirections")),
    "a whole number from 1 to 1e+06");
  EXPECT_EQ(riemann::DescribeSettingRange(Setting("InitialIntegrationStep")),
    "a number above 0 and at most 1e+06 (arc length)");
  EXPECT_EQ(riemann::DescribeSettingRange(Setting("IntegratorType")), "one of euler, rk4, dp45");
  EXPECT_EQ(riemann::DescribeSettingRange(Setting("Radii")),
    "numbers, each above 0 and at most 1e+09 (arc length)");
  EXPECT_EQ(riemann::DescribeSettingRange(Setting("ConeAxis")), "three numbers, not all zero");
}

TEST(SettingValues, DefaultsAreTheDeclaredJson)
{
  const nlohmann::json values = riemann::DefaultValues(Table);
  EXPECT_EQ(values.at("NumberOfDirections"), 400);
  EXPECT_EQ(values.at("ConeAxis"), nlohmann::json({ 0, 0, 1 }));
  EXPECT_EQ(values.at("IntegratorType"), "rk4");
  EXPECT_EQ(values.at("Radii"), nlohmann::json::array());
  EXPECT_EQ(values.at("ScalarBar"), false);
  EXPECT_EQ(values.size(), Table.Count);
}

TEST(SettingValues, ChecksFollowTheDeclaredTypeAndRange)
{
  using nlohmann::json;
  EXPECT_EQ(riemann::CheckSettingValue(Setting("NumberOfDirections"), 1, "n"), "");
  EXPECT_EQ(riemann::CheckSettingValue(Setting("NumberOfDirections"), 0, "n"),
    "n is 0: expected a whole number from 1 to 1e+06");
  EXPECT_EQ(riemann::CheckSettingValue(Setting("NumberOfDirections"), 2.5, "n"),
    "n is 2.5: expected a whole number from 1 to 1e+06");
  EXPECT_EQ(riemann::CheckSettingValue(Setting("NumberOfDirections"), 1000001, "n"),
    "n is 1000001: expected a whole number from 1 to 1e+06");
  EXPECT_NE(riemann::CheckSettingValue(Setting("InitialIntegrationStep"), 0.0, "s"), "");
  EXPECT_EQ(riemann::CheckSettingValue(Setting("ConeAngle"), 0.0, "a"), "");
  EXPECT_NE(riemann::CheckSettingValue(Setting("ConeAngle"), "wide", "a"), "");
  EXPECT_NE(riemann::CheckSettingValue(Setting("ConeAxis"), json({ 0, 0, 0 }), "x"), "");
  EXPECT_NE(riemann::CheckSettingValue(Setting("ConeAxis"), json({ 0, 1 }), "x"), "");
  EXPECT_EQ(riemann::CheckSettingValue(Setting("Observer"), json({ 0, 0, 0 }), "x"), "");
  EXPECT_EQ(riemann::CheckSettingValue(Setting("IntegratorType"), "dp45", "i"), "");
  EXPECT_EQ(riemann::CheckSettingValue(Setting("IntegratorType"), "adams", "i"),
    "i: expected one of euler, rk4, dp45");
  EXPECT_EQ(riemann::CheckSettingValue(Setting("Radii"), json::array(), "r"), "");
  EXPECT_EQ(riemann::CheckSettingValue(Setting("Radii"), json({ 1, -2 }), "r"),
    "r is -2: expected a number above 0 and at most 1e+09 (arc length)");
  EXPECT_NE(riemann::CheckSettingValue(Setting("ScalarBar"), 1, "b"), "");
}

TEST(SettingValues, AWholeObjectIsCheckedInTheTablesOrder)
{
  nlohmann::json values = riemann::DefaultValues(Table);
  EXPECT_EQ(riemann::CheckSettingValues(Table, values), "");
  values["MinimumFA"] = 2.0;
  values["NumberOfDirections"] = 0;
  // NumberOfDirections comes first in the table: its sentence, named as the setting.
  EXPECT_EQ(riemann::CheckSettingValues(Table, values),
    "NumberOfDirections is 0: expected a whole number from 1 to 1e+06");
  values["NumberOfDirections"] = 10;
  EXPECT_EQ(riemann::CheckSettingValues(Table, values), "MinimumFA is 2: expected a number from 0 to 1");
  values.erase("ConeAngle");
  EXPECT_NE(riemann::CheckSettingValues(Table, values), ""); // a missing value is not valid
}

TEST(SettingValues, AnEndTheDeclarationExcludesIsRefused)
{
  // vtkRiemannCutLocus.settings.json: a turn in (0, 180) degrees.
  const SettingDeclaration* angle =
    riemann::declared::vtkRiemannCutLocus::Settings.Find("MinimumAngle");
  ASSERT_NE(angle, nullptr);
  EXPECT_TRUE(angle->MinimumExclusive);
  EXPECT_TRUE(angle->MaximumExclusive);
  EXPECT_EQ(riemann::DescribeSettingRange(*angle), "a number above 0 and below 180 (degrees)");
  EXPECT_EQ(riemann::CheckSettingValue(*angle, 179.5, "a"), "");
  EXPECT_EQ(riemann::CheckSettingValue(*angle, 180, "a"),
    "a is 180: expected a number above 0 and below 180 (degrees)");
  EXPECT_NE(riemann::CheckSettingValue(*angle, 0, "a"), "");
  // The smooth factor's maximum is included.
  const SettingDeclaration* factor =
    riemann::declared::vtkRiemannCutLocus::Settings.Find("SmoothFactor");
  ASSERT_NE(factor, nullptr);
  EXPECT_FALSE(factor->MaximumExclusive);
  EXPECT_EQ(riemann::CheckSettingValue(*factor, factor->Maximum, "f"), "");
  EXPECT_EQ(riemann::declared::vtkRiemannCutLocus::Default::MinimumAngle, 20.0);
}

TEST(SettingValues, TypedTextReadsBackAsTheValue)
{
  std::string error;
  EXPECT_EQ(riemann::ParseSettingText(Setting("NumberOfDirections"), "30", error), 30);
  EXPECT_TRUE(error.empty());
  EXPECT_TRUE(riemann::ParseSettingText(Setting("NumberOfDirections"), "3x", error).is_null());
  EXPECT_EQ(error, "expected a whole number from 1 to 1e+06");
  EXPECT_EQ(riemann::ParseSettingText(Setting("ConeAxis"), "0, 1,0", error),
    nlohmann::json({ 0.0, 1.0, 0.0 }));
  EXPECT_TRUE(riemann::ParseSettingText(Setting("ConeAxis"), "0,1", error).is_null());
  EXPECT_EQ(error, "expected three finite comma-separated numbers X,Y,Z");
  EXPECT_TRUE(riemann::ParseSettingText(Setting("Observer"), "nan,0,0", error).is_null());
  EXPECT_EQ(riemann::ParseSettingText(Setting("Radii"), "1, 2.5", error), nlohmann::json({ 1.0, 2.5 }));
  EXPECT_TRUE(riemann::ParseSettingText(Setting("Radii"), "1,", error).is_null());
  EXPECT_EQ(riemann::ParseSettingText(Setting("IntegratorType"), "euler", error), "euler");
  EXPECT_TRUE(riemann::ParseSettingText(Setting("IntegratorType"), "Euler", error).is_null());
  EXPECT_EQ(riemann::ParseSettingText(Setting("ScalarBar"), "on", error), true);
  for (const SettingDeclaration& setting : Table)
  {
    // The text of each default reads back as the default.
    const nlohmann::json value = riemann::DefaultValue(setting);
    const std::string text = riemann::SettingText(setting, value);
    if (!text.empty())
    {
      EXPECT_EQ(riemann::ParseSettingText(setting, text, error), value) << setting.Name << ": " << text;
    }
  }
}

TEST(SettingValues, PythonSetsEachDeclaredSettingInTheTablesOrder)
{
  nlohmann::json values = riemann::DefaultValues(Table);
  values["Radii"] = { 1.25, 2.5 };
  values["NotDeclared"] = 3;
  const std::vector<std::string> lines = riemann::SettingPythonLines(Table, "e", values);
  const std::vector<std::string> expected{
    "e.SetNumberOfDirections(400)",
    "e.SetConeAngle(180)",
    "e.SetInitialIntegrationStep(0.01)",
    "e.SetConeAxis(0, 0, 1)",
    "e.SetObserver(0, 0, 0)",
    "e.SetIntegratorType(1)  # rk4",
    "e.RemoveAllRadii()",
    "e.AddRadius(1.25)",
    "e.AddRadius(2.5)",
    "e.SetScalarBar(False)",
    "e.SetMinimumFA(0.2)",
  };
  EXPECT_EQ(lines, expected);
}

TEST(SettingValues, TheGeneratedTableIsTheDeclaration)
{
  // vtkRiemannExponentialMap.settings.json, through cmake/RiemannSettings.py;
  // its NumberOfDirections is declared "like" the direction grid's.
  namespace declared = riemann::declared::vtkRiemannExponentialMap;
  const SettingDeclaration* directions = declared::Settings.Find("NumberOfDirections");
  ASSERT_NE(directions, nullptr);
  EXPECT_EQ(riemann::DefaultValue(*directions), declared::Default::NumberOfDirections);
  EXPECT_EQ(directions->Maximum, declared::Maximum::NumberOfDirections);
  EXPECT_STREQ(directions->CommandLineAliases, "--directions,-n");
  EXPECT_STREQ(declared::Settings.ClassName, "vtkRiemannExponentialMap");
}

namespace
{
// A grid's box and points per axis, as vtkRiemannFieldAlgorithm declares them.
constexpr SettingDeclaration GridExample[] = {
  { "Bounds", SettingDeclaration::Bounds, "[-2, 2, -2, 2, -2, 2]", -1e300, false, 1e300, "", "",
    "Bounds", "The box", "", "", "", "", "" },
  { "Dimensions", SettingDeclaration::Dimensions, "[33, 33, 33]", 1.0, false, 512.0, "", "points",
    "Samples", "Points per axis", "--dims", "", "", "", "" },
  { "StartDirection", SettingDeclaration::Direction, "[1, 0, 0]", -1e300, false, 1e300, "", "",
    "Direction", "The direction", "--direction", "", "", "", "", "", "", "ConeAxis" },
};
constexpr riemann::SettingTable Grid{ "vtkGridExample", "Grid", GridExample,
  sizeof(GridExample) / sizeof(GridExample[0]) };
}

// A box must increase along every axis, and the refusal names the axis; a
// grid's counts are whole and each in the range; a direction that cannot be
// normalised is refused with why.
TEST(SettingValues, BoxesGridsAndDirectionsAreCheckedWithTheirReasons)
{
  const SettingDeclaration& bounds = *Grid.Find("Bounds");
  const SettingDeclaration& dims = *Grid.Find("Dimensions");
  const SettingDeclaration& direction = *Grid.Find("StartDirection");
  EXPECT_EQ(riemann::DescribeSettingRange(bounds),
    "six numbers x0,x1,y0,y1,z0,z1 with x0 < x1, y0 < y1, z0 < z1");
  EXPECT_EQ(riemann::DescribeSettingRange(dims), "three whole numbers, each from 1 to 512 (points)");

  EXPECT_EQ(riemann::CheckSettingValue(bounds, { -1, 1, -2, 2, 0, 0.5 }, "Bounds"), "");
  EXPECT_EQ(riemann::CheckSettingValue(bounds, { -1, 1, 2, -2, 0, 0.5 }, "Bounds"),
    "Bounds: the y range needs y0 < y1, got 2 >= -2");
  EXPECT_NE(riemann::CheckSettingValue(bounds, { -1, 1, -2, 2, 0 }, "Bounds"), "");
  EXPECT_NE(riemann::CheckSettingValue(bounds, { -1, 1, -2, 2, 0, "a" }, "Bounds"), "");

  EXPECT_EQ(riemann::CheckSettingValue(dims, { 1, 512, 33 }, "Dimensions"), "");
  EXPECT_NE(riemann::CheckSettingValue(dims, { 0, 3, 3 }, "Dimensions"), "");
  EXPECT_NE(riemann::CheckSettingValue(dims, { 3, 513, 3 }, "Dimensions"), "");
  EXPECT_NE(riemann::CheckSettingValue(dims, { 3, 3.5, 3 }, "Dimensions"), "");
  EXPECT_NE(riemann::CheckSettingValue(dims, { 3, 3 }, "Dimensions"), "");

  EXPECT_EQ(riemann::CheckSettingValue(direction, { 0, 0, 0 }, "StartDirection"),
    "StartDirection is the zero vector: a direction must not be zero");
  EXPECT_EQ(riemann::CheckSettingValue(direction, { 1e-200, 0, 0 }, "StartDirection"),
    "StartDirection is too short to normalise (scale it)");
  EXPECT_EQ(riemann::CheckSettingValue(direction, { 1e-100, 0, 0 }, "StartDirection"), "");

  // Typed text: the box's six numbers, the counts as whole numbers.
  std::string error;
  EXPECT_EQ(riemann::ParseSettingText(bounds, "-1,1,-2,2,0,0.5", error),
    nlohmann::json({ -1.0, 1.0, -2.0, 2.0, 0.0, 0.5 }));
  EXPECT_EQ(error, "");
  EXPECT_TRUE(riemann::ParseSettingText(bounds, "-1,1,-2,2", error).is_null());
  EXPECT_EQ(error, "expected six finite comma-separated numbers X0,X1,Y0,Y1,Z0,Z1");
  const nlohmann::json counts = riemann::ParseSettingText(dims, "9,8,7", error);
  EXPECT_EQ(error, "");
  ASSERT_TRUE(counts.is_array());
  EXPECT_TRUE(counts[0].is_number_integer());
  EXPECT_EQ(counts, nlohmann::json({ 9, 8, 7 }));
  EXPECT_EQ(riemann::SettingText(dims, counts), "9,8,7");

  // Python: one Set call with every number.
  const std::vector<std::string> lines = riemann::SettingPythonLines(
    Grid, "f", { { "Bounds", { -1, 1, -2, 2, 0, 0.5 } }, { "Dimensions", { 9, 8, 7 } } });
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "f.SetBounds(-1, 1, -2, 2, 0, 0.5)");
  EXPECT_EQ(lines[1], "f.SetDimensions(9, 8, 7)");
  EXPECT_STREQ(direction.ProjectAliases, "ConeAxis");
}
