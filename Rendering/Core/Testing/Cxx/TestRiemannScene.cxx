// The scene of the inside view: every scene file parses, every bad input is
// refused with a message naming its JSON path, and the segment intersection
// (the reference the GLSL mirrors) agrees with exact answers and with a
// brute-force sampling of the grid of bars.
#include "RiemannIntegrationSettingsDeclaration.h"
#include "RiemannScene.h"
#include "RiemannSceneParser.h"
#include "RiemannSceneIntersection.h"
#include "RiemannShading.h"

#include "TestDataDirectory.h"

#include <Eigen/Geometry> // cross
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace riemann
{
namespace
{
namespace fs = std::filesystem;

using riemann::testing::DataDirectory;

fs::path ScratchDirectory()
{
  fs::path dir;
  if (const char* out = std::getenv("RIEMANN_TEST_OUTPUT_DIR"))
  {
    dir = fs::path(out);
  }
  else
  {
    dir = fs::temp_directory_path();
  }
  dir /= "TestRiemannScene";
  fs::create_directories(dir);
  return dir;
}


/// The message ParseScene throws for `json` ("" if it parses).
std::string ErrorOf(const std::string& json, const std::string& base = ".")
{
  try
  {
    ParseScene(json, base);
  }
  catch (const SceneDefinitionError& e)
  {
    return e.what();
  }
  return "";
}

Scene OneObject(const SceneObject& object)
{
  Scene scene;
  scene.Objects.push_back(object);
  return scene;
}

SceneObject Sphere(const Vec3& center, double radius)
{
  SceneObject o;
  o.Type = ObjectType::Sphere;
  o.A = center;
  o.Radius = radius;
  return o;
}

SceneObject Box(const Vec3& lo, const Vec3& hi)
{
  SceneObject o;
  o.Type = ObjectType::Box;
  o.A = lo;
  o.B = hi;
  return o;
}

SceneObject Plane(const Vec3& point, const Vec3& normal)
{
  SceneObject o;
  o.Type = ObjectType::Plane;
  o.A = point;
  o.B = normal.normalized();
  return o;
}

SceneObject Grid(double spacing, double thickness, std::initializer_list<double> extent)
{
  SceneObject o;
  o.Type = ObjectType::Grid;
  o.Spacing = spacing;
  o.Thickness = thickness;
  std::copy(extent.begin(), extent.end(), o.Extent);
  return o;
}

void ExpectVec(const Vec3& actual, const Vec3& expected, double tolerance = 1e-12)
{
  EXPECT_LE((actual - expected).norm(), tolerance)
    << "actual " << actual.transpose() << ", expected " << expected.transpose();
}

/// Independent point-in-grid test (RiemannScene.h's definition), with the
/// bars grown by `grow` (negative shrinks): for each bar axis k the point must
/// be within h of a lattice line inside the extent in both other axes, and
/// within the extent grown by h along k.
bool InGrid(const SceneObject& g, const Vec3& p, double grow = 0)
{
  const double s = g.Spacing;
  const double h = 0.5 * g.Thickness + grow;
  for (int k = 0; k < 3; ++k)
  {
    if (p[k] < g.Extent[2 * k] - h || p[k] > g.Extent[2 * k + 1] + h)
    {
      continue;
    }
    bool inBar = true;
    for (int u : { (k + 1) % 3, (k + 2) % 3 })
    {
      const double line = s * std::round(p[u] / s);
      const bool lineInExtent =
        line >= g.Extent[2 * u] - 1e-9 * s && line <= g.Extent[2 * u + 1] + 1e-9 * s;
      inBar = inBar && lineInExtent && std::abs(p[u] - line) <= h;
    }
    if (inBar)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
// Parsing
//------------------------------------------------------------------------------
/// The scenes of the paper's figures and the showcase (Data/scenes).
const char* const ShippedScenes[] = { "paper-grid", "paper-one-bump", "paper-two-bumps",
  "paper-saddle-along-x", "paper-saddle-along-z", "paper-twist", "showcase-lens" };

TEST(Scene, ParsesEverySceneFile)
{
  const fs::path dir = DataDirectory() / "scenes";
  ASSERT_TRUE(fs::is_directory(dir)) << dir;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir))
  {
    if (entry.path().extension() == ".json")
    {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  EXPECT_GE(files.size(), std::size(ShippedScenes));
  for (const fs::path& file : files)
  {
    SCOPED_TRACE(file.string());
    Scene scene;
    ASSERT_NO_THROW(scene = LoadSceneFile(file.string()));
    // The observer must not sit inside an object: the whole picture would be
    // that object.
    SceneHit hit;
    const Vec3 eye = scene.Camera.Position;
    if (scene.HasCamera && IntersectSegment(scene, eye, eye, hit))
    {
      ADD_FAILURE() << "the camera is inside object " << hit.Object;
    }
  }
}

TEST(Scene, ShippedScenesShowSomething)
{
  const fs::path dir = DataDirectory() / "scenes";
  for (const char* name : ShippedScenes)
  {
    SCOPED_TRACE(name);
    const Scene scene = LoadSceneFile((dir / (std::string(name) + ".json")).string());
    EXPECT_FALSE(scene.MetricDefinition.empty());
    ASSERT_TRUE(scene.HasCamera);
    // Most straight rays of the view (Euclidean; the metric bends them) meet
    // something.
    const Vec3 eye = scene.Camera.Position;
    const Vec3 forward = (scene.Camera.LookAt - eye).normalized();
    const Vec3 right = forward.cross(scene.Camera.ViewUp).normalized();
    const Vec3 up = right.cross(forward);
    const double spread = std::tan(0.5 * scene.Camera.ViewAngle * std::acos(-1.0) / 180);
    int seen = 0;
    for (int i = -4; i <= 4; ++i)
    {
      for (int j = -4; j <= 4; ++j)
      {
        const Vec3 ray = forward + spread * (0.25 * i * right + 0.25 * j * up);
        SceneHit hit;
        seen += IntersectSegment(scene, eye, eye + 100 * ray.normalized(), hit);
      }
    }
    EXPECT_GT(seen, 40) << "of 81 straight rays in view";
  }
}

TEST(Scene, PaperScenesShowTheGridFromInside)
{
  const fs::path dir = DataDirectory() / "scenes";
  for (const char* name : { "paper-grid", "paper-one-bump", "paper-two-bumps",
         "paper-saddle-along-x", "paper-saddle-along-z", "paper-twist" })
  {
    SCOPED_TRACE(name);
    const Scene scene = LoadSceneFile((dir / (std::string(name) + ".json")).string());
    ASSERT_EQ(scene.Objects.size(), 1u);
    const SceneObject& grid = scene.Objects[0];
    EXPECT_EQ(grid.Type, ObjectType::Grid);
    EXPECT_EQ(grid.Surface.Type, MaterialType::Position);
    EXPECT_LT(grid.Thickness, 0.1 * grid.Spacing);
    for (int axis = 0; axis < 3; ++axis)
    {
      EXPECT_GT(scene.Camera.Position[axis], grid.Extent[2 * axis]);
      EXPECT_LT(scene.Camera.Position[axis], grid.Extent[2 * axis + 1]);
    }
  }
  const Scene alongX = LoadSceneFile((dir / "paper-saddle-along-x.json").string());
  const Vec3 viewX = alongX.Camera.LookAt - alongX.Camera.Position;
  EXPECT_GT(std::abs(viewX.x()), 0.9 * viewX.norm());
  const Scene alongZ = LoadSceneFile((dir / "paper-saddle-along-z.json").string());
  const Vec3 viewZ = alongZ.Camera.LookAt - alongZ.Camera.Position;
  EXPECT_GT(std::abs(viewZ.z()), 0.9 * viewZ.norm());
  EXPECT_NE(alongX.MetricDefinition.find("quadratic"), std::string::npos);
}

TEST(Scene, ParsesEveryKey)
{
  const fs::path scratch = ScratchDirectory();
  riemann::testing::WriteTestFile(scratch / "sky.hdr", "not really an image; only its existence is checked");
  const std::string json = R"({
    "name": "everything", "description": "every key of the format",
    "metric": {"type": "graph", "gaussians": [{"amplitude": 1, "center": [0,0,0], "sigma": 0.5}]},
    "camera": {"position": [1,2,3], "look_at": [0,0,-1], "view_up": [0,0,1], "fov": 45,
               "projection": "equirectangular"},
    "integrator": {"method": "adaptive", "step": 0.05, "max_steps": 123, "max_length": 12.5,
                   "tolerance": 1e-6},
    "background": {"environment": "sky.hdr"},
    "fog": {"color": [0.1, 0.2, 0.3], "density": 0.25},
    "lighting": "observer",
    "objects": [
      {"type": "grid", "spacing": 0.5, "thickness": 0.1, "extent": [-1,1,-2,2,0,0],
       "material": {"type": "position", "bounds": [0,1,0,2,0,3]}, "name": "lattice"},
      {"type": "sphere", "center": [1,2,3], "radius": 0.5, "material": {"type": "solid", "color": [1,0,0]}},
      {"type": "plane", "point": [0,-2,0], "normal": [0,3,4],
       "material": {"type": "checker", "color": [1,1,1], "color2": [0,0,0], "size": 0.25}},
      {"type": "box", "min": [-1,-1,-1], "max": [1,2,3]}
    ]})";
  const Scene scene = ParseScene(json, scratch.string());
  EXPECT_NE(scene.MetricDefinition.find("gaussians"), std::string::npos);
  ASSERT_TRUE(scene.HasCamera);
  ExpectVec(scene.Camera.Position, Vec3(1, 2, 3));
  ExpectVec(scene.Camera.LookAt, Vec3(0, 0, -1));
  ExpectVec(scene.Camera.ViewUp, Vec3(0, 0, 1));
  EXPECT_EQ(scene.Camera.ViewAngle, 45);
  EXPECT_EQ(scene.Camera.Mode, Projection::Equirectangular);
  EXPECT_EQ(scene.Rays.Integrator, IntegratorType::DormandPrince45);
  EXPECT_EQ(scene.Rays.Step, 0.05);
  EXPECT_EQ(scene.Rays.MaximumSteps, 123);
  EXPECT_EQ(scene.Rays.MaximumLength, 12.5);
  EXPECT_EQ(scene.Rays.Tolerance, 1e-6);
  EXPECT_TRUE(fs::path(scene.EnvironmentImage).is_absolute());
  EXPECT_TRUE(fs::equivalent(scene.EnvironmentImage, scratch / "sky.hdr"));
  ExpectVec(scene.FogColor, Vec3(0.1, 0.2, 0.3));
  EXPECT_EQ(scene.FogDensity, 0.25);
  EXPECT_TRUE(scene.ObserverLight);
  ASSERT_EQ(scene.Objects.size(), 4u);

  const SceneObject& grid = scene.Objects[0];
  EXPECT_EQ(grid.Type, ObjectType::Grid);
  EXPECT_EQ(grid.Spacing, 0.5);
  EXPECT_EQ(grid.Thickness, 0.1);
  const double extent[6] = { -1, 1, -2, 2, 0, 0 };
  const double bounds[6] = { 0, 1, 0, 2, 0, 3 };
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_EQ(grid.Extent[i], extent[i]);
    EXPECT_EQ(grid.Surface.Bounds[i], bounds[i]);
  }
  const SceneObject& sphere = scene.Objects[1];
  EXPECT_EQ(sphere.Type, ObjectType::Sphere);
  ExpectVec(sphere.A, Vec3(1, 2, 3));
  EXPECT_EQ(sphere.Radius, 0.5);
  EXPECT_EQ(sphere.Surface.Type, MaterialType::Solid);
  ExpectVec(sphere.Surface.Color, Vec3(1, 0, 0));
  const SceneObject& plane = scene.Objects[2];
  EXPECT_EQ(plane.Type, ObjectType::Plane);
  ExpectVec(plane.B, Vec3(0, 0.6, 0.8)); // normalised
  EXPECT_EQ(plane.Surface.Type, MaterialType::Checker);
  EXPECT_EQ(plane.Surface.Size, 0.25);
  ExpectVec(plane.Surface.Color2, Vec3::Zero());
  const SceneObject& box = scene.Objects[3];
  EXPECT_EQ(box.Type, ObjectType::Box);
  ExpectVec(box.A, Vec3(-1, -1, -1));
  ExpectVec(box.B, Vec3(1, 2, 3));
  // Default material: position over the object's own extent.
  EXPECT_EQ(box.Surface.Type, MaterialType::Position);
  const double boxBounds[6] = { -1, 1, -1, 2, -1, 3 };
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_EQ(box.Surface.Bounds[i], boxBounds[i]);
  }
}

