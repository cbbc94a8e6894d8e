// vtkRiemannPictureSettings: the camera and picture settings, declared once
// (vtkRiemannPictureSettings.settings.json). A new object holds the
// declared defaults, which are the core camera's plain ones; the checks say
// what is wrong in the declaration's words; a vtkCamera takes and gives the
// observer; and no option of `riemann render` is declared twice.
#include "vtkRiemannPictureSettings.h"

#include "ObserverCamera.h"
#include "RiemannIntegrationSettingsDeclaration.h"
#include "RiemannPictureSettingsDeclaration.h"
#include "vtkRiemannPictureSettingsSettingAccess.h"

#include "vtkCamera.h"
#include "vtkNew.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>
#include <string>

namespace
{
namespace declared = riemann::declared::vtkRiemannPictureSettings;

void ExpectVector(const double* value, const riemann::Vec3& expected, const char* name)
{
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_EQ(value[i], expected[i]) << name << "[" << i << "]";
  }
}
} // namespace

TEST(PictureSettings, ANewObjectHoldsTheDeclaredDefaults)
{
  vtkNew<vtkRiemannPictureSettings> picture;
  EXPECT_EQ(riemann::settings::SettingValues(picture), riemann::DefaultValues(declared::Settings));
  EXPECT_EQ(picture->GetWidth(), 640);
  EXPECT_EQ(picture->GetHeight(), 480);
  EXPECT_EQ(picture->GetBackend(), vtkRiemannPictureSettings::GPU);
  EXPECT_EQ(picture->GetGPUPath(), vtkRiemannPictureSettings::GPU_PATH_AUTO);
  EXPECT_EQ(picture->CheckSettings(), "");
}

TEST(PictureSettings, TheCoreCameraHasTheDeclaredDefaults)
{
  // The core keeps plain defaults (no app strings); they must not part.
  vtkNew<vtkRiemannPictureSettings> picture;
  const riemann::CameraSettings core;
  ExpectVector(picture->GetPosition(), core.Position, "Position");
  ExpectVector(picture->GetLookAt(), core.LookAt, "LookAt");
  ExpectVector(picture->GetViewUp(), core.ViewUp, "ViewUp");
  EXPECT_EQ(picture->GetViewAngle(), core.ViewAngle);
  EXPECT_EQ(picture->GetProjection(), static_cast<int>(core.Mode));
  EXPECT_EQ(vtkRiemannPictureSettings::EQUIRECTANGULAR,
    static_cast<int>(riemann::Projection::Equirectangular));
}

TEST(PictureSettings, ChecksNameTheSettingAndItsRange)
{
  vtkNew<vtkRiemannPictureSettings> picture;
  picture->SetViewAngle(179.0);
  EXPECT_EQ(picture->CheckSettings(), "");
  picture->SetViewAngle(180.0);
  EXPECT_EQ(picture->CheckSettings(),
    "ViewAngle is 180: expected a number above 0 and at most 179 (degrees)");
  picture->SetViewAngle(std::nan(""));
  EXPECT_NE(picture->CheckSettings(), "");
  picture->SetViewAngle(60.0);

  picture->SetSamplesPerPixel(4097);
  EXPECT_EQ(picture->CheckSettings(), "SamplesPerPixel is 4097: expected a whole number from 1 to 4096");
  picture->SetSamplesPerPixel(1);
  picture->SetWidth(0);
  EXPECT_EQ(picture->CheckSettings(), "Width is 0: expected a whole number from 1 to 16384 (pixels)");
  picture->SetWidth(640);

  // A camera that defines no view.
  picture->SetViewUp(0, 0, 2);
  EXPECT_EQ(picture->CheckSettings(), "the view up is along the view direction");
  picture->SetViewUp(0, 0, 0);
  EXPECT_EQ(picture->CheckSettings(), "ViewUp is the zero vector: a direction must not be zero");
  picture->SetViewUp(0, 1, 0);
  picture->SetLookAt(0, 0, 5);
  EXPECT_EQ(picture->CheckSettings(), "the camera is at the point it looks at");
}

