#include "ProjectFile.h"

#include "IntegrationValues.h"
#include "PictureValues.h"

#include "RiemannPictureSettingsDeclaration.h"
#include "RungeKutta.h"

#include "PipelineItems.h"
#include "StudioDocument.h"

#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannScene.h"

#include "vtkRiemannPictureSettings.h"

#include "vtkCamera.h"
#include "vtkNew.h"

#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

#include <cmath>

namespace riemann
{
namespace studio
{
namespace
{
using Json = nlohmann::json;

[[noreturn]] void Fail(const std::string& where, const std::string& why)
{
  throw ProjectError(where + ": " + why);
}

const Json& Member(const Json& object, const char* key, const std::string& where)
{
  if (!object.is_object() || !object.contains(key))
  {
    Fail(where, std::string("missing \"") + key + "\"");
  }
  return object.at(key);
}

std::string String(const Json& value, const std::string& where)
{
  if (!value.is_string())
  {
    Fail(where, "expected a string");
  }
  return value.get<std::string>();
}

double Number(const Json& value, const std::string& where)
{
  if (!value.is_number() || !std::isfinite(value.get<double>()))
  {
    Fail(where, "expected a finite number");
  }
  return value.get<double>();
}

/// The camera settings' names, in the declaration's order.
std::vector<std::string> CameraSettingNames()
{
  std::vector<std::string> names;
  for (const riemann::SettingDeclaration& setting :
    riemann::declared::vtkRiemannPictureSettings::Settings)
  {
    if (vtkRiemannPictureSettings::IsCameraSetting(setting.Name))
    {
      names.push_back(setting.Name);
    }
  }
  return names;
}

/// A project's camera object ("observer", "layout.outside-camera"): the
/// picture settings' camera values (PictureValues.h), a view checked whole.
CameraState ParseCamera(const Json& value, const std::string& where)
{
  std::string error;
  CameraState camera;
  camera.Values = ReadPictureValues(value, CameraSettingNames(), where, error);
  if (!error.empty())
  {
    throw ProjectError(error);
  }
  const std::string why = CheckCameraValues(camera.Values);
  if (!why.empty())
  {
    Fail(where, why);
  }
  return camera;
}

void ParseMetric(const Json& metric, const std::string& folder, ProjectData& project)
{
  project.MetricText = String(Member(metric, "text", "metric"), "metric.text");
  // Relative data files of the metric (a sampled volume) are read from
  // "folder" (relative to the project's), else from the project's folder.
  project.MetricFolder = folder;
  if (metric.contains("folder"))
  {
    const QString given = QString::fromStdString(String(metric.at("folder"), "metric.folder"));
    project.MetricFolder = QFileInfo(given).isRelative()
      ? QDir::cleanPath(QDir(QString::fromStdString(folder)).absoluteFilePath(given)).toStdString()
      : given.toStdString();
  }
  if (metric.contains("parameter-values"))
  {
    const Json& values = metric.at("parameter-values");
    if (!values.is_object())
    {
      Fail("metric.parameter-values", "expected an object of JSON pointers to numbers");
    }
    for (const auto& entry : values.items())
    {
      project.ParameterValues[entry.key()] =
        Number(entry.value(), "metric.parameter-values." + entry.key());
    }
  }
  project.Time = metric.contains("time") ? Number(metric.at("time"), "metric.time") : 0.0;
  if (project.Time < 0.0 || project.Time > 1.0)
  {
    Fail("metric.time", "must be in [0, 1]");
  }
  // The metric itself, as the app would take it.
  vtkNew<vtkRiemannMetric> check;
  check->SetTime(project.Time);
  std::string effective;
  try
  {
    effective = project.ParameterValues.empty()
      ? project.MetricText
      : ApplyParameterValues(project.MetricText, project.ParameterValues);
  }
  catch (const std::exception& e)
  {
    Fail("metric.parameter-values", e.what());
  }
  if (!check->SetDefinition(effective.c_str(), project.MetricFolder.c_str()))
  {
    Fail("metric.text", check->GetLastError());
  }
}

void ParseScene(const Json& scene, const std::string& folder, ProjectData& project)
{
  project.SceneFile = scene.contains("file") ? String(scene.at("file"), "scene.file") : "";
  if (!project.SceneFile.empty() && QFileInfo(QString::fromStdString(project.SceneFile)).isRelative())
  {
    project.SceneFile = QDir::cleanPath(QDir(QString::fromStdString(folder))
                                          .absoluteFilePath(QString::fromStdString(project.SceneFile)))
                          .toStdString();
  }
  project.SceneText = scene.contains("text") ? String(scene.at("text"), "scene.text") : "";
  vtkNew<vtkRiemannScene> check;
  if (!project.SceneFile.empty() && QFileInfo::exists(QString::fromStdString(project.SceneFile)))
  {
    if (!check->SetDefinitionFile(project.SceneFile.c_str()))
    {
      Fail("scene.file", check->GetLastError());
    }
  }
  else if (!project.SceneText.empty())
  {
    project.SceneFile.clear();
    if (!check->SetDefinition(project.SceneText.c_str()))
    {
      Fail("scene.text", check->GetLastError());
    }
  }
  else if (!project.SceneFile.empty())
  {
    Fail("scene.file", "\"" + project.SceneFile + "\" does not exist and there is no text");
  }
}

void ParseInside(const Json& inside, ProjectData& project)
{
  // The renderer and its samples: declared picture settings (PictureValues.h).
  std::string error;
  const Json picture = ReadPictureValues(inside, { "Backend", "SamplesPerPixel" }, "inside", error);
  if (!error.empty())
  {
    throw ProjectError(error);
  }
  project.Backend = picture.at("Backend").get<std::string>();
  project.Samples = picture.at("SamplesPerPixel").get<int>();
  if (inside.contains("use-scene-settings"))
  {
    if (!inside.at("use-scene-settings").is_boolean())
    {
      Fail("inside.use-scene-settings", "expected true or false");
    }
    project.UseSceneSettings = inside.at("use-scene-settings").get<bool>();
  }
  if (inside.contains("integration"))
  {
    // vtkRiemannIntegrationSettings's properties, each in its declared
    // range (IntegrationValues.h).
    const Json& integration = inside.at("integration");
    if (!integration.is_object())
    {
      Fail("inside.integration", "expected an object");
    }
    for (const auto& entry : integration.items())
    {
      const std::string problem = CheckIntegrationValue(entry.key(), entry.value());
      if (!problem.empty())
      {
        Fail("inside.integration." + entry.key(), problem);
      }
    }
    project.Integration = integration;
  }
}

void ParseItems(const Json& items, ProjectData& project)
{
  if (!items.is_array())
  {
    Fail("items", "expected an array");
  }
  for (std::size_t i = 0; i < items.size(); ++i)
  {
    const std::string where = "items[" + std::to_string(i) + "]";
    ItemState state;
    state.Kind = String(Member(items[i], "kind", where), where + ".kind");
    state.Name = items[i].contains("name") ? String(items[i].at("name"), where + ".name") : state.Kind;
    if (items[i].contains("visible"))
    {
      if (!items[i].at("visible").is_boolean())
      {
        Fail(where + ".visible", "expected true or false");
      }
      state.Visible = items[i].at("visible").get<bool>();
    }
    state.Settings = items[i].contains("settings") ? items[i].at("settings") : Json::object();
    // The item's own checks, on a scratch item.
    std::unique_ptr<PipelineItem> scratch = MakePipelineItem(state.Kind, "check");
    if (!scratch)
    {
      Fail(where + ".kind", "unknown kind \"" + state.Kind + "\"");
    }
    const QString why = scratch->ApplySettings(state.Settings);
    if (!why.isEmpty())
    {
      Fail(where + ".settings", why.toStdString());
    }
    project.Items.push_back(state);
  }
}
}

CameraState::CameraState()
  : Values(CameraValues(nullptr))
{
}

void CameraState::From(vtkCamera* camera)
{
  this->Values = CameraValues(camera);
}

void CameraState::To(vtkCamera* camera) const
{
  ApplyCameraValues(this->Values, camera);
}

ProjectData CaptureProject(const StudioDocument& document)
{
  ProjectData project;
  project.MetricText = document.MetricText();
  project.MetricFolder = document.MetricDirectory();
  project.ParameterValues = document.ParameterValues();
  project.Time = document.Time();
  project.SceneFile = document.Scene()->GetDefinitionFile();
  project.SceneText = document.Scene()->GetDefinition();
  project.Observer.From(document.Observer());
  project.UseSceneSettings = document.UseSceneSettings();
  vtkRiemannIntegrationSettings* rays = document.RaySettings();
  project.Integration = IntegrationValues(rays);
  for (const auto& item : document.Items())
  {
    project.Items.push_back(
      { item->Kind(), item->Name().toStdString(), item->IsVisible(), item->Settings() });
  }
  return project;
}

std::string ProjectFingerprint(const StudioDocument& document)
{
  ProjectData project = CaptureProject(document);
  // A slider at the text's own number is no change: the same document
  // whether it was moved there or never moved.
  const Json text = Json::parse(project.MetricText, nullptr, false);
  for (auto value = project.ParameterValues.begin(); value != project.ParameterValues.end();)
  {
    const Json::json_pointer pointer(value->first);
    const bool same = text.is_object() && text.contains(pointer) && text.at(pointer).is_number() &&
      text.at(pointer).get<double>() == value->second;
    value = same ? project.ParameterValues.erase(value) : std::next(value);
  }
  Json json = ProjectToJson(project);
  json.erase("layout");
  return json.dump();
}

nlohmann::json ProjectToJson(const ProjectData& project, const std::string& folder)
{
  // Paths relative to the project file's folder, as Studio.md promises.
  const auto relative = [&folder](const std::string& path)
  {
    return folder.empty() || path.empty()
      ? path
      : QDir(QString::fromStdString(folder)).relativeFilePath(QString::fromStdString(path)).toStdString();
  };
  Json items = Json::array();
  for (const ItemState& item : project.Items)
  {
    items.push_back({ { "kind", item.Kind }, { "name", item.Name }, { "visible", item.Visible },
      { "settings", item.Settings } });
  }
  Json layout = { { "views", project.Views } };
  if (project.HasOutsideCamera)
  {
    layout["outside-camera"] = project.OutsideCamera.Values;
  }
  Json metric = { { "text", project.MetricText }, { "parameter-values", project.ParameterValues },
    { "time", project.Time } };
  if (!project.MetricFolder.empty())
  {
    const std::string metricFolder = relative(project.MetricFolder);
    metric["folder"] = metricFolder.empty() ? "." : metricFolder;
  }
  return { { "riemann-studio", 1 }, { "metric", metric },
    { "scene", { { "file", relative(project.SceneFile) }, { "text", project.SceneText } } },
    { "observer", project.Observer.Values },
    { "inside", { { "Backend", project.Backend }, { "SamplesPerPixel", project.Samples },
                  { "use-scene-settings", project.UseSceneSettings },
                  { "integration", project.Integration } } },
    { "items", items }, { "layout", layout } };
}

bool LooksLikeProject(const std::string& text)
{
  const Json root = Json::parse(text, nullptr, false);
  return root.is_object() && root.contains("riemann-studio");
}

ProjectData ParseProject(const std::string& text, const std::string& folder)
{
  Json root;
  try
  {
    root = Json::parse(text);
  }
  catch (const Json::exception& e)
  {
    std::string message = e.what();
    const std::size_t bracket = message.find("] ");
    throw ProjectError(
      "invalid JSON: " + (bracket == std::string::npos ? message : message.substr(bracket + 2)));
  }
  if (!root.is_object() || !root.contains("riemann-studio"))
  {
    throw ProjectError("not a Riemann Studio project (no \"riemann-studio\" key)");
  }
  if (root.at("riemann-studio") != 1)
  {
    Fail("riemann-studio", "unknown project version (this app reads version 1)");
  }
  for (const auto& entry : root.items())
  {
    static const char* const known[] = { "riemann-studio", "metric", "scene", "observer", "inside",
      "items", "layout" };
    if (std::find_if(std::begin(known), std::end(known),
          [&](const char* key) { return entry.key() == key; }) == std::end(known))
    {
      Fail(entry.key(), "unknown key");
    }
  }
  ProjectData project;
  ParseMetric(Member(root, "metric", "project"), folder, project);
  if (root.contains("scene"))
  {
    ParseScene(root.at("scene"), folder, project);
  }
  project.Observer = ParseCamera(Member(root, "observer", "project"), "observer");
  if (root.contains("inside"))
  {
    ParseInside(root.at("inside"), project);
  }
  if (root.contains("items"))
  {
    ParseItems(root.at("items"), project);
  }
  if (root.contains("layout"))
  {
    const Json& layout = root.at("layout");
    project.Views = layout.contains("views") ? String(layout.at("views"), "layout.views") : "both";
    if (project.Views != "both" && project.Views != "inside" && project.Views != "outside")
    {
      Fail("layout.views", "expected \"both\", \"inside\" or \"outside\"");
    }
    if (layout.contains("outside-camera"))
    {
      project.OutsideCamera = ParseCamera(layout.at("outside-camera"), "layout.outside-camera");
      project.HasOutsideCamera = true;
    }
  }
  return project;
}

QString ApplyProject(const ProjectData& project, StudioDocument& document)
{
  // The scene first: a scene naming a metric would replace the metric text.
  document.RemoveAllItems();
  QString error;
  if (!project.SceneFile.empty())
  {
    error = document.LoadSceneFile(QString::fromStdString(project.SceneFile));
  }
  else if (!project.SceneText.empty())
  {
    error = document.SetSceneText(project.SceneText);
  }
  else
  {
    document.ResetScene();
  }
  if (!error.isEmpty())
  {
    return QStringLiteral("scene: ") + error;
  }
  // A relative "file" in the metric (a sampled volume) is read from its folder.
  document.SetMetricDirectory(project.MetricFolder);
  MetricStatus status = document.SetMetricText(project.MetricText);
  for (const auto& value : project.ParameterValues)
  {
    if (status.Ok())
    {
      status = document.SetParameterValue(value.first, value.second);
    }
  }
  if (status.Ok())
  {
    status = document.SetTime(project.Time);
  }
  if (!status.Ok())
  {
    return QStringLiteral("metric: ") + status.Message;
  }
  vtkRiemannIntegrationSettings* rays = document.RaySettings();
  ApplyIntegrationValues(project.Integration, rays);
  document.SetUseSceneSettings(project.UseSceneSettings);
  project.Observer.To(document.Observer());
  document.ObserverChanged();
  for (const ItemState& state : project.Items)
  {
    std::unique_ptr<PipelineItem> item =
      MakePipelineItem(state.Kind, QString::fromStdString(state.Name));
    item->ApplySettings(state.Settings);
    item->SetVisible(state.Visible);
    document.AddItem(std::move(item));
  }
  return QString();
}

QString WriteFileAtomically(const QString& path, const QByteArray& bytes)
{
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly))
  {
    return QStringLiteral("%1: cannot write: %2").arg(path, file.errorString());
  }
  if (file.write(bytes) != bytes.size())
  {
    const QString why = file.errorString();
    file.cancelWriting();
    return QStringLiteral("%1: writing failed: %2").arg(path, why);
  }
  if (!file.commit())
  {
    return QStringLiteral("%1: writing failed: %2").arg(path, file.errorString());
  }
  return QString();
}
}
}