TEST(Scene, DefaultsAndDefaultBounds)
{
  const Scene empty = ParseScene("{}");
  EXPECT_TRUE(empty.Objects.empty());
  EXPECT_FALSE(empty.HasCamera);
  EXPECT_TRUE(empty.MetricDefinition.empty());
  EXPECT_TRUE(empty.EnvironmentImage.empty());
  EXPECT_EQ(empty.Rays.Integrator, IntegratorType::RungeKutta4);
  EXPECT_EQ(empty.FogDensity, 0.0);
  EXPECT_FALSE(empty.ObserverLight);

  const Scene scene = ParseScene(R"({"objects": [
      {"type": "grid"},
      {"type": "sphere", "center": [1,2,3], "radius": 0.5},
      {"type": "plane", "point": [0,0,0], "normal": [0,0,1]},
      {"type": "grid", "extent": [-2,2,-2,2,0,0], "material": {"type": "position"}}],
    "background": [0, 0.5, 1], "lighting": "none",
    "integrator": {"method": "euler"}})");
  const SceneObject& grid = scene.Objects[0];
  EXPECT_EQ(grid.Spacing, 1.0);
  EXPECT_EQ(grid.Thickness, 0.06);
  const double paper[6] = { -4, 4, -4, 4, -4, 4 };
  const double sphereBounds[6] = { 0.5, 1.5, 1.5, 2.5, 2.5, 3.5 };
  const double planeBounds[6] = { -5, 5, -5, 5, -5, 5 };
  const double flatBounds[6] = { -2, 2, -2, 2, -1, 1 }; // a flat axis widened to +-1
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_EQ(grid.Extent[i], paper[i]);
    EXPECT_EQ(grid.Surface.Bounds[i], paper[i]);
    EXPECT_EQ(scene.Objects[1].Surface.Bounds[i], sphereBounds[i]);
    EXPECT_EQ(scene.Objects[2].Surface.Bounds[i], planeBounds[i]);
    EXPECT_EQ(scene.Objects[3].Surface.Bounds[i], flatBounds[i]);
  }
  ExpectVec(scene.Background, Vec3(0, 0.5, 1));
  EXPECT_FALSE(scene.ObserverLight);
  EXPECT_EQ(scene.Rays.Integrator, IntegratorType::Euler);
}

