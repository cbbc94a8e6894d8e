#include "CameraPathFile.h"

#include "JsonValidation.h"
#include "RiemannPictureSettingsDeclaration.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace riemann
{
namespace
{
using Json = nlohmann::json;

[[noreturn]] void Fail(const std::string& path, const std::string& message)
{
  json::Fail<CameraPathFileError>(path, message);
}

double Number(const Json& value, const std::string& path)
{
  if (!value.is_number() || !std::isfinite(value.get<double>()))
  {
    Fail(path, "expected a finite number, got " + json::Describe(value));
  }
  return value.get<double>();
}

double Positive(const Json& value, const std::string& path)
{
  const double number = Number(value, path);
  if (!(number > 0))
  {
    Fail(path, "expected a positive number, got " + json::Describe(value));
  }
  return number;
}

Vec3 Vector(const Json& value, const std::string& path)
{
  if (!value.is_array() || value.size() != 3)
  {
    Fail(path, "expected [x, y, z], got " + json::Describe(value));
  }
  return Vec3(
    Number(value[0], path + "[0]"), Number(value[1], path + "[1]"), Number(value[2], path + "[2]"));
}

/// A camera key of the file: the declared scene key of the picture setting
/// `name` (vtkRiemannPictureSettings.settings.json), as a scene's camera block has it.
const char* SceneKey(const char* name)
{
  return riemann::declared::vtkRiemannPictureSettings::Settings.Find(name)->SceneKey;
}

void ReadTime(const Json& value, const std::string& path, CameraPathFile& file)
{
  if (value.is_number())
  {
    file.TimeFrom = file.TimeTo = Number(value, path);
    return;
  }
  if (!value.is_array() || value.size() != 2)
  {
    Fail(path, "expected t or [t0, t1], got " + json::Describe(value));
  }
  file.TimeFrom = Number(value[0], path + "[0]");
  file.TimeTo = Number(value[1], path + "[1]");
}

Json ToJson(const Vec3& v)
{
  return Json::array({ v[0], v[1], v[2] });
}
/// ParseCameraPathFile, its errors not yet located in the text.
CameraPathFile ParseCameraPathText(const std::string& text, const std::string& where)
{
  const Json root = json::Parse<CameraPathFileError>(text, where, "");
  const char* position = SceneKey("Position");
  const char* lookAt = SceneKey("LookAt");
  const char* viewUp = SceneKey("ViewUp");
  const char* fov = SceneKey("ViewAngle");
  json::CheckKeys<CameraPathFileError>(
    root, where, { "path", position, lookAt, viewUp, fov, "length", "keys", "step", "time" });
  CameraPathFile file;
  CameraPathSettings& settings = file.Settings;
  const std::string kind = [&]() {
    const Json& value = json::Required<CameraPathFileError>(root, "path", where);
    if (!value.is_string())
    {
      Fail(where + ".path", "expected \"geodesic\" or \"spline\", got " + json::Describe(value));
    }
    return value.get<std::string>();
  }();
  if (kind == "geodesic")
  {
    settings.Kind = CameraPathKind::Geodesic;
    settings.Start.Position =
      Vector(json::Required<CameraPathFileError>(root, position, where), where + "." + position);
    settings.Start.LookAt =
      Vector(json::Required<CameraPathFileError>(root, lookAt, where), where + "." + lookAt);
    settings.Length =
      Positive(json::Required<CameraPathFileError>(root, "length", where), where + ".length");
    if (root.contains("keys"))
    {
      Fail(where + ".keys", "a geodesic path has no keys (it is \"path\": \"spline\"'s)");
    }
  }
  else if (kind == "spline")
  {
    settings.Kind = CameraPathKind::Spline;
    const Json& keys = json::Required<CameraPathFileError>(root, "keys", where);
    if (!keys.is_array() || keys.size() < 2)
    {
      Fail(where + ".keys", "expected at least 2 key positions, got " + json::Describe(keys));
    }
    for (size_t k = 0; k < keys.size(); ++k)
    {
      settings.Keys.push_back(Vector(keys[k], where + ".keys[" + std::to_string(k) + "]"));
    }
    for (const char* key : { position, lookAt, "length" })
    {
      if (root.contains(key))
      {
        Fail(where + "." + key,
          "a spline path starts at its first key and looks along the spline: no " +
            json::Quoted(key));
      }
    }
  }
  else
  {
    Fail(where + ".path", "unknown path " + json::Quoted(kind) + "; expected \"geodesic\" or \"spline\"");
  }
  if (root.contains(viewUp))
  {
    settings.Start.ViewUp = Vector(root.at(viewUp), where + "." + viewUp);
  }
  if (root.contains(fov))
  {
    settings.Start.ViewAngle = Positive(root.at(fov), where + "." + fov);
    file.ViewAngleGiven = true;
  }
  if (root.contains("step"))
  {
    settings.Step = Positive(root.at("step"), where + ".step");
  }
  if (root.contains("time"))
  {
    ReadTime(root.at("time"), where + ".time", file);
  }
  return file;
}
} // namespace

CameraPathFile ParseCameraPathFile(const std::string& text, const std::string& where)
{
  return LocatingErrorsIn(text, [&]() { return ParseCameraPathText(text, where); });
}

CameraPathFile ReadCameraPathFile(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  if (!in)
  {
    throw CameraPathFileError(fileName + ": cannot be read");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return ParseCameraPathFile(text.str(), fileName);
}

std::string CameraPathFileText(const CameraPathFile& file)
{
  const CameraPathSettings& settings = file.Settings;
  Json root;
  root["path"] = CameraPathKindName(settings.Kind);
  if (settings.Kind == CameraPathKind::Geodesic)
  {
    root[SceneKey("Position")] = ToJson(settings.Start.Position);
    root[SceneKey("LookAt")] = ToJson(settings.Start.LookAt);
    root["length"] = settings.Length;
  }
  else
  {
    root["keys"] = Json::array();
    for (const Vec3& key : settings.Keys)
    {
      root["keys"].push_back(ToJson(key));
    }
  }
  root[SceneKey("ViewUp")] = ToJson(settings.Start.ViewUp);
  root[SceneKey("ViewAngle")] = settings.Start.ViewAngle;
  root["step"] = settings.Step;
  root["time"] = Json::array({ file.TimeFrom, file.TimeTo });
  return root.dump(2) + "\n";
}
} // namespace riemann
