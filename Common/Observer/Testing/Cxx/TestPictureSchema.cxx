// The picture schema (PictureSchema.h) is the one description of the
// camera's and the picture's settings: its defaults are CameraSettings',
// its names unique on every surface, its checks say what is wrong in its
// words, and the integration schema writes its ranges the same way
// (SettingRange.h).
#include "RiemannIntegrationSettingsDeclaration.h"
#include "SettingValues.h"
#include "ObserverCamera.h"
#include "PictureSchema.h"

#include <Eigen/Geometry> // cross
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <string>

using namespace riemann;

TEST(PictureSchema, NamesAreUniqueOnEverySurface)
{
  std::set<std::string> core, property, scene, project, flag, label;
  const auto unique = [](std::set<std::string>& names, const char* name)
  {
    if (*name)
    {
      EXPECT_TRUE(names.insert(name).second) << name;
    }
  };
  for (const PictureSetting& s : PictureSchema)
  {
    unique(core, s.Core);
    unique(property, s.Property);
    unique(scene, s.SceneKey);
    unique(project, s.ProjectKey);
    unique(flag, s.Flag);
    unique(label, s.Label);
    EXPECT_EQ(std::string(s.Flag).rfind("--", 0), 0u) << s.Flag;
    EXPECT_GT(std::string(s.Help).size(), 10u) << s.Flag;
    // A scene's key names a camera setting: the scene holds no picture size.
    EXPECT_TRUE(!*s.SceneKey || *s.Core) << s.SceneKey;
  }
  // Every setting is an option of `riemann render`; the camera's five are a
  // scene's "camera" keys; no flag repeats an integration flag.
  EXPECT_EQ(flag.size(), PictureSchema.size());
  EXPECT_EQ(scene.size(), 5u);
  for (const SettingDeclaration& s : riemann::declared::vtkRiemannIntegrationSettings::Settings)
  {
    std::stringstream names(riemann::CommandLineNames(s));
    for (std::string name; std::getline(names, name, ',');)
    {
      EXPECT_EQ(flag.count(name), 0u) << name;
    }
  }
}

TEST(PictureSchema, CameraSettingsAreTheDefaults)
{
  const CameraSettings camera;
  const auto vector = [](PictureSettingId id)
  {
    const auto& v = PictureSettingOf(id).Default;
    return Vec3(v[0], v[1], v[2]);
  };
  EXPECT_EQ(camera.Position, vector(PictureSettingId::Position));
  EXPECT_EQ(camera.LookAt, vector(PictureSettingId::LookAt));
  EXPECT_EQ(camera.ViewUp, vector(PictureSettingId::ViewUp));
  EXPECT_EQ(camera.ViewAngle, PictureSettingOf(PictureSettingId::ViewAngle).Default[0]);
  EXPECT_EQ(camera.Mode, Projection::Perspective);
  // The values SceneFormat.md's camera table states.
  EXPECT_EQ(camera.Position, Vec3(0, 0, 5));
  EXPECT_EQ(camera.ViewAngle, 60.0);
  // The default camera defines a view.
  EXPECT_GT((camera.LookAt - camera.Position).cross(camera.ViewUp).norm(), 0.0);
}

TEST(PictureSchema, DefaultsAreValid)
{
  for (const PictureSetting& s : PictureSchema)
  {
    switch (s.Type)
    {
      case PictureSetting::Point:
      case PictureSetting::Direction:
        EXPECT_EQ(CheckPictureVector(s, s.Default.data(), s.Flag), "") << s.Flag;
        break;
      case PictureSetting::Choice:
        EXPECT_EQ(PictureChoiceIndex(s, PictureDefaultChoice(s)), static_cast<int>(s.Default[0]))
          << s.Flag;
        EXPECT_GE(PictureChoices(s).size(), 2u) << s.Flag;
        break;
      default:
        EXPECT_EQ(CheckPictureValue(s, s.Default[0], s.Flag), "") << s.Flag;
        break;
    }
  }
}

TEST(PictureSchema, ChecksNameTheSettingAndItsRange)
{
  const PictureSetting& angle = PictureSettingOf(PictureSettingId::ViewAngle);
  // vtkCamera clamps above 179 degrees: the schema refuses, never clamps.
  EXPECT_EQ(CheckPictureValue(angle, 179.0, "--fov"), "");
  EXPECT_EQ(CheckPictureValue(angle, 179.5, "--fov"),
    "--fov is 179.5: expected a number above 0 and at most 179 (degrees)");
  EXPECT_NE(CheckPictureValue(angle, 0.0, "--fov"), "");
  EXPECT_NE(CheckPictureValue(angle, std::nan(""), "--fov"), "");
  EXPECT_EQ(PictureInterval(angle), "(0, 179]");

  const PictureSetting& samples = PictureSettingOf(PictureSettingId::Samples);
  EXPECT_EQ(CheckPictureValue(samples, 4096, "s"), "");
  EXPECT_NE(CheckPictureValue(samples, 4097, "s"), "");
  EXPECT_NE(CheckPictureValue(samples, 2.5, "s"), "");
  EXPECT_EQ(DescribePictureValues(samples), "a whole number from 1 to 4096");

  const PictureSetting& up = PictureSettingOf(PictureSettingId::ViewUp);
  const double zero[3] = { 0, 0, 0 };
  const double nan[3] = { 0, std::nan(""), 1 };
  const double fine[3] = { 0, 0, 2 };
  EXPECT_EQ(CheckPictureVector(up, zero, "view_up"),
    "view_up is 0,0,0: expected three finite comma-separated numbers X,Y,Z, not all 0");
  EXPECT_NE(CheckPictureVector(up, nan, "view_up"), "");
  EXPECT_EQ(CheckPictureVector(up, fine, "view_up"), "");
  // A point may be the origin, not a NaN.
  const PictureSetting& position = PictureSettingOf(PictureSettingId::Position);
  EXPECT_EQ(CheckPictureVector(position, zero, "p"), "");
  EXPECT_NE(CheckPictureVector(position, nan, "p"), "");

  const PictureSetting& projection = PictureSettingOf(PictureSettingId::Projection);
  EXPECT_EQ(PictureChoiceIndex(projection, "equirectangular"),
    static_cast<int>(Projection::Equirectangular));
  EXPECT_EQ(PictureChoiceIndex(projection, "fisheye"), -1);
  EXPECT_EQ(DescribePictureValues(projection), "perspective or equirectangular");
  EXPECT_EQ(DescribePictureValues(PictureSettingOf(PictureSettingId::GPUPath)),
    "auto, fragment or compute");
}

TEST(PictureSchema, PictureAndDeclaredSettingsWriteRangesAlike)
{
  // One sentence for a range, whether a schema or a declaration gives it.
  const SettingRange range{ 0.0, true, 1e9, false, "arc length" };
  const SettingDeclaration& length =
    *riemann::declared::vtkRiemannIntegrationSettings::Settings.Find("MaximumPropagation");
  EXPECT_EQ(riemann::DescribeSettingRange(length), DescribeSettingRange(range));
  EXPECT_EQ(riemann::CheckSettingValue(length, -1, "x"), CheckSettingValue(range, -1, "x"));
}