TEST(Scene, DefaultScene)
{
  const Scene scene = DefaultScene();
  ASSERT_EQ(scene.Objects.size(), 1u);
  const SceneObject& grid = scene.Objects[0];
  EXPECT_EQ(grid.Type, ObjectType::Grid);
  EXPECT_EQ(grid.Spacing, 1.0);
  EXPECT_EQ(grid.Thickness, 0.06);
  EXPECT_EQ(grid.Surface.Type, MaterialType::Position);
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_EQ(grid.Extent[i], i % 2 ? 4 : -4);
    EXPECT_EQ(grid.Surface.Bounds[i], i % 2 ? 4 : -4);
  }
  EXPECT_TRUE(scene.HasCamera);
  ExpectVec(scene.Camera.Position, Vec3(0, 0, 7.5));
  ExpectVec(scene.Camera.LookAt, Vec3::Zero());
  ExpectVec(scene.Camera.ViewUp, Vec3(0, 1, 0));
  EXPECT_EQ(scene.Camera.ViewAngle, 60);
  EXPECT_EQ(scene.Camera.Mode, Projection::Perspective);
  EXPECT_EQ(scene.Rays.Integrator, IntegratorType::RungeKutta4);
  EXPECT_EQ(scene.Rays.Step, 0.02);
  EXPECT_EQ(scene.Rays.MaximumSteps, 800);
  EXPECT_EQ(scene.Rays.MaximumLength, 30);
  EXPECT_LT(scene.Background.maxCoeff(), 0.2);
  EXPECT_EQ(scene.FogDensity, 0.02);
  ExpectVec(scene.FogColor, Vec3::Zero());
  EXPECT_FALSE(scene.ObserverLight);
  EXPECT_TRUE(scene.MetricDefinition.empty());
  EXPECT_TRUE(scene.EnvironmentImage.empty());
}

TEST(Scene, MetricByFileOrInline)
{
  const fs::path scenes = DataDirectory() / "scenes";
  const Scene byFile = ParseScene(R"({"metric": "../metrics/twist.json"})", scenes.string());
  EXPECT_NE(byFile.MetricDefinition.find("twist"), std::string::npos);
  const Scene inlined = ParseScene(R"({"metric": {"type": "euclidean"}})");
  EXPECT_NE(inlined.MetricDefinition.find("euclidean"), std::string::npos);

  std::string error = ErrorOf(R"({"metric": "../metrics/no-such.json"})", scenes.string());
  EXPECT_NE(error.find("scene.metric: metric file \"../metrics/no-such.json\" not found"),
    std::string::npos)
    << error;
  error = ErrorOf(R"({"metric": {"type": "graph", "gaussians": [{"amplitude": 1,
    "center": [0,0,0], "sigma": -1}]}})");
  EXPECT_NE(error.find("scene.metric: metric.gaussians[0].sigma"), std::string::npos) << error;
  error = ErrorOf(R"({"metric": 3})");
  EXPECT_NE(
    error.find("scene.metric: expected a metric file name or a metric object"), std::string::npos)
    << error;
}

TEST(Scene, LoadSceneFileNamesTheFile)
{
  const fs::path scratch = ScratchDirectory();
  const fs::path bad = scratch / "bad-scene.json";
  riemann::testing::WriteTestFile(bad, R"({"objects": [{"type": "sphere", "center": [0,0,0], "radius": 0}]})");
  try
  {
    LoadSceneFile(bad.string());
    ADD_FAILURE() << "no error";
  }
  catch (const SceneDefinitionError& e)
  {
    EXPECT_EQ(std::string(e.what()),
      bad.string() + ": scene.objects[0].radius: expected a positive number, got 0");
  }
  const fs::path missing = scratch / "no-such-scene.json";
  try
  {
    LoadSceneFile(missing.string());
    ADD_FAILURE() << "no error";
  }
  catch (const SceneDefinitionError& e)
  {
    EXPECT_EQ(std::string(e.what()), missing.string() + ": the scene file does not exist");
  }
  // Relative names resolve against the scene file's folder.
  fs::create_directories(scratch / "sub");
  riemann::testing::WriteTestFile(scratch / "sub" / "metric.json", R"({"type": "diffeo", "preset": "twist"})");
  riemann::testing::WriteTestFile(scratch / "sub" / "scene.json", R"({"metric": "metric.json"})");
  EXPECT_NE(LoadSceneFile((scratch / "sub" / "scene.json").string()).MetricDefinition.find("twist"),
    std::string::npos);
}

