// vtkRiemannCameraPath's declared settings (vtkRiemannCameraPath.settings.json):
// a new filter holds the declared defaults, and its first frame is the
// inside view's own default camera (vtkRiemannPictureSettings's, whose
// settings the camera path's declaration takes with "like"), so a flight
// that nobody placed starts where the inside view looks from.
#include "RiemannCameraPathDeclaration.h"
#include "vtkRiemannCameraPath.h"
#include "vtkRiemannCameraPathSettingAccess.h"
#include "vtkRiemannPictureSettings.h"

#include "vtkNew.h"

#include <gtest/gtest.h>

namespace
{
namespace declared = riemann::declared::vtkRiemannCameraPath;

void ExpectSameVector(const double* value, const double* expected, const char* name)
{
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_EQ(value[i], expected[i]) << name << "[" << i << "]";
  }
}
} // namespace

TEST(CameraPath, ANewFilterHoldsTheDeclaredDefaults)
{
  vtkNew<vtkRiemannCameraPath> path;
  const nlohmann::json values = riemann::settings::SettingValues(path);
  EXPECT_EQ(values, riemann::DefaultValues(declared::Settings));
  EXPECT_EQ(path->GetPathType(), vtkRiemannCameraPath::GEODESIC);
  EXPECT_EQ(path->GetLength(), declared::Default::Length);
  EXPECT_EQ(path->GetNumberOfFrames(), declared::Default::NumberOfFrames);
  EXPECT_EQ(path->GetStep(), declared::Default::Step);
}

TEST(CameraPath, TheFirstFrameIsTheInsideViewsDefaultCamera)
{
  vtkNew<vtkRiemannCameraPath> path;
  vtkNew<vtkRiemannPictureSettings> picture;
  ExpectSameVector(path->GetPosition(), picture->GetPosition(), "Position");
  ExpectSameVector(path->GetLookAt(), picture->GetLookAt(), "LookAt");
  ExpectSameVector(path->GetViewUp(), picture->GetViewUp(), "ViewUp");
}

TEST(CameraPath, DeclaredValuesSetTheFilterAndReadBack)
{
  vtkNew<vtkRiemannCameraPath> path;
  const nlohmann::json values = { { "PathType", "spline" }, { "Position", { 1.0, 2.0, 3.0 } },
    { "Length", 2.5 }, { "NumberOfFrames", 7 }, { "Step", 0.01 } };
  for (auto item = values.begin(); item != values.end(); ++item)
  {
    EXPECT_EQ(riemann::CheckSettingValue(*declared::Settings.Find(item.key()), item.value(), item.key()), "");
  }
  riemann::settings::ApplySettings(path, values);
  EXPECT_EQ(path->GetPathType(), vtkRiemannCameraPath::SPLINE);
  EXPECT_EQ(path->GetPosition()[2], 3.0);
  EXPECT_EQ(path->GetLength(), 2.5);
  EXPECT_EQ(path->GetNumberOfFrames(), 7);
  const nlohmann::json back = riemann::settings::SettingValues(path);
  for (auto item = values.begin(); item != values.end(); ++item)
  {
    EXPECT_EQ(back.at(item.key()), item.value()) << item.key();
  }
  // Outside the declared range: refused with the range's words.
  EXPECT_EQ(riemann::CheckSettingValue(*declared::Settings.Find("Length"), 0.0, "Length"),
    "Length is 0: expected a number above 0 and at most 1e+06 (arc length)");
}
