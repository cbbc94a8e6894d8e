#include "RiemannScene.h"

#include "JsonValidation.h"
#include "MetricDefinition.h"

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
constexpr std::streamoff MaximumFileSize = 64 << 20;
/// Lattice lines per axis of one grid (keeps the intersection loops bounded).
constexpr double MaximumLatticeLines = 10000;
constexpr int MaximumIntegratorSteps = 1000000;

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
std::string MetricText(const Json& value, const std::string& path, const std::string& baseDirectory)
{
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
    ParseMetricDefinition(text);
  }
  catch (const MetricDefinitionError& e)
  {
    Fail(path, where + e.what());
  }
  return text;
}

CameraSettings Camera(const Json& object, const std::string& path)
{
  CheckKeys(object, path, { "position", "look_at", "view_up", "fov", "projection" });
  CameraSettings camera;
  if (object.contains("position"))
  {
    camera.Position = Vector(object.at("position"), path + ".position");
  }
  if (object.contains("look_at"))
  {
    camera.LookAt = Vector(object.at("look_at"), path + ".look_at");
  }
  if (object.contains("view_up"))
  {
    camera.ViewUp = Vector(object.at("view_up"), path + ".view_up");
  }
  if (object.contains("fov"))
  {
    camera.ViewAngle = Number(object.at("fov"), path + ".fov");
    if (!(camera.ViewAngle > 0 && camera.ViewAngle < 180))
    {
      Fail(
        path + ".fov", "expected a view angle in (0, 180) degrees, got " + object.at("fov").dump());
    }
  }
  if (object.contains("projection"))
  {
    const std::string mode = String(object.at("projection"), path + ".projection");
    if (mode == "perspective")
    {
      camera.Mode = Projection::Perspective;
    }
    else if (mode == "equirectangular")
    {
      camera.Mode = Projection::Equirectangular;
    }
    else
    {
      Fail(path + ".projection",
        "unknown projection \"" + mode + "\"; expected \"perspective\" or \"equirectangular\"");
    }
  }
  const Vec3 forward = camera.LookAt - camera.Position;
  if (forward.squaredNorm() == 0)
  {
    Fail(path, "position and look_at are the same point; the view direction is undefined");
  }
  if (camera.ViewUp.squaredNorm() == 0)
  {
    Fail(path + ".view_up", "expected a non-zero vector");
  }
  // Gram-Schmidt (in any g) fails exactly when up is parallel to forward.
  if (forward.cross(camera.ViewUp).norm() <= 1e-9 * forward.norm() * camera.ViewUp.norm())
  {
    Fail(path + ".view_up", "parallel to the view direction (look_at - position)");
  }
  return camera;
}

RaySettings Integrator(const Json& object, const std::string& path)
{
  CheckKeys(object, path, { "method", "step", "max_steps", "max_length", "tolerance" });
  RaySettings rays;
  if (object.contains("method"))
  {
    const std::string method = String(object.at("method"), path + ".method");
    if (method == "euler")
    {
      rays.Integrator = IntegratorType::Euler;
    }
    else if (method == "rk4")
    {
      rays.Integrator = IntegratorType::RungeKutta4;
    }
    else if (method == "adaptive" || method == "dp45")
    {
      rays.Integrator = IntegratorType::DormandPrince45;
    }
    else
    {
      Fail(path + ".method",
        "unknown method \"" + method + "\"; expected \"euler\", \"rk4\" or \"adaptive\"");
    }
  }
  if (object.contains("step"))
  {
    rays.Step = Positive(object.at("step"), path + ".step");
  }
  if (object.contains("max_steps"))
  {
    const Json& value = object.at("max_steps");
    const double steps = value.is_number() ? value.get<double>() : 0.0;
    if (!value.is_number() || steps != std::floor(steps) || steps < 1 ||
      steps > MaximumIntegratorSteps)
    {
      Fail(path + ".max_steps",
        "expected an integer in [1, " + std::to_string(MaximumIntegratorSteps) + "], got " +
          Describe(value));
    }
    rays.MaximumSteps = static_cast<int>(steps);
  }
  if (object.contains("max_length"))
  {
    rays.MaximumLength = Positive(object.at("max_length"), path + ".max_length");
  }
  if (object.contains("tolerance"))
  {
    rays.Tolerance = Positive(object.at("tolerance"), path + ".tolerance");
  }
  return rays;
}