TEST(Scene, RefusesBadInput)
{
  std::string many;
  for (int i = 0; i <= MaximumSpheres; ++i)
  {
    many += std::string(i ? "," : "") + R"({"type": "sphere", "center": [0,0,0], "radius": 1})";
  }
  std::string planes;
  for (int i = 0; i <= MaximumPlanes; ++i)
  {
    planes +=
      std::string(i ? "," : "") + R"({"type": "plane", "point": [0,0,0], "normal": [0,0,1]})";
  }
  std::string boxes;
  for (int i = 0; i <= MaximumBoxes; ++i)
  {
    boxes += std::string(i ? "," : "") + R"({"type": "box", "min": [0,0,0], "max": [1,1,1]})";
  }
  std::string grids;
  for (int i = 0; i <= MaximumGrids; ++i)
  {
    grids += std::string(i ? "," : "") + R"({"type": "grid"})";
  }
  const std::pair<std::string, std::string> cases[] = {
    // Syntax and top level.
    { R"({"objects": [)", "scene: invalid JSON" },
    // nlohmann::json throws out_of_range, not parse_error, for this one.
    { R"({"fog": {"density": 1e400}})", "scene: invalid JSON" },
    { R"([1, 2])", "scene: expected a JSON object, got an array of 2" },
    { R"({"objets": []})", "scene: unknown key \"objets\"; expected one of \"metric\"" },
    { R"({"name": 3})", "scene.name: expected a string, got 3" },
    // Camera.
    { R"({"camera": {"position": [0,0,1], "look_at": [0,0,1]}})",
      "scene.camera: position and look_at are the same point" },
    // The declared range and words (vtkRiemannPictureSettings.settings.json), as `riemann render --fov` says them.
    { R"({"camera": {"fov": 0}})",
      "scene.camera.fov: expected a number above 0 and at most 179 (degrees), got 0" },
    { R"({"camera": {"fov": 179.5}})", "scene.camera.fov: expected a number above 0 and at most 179" },
    { R"({"camera": {"fov": "wide"}})",
      "scene.camera.fov: expected a number above 0 and at most 179 (degrees), got the string" },
    { R"({"camera": {"position": [0,0]}})",
      "scene.camera.position: expected an array of 3 numbers, got an array of 2" },
    { R"({"camera": {"position": [0,0,"z"]}})", "scene.camera.position[2]: expected a number" },
    { R"({"camera": {"projection": "fisheye"}})",
      "scene.camera.projection: expected one of perspective, equirectangular, got the string \"fisheye\"" },
    { R"({"camera": {"view_up": [0,0,0]}})", "scene.camera.view_up: expected three numbers, not all zero, got [0,0,0]" },
    { R"({"camera": {"view_up": [0,0,-2]}})",
      "scene.camera.view_up: parallel to the view direction" },
    { R"({"camera": {"lookat": [0,0,0]}})", "scene.camera: unknown key \"lookat\"" },
    { R"({"camera": [0,0,5]})", "scene.camera: expected an object, got an array of 3" },
    // Integrator.
    // Integrator: the declared ranges (vtkRiemannIntegrationSettings.settings.json).
    { R"({"integrator": {"method": "rk45"}})", "scene.integrator.method: unknown method \"rk45\"" },
    { R"({"integrator": {"step": 0}})",
      "scene.integrator.step: expected a number from 1e-09 to 1e+06 (arc length), got 0" },
    { R"({"integrator": {"step": -0.1}})", "scene.integrator.step: expected a number from 1e-09" },
    { R"({"integrator": {"step": "big"}})", "scene.integrator.step: expected a number from 1e-09" },
    { R"({"integrator": {"max_steps": 0}})",
      "scene.integrator.max_steps: expected a whole number from 1 to 1e+09 (steps), got 0" },
    { R"({"integrator": {"max_steps": 2e9}})",
      "scene.integrator.max_steps: expected a whole number from 1 to 1e+09" },
    { R"({"integrator": {"max_steps": 10.5}})",
      "scene.integrator.max_steps: expected a whole number from 1 to 1e+09" },
    { R"({"integrator": {"max_length": 0}})",
      "scene.integrator.max_length: expected a number above 0 and at most 1e+09 (arc length)" },
    { R"({"integrator": {"tolerance": -1}})",
      "scene.integrator.tolerance: expected a number from 1e-15 to 1" },
    { R"({"integrator": {"tolerance": 2}})",
      "scene.integrator.tolerance: expected a number from 1e-15 to 1" },
    { R"({"integrator": {"steps": 10}})", "scene.integrator: unknown key \"steps\"" },
    // Background, fog, lighting.
    { R"({"background": [0, 0, 2]})", "scene.background[2]: expected a number in [0, 1], got 2" },
    { R"({"background": [0, 0]})", "scene.background: expected a colour" },
    { R"({"background": "black"})", "scene.background: expected a colour [r, g, b] or" },
    { R"({"background": {"environment": "no-such-sky.exr"}})",
      "scene.background.environment: environment image \"no-such-sky.exr\" not found" },
    { R"({"background": {"environment": 1}})", "scene.background.environment: expected a string" },
    { R"({"background": {"image": "sky.exr"}})", "scene.background: unknown key \"image\"" },
    { R"({"fog": {"density": -0.1}})", "scene.fog.density: expected a non-negative number" },
    { R"({"fog": {"color": [0, -1, 0]}})", "scene.fog.color[1]: expected a number in [0, 1]" },
    { R"({"fog": {"colour": [0, 0, 0]}})", "scene.fog: unknown key \"colour\"" },
    { R"({"lighting": "sun"})", "scene.lighting: unknown lighting \"sun\"" },
    // Objects.
    { R"({"objects": {}})", "scene.objects: expected an array of objects" },
    { R"({"objects": [3]})", "scene.objects[0]: expected an object, got 3" },
    { R"({"objects": [{"radius": 1}]})", "scene.objects[0]: missing required key \"type\"" },
    { R"({"objects": [{"type": "cone"}]})", "scene.objects[0].type: unknown object type \"cone\"" },
    { R"({"objects": [{"type": "sphere", "center": [0,0,0]}]})",
      "scene.objects[0]: missing required key \"radius\"" },
    { R"({"objects": [{"type": "grid"}, {"type": "sphere", "center": [0,0,0], "radius": 0}]})",
      "scene.objects[1].radius: expected a positive number, got 0" },
    { R"({"objects": [{"type": "sphere", "center": [0,0,0], "radius": -1}]})",
      "scene.objects[0].radius: expected a positive number, got -1" },
    { R"({"objects": [{"type": "sphere", "centre": [0,0,0], "radius": 1}]})",
      "scene.objects[0]: unknown key \"centre\"" },
    { R"({"objects": [{"type": "sphere", "center": [0,0,0,0], "radius": 1}]})",
      "scene.objects[0].center: expected an array of 3 numbers, got an array of 4" },
    { R"({"objects": [{"type": "grid", "spacing": 0}]})",
      "scene.objects[0].spacing: expected a positive number, got 0" },
    { R"({"objects": [{"type": "grid", "thickness": -0.1}]})",
      "scene.objects[0].thickness: expected a positive number" },
    { R"({"objects": [{"type": "grid", "spacing": 0.5, "thickness": 0.5}]})",
      "scene.objects[0].thickness: must be less than the spacing" },
    { R"({"objects": [{"type": "grid", "extent": [1,-1,0,1,0,1]}]})",
      "scene.objects[0].extent: min > max on x" },
    { R"({"objects": [{"type": "grid", "extent": [0,1,0,1,2,1]}]})",
      "scene.objects[0].extent: min > max on z" },
    { R"({"objects": [{"type": "grid", "extent": [0,1,0,1]}]})",
      "scene.objects[0].extent: expected an array of 6 numbers" },
    { R"({"objects": [{"type": "grid", "spacing": 0.0005, "thickness": 0.0001}]})",
      "scene.objects[0].spacing: the extent holds more than 10000 lattice lines along x" },
    // Lattice indices past 2^53 no longer step by 1 (the intersection loop hung).
    { R"({"objects": [{"type": "grid", "extent": [0,0,1e20,1e20,0,0]}]})",
      "scene.objects[0].extent: reaches more than 1000000 spacings from the origin along y" },
    { R"({"objects": [{"type": "plane", "point": [0,0,0], "normal": [0,0,0]}]})",
      "scene.objects[0].normal: expected a non-zero vector" },
    { R"({"objects": [{"type": "box", "min": [0,2,0], "max": [1,1,1]}]})",
      "scene.objects[0]: min > max on y" },
    { R"({"objects": [{"type": "box", "min": [0,0,0]}]})",
      "scene.objects[0]: missing required key \"max\"" },
    { "{\"objects\": [" + many + "]}",
      "scene.objects[16]: more than 16 spheres (the GPU pass's limit)" },
    { "{\"objects\": [" + planes + "]}", "scene.objects[8]: more than 8 planes" },
    { "{\"objects\": [" + boxes + "]}", "scene.objects[16]: more than 16 boxes" },
    { "{\"objects\": [" + grids + "]}", "scene.objects[4]: more than 4 grids" },
    // Materials.
    { R"({"objects": [{"type": "grid", "material": {"type": "glass"}}]})",
      "scene.objects[0].material.type: unknown material \"glass\"" },
    { R"({"objects": [{"type": "grid", "material": {"color": [1,0,0]}}]})",
      "scene.objects[0].material: missing required key \"type\"" },
    { R"({"objects": [{"type": "grid", "material": "red"}]})",
      "scene.objects[0].material: expected an object, got the string \"red\"" },
    { R"({"objects": [{"type": "grid", "material": {"type": "solid", "color": [1,0]}}]})",
      "scene.objects[0].material.color: expected a colour" },
    { R"({"objects": [{"type": "grid", "material": {"type": "solid", "size": 1}}]})",
      "scene.objects[0].material: unknown key \"size\"" },
    { R"({"objects": [{"type": "grid", "material": {"type": "checker", "size": 0}}]})",
      "scene.objects[0].material.size: expected a positive number, got 0" },
    { R"({"objects": [{"type": "grid", "material": {"type": "checker", "color2": [2,0,0]}}]})",
      "scene.objects[0].material.color2[0]: expected a number in [0, 1]" },
    { R"({"objects": [{"type": "grid", "material": {"type": "position", "bounds": [0,1,1,1,0,1]}}]})",
      "scene.objects[0].material.bounds: min > max on y (1 >= 1)" },
  };
  for (const auto& c : cases)
  {
    const std::string error = ErrorOf(c.first);
    EXPECT_NE(error.find(c.second), std::string::npos)
      << "input:    " << c.first.substr(0, 200) << "\nexpected: " << c.second
      << "\ngot:      " << (error.empty() ? "(no error)" : error);
  }
}

