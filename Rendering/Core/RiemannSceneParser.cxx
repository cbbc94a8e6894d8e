#include "RiemannSceneParser.h"

#include "JsonValidation.h"
#include "InputFiles.h"
#include "MetricDefinition.h"
#include "RiemannIntegrationSettingsDeclaration.h"
#include "RiemannPictureSettingsDeclaration.h"
#include "SettingValues.h"

#include <Eigen/Geometry> // cross

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace riemann
{
namespace
{
using json::Describe;
using json::Json;

[[noreturn]] void Fail(const std::string& path, const std::string& message)
{
  json::Fail<SceneDefinitionError>(path, message);
}

void CheckKeys(
  const Json& object, const std::string& path, std::initializer_list<const char*> allowed)
{
  json::CheckKeys<SceneDefinitionError>(object, path, allowed);
}

const Json& Required(const Json& object, const char* key, const std::string& path)
{
  return json::Required<SceneDefinitionError>(object, key, path);
}

/// Guards against absurd inputs (a scene is typed by a person).
constexpr std::uint64_t MaximumFileSize = 64 << 20;
/// Lattice lines per axis of one grid (keeps the intersection loops bounded).
constexpr double MaximumLatticeLines = 10000;
/// Lattice line indices |extent / spacing| per axis: the intersection loops
/// step through line indices by 1 (in floats on the GPU, exact to 2^24), and
/// past 2^53 (2^24) a step no longer moves (the loop never ends).
constexpr double MaximumLatticeIndex = 1e6;

double Number(const Json& value, const std::string& path)
{
  if (!value.is_number())
  {
    Fail(path, "expected a number, got " + Describe(value));
  }
  const double number = value.get<double>();
  if (!std::isfinite(number))
  {
    Fail(path, "expected a finite number");
  }
  return number;
}

double Positive(const Json& value, const std::string& path)
{
  if (!value.is_number() || !(value.get<double>() > 0) || !std::isfinite(value.get<double>()))
  {
    Fail(path, "expected a positive number, got " + Describe(value));
  }
  return value.get<double>();
}

std::string String(const Json& value, const std::string& path)
{
  if (!value.is_string())
  {
    Fail(path, "expected a string, got " + Describe(value));
  }
  return value.get<std::string>();
}

Vec3 Vector(const Json& value, const std::string& path)
{
  if (!value.is_array() || value.size() != 3)
  {
    Fail(path, "expected an array of 3 numbers, got " + Describe(value));
  }
  return Vec3(
    Number(value[0], path + "[0]"), Number(value[1], path + "[1]"), Number(value[2], path + "[2]"));
}

Vec3 Color(const Json& value, const std::string& path)
{
  if (!value.is_array() || value.size() != 3)
  {
    Fail(path, "expected a colour, an array of 3 numbers in [0, 1], got " + Describe(value));
  }
  Vec3 color;
  for (int i = 0; i < 3; ++i)
  {
    const std::string itemPath = path + "[" + std::to_string(i) + "]";
    color[i] = Number(value[i], itemPath);
    if (color[i] < 0 || color[i] > 1)
    {
      Fail(itemPath, "expected a number in [0, 1], got " + value[i].dump());
    }
  }
  return color;
}

const char* AxisName(int axis)
{
  return axis == 0 ? "x" : (axis == 1 ? "y" : "z");
}

/// [x0,x1,y0,y1,z0,z1] with x0 <= x1 (x0 < x1 when `strict`), ...
void Bounds(const Json& value, const std::string& path, bool strict, double bounds[6])
{
  if (!value.is_array() || value.size() != 6)
  {
    Fail(path, "expected an array of 6 numbers [x0,x1,y0,y1,z0,z1], got " + Describe(value));
  }
  for (int i = 0; i < 6; ++i)
  {
    bounds[i] = Number(value[i], path + "[" + std::to_string(i) + "]");
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    const double lo = bounds[2 * axis];
    const double hi = bounds[2 * axis + 1];
    if (lo > hi || (strict && lo == hi))
    {
      Fail(path,
        std::string("min > max on ") + AxisName(axis) + " (" + value[2 * axis].dump() + " " +
          (strict ? ">=" : ">") + " " + value[2 * axis + 1].dump() + ")");
    }
  }
}

std::filesystem::path Resolve(const std::string& name, const std::string& baseDirectory)
{
  std::filesystem::path path(name);
  if (path.is_relative())
  {
    path = std::filesystem::path(baseDirectory.empty() ? "." : baseDirectory) / path;
  }
  std::error_code error;
  std::filesystem::path absolute = std::filesystem::absolute(path, error);
  return (error ? path : absolute).lexically_normal();
}

//------------------------------------------------------------------------------
// Parts of the scene
//------------------------------------------------------------------------------
std::string MetricText(const Json& value, const std::string& path, const std::string& baseDirectory,
  std::shared_ptr<const Metric>& parsed, std::string& metricDirectory)
{
  metricDirectory = baseDirectory;
  std::string text;
  std::string where;
  if (value.is_string())
  {
    const std::string name = value.get<std::string>();
    const std::filesystem::path file = Resolve(name, baseDirectory);
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error))
    {
      Fail(path, "metric file \"" + name + "\" not found (looked for " + file.string() + ")");
    }
    try
    {
      text = ReadMetricDefinitionFile(file.string());
    }
    catch (const MetricDefinitionError& e)
    {
      Fail(path, e.what());
    }
    where = file.string() + ": ";
    metricDirectory = file.parent_path().string();
  }
  else if (value.is_object())
  {
    text = value.dump();
  }
  else
  {
    Fail(path, "expected a metric file name or a metric object, got " + Describe(value));
  }
  // A bad metric is a bad scene: say so now, not when the renderer builds it.
  try
  {
    parsed = ParseMetricDefinition(text, 0.0, metricDirectory);
  }
  catch (const MetricDefinitionError& e)
  {
    Fail(path, where + e.what());
  }
  return text;
}