/// Default Position bounds: `extent` with flat axes widened to +-1.
void SetDefaultBounds(Material& material, const Vec3& lo, const Vec3& hi)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    const bool flat = !(hi[axis] > lo[axis]);
    material.Bounds[2 * axis] = flat ? lo[axis] - 1 : lo[axis];
    material.Bounds[2 * axis + 1] = flat ? hi[axis] + 1 : hi[axis];
  }
}

Material ParseMaterial(const Json& object, const std::string& path, const Vec3& lo, const Vec3& hi)
{
  Material material;
  SetDefaultBounds(material, lo, hi);
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

SceneObject ParseObject(const Json& object, const std::string& path, const std::string& baseDirectory)
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
    }
    lo = Vec3(result.Extent[0], result.Extent[2], result.Extent[4]);
    hi = Vec3(result.Extent[1], result.Extent[3], result.Extent[5]);
  }
  else if (type == "sphere")
  {
    CheckKeys(object, path, { "type", "center", "radius", "material" });
    result.Type = ObjectType::Sphere;
    result.A = Vector(Required(object, "center", path), path + ".center");
    result.Radius = Positive(Required(object, "radius", path), path + ".radius");
    lo = result.A - Vec3::Constant(result.Radius);
    hi = result.A + Vec3::Constant(result.Radius);
  }
  else if (type == "plane")
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
  else if (type == "box")
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
  else if (type == "mesh")
  {
    CheckKeys(object, path,
      { "type", "file", "material", "color_array", "color_map", "color_range" });
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
    result.HasMaterialBounds = object.contains("material") &&
      object.at("material").is_object() && object.at("material").contains("bounds");
    // Placeholder bounds until the triangles are known (SetMesh).
    lo = Vec3::Constant(-1);
    hi = Vec3::Constant(1);
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
    SetDefaultBounds(result.Surface, lo, hi);
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

//------------------------------------------------------------------------------
// Intersection kernels. Each tests the segment p(t) = a + t d, t in [0, 1],
// and on a hit sets the fraction t and the normal. They are written to be
// mirrored line by line in GLSL: no allocation, fixed small loops.
//------------------------------------------------------------------------------
constexpr double Infinity = std::numeric_limits<double>::infinity();

/// -d / |d|, or zero for d == 0: the normal of a hit at a start inside a solid.
Vec3 FacingNormal(const Vec3& d)
{
  const double length = d.norm();
  return length > 0 ? Vec3(-d / length) : Vec3(Vec3::Zero());
}

/**
 * Slab test of the closed box [lo, hi]. On return [enter, exit] is the
 * parameter interval of the infinite line a + t d inside the box (enter is
 * -inf when no slab bounds it from below) and `axis` the axis whose slab gave
 * `enter` (-1 if none). True when that interval meets [0, 1].
 * An axis with d == 0 constrains nothing if a is within its slab and rejects
 * otherwise (no division by zero).
 */
bool SlabTest(const Vec3& a, const Vec3& d, const Vec3& lo, const Vec3& hi, double& enter,
  double& exit, int& axis)
{
  enter = -Infinity;
  exit = Infinity;
  axis = -1;
  for (int i = 0; i < 3; ++i)
  {
    if (d[i] == 0)
    {
      if (a[i] < lo[i] || a[i] > hi[i])
      {
        return false;
      }
      continue;
    }
    const double t0 = (lo[i] - a[i]) / d[i];
    const double t1 = (hi[i] - a[i]) / d[i];
    const double tNear = std::min(t0, t1);
    const double tFar = std::max(t0, t1);
    if (tNear > enter)
    {
      enter = tNear;
      axis = i;
    }
    exit = std::min(exit, tFar);
  }
  return enter <= exit && exit >= 0 && enter <= 1;
}

/**
 * Closed box. A start in the box (enter <= 0) hits at 0 with the facing
 * normal; otherwise the hit is the entry face, normal -sign(d_axis) e_axis.
 */
bool IntersectBox(
  const Vec3& a, const Vec3& d, const Vec3& lo, const Vec3& hi, double& fraction, Vec3& normal)
{
  double enter;
  double exit;
  int axis;
  if (!SlabTest(a, d, lo, hi, enter, exit, axis))
  {
    return false;
  }
  if (enter <= 0)
  {
    fraction = 0;
    normal = FacingNormal(d);
    return true;
  }
  fraction = enter;
  normal = Vec3::Zero();
  normal[axis] = d[axis] > 0 ? -1.0 : 1.0;
  return true;
}

/**
 * Closed ball |p - c| <= r: with m = a - c, solve |m + t d|^2 = r^2, i.e.
 * A t^2 + 2 B t + C = 0 with A = d.d, B = d.m, C = m.m - r^2. C <= 0 means
 * the start is in the ball (fraction 0, facing normal). Otherwise the ray
 * must approach (B < 0) with a real root; the first root
 * t = (-B - sqrt(B^2 - A C)) / A must be <= 1. Normal (p - c) / r.
 */
bool IntersectSphere(
  const Vec3& a, const Vec3& d, const Vec3& center, double radius, double& fraction, Vec3& normal)
{
  const Vec3 m = a - center;
  const double A = d.dot(d);
  const double B = d.dot(m);
  const double C = m.dot(m) - radius * radius;
  if (C <= 0)
  {
    fraction = 0;
    normal = FacingNormal(d);
    return true;
  }
  const double discriminant = B * B - A * C;
  if (B >= 0 || discriminant < 0)
  {
    return false;
  }
  const double t = (-B - std::sqrt(discriminant)) / A;
  if (t > 1)
  {
    return false;
  }
  fraction = std::max(t, 0.0);
  normal = (a + fraction * d - center) / radius;
  return true;
}

/**
 * Two-sided plane n.(p - q) = 0 (n unit). With signed distances sa, sb of
 * the ends, the segment hits when sa sb <= 0, at sa / (sa - sb) (0 when the
 * segment lies in the plane). The normal faces the ray: n if sa - sb >= 0
 * (moving towards -n), else -n.
 */
bool IntersectPlane(const Vec3& a, const Vec3& d, const Vec3& point, const Vec3& unitNormal,
  double& fraction, Vec3& normal)
{
  const double sa = unitNormal.dot(a - point);
  const double sb = unitNormal.dot(a + d - point);
  if (sa * sb > 0)
  {
    return false;
  }
  fraction = sa == sb ? 0.0 : std::clamp(sa / (sa - sb), 0.0, 1.0);
  normal = sa - sb >= 0 ? unitNormal : Vec3(-unitNormal);
  return true;
}

/**
 * The grid of bars (the geometry is in RiemannScene.h). The segment is first
 * clipped to the grid's bounding box (the extent grown by h = thickness / 2)
 * and cut into pieces no longer than the spacing. For each piece in order and
 * each bar axis k, the candidate bars are the lattice lines (i s, j s) whose
 * bar section overlaps the piece's bounding box in the two other axes:
 *   i in [ceil((min_u - h) / s), floor((max_u + h) / s)]  (widened by 1e-9)
 * intersected with the lattice lines inside the extent,
 *   i in [ceil(E0_u / s - 1e-9), floor(E1_u / s + 1e-9)].
 * Each candidate bar box is slab-tested against the whole segment (exact,
 * IntersectBox). A bar not yet enumerated does not meet the pieces so far, so
 * once the best fraction lies within the pieces done, it is the first hit.
 * A ray-marching shader sees segments much shorter than the spacing: one
 * piece, 0 to 2 candidates per axis and direction.
 */
bool IntersectGrid(
  const SceneObject& grid, const Vec3& a, const Vec3& d, double& fraction, Vec3& normal)
{
  const double s = grid.Spacing;
  const double h = 0.5 * grid.Thickness;
  const Vec3 extentLo(grid.Extent[0], grid.Extent[2], grid.Extent[4]);
  const Vec3 extentHi(grid.Extent[1], grid.Extent[3], grid.Extent[5]);
  const Vec3 outerLo = extentLo - Vec3::Constant(h);
  const Vec3 outerHi = extentHi + Vec3::Constant(h);
  double enter;
  double exit;
  int enterAxis;
  if (!(s > 0) || !SlabTest(a, d, outerLo, outerHi, enter, exit, enterAxis))
  {
    return false;
  }
  const double t0 = std::max(enter, 0.0);
  const double t1 = std::min(exit, 1.0);

  // Lattice lines inside the extent (as doubles: no integer overflow).
  constexpr double slack = 1e-9;
  double firstLine[3];
  double lastLine[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    firstLine[axis] = std::ceil(extentLo[axis] / s - slack);
    lastLine[axis] = std::floor(extentHi[axis] / s + slack);
  }

  const double length = d.norm() * (t1 - t0);
  const int pieces = static_cast<int>(std::clamp(std::ceil(length / s), 1.0, 65536.0));
  bool found = false;
  double best = Infinity;
  for (int piece = 0; piece < pieces; ++piece)
  {
    const double ta = t0 + (t1 - t0) * piece / pieces;
    const double tb = piece + 1 == pieces ? t1 : t0 + (t1 - t0) * (piece + 1) / pieces;
    const Vec3 pa = a + ta * d;
    const Vec3 pb = a + tb * d;
    const Vec3 boxLo = pa.cwiseMin(pb);
    const Vec3 boxHi = pa.cwiseMax(pb);
    for (int k = 0; k < 3; ++k)
    {
      const int u = (k + 1) % 3;
      const int v = (k + 2) % 3;
      const double i0 = std::max(firstLine[u], std::ceil((boxLo[u] - h) / s - slack));
      const double i1 = std::min(lastLine[u], std::floor((boxHi[u] + h) / s + slack));
      const double j0 = std::max(firstLine[v], std::ceil((boxLo[v] - h) / s - slack));
      const double j1 = std::min(lastLine[v], std::floor((boxHi[v] + h) / s + slack));
      for (double i = i0; i <= i1; ++i)
      {
        for (double j = j0; j <= j1; ++j)
        {
          Vec3 barLo;
          Vec3 barHi;
          barLo[k] = outerLo[k];
          barHi[k] = outerHi[k];
          barLo[u] = i * s - h;
          barHi[u] = i * s + h;
          barLo[v] = j * s - h;
          barHi[v] = j * s + h;
          double t;
          Vec3 n;
          if (IntersectBox(a, d, barLo, barHi, t, n) && t < best)
          {
            found = true;
            best = t;
            fraction = t;
            normal = n;
          }
        }
      }
    }
    if (found && best <= tb)
    {
      break;
    }
  }
  return found;
}
} // namespace