//------------------------------------------------------------------------------
// Intersection: exact answers
//------------------------------------------------------------------------------
TEST(Intersect, SphereEntryPointAndNormal)
{
  const Scene scene = OneObject(Sphere(Vec3(1, 2, 3), 0.5));
  SceneHit hit;
  // Along -z towards the centre: enters at z = 3.5, a quarter of the way.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(1, 2, 5), Vec3(1, 2, -3), hit));
  EXPECT_NEAR(hit.Fraction, 1.5 / 8, 1e-14);
  ExpectVec(hit.Position, Vec3(1, 2, 3.5));
  ExpectVec(hit.Normal, Vec3(0, 0, 1));
  EXPECT_EQ(hit.Object, 0);
  // Off-centre: x = 1.3 meets the sphere at z = 3 + 0.4.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(1.3, 2, 4), Vec3(1.3, 2, 2), hit));
  ExpectVec(hit.Position, Vec3(1.3, 2, 3.4));
  ExpectVec(hit.Normal, Vec3(0.6, 0, 0.8));
  // Too short, passing by, moving away: no hit.
  EXPECT_FALSE(IntersectSegment(scene, Vec3(1, 2, 5), Vec3(1, 2, 3.6), hit));
  EXPECT_FALSE(IntersectSegment(scene, Vec3(1.6, 2, 5), Vec3(1.6, 2, -3), hit));
  EXPECT_FALSE(IntersectSegment(scene, Vec3(1, 2, 3.6), Vec3(1, 2, 5), hit));
  // Ending exactly on the surface hits at 1.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(1, 2, 4.5), Vec3(1, 2, 3.5), hit));
  EXPECT_NEAR(hit.Fraction, 1.0, 1e-14);
  // Starting inside: fraction 0, normal facing the ray.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(1, 2.1, 3), Vec3(3, 2.1, 3), hit));
  EXPECT_EQ(hit.Fraction, 0.0);
  ExpectVec(hit.Position, Vec3(1, 2.1, 3));
  ExpectVec(hit.Normal, Vec3(-1, 0, 0));
}

TEST(Intersect, BoxFaces)
{
  const Scene scene = OneObject(Box(Vec3(-1, -2, -3), Vec3(1, 2, 3)));
  struct Case
  {
    Vec3 A, B, Position, Normal;
  };
  const Case cases[] = {
    { Vec3(-5, 0.5, 0.5), Vec3(5, 0.5, 0.5), Vec3(-1, 0.5, 0.5), Vec3(-1, 0, 0) },
    { Vec3(5, 0.5, 0.5), Vec3(-5, 0.5, 0.5), Vec3(1, 0.5, 0.5), Vec3(1, 0, 0) },
    { Vec3(0.5, -6, 0.5), Vec3(0.5, 6, 0.5), Vec3(0.5, -2, 0.5), Vec3(0, -1, 0) },
    { Vec3(0.5, 6, 0.5), Vec3(0.5, -6, 0.5), Vec3(0.5, 2, 0.5), Vec3(0, 1, 0) },
    { Vec3(0.5, 0.5, -7), Vec3(0.5, 0.5, 7), Vec3(0.5, 0.5, -3), Vec3(0, 0, -1) },
    { Vec3(0.5, 0.5, 7), Vec3(0.5, 0.5, -7), Vec3(0.5, 0.5, 3), Vec3(0, 0, 1) },
    // Oblique, through the x = 1 face at (1, 1, 2).
    { Vec3(3, 2, 3), Vec3(-1, 0, 1), Vec3(1, 1, 2), Vec3(1, 0, 0) },
  };
  for (const Case& c : cases)
  {
    SceneHit hit;
    ASSERT_TRUE(IntersectSegment(scene, c.A, c.B, hit)) << c.A.transpose();
    ExpectVec(hit.Position, c.Position);
    ExpectVec(hit.Normal, c.Normal);
    EXPECT_NEAR(hit.Fraction, (c.Position - c.A).norm() / (c.B - c.A).norm(), 1e-14);
  }
  SceneHit hit;
  EXPECT_FALSE(IntersectSegment(scene, Vec3(-5, 0, 0), Vec3(-1.01, 0, 0), hit));
  EXPECT_FALSE(IntersectSegment(scene, Vec3(-5, 2.5, 0), Vec3(5, 2.5, 0), hit));
  EXPECT_FALSE(IntersectSegment(scene, Vec3(2, 0, 0), Vec3(5, 0, 0), hit));
  // Axis-parallel segments in a face's plane hit it (the box is closed).
  ASSERT_TRUE(IntersectSegment(scene, Vec3(-5, 2, 0), Vec3(5, 2, 0), hit));
  ExpectVec(hit.Position, Vec3(-1, 2, 0));
  // Inside: fraction 0, normal facing the ray.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(0, 0, 0), Vec3(0, 0, 10), hit));
  EXPECT_EQ(hit.Fraction, 0.0);
  ExpectVec(hit.Normal, Vec3(0, 0, -1));
  // A point (a == b) inside hits with a zero normal.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(0, 0, 0), Vec3(0, 0, 0), hit));
  ExpectVec(hit.Normal, Vec3::Zero());
}

TEST(Intersect, TwoSidedPlane)
{
  const Scene scene = OneObject(Plane(Vec3(0, -2, 0), Vec3(0, 1, 0)));
  SceneHit hit;
  ASSERT_TRUE(IntersectSegment(scene, Vec3(1, 0, 0), Vec3(1, -4, 2), hit));
  EXPECT_NEAR(hit.Fraction, 0.5, 1e-15);
  ExpectVec(hit.Position, Vec3(1, -2, 1));
  ExpectVec(hit.Normal, Vec3(0, 1, 0));
  // From below: the normal faces the ray.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(0, -3, 0), Vec3(0, -1, 0), hit));
  EXPECT_NEAR(hit.Fraction, 0.5, 1e-15);
  ExpectVec(hit.Normal, Vec3(0, -1, 0));
  EXPECT_FALSE(IntersectSegment(scene, Vec3(0, 0, 0), Vec3(5, -1.9, 0), hit));
  EXPECT_FALSE(IntersectSegment(scene, Vec3(0, -3, 0), Vec3(5, -2.1, 0), hit));
  // Touching at the end, and lying in the plane.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(0, 0, 0), Vec3(0, -2, 0), hit));
  EXPECT_EQ(hit.Fraction, 1.0);
  ASSERT_TRUE(IntersectSegment(scene, Vec3(0, -2, 0), Vec3(3, -2, 0), hit));
  EXPECT_EQ(hit.Fraction, 0.0);
  // Oblique plane.
  const Scene oblique = OneObject(Plane(Vec3(1, 1, 1), Vec3(1, 1, 1)));
  ASSERT_TRUE(IntersectSegment(oblique, Vec3(0, 0, 0), Vec3(2, 2, 2), hit));
  EXPECT_NEAR(hit.Fraction, 0.5, 1e-15);
  ExpectVec(hit.Normal, Vec3(-1, -1, -1) / std::sqrt(3.0));
}

