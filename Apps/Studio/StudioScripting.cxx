#include "StudioScripting.h"

#include "AnimationExport.h"
#include "DocumentHistory.h"
#include "JobRunner.h"
#include "MetricEditor.h"
#include "PipelineBrowser.h"
#include "PictureValues.h"
#include "PipelineItem.h"
#include "ProjectFile.h"
#include "PythonTrace.h"
#include "StudioDocument.h"
#include "StudioMainWindow.h"

#include "RiemannPictureSettingsDeclaration.h"
#include "SettingValues.h"

#include "vtkRiemannPictureSettings.h"

#include "vtkCamera.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QUndoStack>

#include <map>
#include <stdexcept>

namespace riemann
{
namespace studio
{
namespace
{
using Json = nlohmann::json;

[[noreturn]] void Fail(const QString& message)
{
  throw std::runtime_error(message.toStdString());
}

const Json& Argument(const Json& args, size_t index)
{
  static const Json none;
  return index < args.size() ? args[index] : none;
}

QString Text(const Json& args, size_t index, const char* what)
{
  const Json& value = Argument(args, index);
  if (!value.is_string())
  {
    Fail(QStringLiteral("%1: expected a string, got %2").arg(what).arg(QString::fromStdString(value.dump())));
  }
  return QString::fromStdString(value.get<std::string>());
}

PipelineItem* ItemNamed(StudioDocument* document, const QString& name)
{
  for (const auto& item : document->Items())
  {
    if (item->Name() == name)
    {
      return item.get();
    }
  }
  QStringList names;
  for (const auto& item : document->Items())
  {
    names << "\"" + item->Name() + "\"";
  }
  Fail("no item named \"" + name + "\"" +
    (names.isEmpty() ? QStringLiteral(" (the pipeline is empty)") : "; items: " + names.join(", ")));
}

/// Properties applied as the properties panel applies them: all or none.
void Apply(PipelineItem* item, const Json& properties)
{
  if (!properties.is_object())
  {
    Fail("properties must be keyword arguments");
  }
  if (properties.empty())
  {
    return;
  }
  const QString error = item->ApplySettings(properties);
  if (!error.isEmpty())
  {
    Fail(item->Name() + ": " + error);
  }
}

StudioMainWindow::Shot ShotNamed(const QString& view)
{
  if (view == "inside")
  {
    return StudioMainWindow::InsideShot;
  }
  if (view == "outside")
  {
    return StudioMainWindow::OutsideShot;
  }
  if (view == "both")
  {
    return StudioMainWindow::BothShot;
  }
  if (view == "window")
  {
    return StudioMainWindow::WindowShot;
  }
  Fail("view \"" + view + "\": expected \"inside\", \"outside\", \"both\" or \"window\"");
}

void ReadSize(const Json& size, AnimationSettings& settings)
{
  if (!size.is_array() || size.size() != 2 || !size[0].is_number_integer() || !size[1].is_number_integer())
  {
    Fail(QStringLiteral("size: expected (width, height), got %1").arg(QString::fromStdString(size.dump())));
  }
  settings.Width = size[0].get<int>();
  settings.Height = size[1].get<int>();
}

/// The history knows every change made so far (it compares after events).
void Settled(StudioMainWindow& window)
{
  window.UndoHistory()->Record();
}

using StudioFunction = Json (*)(StudioMainWindow&, const Json&);

Json StudioOpen(StudioMainWindow& window, const Json& args)
{
  const QString error = window.OpenFile(Text(args, 0, "path"), false);
  if (!error.isEmpty())
  {
    Fail(error);
  }
  return nullptr;
}

Json StudioItems(StudioMainWindow& window, const Json&)
{
  StudioDocument* document = window.Document();
  Json names = Json::array();
  for (const auto& item : document->Items())
  {
    names.push_back(item->Name().toStdString());
  }
  return names;
}

Json StudioAdd(StudioMainWindow& window, const Json& args)
{
  StudioDocument* document = window.Document();
  const std::string kind = Text(args, 0, "kind").toStdString();
  PipelineItem* item = document->AddItem(kind);
  if (!item)
  {
    Fail(QString::fromStdString("unknown kind \"" + kind + "\""));
  }
  try
  {
    Apply(item, Argument(args, 1).is_null() ? Json::object() : Argument(args, 1));
  }
  catch (const std::runtime_error&)
  {
    document->RemoveItem(item);
    throw;
  }
  Settled(window);
  return item->Name().toStdString();
}

Json StudioSet(StudioMainWindow& window, const Json& args)
{
  StudioDocument* document = window.Document();
  Apply(ItemNamed(document, Text(args, 0, "item")), Argument(args, 1));
  Settled(window);
  return nullptr;
}

Json StudioGet(StudioMainWindow& window, const Json& args)
{
  StudioDocument* document = window.Document();
  PipelineItem* item = ItemNamed(document, Text(args, 0, "item"));
  Json settings = item->Settings();
  settings["kind"] = item->Kind();
  settings["class"] = item->FilterClass();
  if (!item->Preset().empty())
  {
    settings["preset"] = item->Preset();
  }
  settings["visible"] = item->IsVisible();
  return settings;
}

/// The item's form as the properties panel shows it (ParaView's ListProperties).
Json StudioProperties(StudioMainWindow& window, const Json& args)
{
  static const char* const types[] = { "number", "integer", "vector3", "numbers6", "integers3",
    "choice", "boolean", "number_list", "point_list" };
  PipelineItem* item = ItemNamed(window.Document(), Text(args, 0, "item"));
  Json fields = Json::array();
  for (const PropertySpec& spec : item->Properties())
  {
    Json choices = Json::array();
    for (const QString& choice : spec.Choices)
    {
      choices.push_back(choice.toStdString());
    }
    fields.push_back({ { "key", spec.Key }, { "label", spec.Label.toStdString() },
      { "type", types[spec.Type] }, { "minimum", spec.Minimum }, { "maximum", spec.Maximum },
      { "minimum_exclusive", spec.MinimumExclusive },
      { "maximum_exclusive", spec.MaximumExclusive }, { "non_zero", spec.NonZero },
      { "choices", choices }, { "help", spec.Help.toStdString() }, { "display", spec.Display } });
  }
  return fields;
}

/// The Python script that rebuilds the session (File > Export > Python Script).
Json StudioPythonScript(StudioMainWindow& window, const Json&)
{
  return PythonScript(*window.Document());
}

Json StudioRemove(StudioMainWindow& window, const Json& args)
{
  StudioDocument* document = window.Document();
  document->RemoveItem(ItemNamed(document, Text(args, 0, "item")));
  Settled(window);
  return nullptr;
}

Json StudioShow(StudioMainWindow& window, const Json& args)
{
  StudioDocument* document = window.Document();
  ItemNamed(document, Text(args, 0, "item"))->SetVisible(Argument(args, 1).get<bool>());
  Settled(window);
  return nullptr;
}

Json StudioMetric(StudioMainWindow& window, const Json& args)
{
  StudioDocument* document = window.Document();
  if (!Argument(args, 0).is_null())
  {
    const QString error = window.Editor()->SetText(Text(args, 0, "text"));
    if (!error.isEmpty())
    {
      Fail("metric: " + error);
    }
    Settled(window);
  }
  return document->MetricText();
}

Json StudioTime(StudioMainWindow& window, const Json& args)
{
  StudioDocument* document = window.Document();
  const Json& t = Argument(args, 0);
  if (!t.is_null())
  {
    if (!t.is_number())
    {
      Fail("time: expected a number");
    }
    const MetricStatus status = document->SetTime(t.get<double>());
    if (!status.Ok())
    {
      Fail("time: " + status.Message);
    }
    Settled(window);
  }
  return document->Time();
}

Json StudioRename(StudioMainWindow& window, const Json& args)
{
  StudioDocument* document = window.Document();
  PipelineItem* item = ItemNamed(document, Text(args, 0, "item"));
  const QString newName = Text(args, 1, "name").trimmed();
  if (newName.isEmpty())
  {
    Fail("rename: an item's name cannot be empty");
  }
  item->SetName(newName);
  Settled(window);
  return item->Name().toStdString();
}

Json StudioParameter(StudioMainWindow& window, const Json& args)
{
  StudioDocument* document = window.Document();
  const std::string pointer = Text(args, 0, "parameter").toStdString();
  bool known = false;
  for (const MetricParameter& parameter : document->Parameters())
  {
    known = known || parameter.Pointer == pointer;
  }
  if (!known)
  {
    Fail(QString::fromStdString("no parameter \"" + pointer +
      "\" in the metric (parameters are named by their JSON pointer, e.g. \"/parameters/a\")"));
  }
  const Json& value = Argument(args, 1);
  if (value.is_number())
  {
    const MetricStatus status = document->SetParameterValue(pointer, value.get<double>());
    if (!status.Ok())
    {
      Fail("parameter: " + status.Message);
    }
    Settled(window);
  }
  return document->ParameterValue(pointer);
}

/// observer(position, look_at, view_up): the camera's points and direction,
/// named as a scene's camera block names them (the declared scene keys).
Json StudioObserver(StudioMainWindow& window, const Json& args)
{
  StudioDocument* document = window.Document();
  vtkCamera* observer = document->Observer();
  const Json& given = Argument(args, 0);
  const Json current = CameraValues(observer);
  Json changes = Json::object();
  Json result = Json::object();
  for (const riemann::SettingDeclaration& setting :
    riemann::declared::vtkRiemannPictureSettings::Settings)
  {
    if (!vtkRiemannPictureSettings::IsCameraSetting(setting.Name) || !current.at(setting.Name).is_array())
    {
      continue; // the view angle is the form's
    }
    const char* key = setting.SceneKey;
    result[key] = current.at(setting.Name);
    if (given.is_object() && given.contains(key) && !given.at(key).is_null())
    {
      const std::string why = riemann::CheckSettingValue(setting, given.at(key), key);
      if (!why.empty())
      {
        Fail(QStringLiteral("observer: %1").arg(QString::fromStdString(why)));
      }
      changes[setting.Name] = given.at(key);
    }
  }
  if (changes.empty())
  {
    return result;
  }
  const std::string refused = ApplyCameraValues(changes, observer);
  if (!refused.empty())
  {
    Fail(QStringLiteral("observer: %1").arg(QString::fromStdString(refused)));
  }
  document->ObserverChanged();
  Settled(window);
  const Json moved = CameraValues(observer);
  for (const riemann::SettingDeclaration& setting :
    riemann::declared::vtkRiemannPictureSettings::Settings)
  {
    if (result.contains(setting.SceneKey))
    {
      result[setting.SceneKey] = moved.at(setting.Name);
    }
  }
  return result;
}

/// undo() and redo(): the step's name, or null when there is none.
Json UndoOrRedo(StudioMainWindow& window, bool undo)
{
  Settled(window);
  QUndoStack* stack = window.UndoStack();
  const bool can = undo ? stack->canUndo() : stack->canRedo();
  const std::string text = (undo ? stack->undoText() : stack->redoText()).toStdString();
  if (can)
  {
    undo ? stack->undo() : stack->redo();
  }
  return can ? Json(text) : Json(nullptr);
}

Json StudioUndo(StudioMainWindow& window, const Json&)
{
  return UndoOrRedo(window, true);
}

Json StudioRedo(StudioMainWindow& window, const Json&)
{
  return UndoOrRedo(window, false);
}

Json StudioSave(StudioMainWindow& window, const Json& args)
{
  const QString error = window.SaveProject(Text(args, 0, "path"));
  if (!error.isEmpty())
  {
    Fail(error);
  }
  return nullptr;
}

Json StudioProject(StudioMainWindow& window, const Json&)
{
  StudioDocument* document = window.Document();
  return Json::parse(ProjectFingerprint(*document));
}

Json StudioScreenshot(StudioMainWindow& window, const Json& args)
{
  const QString path = Text(args, 0, "path");
  const StudioMainWindow::Shot view = ShotNamed(Text(args, 1, "view"));
  QString error;
  if (Argument(args, 2).is_null() || view == StudioMainWindow::WindowShot)
  {
    error = window.SaveScreenshot(path, view);
  }
  else
  {
    AnimationSettings picture;
    picture.Frames = 1;
    picture.AnimateTime = false;
    picture.View = view;
    picture.Output = path;
    ReadSize(Argument(args, 2), picture);
    error = ExportAnimation(window, picture);
  }
  if (!error.isEmpty())
  {
    Fail(error);
  }
  return nullptr;
}

Json StudioExportAnimation(StudioMainWindow& window, const Json& args)
{
  AnimationSettings animation;
  animation.Output = Text(args, 0, "path");
  const Json& options = Argument(args, 1);
  animation.Frames = options.value("frames", animation.Frames);
  animation.View = ShotNamed(QString::fromStdString(options.value("view", std::string("inside"))));
  if (options.contains("size"))
  {
    ReadSize(options.at("size"), animation);
  }
  const Json time = options.value("time", Json::array({ 0.0, 1.0 }));
  animation.AnimateTime = !time.is_null();
  if (animation.AnimateTime)
  {
    animation.TimeFrom = time.at(0).get<double>();
    animation.TimeTo = time.at(1).get<double>();
  }
  animation.CameraPath = QString::fromStdString(options.value("camera_path", std::string()));
  const QString error = ExportAnimation(window, animation);
  if (!error.isEmpty())
  {
    Fail(error);
  }
  return nullptr;
}

Json StudioSelect(StudioMainWindow& window, const Json& args)
{
  StudioDocument* document = window.Document();
  const Json& item = Argument(args, 0);
  if (item.is_null())
  {
    window.Browser()->SelectMetric();
  }
  else
  {
    window.Browser()->Select(ItemNamed(document, Text(args, 0, "item")));
  }
  return nullptr;
}

Json StudioDock(StudioMainWindow& window, const Json& args)
{
  const QString which = Text(args, 0, "dock");
  QDockWidget* dock = which == "python" ? window.PythonShellDock()
    : which == "spreadsheet"            ? window.SpreadsheetDock()
                                        : nullptr;
  if (!dock)
  {
    Fail("dock \"" + which + "\": expected \"python\" or \"spreadsheet\"");
  }
  dock->setVisible(Argument(args, 1).get<bool>());
  const Json& height = Argument(args, 2);
  if (height.is_number_integer() && height.get<int>() > 0)
  {
    window.resizeDocks({ dock }, { height.get<int>() }, Qt::Vertical);
  }
  return nullptr;
}

Json StudioWait(StudioMainWindow&, const Json& args)
{
  const Json& seconds = Argument(args, 0);
  if (!seconds.is_number() || !(seconds.get<double>() >= 0) || seconds.get<double>() > 3600)
  {
    Fail("wait: expected seconds from 0 to 3600");
  }
  // The window goes on meanwhile: events, finished jobs, pictures.
  QElapsedTimer timer;
  timer.start();
  const qint64 milliseconds = static_cast<qint64>(seconds.get<double>() * 1000.0);
  do
  {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
  } while (timer.elapsed() < milliseconds);
  return nullptr;
}

Json StudioCancel(StudioMainWindow& window, const Json&)
{
  StudioDocument* document = window.Document();
  document->CancelAll();
  return nullptr;
}

Json StudioRunning(StudioMainWindow& window, const Json&)
{
  StudioDocument* document = window.Document();
  return document->Jobs()->NumberOfRunningJobs();
}

Json StudioRender(StudioMainWindow& window, const Json&)
{
  window.Settle();
  return nullptr;
}

/// The studio module's functions, by name (StudioPython.cxx's Python side
/// calls them with its arguments as a JSON list).
const std::map<std::string, StudioFunction>& StudioFunctions()
{
  static const std::map<std::string, StudioFunction> functions{
    { "open", StudioOpen },
    { "items", StudioItems },
    { "add", StudioAdd },
    { "set", StudioSet },
    { "get", StudioGet },
    { "properties", StudioProperties },
    { "python", StudioPythonScript },
    { "remove", StudioRemove },
    { "show", StudioShow },
    { "metric", StudioMetric },
    { "time", StudioTime },
    { "rename", StudioRename },
    { "parameter", StudioParameter },
    { "observer", StudioObserver },
    { "undo", StudioUndo },
    { "redo", StudioRedo },
    { "save", StudioSave },
    { "project", StudioProject },
    { "screenshot", StudioScreenshot },
    { "export_animation", StudioExportAnimation },
    { "select", StudioSelect },
    { "dock", StudioDock },
    { "wait", StudioWait },
    { "cancel", StudioCancel },
    { "running", StudioRunning },
    { "render", StudioRender },
  };
  return functions;
}
} // namespace

Json CallStudio(StudioMainWindow& window, const std::string& name, const Json& args)
{
  const auto& functions = StudioFunctions();
  const auto function = functions.find(name);
  if (function == functions.end())
  {
    Fail(QString::fromStdString("studio has no function \"" + name + "\""));
  }
  return function->second(window, args);
}
}
}