TEST(PictureSettings, ACameraTakesAndGivesTheObserver)
{
  vtkNew<vtkRiemannPictureSettings> picture;
  picture->SetPosition(1, 2, 3);
  picture->SetLookAt(0, 0, -1);
  picture->SetViewUp(0, 0, 1);
  picture->SetViewAngle(45);
  vtkNew<vtkCamera> camera;
  picture->ApplyTo(camera);
  EXPECT_EQ(camera->GetPosition()[1], 2.0);
  EXPECT_EQ(camera->GetFocalPoint()[2], -1.0);
  EXPECT_EQ(camera->GetViewAngle(), 45.0);

  vtkNew<vtkRiemannPictureSettings> back;
  back->SetFromCamera(camera);
  EXPECT_EQ(back->GetPosition()[0], 1.0);
  EXPECT_EQ(back->GetLookAt()[2], -1.0);
  EXPECT_EQ(back->GetViewAngle(), 45.0);
  // vtkCamera keeps its view up orthogonal to the view: this one already is.
  EXPECT_NEAR(back->GetViewUp()[2], 1.0, 1e-12);

  const riemann::CameraSettings core = back->GetCameraSettings();
  EXPECT_EQ(core.Position, riemann::Vec3(1, 2, 3));
  EXPECT_EQ(core.ViewAngle, 45.0);

  vtkNew<vtkRiemannPictureSettings> copy;
  copy->SetSamplesPerPixel(16);
  copy->SetProjection(vtkRiemannPictureSettings::EQUIRECTANGULAR);
  back->DeepCopy(copy);
  EXPECT_EQ(riemann::settings::SettingValues(back), riemann::settings::SettingValues(copy));
}

TEST(PictureSettings, NoOptionOfRenderIsDeclaredTwice)
{
  // `riemann render` takes the picture's and the integration's options: no
  // name (or old spelling) may be both, and every scene key is a camera's.
  std::set<std::string> names;
  const auto add = [&names](const riemann::SettingTable& table)
  {
    for (const riemann::SettingDeclaration& s : table)
    {
      std::stringstream list(riemann::CommandLineNames(s));
      for (std::string name; std::getline(list, name, ',');)
      {
        EXPECT_TRUE(names.insert(name).second) << name;
      }
    }
  };
  add(declared::Settings);
  add(riemann::declared::vtkRiemannIntegrationSettings::Settings);
  EXPECT_EQ(names.count("--camera-position"), 1u);
  EXPECT_EQ(names.count("--fov"), 1u);
  EXPECT_EQ(names.count("--samples"), 1u);
  std::set<std::string> scene;
  for (const riemann::SettingDeclaration& s : declared::Settings)
  {
    if (*s.SceneKey)
    {
      EXPECT_TRUE(scene.insert(s.SceneKey).second) << s.SceneKey;
    }
  }
  EXPECT_EQ(scene, (std::set<std::string>{ "position", "look_at", "view_up", "fov", "projection" }));
}

TEST(PictureSettings, TheCameraSettingsAreThoseACameraTakes)
{
  // IsCameraSetting names exactly the settings ApplyTo gives a vtkCamera:
  // changing any other leaves the camera as it was.
  for (const riemann::SettingDeclaration& s : declared::Settings)
  {
    vtkNew<vtkRiemannPictureSettings> picture;
    vtkNew<vtkCamera> before;
    picture->ApplyTo(before);
    nlohmann::json values = riemann::settings::SettingValues(picture);
    nlohmann::json& value = values[s.Name];
    if (value.is_array())
    {
      value[0] = value[0].get<double>() + 0.5;
    }
    else if (value.is_string())
    {
      value = riemann::ChoiceNames(s).back();
    }
    else
    {
      value = value.get<double>() + 1;
    }
    riemann::settings::ApplySettings(picture, values);
    vtkNew<vtkCamera> after;
    picture->ApplyTo(after);
    const bool cameraChanged = after->GetPosition()[0] != before->GetPosition()[0] ||
      after->GetFocalPoint()[0] != before->GetFocalPoint()[0] ||
      after->GetViewUp()[0] != before->GetViewUp()[0] ||
      after->GetViewAngle() != before->GetViewAngle();
    EXPECT_EQ(vtkRiemannPictureSettings::IsCameraSetting(s.Name), cameraChanged) << s.Name;
  }
}