TEST(Intersect, GridBars)
{
  // Spacing 1, thickness 0.1 (h = 0.05), extent [-2,2]^3.
  const Scene scene = OneObject(Grid(1.0, 0.1, { -2, 2, -2, 2, -2, 2 }));
  SceneHit hit;
  // Along x at y = 0.5, z = 0: only the z-bars (x = i, y = j) are not met
  // (y = 0.5 is between lines); the y-bars (x = i, z = 0) are: first at
  // x = -2 - 0.05 coming from x = -3.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(-3, 0.5, 0), Vec3(3, 0.5, 0), hit));
  ExpectVec(hit.Position, Vec3(-2.05, 0.5, 0));
  ExpectVec(hit.Normal, Vec3(-1, 0, 0));
  // A short segment crossing the z-bar (x = 1, y = 0) at a known point.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(0.8, 0.02, 0.5), Vec3(1.2, 0.02, 0.5), hit));
  ExpectVec(hit.Position, Vec3(0.95, 0.02, 0.5));
  EXPECT_NEAR(hit.Fraction, 0.375, 1e-12);
  ExpectVec(hit.Normal, Vec3(-1, 0, 0));
  // Oblique, down onto the top face of the x-bar (y = 1, z = 0).
  ASSERT_TRUE(IntersectSegment(scene, Vec3(0.5, 1.25, 0.2), Vec3(0.5, 1.0, 0.0), hit));
  // Enters the slab y <= 1.05 at fraction 0.8 (z = 0.04, inside |z| <= 0.05).
  ExpectVec(hit.Position, Vec3(0.5, 1.05, 0.04));
  ExpectVec(hit.Normal, Vec3(0, 1, 0));
  // Between bars: misses.
  EXPECT_FALSE(IntersectSegment(scene, Vec3(0.2, 0.3, 0.4), Vec3(0.8, 0.7, 0.6), hit));
  EXPECT_FALSE(IntersectSegment(scene, Vec3(0.5, 0.5, -3), Vec3(0.5, 0.5, 3), hit));
  // Just past a bar's side (0.051 from the line) misses, 0.049 hits.
  EXPECT_FALSE(IntersectSegment(scene, Vec3(0.5, 0.051, 0.5), Vec3(1.5, 0.051, 0.5), hit));
  EXPECT_TRUE(IntersectSegment(scene, Vec3(0.5, 0.049, 0.5), Vec3(1.5, 0.049, 0.5), hit));
  // Starting inside a bar: fraction 0, normal facing the ray.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(1.01, -0.02, 0.5), Vec3(1.5, 0.3, 0.5), hit));
  EXPECT_EQ(hit.Fraction, 0.0);
  ExpectVec(hit.Position, Vec3(1.01, -0.02, 0.5));
  ExpectVec(hit.Normal, -Vec3(0.49, 0.32, 0).normalized());
  // A bar crossing (node) is inside too.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(1, 1, 1), Vec3(1.001, 1, 1), hit));
  EXPECT_EQ(hit.Fraction, 0.0);
}

TEST(Intersect, GridExtentClipping)
{
  // Extent [-1, 1.5] x [-1, 1] x [-1, 1], h = 0.05: lattice lines x in
  // {-1, 0, 1} (1.5 is not one), bars along x reach 1.5 + 0.05.
  const Scene scene = OneObject(Grid(1.0, 0.1, { -1, 1.5, -1, 1, -1, 1 }));
  SceneHit hit;
  // Along -x on the x-bar (y = 0, z = 0.02 from it): the bar ends at x = 1.55.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(3, 0, 0.02), Vec3(1.2, 0, 0.02), hit));
  ExpectVec(hit.Position, Vec3(1.55, 0, 0.02));
  ExpectVec(hit.Normal, Vec3(1, 0, 0));
  // No z-bar at x = 2 (outside the extent), none at y = 2 either.
  EXPECT_FALSE(IntersectSegment(scene, Vec3(2, 0.5, -3), Vec3(2, 0.5, 3), hit));
  EXPECT_FALSE(IntersectSegment(scene, Vec3(0.5, 2, -3), Vec3(0.5, 2, 3), hit));
  // The z-bar at (x, y) = (1, 1) is the outermost: full section, ends at z = +-1.05.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(1.04, 1.04, 3), Vec3(1.04, 1.04, 0), hit));
  ExpectVec(hit.Position, Vec3(1.04, 1.04, 1.05));
  ExpectVec(hit.Normal, Vec3(0, 0, 1));
  ASSERT_TRUE(IntersectSegment(scene, Vec3(2, 1.04, 0.5), Vec3(0, 1.04, 0.5), hit));
  ExpectVec(hit.Position, Vec3(1.05, 1.04, 0.5));
  // A flat extent in z is a planar grid of full bars.
  const Scene flat = OneObject(Grid(1.0, 0.1, { -2, 2, -2, 2, 0, 0 }));
  ASSERT_TRUE(IntersectSegment(flat, Vec3(0.5, 1.02, 3), Vec3(0.5, 1.02, -3), hit));
  ExpectVec(hit.Position, Vec3(0.5, 1.02, 0.05));
  EXPECT_FALSE(IntersectSegment(flat, Vec3(0.5, 0.5, 3), Vec3(0.5, 0.5, -3), hit));
  EXPECT_FALSE(IntersectSegment(flat, Vec3(-3, 0, 0.2), Vec3(3, 0, 0.2), hit));
}

TEST(Intersect, LongSegmentsThroughTheGrid)
{
  // A long segment is cut into pieces: the first hit must be the same as for
  // the first of many short segments marching along it.
  const Scene scene = OneObject(Grid(0.5, 0.04, { -4, 4, -4, 4, -4, 4 }));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-6, 6);
  for (int trial = 0; trial < 300; ++trial)
  {
    const Vec3 a(uniform(random), uniform(random), uniform(random));
    const Vec3 b(uniform(random), uniform(random), uniform(random));
    SceneHit whole;
    const bool hitWhole = IntersectSegment(scene, a, b, whole);
    const int marches = 2000;
    bool hitMarch = false;
    SceneHit march;
    for (int m = 0; m < marches && !hitMarch; ++m)
    {
      const Vec3 p = a + (b - a) * (double(m) / marches);
      const Vec3 q = a + (b - a) * (double(m + 1) / marches);
      if (IntersectSegment(scene, p, q, march))
      {
        hitMarch = true;
        march.Fraction = (m + march.Fraction) / marches;
      }
    }
    ASSERT_EQ(hitWhole, hitMarch) << a.transpose() << " -> " << b.transpose();
    if (hitWhole)
    {
      EXPECT_NEAR(whole.Fraction, march.Fraction, 1e-9);
      ExpectVec(whole.Position, march.Position, 1e-9);
    }
  }
}