//------------------------------------------------------------------------------
Scene ParseScene(const std::string& json, const std::string& baseDirectory)
{
  const std::string path = "scene";
  Json root;
  try
  {
    root = Json::parse(json);
  }
  catch (const Json::parse_error& e)
  {
    Fail(path, std::string("invalid JSON: ") + e.what());
  }
  if (!root.is_object())
  {
    Fail(path, "expected a JSON object, got " + Describe(root));
  }
  CheckKeys(
    root, path, { "metric", "camera", "integrator", "background", "fog", "lighting", "objects" });

  Scene scene;
  if (root.contains("metric"))
  {
    scene.MetricDefinition = MetricText(root.at("metric"), path + ".metric", baseDirectory);
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

Scene LoadSceneFile(const std::string& path)
{
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file)
  {
    throw SceneDefinitionError(path + ": cannot open the scene file");
  }
  if (file.tellg() > MaximumFileSize)
  {
    throw SceneDefinitionError(path + ": file too large for a scene definition");
  }
  file.seekg(0);
  std::ostringstream text;
  text << file.rdbuf();
  std::string baseDirectory = std::filesystem::path(path).parent_path().string();
  if (baseDirectory.empty())
  {
    baseDirectory = ".";
  }
  try
  {
    return ParseScene(text.str(), baseDirectory);
  }
  catch (const SceneDefinitionError& e)
  {
    throw SceneDefinitionError(path + ": " + e.what());
  }
}

Scene DefaultScene()
{
  Scene scene;
  SceneObject grid;
  grid.Type = ObjectType::Grid;
  grid.Spacing = 1.0;
  grid.Thickness = 0.06;
  for (int axis = 0; axis < 3; ++axis)
  {
    grid.Extent[2 * axis] = -4;
    grid.Extent[2 * axis + 1] = 4;
  }
  grid.Surface.Type = MaterialType::Position;
  std::copy(grid.Extent, grid.Extent + 6, grid.Surface.Bounds);
  scene.Objects.push_back(grid);

  scene.Camera.Position = Vec3(0, 0, 7.5);
  scene.Camera.LookAt = Vec3::Zero();
  scene.Camera.ViewUp = Vec3(0, 1, 0);
  scene.Camera.ViewAngle = 60.0;
  scene.Camera.Mode = Projection::Perspective;
  scene.HasCamera = true;

  scene.Rays.Integrator = IntegratorType::RungeKutta4;
  scene.Rays.Step = 0.02;
  scene.Rays.MaximumSteps = 800;
  scene.Rays.MaximumLength = 30.0;

  scene.Background = Vec3(0.05, 0.05, 0.08);
  scene.FogColor = Vec3::Zero();
  scene.FogDensity = 0.02;
  scene.ObserverLight = false;
  return scene;
}

//------------------------------------------------------------------------------
bool IntersectSegment(const Scene& scene, const Vec3& a, const Vec3& b, SceneHit& hit)
{
  const Vec3 d = b - a;
  bool found = false;
  double best = Infinity;
  for (size_t index = 0; index < scene.Objects.size(); ++index)
  {
    const SceneObject& object = scene.Objects[index];
    double t = Infinity;
    Vec3 normal;
    bool hits = false;
    switch (object.Type)
    {
      case ObjectType::Grid:
        hits = IntersectGrid(object, a, d, t, normal);
        break;
      case ObjectType::Sphere:
        hits = IntersectSphere(a, d, object.A, object.Radius, t, normal);
        break;
      case ObjectType::Plane:
        hits = IntersectPlane(a, d, object.A, object.B, t, normal);
        break;
      case ObjectType::Box:
        hits = IntersectBox(a, d, object.A, object.B, t, normal);
        break;
      case ObjectType::Mesh:
        // Intersected by the CPU tracer (Embree), not here.
        break;
    }
    // Strictly smaller: a tie keeps the object listed first.
    if (hits && t < best)
    {
      found = true;
      best = t;
      hit.Fraction = t;
      hit.Normal = normal;
      hit.Object = static_cast<int>(index);
      hit.Primitive = -1;
    }
  }
  if (found)
  {
    hit.Position = a + hit.Fraction * d;
  }
  return found;
}

Vec3 SurfaceColor(const Scene& scene, const SceneHit& hit)
{
  if (hit.Object < 0 || hit.Object >= static_cast<int>(scene.Objects.size()))
  {
    return Vec3::Zero();
  }
  const SceneObject& object = scene.Objects[hit.Object];
  if (object.Type == ObjectType::Mesh && object.Mesh >= 0 &&
    object.Mesh < static_cast<int>(scene.Meshes.size()) && hit.Primitive >= 0)
  {
    const TriangleMesh& mesh = *scene.Meshes[object.Mesh];
    if (!mesh.Colors.empty() && static_cast<std::size_t>(hit.Primitive) < mesh.NumberOfTriangles())
    {
      const unsigned int* corner = &mesh.Triangles[3 * static_cast<std::size_t>(hit.Primitive)];
      const double w[3] = { 1.0 - hit.U - hit.V, hit.U, hit.V };
      Vec3 color = Vec3::Zero();
      for (int k = 0; k < 3; ++k)
      {
        const float* c = &mesh.Colors[3 * static_cast<std::size_t>(corner[k])];
        color += w[k] * Vec3(c[0], c[1], c[2]);
      }
      return color.cwiseMax(0.0).cwiseMin(1.0);
    }
  }
  const Material& material = object.Surface;
  switch (material.Type)
  {
    case MaterialType::Position:
    {
      Vec3 color;
      for (int axis = 0; axis < 3; ++axis)
      {
        const double lo = material.Bounds[2 * axis];
        const double width = material.Bounds[2 * axis + 1] - lo;
        color[axis] = width > 0 ? std::clamp((hit.Position[axis] - lo) / width, 0.0, 1.0) : 0.5;
      }
      return color;
    }
    case MaterialType::Solid:
      return material.Color;
    case MaterialType::Checker:
    {
      const double size = material.Size > 0 ? material.Size : 1.0;
      const double normalLength = hit.Normal.norm();
      const Vec3 inward = normalLength > 0 ? Vec3(-hit.Normal / normalLength) : Vec3(Vec3::Zero());
      const Vec3 q = hit.Position + (1e-6 * size) * inward;
      const double cells =
        std::floor(q.x() / size) + std::floor(q.y() / size) + std::floor(q.z() / size);
      return std::fmod(std::abs(cells), 2.0) == 0 ? material.Color : material.Color2;
    }
  }
  return Vec3::Zero();
}
//------------------------------------------------------------------------------
std::string CheckMesh(const TriangleMesh& mesh)
{
  const std::size_t points = mesh.NumberOfPoints();
  if (mesh.Points.size() % 3 != 0 || mesh.Triangles.size() % 3 != 0)
  {
    return "the point or triangle array is not a multiple of 3 long";
  }
  if (mesh.NumberOfTriangles() == 0)
  {
    return "the mesh has no triangles (empty, or only points and lines)";
  }
  if (!mesh.Normals.empty() && mesh.Normals.size() != mesh.Points.size())
  {
    return "the normal array does not match the points";
  }
  if (!mesh.Colors.empty() && mesh.Colors.size() != mesh.Points.size())
  {
    return "the colour array does not match the points";
  }
  for (std::size_t i = 0; i < mesh.Points.size(); ++i)
  {
    if (!std::isfinite(mesh.Points[i]))
    {
      return "point " + std::to_string(i / 3) + " has a coordinate that is not finite";
    }
  }
  for (std::size_t i = 0; i < mesh.Triangles.size(); ++i)
  {
    if (mesh.Triangles[i] >= points)
    {
      return "triangle " + std::to_string(i / 3) + " names point " +
        std::to_string(mesh.Triangles[i]) + " of " + std::to_string(points);
    }
  }
  return std::string();
}

namespace
{
void MeshBounds(const TriangleMesh& mesh, Vec3& lo, Vec3& hi)
{
  lo = Vec3::Constant(Infinity);
  hi = Vec3::Constant(-Infinity);
  for (std::size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      lo[axis] = std::min<double>(lo[axis], mesh.Points[3 * i + axis]);
      hi[axis] = std::max<double>(hi[axis], mesh.Points[3 * i + axis]);
    }
  }
}
}

