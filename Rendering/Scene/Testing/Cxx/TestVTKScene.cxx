// vtkRiemannScene: the VTK handle on a riemann::Scene (no rendering).
#include "vtkRiemannScene.h"

#include "RiemannScene.h"

#include "vtkCamera.h"
#include "vtkNew.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace
{
std::filesystem::path DataDirectory()
{
  const char* dir = std::getenv("RIEMANN_DATA_DIR");
  return dir && *dir
    ? std::filesystem::path(dir)
    : std::filesystem::path(RIEMANN_TEST_DATA_DIR);
}
}

TEST(VTKScene, DefaultUntilDefined)
{
  vtkNew<vtkRiemannScene> scene;
  EXPECT_FALSE(scene->HasDefinition());
  EXPECT_STREQ(scene->GetDefinition(), "");
  // Without a definition: the default scene (the paper's grid).
  const riemann::Scene defaults = riemann::DefaultScene();
  EXPECT_EQ(scene->GetNumberOfObjects(), static_cast<int>(defaults.Objects.size()));
  EXPECT_EQ(scene->GetScene().Objects.size(), defaults.Objects.size());
  EXPECT_EQ(scene->HasCamera(), defaults.HasCamera);
  ASSERT_TRUE(scene->GetSceneSnapshot());
}

TEST(VTKScene, BadInputKeepsTheScene)
{
  vtkNew<vtkRiemannScene> scene;
  const char* json = R"({"objects": [{"type": "sphere", "center": [1, 2, 3], "radius": 0.5}]})";
  ASSERT_TRUE(scene->SetDefinition(json)) << scene->GetLastError();
  EXPECT_TRUE(scene->HasDefinition());
  EXPECT_STREQ(scene->GetLastError(), "");
  EXPECT_EQ(scene->GetNumberOfObjects(), 1);
  const vtkMTimeType time = scene->GetMTime();

  EXPECT_FALSE(scene->SetDefinition(R"({"objects": [{"type": "sphere", "radius": -1}]})"));
  EXPECT_NE(std::string(scene->GetLastError()).find("scene.objects[0]"), std::string::npos)
    << scene->GetLastError();
  EXPECT_FALSE(scene->SetDefinition(nullptr));
  EXPECT_FALSE(scene->SetDefinitionFile("/no/such/scene.json"));
  EXPECT_NE(std::string(scene->GetLastError()).find("/no/such/scene.json"), std::string::npos);
  // The last good scene is still there, untouched.
  EXPECT_EQ(scene->GetNumberOfObjects(), 1);
  EXPECT_STREQ(scene->GetDefinition(), json);
  EXPECT_EQ(scene->GetScene().Objects[0].A, riemann::Vec3(1, 2, 3));
  EXPECT_EQ(scene->GetMTime(), time);
}

TEST(VTKScene, FileWithMetricAndCamera)
{
  const std::filesystem::path file = DataDirectory() / "scenes" / "paper-one-bump.json";
  vtkNew<vtkRiemannScene> scene;
  ASSERT_TRUE(scene->SetDefinitionFile(file.string().c_str())) << scene->GetLastError();
  EXPECT_EQ(scene->GetDefinitionFile(), file.string());
  EXPECT_NE(std::string(scene->GetDefinition()).find("\"objects\""), std::string::npos);
  // The metric named relative to the scene file was read.
  ASSERT_TRUE(scene->HasMetricDefinition());
  EXPECT_NE(scene->GetMetricDefinition().find("gaussians"), std::string::npos);

  ASSERT_TRUE(scene->HasCamera());
  vtkNew<vtkCamera> camera;
  camera->SetUseHorizontalViewAngle(true);
  ASSERT_TRUE(scene->ApplyCamera(camera));
  const riemann::CameraSettings& c = scene->GetScene().Camera;
  EXPECT_DOUBLE_EQ(camera->GetPosition()[0], c.Position.x());
  EXPECT_DOUBLE_EQ(camera->GetFocalPoint()[2], c.LookAt.z());
  EXPECT_DOUBLE_EQ(camera->GetViewAngle(), c.ViewAngle);
  EXPECT_FALSE(camera->GetUseHorizontalViewAngle());
  EXPECT_FALSE(scene->ApplyCamera(nullptr));

  vtkNew<vtkRiemannScene> noCamera;
  ASSERT_TRUE(noCamera->SetDefinition(R"({"objects": []})"));
  EXPECT_FALSE(noCamera->HasCamera());
  EXPECT_FALSE(noCamera->ApplyCamera(camera));
}

TEST(VTKScene, ShallowCopySharesTheParsedScene)
{
  vtkNew<vtkRiemannScene> scene;
  const char* json = R"({"objects": [{"type": "sphere", "center": [1, 2, 3], "radius": 0.5}]})";
  ASSERT_TRUE(scene->SetDefinition(json)) << scene->GetLastError();
  vtkNew<vtkRiemannScene> copy;
  copy->ShallowCopy(scene);
  EXPECT_STREQ(copy->GetDefinition(), json);
  EXPECT_EQ(&copy->GetScene(), &scene->GetScene()); // shared, not parsed again
  // Redefining the original leaves the copy's scene alone (what a job on
  // another thread relies on).
  ASSERT_TRUE(scene->SetDefinition(R"({"objects": []})")) << scene->GetLastError();
  EXPECT_EQ(copy->GetNumberOfObjects(), 1);
  EXPECT_EQ(copy->GetScene().Objects[0].A, riemann::Vec3(1, 2, 3));
  // A copy of an undefined scene is the default scene again.
  vtkNew<vtkRiemannScene> undefined;
  copy->ShallowCopy(undefined);
  EXPECT_FALSE(copy->HasDefinition());
  EXPECT_EQ(copy->GetNumberOfObjects(), undefined->GetNumberOfObjects());
}