TEST(Intersect, FirstHitAmongObjects)
{
  Scene scene;
  scene.Objects.push_back(Box(Vec3(-1, -1, 4), Vec3(1, 1, 6)));       // far
  scene.Objects.push_back(Sphere(Vec3(0, 0, 2), 0.5));                // near
  scene.Objects.push_back(Plane(Vec3(0, 0, 8), Vec3(0, 0, 1)));       // farthest
  scene.Objects.push_back(Grid(1.0, 0.1, { -3, 3, -3, 3, -10, -5 })); // behind
  SceneHit hit;
  ASSERT_TRUE(IntersectSegment(scene, Vec3(0, 0, 0), Vec3(0, 0, 10), hit));
  EXPECT_EQ(hit.Object, 1);
  ExpectVec(hit.Position, Vec3(0, 0, 1.5));
  ASSERT_TRUE(IntersectSegment(scene, Vec3(0.8, 0, 0), Vec3(0.8, 0, 10), hit));
  EXPECT_EQ(hit.Object, 0);
  ExpectVec(hit.Position, Vec3(0.8, 0, 4));
  ASSERT_TRUE(IntersectSegment(scene, Vec3(2, 0.5, 0), Vec3(2, 0.5, 10), hit));
  EXPECT_EQ(hit.Object, 2);
  ASSERT_TRUE(IntersectSegment(scene, Vec3(0, 0, 0), Vec3(0, 0, -10), hit));
  EXPECT_EQ(hit.Object, 3);
  ExpectVec(hit.Position, Vec3(0, 0, -4.95));
  // The reverse direction meets them in the reverse order.
  ASSERT_TRUE(IntersectSegment(scene, Vec3(0, 0, 10), Vec3(0, 0, 0), hit));
  EXPECT_EQ(hit.Object, 2);
  // Ties go to the object listed first.
  Scene tie;
  tie.Objects.push_back(Plane(Vec3(0, 0, 1), Vec3(0, 0, 1)));
  tie.Objects.push_back(Box(Vec3(-1, -1, 1), Vec3(1, 1, 2)));
  ASSERT_TRUE(IntersectSegment(tie, Vec3(0, 0, 0), Vec3(0, 0, 3), hit));
  EXPECT_EQ(hit.Object, 0);
  // Nothing hit: hit is left alone.
  hit.Object = 42;
  EXPECT_FALSE(IntersectSegment(scene, Vec3(0, 0, 0), Vec3(0, 0.2, 0.2), hit));
  EXPECT_EQ(hit.Object, 42);
  EXPECT_FALSE(IntersectSegment(Scene(), Vec3(0, 0, 0), Vec3(1, 1, 1), hit));
}

/// 10000 random short segments against fine sampling with the independent
/// point-in-bars test: no hit missed by more than the sampling resolution and
/// no hit where there is no bar. A hit before the first inside sample by more
/// than a sample is a bar grazed between two samples (an edge or corner cut
/// shorter than a sample, like segment 6431 of the second grid): sampling
/// cannot see it, so it is only checked to be a point on a bar's surface.
void CrossCheckGrid(const SceneObject& grid, unsigned seed)
{
  const Scene scene = OneObject(grid);
  std::mt19937 random(seed);
  // Start points in the extent grown by half a spacing (clipping is tested too).
  std::uniform_real_distribution<double> unit(0, 1);
  auto position = [&](int axis)
  {
    const double lo = grid.Extent[2 * axis] - 0.5 * grid.Spacing;
    const double hi = grid.Extent[2 * axis + 1] + 0.5 * grid.Spacing;
    return lo + (hi - lo) * unit(random);
  };
  std::uniform_real_distribution<double> gaussian(-1, 1);
  std::uniform_real_distribution<double> length(0.005, 0.6);
  const int samples = 4000;
  int hits = 0;
  int insideStarts = 0;
  int grazes = 0;
  for (int trial = 0; trial < 10000; ++trial)
  {
    // One draw per statement, x then y then z: the order in which function
    // arguments are evaluated is unspecified (GCC and clang differ), so
    // draws in one argument list would make the segments compiler-dependent.
    Vec3 a;
    for (int axis = 0; axis < 3; ++axis)
    {
      a[axis] = position(axis);
    }
    if (trial % 4 < 2)
    {
      // Near a lattice line in one (or two: near a bar) of the axes, so that
      // hits, grazing segments and starts inside bars are common.
      const int k = trial % 3;
      for (int u = 1; u <= 1 + trial % 4; ++u)
      {
        const int axis = (k + u) % 3;
        a[axis] = grid.Spacing * std::round(a[axis] / grid.Spacing) +
          0.8 * grid.Thickness * gaussian(random);
      }
    }
    Vec3 direction;
    for (int axis = 0; axis < 3; ++axis)
    {
      direction[axis] = gaussian(random);
    }
    if (trial % 7 == 0)
    {
      direction[trial % 3] = 0; // axis-parallel components
    }
    if (direction.norm() < 1e-3)
    {
      continue;
    }
    const Vec3 b = a + length(random) * direction.normalized();
    const Vec3 d = b - a;

    int firstInside = -1;
    for (int i = 0; i <= samples && firstInside < 0; ++i)
    {
      if (InGrid(grid, a + (double(i) / samples) * d))
      {
        firstInside = i;
      }
    }
    SceneHit hit;
    const bool found = IntersectSegment(scene, a, b, hit);
    const std::string where = "segment " + std::to_string(trial);
    if (firstInside >= 0)
    {
      ASSERT_TRUE(found) << where << ": missed a bar sampled at fraction "
                         << double(firstInside) / samples;
      // The first hit is no later than the first inside sample...
      EXPECT_LE(hit.Fraction, double(firstInside) / samples + 1e-12) << where;
      insideStarts += firstInside == 0;
    }
    if (found)
    {
      ++hits;
      // No false hit: the reported point is on a bar (up to rounding)...
      EXPECT_TRUE(InGrid(grid, hit.Position, 1e-9)) << where << " at " << hit.Position.transpose();
      ExpectVec(hit.Position, a + hit.Fraction * d, 1e-12);
      // ...on its surface unless the segment starts in a bar (the entry point,
      // not a point past it)...
      if (hit.Fraction > 0)
      {
        EXPECT_FALSE(InGrid(grid, hit.Position, -1e-9))
          << where << " at " << hit.Position.transpose();
      }
      // A hit earlier than the sample before the first inside one (or with no
      // inside sample) is a bar the segment crosses between two samples, both
      // outside: a graze of an edge or a corner shorter than a sample, which
      // sampling cannot bound from below (the checks above are all it gets).
      // Otherwise the hit lies between the last outside sample and the first
      // inside one.
      const bool seen =
        firstInside >= 0 && hit.Fraction >= double(firstInside - 1) / samples - 1e-12;
      grazes += !seen;
      // The normal is the facing normal at a start inside, else a unit axis.
      if (hit.Fraction == 0 && InGrid(grid, a))
      {
        ExpectVec(hit.Normal, -d.normalized());
      }
      else
      {
        EXPECT_NEAR(hit.Normal.cwiseAbs().sum(), 1.0, 1e-15);
        EXPECT_NEAR(hit.Normal.norm(), 1.0, 1e-15);
        EXPECT_LT(hit.Normal.dot(d), 0) << where;
      }
    }
  }
  // The test exercised what it claims to.
  EXPECT_GT(hits, 1500);
  EXPECT_GT(insideStarts, 300);
  std::printf("grid cross-check: %d of 10000 segments hit, %d start inside a bar, %d graze a "
              "bar between two samples\n",
    hits, insideStarts, grazes);
}

TEST(Intersect, GridAgainstBruteForceSampling)
{
  CrossCheckGrid(Grid(1.0, 0.06, { -2, 2, -2, 2, -2, 2 }), 1);
  // Thick bars, a spacing that is not a power of two, and an extent off the
  // lattice: clipping and rounding of lattice indices.
  CrossCheckGrid(Grid(0.3, 0.12, { -1.3, 1.7, -2.0, 0.9, -0.6, 0.6 }), 2);
}