void SetMesh(Scene& scene, std::size_t object, std::shared_ptr<const TriangleMesh> mesh)
{
  if (object >= scene.Objects.size() || scene.Objects[object].Type != ObjectType::Mesh)
  {
    throw SceneDefinitionError(
      "scene.objects[" + std::to_string(object) + "]: not a mesh object");
  }
  SceneObject& target = scene.Objects[object];
  const std::string where = "scene.objects[" + std::to_string(object) + "]" +
    (target.MeshFile.empty() ? std::string() : " (" + target.MeshFile + ")");
  if (!mesh)
  {
    throw SceneDefinitionError(where + ": no mesh");
  }
  const std::string problem = CheckMesh(*mesh);
  if (!problem.empty())
  {
    throw SceneDefinitionError(where + ": " + problem);
  }
  if (!target.HasMaterialBounds)
  {
    Vec3 lo;
    Vec3 hi;
    MeshBounds(*mesh, lo, hi);
    SetDefaultBounds(target.Surface, lo, hi);
  }
  if (target.Mesh >= 0 && target.Mesh < static_cast<int>(scene.Meshes.size()))
  {
    scene.Meshes[target.Mesh] = std::move(mesh);
  }
  else
  {
    target.Mesh = static_cast<int>(scene.Meshes.size());
    scene.Meshes.push_back(std::move(mesh));
  }
}

std::size_t AddMesh(
  Scene& scene, std::shared_ptr<const TriangleMesh> mesh, const Material& material, bool keepBounds)
{
  SceneObject object;
  object.Type = ObjectType::Mesh;
  object.Surface = material;
  object.HasMaterialBounds = keepBounds;
  scene.Objects.push_back(object);
  const std::size_t index = scene.Objects.size() - 1;
  try
  {
    SetMesh(scene, index, std::move(mesh));
  }
  catch (...)
  {
    scene.Objects.pop_back();
    throw;
  }
  return index;
}
} // namespace riemann