/// The declared picture setting (vtkRiemannPictureSettings.settings.json) named `name`.
const SettingDeclaration& PictureSettingNamed(const char* name)
{
  return *riemann::declared::vtkRiemannPictureSettings::Settings.Find(name);
}

/// The camera block's value of `setting` (under its scene key), in its declared range.
Json CameraValue(const Json& object, const SettingDeclaration& setting, const std::string& path)
{
  const std::string where = path + "." + setting.SceneKey;
  const Json& value = object.at(setting.SceneKey);
  if (setting.Type == SettingDeclaration::Point || setting.Type == SettingDeclaration::Direction)
  {
    Vector(value, where); // says which number is not one
  }
  if (!CheckSettingValue(setting, value, where).empty())
  {
    // Three numbers that are not valid are shown as they are ([0,0,0]).
    const std::string got = value.is_array() ? value.dump() : Describe(value);
    Fail(where, "expected " + DescribeSettingRange(setting) + ", got " + got);
  }
  return value;
}

CameraSettings Camera(const Json& object, const std::string& path)
{
  // The block's keys are the declared scene keys of the picture settings, in their order.
  std::vector<const char*> keys;
  for (const SettingDeclaration& setting : riemann::declared::vtkRiemannPictureSettings::Settings)
  {
    if (*setting.SceneKey)
    {
      keys.push_back(setting.SceneKey);
    }
  }
  json::CheckKeys<SceneDefinitionError>(object, path, keys);
  CameraSettings camera;
  const auto vector = [&](const char* name, Vec3& out)
  {
    const SettingDeclaration& setting = PictureSettingNamed(name);
    if (object.contains(setting.SceneKey))
    {
      const Json v = CameraValue(object, setting, path);
      out = Vec3(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
    }
  };
  vector("Position", camera.Position);
  vector("LookAt", camera.LookAt);
  vector("ViewUp", camera.ViewUp);
  const SettingDeclaration& angle = PictureSettingNamed("ViewAngle");
  if (object.contains(angle.SceneKey))
  {
    camera.ViewAngle = CameraValue(object, angle, path).get<double>();
  }
  const SettingDeclaration& projection = PictureSettingNamed("Projection");
  if (object.contains(projection.SceneKey))
  {
    camera.Mode = static_cast<Projection>(
      ChoiceIndex(projection, CameraValue(object, projection, path).get<std::string>()));
  }
  const Vec3 forward = camera.LookAt - camera.Position;
  if (forward.squaredNorm() == 0)
  {
    Fail(path, "position and look_at are the same point; the view direction is undefined");
  }
  // Gram-Schmidt (in any g) fails exactly when up is parallel to forward.
  if (forward.cross(camera.ViewUp).norm() <= 1e-9 * forward.norm() * camera.ViewUp.norm())
  {
    Fail(path + ".view_up", "parallel to the view direction (look_at - position)");
  }
  return camera;
}

/// The declared integration setting a scene's "integrator" block sets with `key`.
const SettingDeclaration& IntegrationSettingOfKey(const char* name)
{
  return *riemann::declared::vtkRiemannIntegrationSettings::Settings.Find(name);
}

/// The value of one of the integrator block's numbers, in the range the
/// declaration of vtkRiemannIntegrationSettings gives the setting.
double IntegrationNumber(const Json& object, const SettingDeclaration& setting, const std::string& path)
{
  const std::string where = path + "." + setting.SceneKey;
  const Json& value = object.at(setting.SceneKey);
  if (!value.is_number() || !CheckSettingValue(setting, value, where).empty())
  {
    Fail(where, "expected " + DescribeSettingRange(setting) + ", got " + Describe(value));
  }
  return value.get<double>();
}

RaySettings Integrator(const Json& object, const std::string& path)
{
  // The block's keys are the declared settings' scene keys, in the declaration's order.
  std::vector<const char*> keys;
  for (const SettingDeclaration& setting : riemann::declared::vtkRiemannIntegrationSettings::Settings)
  {
    if (*setting.SceneKey)
    {
      keys.push_back(setting.SceneKey);
    }
  }
  json::CheckKeys<SceneDefinitionError>(object, path, keys);
  RaySettings rays;
  const char* methodKey = IntegrationSettingOfKey("IntegratorType").SceneKey;
  if (object.contains(methodKey))
  {
    const std::string method = String(object.at(methodKey), path + "." + methodKey);
    if (!ParseIntegratorName(method, rays.Integrator))
    {
      Fail(path + "." + methodKey,
        "unknown method \"" + method + "\"; expected \"euler\", \"rk4\" or \"dp45\"");
    }
  }
  // Each number the block may give, and where the rays keep it.
  const SettingDeclaration& step = IntegrationSettingOfKey("InitialIntegrationStep");
  const SettingDeclaration& steps = IntegrationSettingOfKey("MaximumNumberOfSteps");
  const SettingDeclaration& length = IntegrationSettingOfKey("MaximumPropagation");
  const SettingDeclaration& tolerance = IntegrationSettingOfKey("MaximumError");
  if (object.contains(step.SceneKey))
  {
    rays.Step = IntegrationNumber(object, step, path);
  }
  if (object.contains(steps.SceneKey))
  {
    rays.MaximumSteps = static_cast<int>(IntegrationNumber(object, steps, path));
  }
  if (object.contains(length.SceneKey))
  {
    rays.MaximumLength = IntegrationNumber(object, length, path);
  }
  if (object.contains(tolerance.SceneKey))
  {
    rays.Tolerance = IntegrationNumber(object, tolerance, path);
  }
  return rays;
}

Material ParseMaterial(const Json& object, const std::string& path, const Vec3& lo, const Vec3& hi)
{
  Material material;
  SetDefaultMaterialBounds(material, lo, hi);
  if (!object.is_object())
  {
    Fail(path, "expected an object, got " + Describe(object));
  }
  const std::string type = String(Required(object, "type", path), path + ".type");
  if (type == "position")
  {
    CheckKeys(object, path, { "type", "bounds" });
    material.Type = MaterialType::Position;
    if (object.contains("bounds"))
    {
      Bounds(object.at("bounds"), path + ".bounds", true, material.Bounds);
    }
  }
  else if (type == "solid")
  {
    CheckKeys(object, path, { "type", "color" });
    material.Type = MaterialType::Solid;
    if (object.contains("color"))
    {
      material.Color = Color(object.at("color"), path + ".color");
    }
  }
  else if (type == "checker")
  {
    CheckKeys(object, path, { "type", "color", "color2", "size" });
    material.Type = MaterialType::Checker;
    if (object.contains("color"))
    {
      material.Color = Color(object.at("color"), path + ".color");
    }
    if (object.contains("color2"))
    {
      material.Color2 = Color(object.at("color2"), path + ".color2");
    }
    if (object.contains("size"))
    {
      material.Size = Positive(object.at("size"), path + ".size");
    }
  }
  else
  {
    Fail(path + ".type",
      "unknown material \"" + type + "\"; expected \"position\", \"solid\" or \"checker\"");
  }
  return material;
}

/// Mesh file extensions that the VTK layer reads (vtkRiemannScene).
bool IsMeshExtension(std::string extension)
{
  for (char& c : extension)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return extension == ".vtp" || extension == ".ply" || extension == ".obj" || extension == ".stl";
}

// ParseObject's steps: one parser per object type. Each checks the object's
// keys, fills `result` and sets [lo, hi], the box that a "position" material
// spans by default.

/// A "grid": the paper's lattice of bars unless told otherwise.
void ParseGrid(const Json& object, const std::string& path, SceneObject& result, Vec3& lo, Vec3& hi)
{
  CheckKeys(object, path, { "type", "spacing", "thickness", "extent", "material" });
  result.Type = ObjectType::Grid;
  // The paper's grid unless told otherwise.
  result.Spacing = 1.0;
  result.Thickness = 0.06;
  const double paperExtent[6] = { -4, 4, -4, 4, -4, 4 };
  std::copy(paperExtent, paperExtent + 6, result.Extent);
  if (object.contains("spacing"))
  {
    result.Spacing = Positive(object.at("spacing"), path + ".spacing");
  }
  if (object.contains("thickness"))
  {
    result.Thickness = Positive(object.at("thickness"), path + ".thickness");
  }
  if (!(result.Thickness < result.Spacing))
  {
    Fail(path + ".thickness",
      "must be less than the spacing (" + Json(result.Thickness).dump() +
        " >= " + Json(result.Spacing).dump() + "): the bars would fill space");
  }
  if (object.contains("extent"))
  {
    Bounds(object.at("extent"), path + ".extent", false, result.Extent);
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    const double lines = (result.Extent[2 * axis + 1] - result.Extent[2 * axis]) / result.Spacing;
    if (!(lines <= MaximumLatticeLines))
    {
      Fail(path + ".spacing",
        std::string("the extent holds more than ") +
          std::to_string(static_cast<int>(MaximumLatticeLines)) + " lattice lines along " +
          AxisName(axis) + "; use a larger spacing or a smaller extent");
    }
    const double farthest =
      std::max(std::abs(result.Extent[2 * axis]), std::abs(result.Extent[2 * axis + 1])) /
      result.Spacing;
    if (!(farthest <= MaximumLatticeIndex))
    {
      Fail(path + ".extent",
        std::string("reaches more than ") + std::to_string(static_cast<int>(MaximumLatticeIndex)) +
          " spacings from the origin along " + AxisName(axis) +
          "; use a larger spacing or an extent nearer the origin");
    }
  }
  lo = Vec3(result.Extent[0], result.Extent[2], result.Extent[4]);
  hi = Vec3(result.Extent[1], result.Extent[3], result.Extent[5]);
}

void ParseSphere(
  const Json& object, const std::string& path, SceneObject& result, Vec3& lo, Vec3& hi)
{
  CheckKeys(object, path, { "type", "center", "radius", "material" });
  result.Type = ObjectType::Sphere;
  result.A = Vector(Required(object, "center", path), path + ".center");
  result.Radius = Positive(Required(object, "radius", path), path + ".radius");
  lo = result.A - Vec3::Constant(result.Radius);
  hi = result.A + Vec3::Constant(result.Radius);
}

/// A "plane": a point and a unit normal; the material spans [-5, 5]^3.
void ParsePlane(
  const Json& object, const std::string& path, SceneObject& result, Vec3& lo, Vec3& hi)
{
  CheckKeys(object, path, { "type", "point", "normal", "material" });
  result.Type = ObjectType::Plane;
  result.A = Vector(Required(object, "point", path), path + ".point");
  const Vec3 normal = Vector(Required(object, "normal", path), path + ".normal");
  const double length = normal.norm();
  if (!(length > 0) || !std::isfinite(length))
  {
    Fail(path + ".normal", "expected a non-zero vector");
  }
  result.B = normal / length;
  lo = Vec3::Constant(-5);
  hi = Vec3::Constant(5);
}

void ParseBox(const Json& object, const std::string& path, SceneObject& result, Vec3& lo, Vec3& hi)
{
  CheckKeys(object, path, { "type", "min", "max", "material" });
  result.Type = ObjectType::Box;
  result.A = Vector(Required(object, "min", path), path + ".min");
  result.B = Vector(Required(object, "max", path), path + ".max");
  for (int axis = 0; axis < 3; ++axis)
  {
    if (result.A[axis] > result.B[axis])
    {
      Fail(path,
        std::string("min > max on ") + AxisName(axis) + " (" + object.at("min")[axis].dump() +
          " > " + object.at("max")[axis].dump() + ")");
    }
  }
  lo = result.A;
  hi = result.B;
}

/// A "mesh": a file the VTK layer reads (checked to exist here), and how to
/// colour it by one of its point arrays.
void ParseMesh(const Json& object, const std::string& path, const std::string& baseDirectory,
  SceneObject& result, Vec3& lo, Vec3& hi)
{
  CheckKeys(
    object, path, { "type", "file", "material", "color_array", "color_map", "color_range" });
  result.Type = ObjectType::Mesh;
  const std::string filePath = path + ".file";
  const std::string name = String(Required(object, "file", path), filePath);
  const std::filesystem::path file = Resolve(name, baseDirectory);
  if (!IsMeshExtension(file.extension().string()))
  {
    Fail(filePath,
      "unknown mesh format \"" + file.extension().string() + "\" of \"" + name +
        "\"; expected .vtp, .ply, .obj or .stl");
  }
  std::error_code error;
  if (name.empty() || !std::filesystem::is_regular_file(file, error))
  {
    Fail(filePath, "mesh file \"" + name + "\" not found (looked for " + file.string() + ")");
  }
  result.MeshFile = file.string();
  if (object.contains("color_array"))
  {
    result.ColorArray = String(object.at("color_array"), path + ".color_array");
  }
  if (object.contains("color_map"))
  {
    result.ColorMap = String(object.at("color_map"), path + ".color_map");
    if (result.ColorMap != "cool-to-warm" && result.ColorMap != "viridis" &&
      result.ColorMap != "grayscale" && result.ColorMap != "rainbow")
    {
      Fail(path + ".color_map",
        "unknown colour map \"" + result.ColorMap +
          "\"; expected \"cool-to-warm\", \"viridis\", \"grayscale\" or \"rainbow\"");
    }
  }
  if (object.contains("color_range"))
  {
    const Json& range = object.at("color_range");
    const std::string rangePath = path + ".color_range";
    if (!range.is_array() || range.size() != 2)
    {
      Fail(rangePath, "expected [min, max], got " + Describe(range));
    }
    result.ColorRange[0] = Number(range[0], rangePath + "[0]");
    result.ColorRange[1] = Number(range[1], rangePath + "[1]");
    if (!(result.ColorRange[0] < result.ColorRange[1]))
    {
      Fail(rangePath, "expected min < max, got " + range.dump());
    }
    result.HasColorRange = true;
  }
  result.HasMaterialBounds = object.contains("material") && object.at("material").is_object() &&
    object.at("material").contains("bounds");
  // Placeholder bounds until the triangles are known (SetMesh).
  lo = Vec3::Constant(-1);
  hi = Vec3::Constant(1);
}

/// One entry of "objects": its type's parser, then its material.
SceneObject ParseObject(
  const Json& object, const std::string& path, const std::string& baseDirectory)
{
  if (!object.is_object())
  {
    Fail(path, "expected an object, got " + Describe(object));
  }
  const std::string type = String(Required(object, "type", path), path + ".type");
  SceneObject result;
  Vec3 lo;
  Vec3 hi;
  if (type == "grid")
  {
    ParseGrid(object, path, result, lo, hi);
  }
  else if (type == "sphere")
  {
    ParseSphere(object, path, result, lo, hi);
  }
  else if (type == "plane")
  {
    ParsePlane(object, path, result, lo, hi);
  }
  else if (type == "box")
  {
    ParseBox(object, path, result, lo, hi);
  }
  else if (type == "mesh")
  {
    ParseMesh(object, path, baseDirectory, result, lo, hi);
  }
  else
  {
    Fail(path + ".type",
      "unknown object type \"" + type +
        "\"; expected \"grid\", \"sphere\", \"plane\", \"box\" or \"mesh\"");
  }
  if (object.contains("material"))
  {
    result.Surface = ParseMaterial(object.at("material"), path + ".material", lo, hi);
  }
  else
  {
    SetDefaultMaterialBounds(result.Surface, lo, hi);
  }
  return result;
}

void ParseObjects(
  const Json& list, const std::string& path, Scene& scene, const std::string& baseDirectory)
{
  if (!list.is_array())
  {
    Fail(path, "expected an array of objects, got " + Describe(list));
  }
  int counts[5] = { 0, 0, 0, 0, 0 };
  const int limits[5] = { MaximumGrids, MaximumSpheres, MaximumPlanes, MaximumBoxes,
    MaximumMeshes };
  const char* plural[5] = { "grids", "spheres", "planes", "boxes", "meshes" };
  for (size_t i = 0; i < list.size(); ++i)
  {
    const std::string itemPath = path + "[" + std::to_string(i) + "]";
    SceneObject object = ParseObject(list[i], itemPath, baseDirectory);
    const int type = static_cast<int>(object.Type);
    if (++counts[type] > limits[type])
    {
      Fail(itemPath,
        std::string("more than ") + std::to_string(limits[type]) + " " + plural[type] +
          (type == static_cast<int>(ObjectType::Mesh) ? std::string(" (the CPU tracer's limit)")
                                                      : std::string(" (the GPU pass's limit)")));
    }
    scene.Objects.push_back(object);
  }
}

/// ParseScene, its errors not yet located in the text.
Scene ParseSceneText(const std::string& json, const std::string& baseDirectory)
{
  const std::string path = "scene";
  // Syntax errors, and numbers out of double's range (out_of_range.406).
  const Json root = json::Parse<SceneDefinitionError>(json, path, "invalid JSON: ");
  if (!root.is_object())
  {
    Fail(path, "expected a JSON object, got " + Describe(root));
  }
  CheckKeys(
    root, path, { "metric", "camera", "integrator", "background", "fog", "lighting", "objects" });

  Scene scene;
  if (root.contains("metric"))
  {
    scene.MetricDefinition = MetricText(root.at("metric"), path + ".metric", baseDirectory,
      scene.ParsedMetric, scene.MetricDirectory);
  }
  if (root.contains("camera"))
  {
    scene.Camera = Camera(root.at("camera"), path + ".camera");
    scene.HasCamera = true;
  }
  if (root.contains("integrator"))
  {
    scene.Rays = Integrator(root.at("integrator"), path + ".integrator");
  }
  if (root.contains("background"))
  {
    const Json& background = root.at("background");
    const std::string backgroundPath = path + ".background";
    if (background.is_object())
    {
      CheckKeys(background, backgroundPath, { "environment" });
      const std::string environmentPath = backgroundPath + ".environment";
      const std::string name =
        String(Required(background, "environment", backgroundPath), environmentPath);
      const std::filesystem::path file = Resolve(name, baseDirectory);
      std::error_code error;
      if (name.empty() || !std::filesystem::is_regular_file(file, error))
      {
        Fail(environmentPath,
          "environment image \"" + name + "\" not found (looked for " + file.string() + ")");
      }
      scene.EnvironmentImage = file.string();
    }
    else if (background.is_array())
    {
      scene.Background = Color(background, backgroundPath);
    }
    else
    {
      Fail(backgroundPath,
        "expected a colour [r, g, b] or {\"environment\": file}, got " + Describe(background));
    }
  }
  if (root.contains("fog"))
  {
    const Json& fog = root.at("fog");
    const std::string fogPath = path + ".fog";
    CheckKeys(fog, fogPath, { "color", "density" });
    if (fog.contains("color"))
    {
      scene.FogColor = Color(fog.at("color"), fogPath + ".color");
    }
    if (fog.contains("density"))
    {
      scene.FogDensity = Number(fog.at("density"), fogPath + ".density");
      if (scene.FogDensity < 0)
      {
        Fail(
          fogPath + ".density", "expected a non-negative number, got " + fog.at("density").dump());
      }
    }
  }
  if (root.contains("lighting"))
  {
    const std::string lighting = String(root.at("lighting"), path + ".lighting");
    if (lighting != "none" && lighting != "observer")
    {
      Fail(path + ".lighting",
        "unknown lighting \"" + lighting + "\"; expected \"none\" or \"observer\"");
    }
    scene.ObserverLight = lighting == "observer";
  }
  if (root.contains("objects"))
  {
    ParseObjects(root.at("objects"), path + ".objects", scene, baseDirectory);
  }
  return scene;
}

} // namespace

//------------------------------------------------------------------------------
Scene ParseScene(const std::string& json, const std::string& baseDirectory)
{
  return LocatingErrorsIn(json, [&]() { return ParseSceneText(json, baseDirectory); });
}

Scene LoadSceneFile(const std::string& path)
{
  std::string text;
  try
  {
    text = ReadInputFile(path, "the scene file", MaximumFileSize);
  }
  catch (const std::runtime_error& e)
  {
    throw SceneDefinitionError(e.what());
  }
  std::string baseDirectory = std::filesystem::path(path).parent_path().string();
  if (baseDirectory.empty())
  {
    baseDirectory = ".";
  }
  try
  {
    return ParseScene(text, baseDirectory);
  }
  catch (const SceneDefinitionError& e)
  {
    throw SceneDefinitionError(path + ": ", e);
  }
}
} // namespace riemann