TEST(Intersect, GridBarGrazedBetweenTwoSamples)
{
  // Segment 6431 of the second cross-check grid: it cuts the corner of the bar
  // along x through (y, z) = (-1.8, 0.3), entering its face y = -1.86 at
  // fraction 0.7260147 and leaving its face z = 0.24 at 0.7261697 (exact
  // arithmetic): 1.55e-4 of the segment, between the samples 2904 and 2905
  // of 4000, so sampling first sees a bar at 3676 (0.919). The hit is the corner.
  const SceneObject grid = Grid(0.3, 0.12, { -1.3, 1.7, -2.0, 0.9, -0.6, 0.6 });
  const Vec3 a(-0.19472545770454697, -2.120649774620007, 0.50050079680441062);
  const Vec3 b(-0.24399590618971345, -1.7616353311966073, 0.14176813862179133);
  const Vec3 d = b - a;
  SceneHit hit;
  ASSERT_TRUE(IntersectSegment(OneObject(grid), a, b, hit));
  EXPECT_NEAR(hit.Fraction, 0.7260147311472165, 1e-12);
  EXPECT_NEAR(hit.Position.y(), -1.86, 1e-12);
  ExpectVec(hit.Normal, Vec3(0, -1, 0));
  EXPECT_TRUE(InGrid(grid, a + 0.72609 * d));  // inside the corner
  EXPECT_FALSE(InGrid(grid, a + 0.726 * d));   // sample 2904
  EXPECT_FALSE(InGrid(grid, a + 0.72625 * d)); // sample 2905
  EXPECT_FALSE(InGrid(grid, a + 0.7262 * d));  // past the corner
  EXPECT_TRUE(InGrid(grid, a + 0.919 * d));    // sample 3676: the next bar
}

//------------------------------------------------------------------------------
// Colours
//------------------------------------------------------------------------------
TEST(SurfaceColor, Materials)
{
  Scene scene;
  SceneObject box = Box(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  const double bounds[6] = { 0, 2, -1, 1, 1, 3 };
  std::copy(bounds, bounds + 6, box.Surface.Bounds);
  scene.Objects.push_back(box);
  SceneHit hit;
  hit.Object = 0;
  hit.Normal = Vec3(0, 0, 1);
  hit.Position = Vec3(0.5, 0.5, 5);
  ExpectVec(SurfaceColor(scene, hit), Vec3(0.25, 0.75, 1.0)); // clamped z
  hit.Position = Vec3(-3, -1, 1);
  ExpectVec(SurfaceColor(scene, hit), Vec3(0, 0, 0));

  scene.Objects[0].Surface.Type = MaterialType::Solid;
  scene.Objects[0].Surface.Color = Vec3(0.1, 0.2, 0.3);
  ExpectVec(SurfaceColor(scene, hit), Vec3(0.1, 0.2, 0.3));

  Material& checker = scene.Objects[0].Surface;
  checker.Type = MaterialType::Checker;
  checker.Color = Vec3(1, 1, 1);
  checker.Color2 = Vec3(0, 0, 0);
  checker.Size = 0.5;
  hit.Normal = Vec3(0, 1, 0);
  hit.Position = Vec3(0.25, 0.25, 0.25); // cells 0 0 0: even
  ExpectVec(SurfaceColor(scene, hit), Vec3(1, 1, 1));
  hit.Position = Vec3(0.75, 0.25, 0.25); // 1 0 0: odd
  ExpectVec(SurfaceColor(scene, hit), Vec3(0, 0, 0));
  hit.Position = Vec3(-0.25, 0.25, 0.25); // -1 0 0: odd
  ExpectVec(SurfaceColor(scene, hit), Vec3(0, 0, 0));
  hit.Position = Vec3(-0.25, -0.25, 0.25); // -1 -1 0: even
  ExpectVec(SurfaceColor(scene, hit), Vec3(1, 1, 1));
  // A face lying on a checker plane: evaluated just inside, so rounding noise
  // in the hit position does not flip the colour.
  hit.Normal = Vec3(0, 1, 0); // the top face y = 1 of the box
  hit.Position = Vec3(0.25, 1.0, 0.25);
  const Vec3 onFace = SurfaceColor(scene, hit);
  hit.Position = Vec3(0.25, 1.0 + 1e-13, 0.25);
  ExpectVec(SurfaceColor(scene, hit), onFace);
  hit.Position = Vec3(0.25, 1.0 - 1e-13, 0.25);
  ExpectVec(SurfaceColor(scene, hit), onFace);
  ExpectVec(onFace, Vec3(0, 0, 0)); // cell (0, 1, 0) inside the box: odd

  hit.Object = 3;
  ExpectVec(SurfaceColor(scene, hit), Vec3::Zero());
}

TEST(SurfaceColor, PositionColoursOfTheDefaultGrid)
{
  const Scene scene = DefaultScene();
  SceneHit hit;
  ASSERT_TRUE(IntersectSegment(scene, Vec3(0.5, 0.02, 7.5), Vec3(0.5, 0.02, -7.5), hit));
  ExpectVec(hit.Position, Vec3(0.5, 0.02, 4.03));
  ExpectVec(SurfaceColor(scene, hit), Vec3(4.5 / 8, 4.02 / 8, 1.0));
}
} // namespace
} // namespace riemann

//------------------------------------------------------------------------------
TEST(EnvironmentMapImage, GreyRepeatsAndAnImageWithoutPixelsIsACallersBug)
{
  // SetImage takes the pixels (a grey image's one channel in r, g and b); an
  // image without pixels breaks its contract: std::invalid_argument, the
  // logic_error family of ErrorConventions.md, and the map stays as it was.
  riemann::Image grey;
  grey.Width = 2;
  grey.Height = 1;
  grey.Channels = 1;
  grey.Pixels = { 0.25f, 0.75f };
  riemann::EnvironmentMap map;
  map.SetImage(grey);
  ASSERT_EQ(map.Width, 2);
  ASSERT_EQ(map.Height, 1);
  EXPECT_EQ(map.Rgb, (std::vector<float>{ 0.25f, 0.25f, 0.25f, 0.75f, 0.75f, 0.75f }));

  for (const riemann::Image& bad :
    { riemann::Image(), riemann::Image{ 4, 4, 3, std::vector<float>(10) } })
  {
    EXPECT_THROW(map.SetImage(bad), std::invalid_argument);
    EXPECT_EQ(map.Width, 2);
  }
}

//------------------------------------------------------------------------------
TEST(Scene, RayDefaultsAreTheDeclaredPreset)
{
  // A scene's "integrator" block: its keys and ranges are the declared ones
  // of vtkRiemannIntegrationSettings (vtkRiemannIntegrationSettings.settings.json),
  // its defaults (RaySettings' plain ones) the declared "Rays" preset.
  namespace preset = riemann::declared::vtkRiemannIntegrationSettings::Rays;
  const riemann::RaySettings rays;
  EXPECT_EQ(static_cast<int>(rays.Integrator), preset::IntegratorType);
  EXPECT_EQ(rays.Step, preset::InitialIntegrationStep);
  EXPECT_EQ(rays.Tolerance, preset::MaximumError);
  EXPECT_EQ(rays.MaximumLength, preset::MaximumPropagation);
  EXPECT_EQ(rays.MaximumSteps, preset::MaximumNumberOfSteps);
  EXPECT_EQ(riemann::ParseScene("{}").Rays.Step, rays.Step);

  // Every key of the schema is a key of the block, at the edge of its range.
  const riemann::Scene scene = riemann::ParseScene(R"({"integrator": {"method": "dp45",
    "step": 1e-9, "tolerance": 1, "max_length": 1e9, "max_steps": 1e9}})");
  EXPECT_EQ(scene.Rays.Integrator, riemann::IntegratorType::DormandPrince45);
  EXPECT_EQ(scene.Rays.Step, 1e-9);
  EXPECT_EQ(scene.Rays.Tolerance, 1.0);
  EXPECT_EQ(scene.Rays.MaximumLength, 1e9);
  EXPECT_EQ(scene.Rays.MaximumSteps, 1000000000);
}
