#include "StudioDocument.h"

#include "TimeRangeSampler.h"

#include "PipelineItems.h"

#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannObserverSettings.h"
#include "vtkRiemannScene.h"

#include "vtkAlgorithm.h"
#include "vtkCamera.h"

#include <algorithm>
#include <stdexcept>

namespace riemann
{
namespace studio
{
namespace
{
bool SameParameters(const std::vector<MetricParameter>& a, const std::vector<MetricParameter>& b)
{
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
    [](const MetricParameter& p, const MetricParameter& q) {
      return p.Pointer == q.Pointer && p.Name == q.Name && p.Value == q.Value &&
        p.Animated == q.Animated;
    });
}
}

const char* StudioDocument::DefaultMetricText()
{
  return R"json({
  "type": "graph",
  "name": "The paper's Gaussian bump",
  "description": "Graph of f = a exp(-|p|^2 / (2 s^2)) as a hypersurface of R^4.",
  "parameters": {"a": 1.0, "s": 0.5},
  "f": "a * exp(-(x^2 + y^2 + z^2) / (2 * s^2))"
}
)json";
}

StudioDocument::StudioDocument(QObject* parent)
  : QObject(parent)
{
  vtkRiemannSetRayDefaults(this->Rays);
  this->SetMetricText(DefaultMetricText());
  this->ResetObserver();
}

StudioDocument::~StudioDocument()
{
  this->Runner.Close();
}

MetricStatus StudioDocument::Install(
  const std::string& text, const std::map<std::string, double>& values)
{
  MetricStatus status;
  std::string effective;
  try
  {
    effective = values.empty() ? text : ApplyParameterValues(text, values);
  }
  catch (const std::exception& e)
  {
    status.Message = QString::fromStdString(e.what());
    return status;
  }
  if (!this->CurrentMetric->SetDefinition(effective.c_str(), this->MetricFolder.c_str()))
  {
    status.Message = QString::fromStdString(this->CurrentMetric->GetLastError());
    // The parser located the error in the text it read. Parameter values
    // only change number tokens, so the failing path is the same in the
    // user's text; its line and column are found there.
    JsonErrorPlace place = this->CurrentMetric->GetLastErrorPlace();
    if (!values.empty())
    {
      LocateJsonError(text, place);
    }
    status.Location = place.Text;
  }
  return status;
}

MetricStatus StudioDocument::SetMetricText(const std::string& text)
{
  const std::vector<MetricParameter> parameters = FindMetricParameters(text);
  // Slider values survive an edit of the text elsewhere; a parameter whose
  // value was typed anew in the text takes the typed value.
  std::map<std::string, double> values;
  for (const MetricParameter& parameter : parameters)
  {
    auto old = std::find_if(this->TextParameters.begin(), this->TextParameters.end(),
      [&](const MetricParameter& p) { return p.Pointer == parameter.Pointer; });
    auto value = this->Values.find(parameter.Pointer);
    if (!parameter.Animated && old != this->TextParameters.end() &&
      old->Value == parameter.Value && value != this->Values.end())
    {
      values.insert(*value);
    }
  }
  MetricStatus status = this->Install(text, values);
  if (!status.Ok())
  {
    return status;
  }
  const bool newParameters = !SameParameters(parameters, this->TextParameters);
  this->Text = text;
  this->TextParameters = parameters;
  this->Values = values;
  if (newParameters)
  {
    Q_EMIT this->ParametersChanged();
  }
  Q_EMIT this->MetricChanged();
  this->RunDependents(true, false, false);
  return status;
}

std::string StudioDocument::EffectiveMetricText() const
{
  return this->Values.empty() ? this->Text : ApplyParameterValues(this->Text, this->Values);
}

double StudioDocument::ParameterValue(const std::string& pointer) const
{
  auto value = this->Values.find(pointer);
  if (value != this->Values.end())
  {
    return value->second;
  }
  for (const MetricParameter& parameter : this->TextParameters)
  {
    if (parameter.Pointer == pointer)
    {
      return parameter.Value;
    }
  }
  return 0.0;
}

MetricStatus StudioDocument::SetParameterValue(const std::string& pointer, double value)
{
  std::map<std::string, double> values = this->Values;
  values[pointer] = value;
  MetricStatus status = this->Install(this->Text, values);
  if (status.Ok())
  {
    this->Values = values;
    Q_EMIT this->MetricChanged();
    this->RunDependents(true, false, false);
  }
  return status;
}

MetricStatus StudioDocument::SetTime(double t)
{
  MetricStatus status;
  if (!this->CurrentMetric->SetTime(t))
  {
    status.Message = QString::fromStdString(this->CurrentMetric->GetLastError());
    return status;
  }
  Q_EMIT this->MetricChanged();
  this->RunDependents(true, false, false);
  return status;
}

double StudioDocument::Time() const
{
  return this->CurrentMetric->GetTime();
}

QString StudioDocument::SetSceneText(const std::string& text)
{
  vtkNew<vtkRiemannScene> scene;
  if (!scene->SetDefinition(text.c_str()))
  {
    return QString::fromStdString(scene->GetLastError());
  }
  if (scene->HasMetricDefinition())
  {
    this->MetricFolder = scene->GetSceneSnapshot()->MetricDirectory;
    const MetricStatus status = this->SetMetricText(scene->GetMetricDefinition());
    if (!status.Ok())
    {
      return QStringLiteral("the scene's metric: ") + status.Message;
    }
  }
  this->CurrentScene->ShallowCopy(scene);
  this->ResetObserver();
  Q_EMIT this->SceneChanged();
  this->RunDependents(false, true, false);
  return QString();
}

QString StudioDocument::LoadSceneFile(const QString& path)
{
  vtkNew<vtkRiemannScene> scene;
  if (!scene->SetDefinitionFile(path.toLocal8Bit().constData()))
  {
    return QString::fromStdString(scene->GetLastError());
  }
  if (scene->HasMetricDefinition())
  {
    const MetricStatus status = this->SetMetricText(scene->GetMetricDefinition());
    if (!status.Ok())
    {
      return path + QStringLiteral(": the scene's metric: ") + status.Message;
    }
  }
  this->CurrentScene->ShallowCopy(scene);
  this->ResetObserver();
  Q_EMIT this->SceneChanged();
  this->RunDependents(false, true, false);
  return QString();
}

void StudioDocument::ResetScene()
{
  vtkNew<vtkRiemannScene> undefined;
  this->CurrentScene->ShallowCopy(undefined);
  this->ResetObserver();
  Q_EMIT this->SceneChanged();
  this->RunDependents(false, true, false);
}

void StudioDocument::ResetObserver()
{
  // Without a camera of its own, the observer's defaults (the declared
  // picture settings', as `riemann render` and a scene's camera block take them).
  if (!this->CurrentScene->ApplyCamera(this->ObserverCamera))
  {
    vtkRiemannScene::ApplyDefaultCamera(this->ObserverCamera);
  }
  this->ObserverChanged();
}

void StudioDocument::ObserverChanged()
{
  Q_EMIT this->ObserverMoved();
  this->RunDependents(false, false, true);
}

void StudioDocument::SetUseSceneSettings(bool use)
{
  if (use != this->SceneSettings)
  {
    this->SceneSettings = use;
    this->RunDependents(false, true, false);
  }
}

void StudioDocument::SetViewSize(int width, int height)
{
  if (width > 0 && height > 0 && (width != this->Width || height != this->Height))
  {
    this->Width = width;
    this->Height = height;
    this->RunDependents(false, false, true);
  }
}

PipelineItem* StudioDocument::AddItem(std::unique_ptr<PipelineItem> item)
{
  if (!item)
  {
    return nullptr;
  }
  PipelineItem* added = item.get();
  this->ItemList.push_back(std::move(item));
  QObject::connect(added, &PipelineItem::SettingsChanged, this, [this, added](bool needsRun) {
    if (needsRun)
    {
      this->Run(added);
    }
    else
    {
      this->SampleTimeRange(added); // the colouring array or range may have changed
    }
  });
  QObject::connect(added, &PipelineItem::VisibilityChanged, this, [this, added]() {
    if (added->IsVisible() && this->Stale.count(added) > 0)
    {
      this->Run(added);
    }
  });
  Q_EMIT this->ItemAdded(added);
  this->Run(added);
  return added;
}

PipelineItem* StudioDocument::AddItem(const std::string& kind)
{
  return this->AddItem(MakePipelineItem(kind, this->UniqueName(PipelineItemLabel(kind).remove(' '))));
}

void StudioDocument::RemoveItem(PipelineItem* item)
{
  const int index = this->IndexOf(item);
  if (index < 0)
  {
    return;
  }
  this->Stale.erase(item);
  this->Computed.erase(item);
  this->UserCancelled.erase(item);
  this->Runner.Cancel(item);
  this->Runner.Cancel(item->TimeRangeKey());
  std::unique_ptr<PipelineItem> removed = std::move(this->ItemList[index]);
  this->ItemList.erase(this->ItemList.begin() + index);
  this->Errors.erase(item);
  Q_EMIT this->ItemRemoved(item);
  // Deleted later: a queued signal of the item may still be on its way.
  removed.release()->deleteLater();
}

void StudioDocument::RemoveAllItems()
{
  while (!this->ItemList.empty())
  {
    this->RemoveItem(this->ItemList.back().get());
  }
}

int StudioDocument::IndexOf(const PipelineItem* item) const
{
  for (std::size_t i = 0; i < this->ItemList.size(); ++i)
  {
    if (this->ItemList[i].get() == item)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}

QString StudioDocument::UniqueName(const QString& base) const
{
  for (int n = 1;; ++n)
  {
    const QString name = base + QString::number(n);
    const bool used = std::any_of(this->ItemList.begin(), this->ItemList.end(),
      [&](const std::unique_ptr<PipelineItem>& item) { return item->Name() == name; });
    if (!used)
    {
      return name;
    }
  }
}

JobInputs StudioDocument::MakeJobInputs() const
{
  JobInputs inputs;
  inputs.Metric = this->CurrentMetric;
  inputs.Scene = this->CurrentScene;
  inputs.Observer = this->ObserverCamera;
  inputs.Width = this->Width;
  inputs.Height = this->Height;
  inputs.RaySettings = this->Rays;
  inputs.UseSceneSettings = this->SceneSettings;
  return inputs;
}

void StudioDocument::Run(PipelineItem* item)
{
  if (this->IndexOf(item) < 0 || !this->CurrentMetric->HasDefinition())
  {
    return;
  }
  // A hidden item does not compute (a 200,000-direction locus nobody sees
  // would hold the cores): it is stale, and computes when shown again.
  if (!item->IsVisible())
  {
    this->Stale.insert(item);
    return;
  }
  this->Stale.erase(item);
  vtkSmartPointer<vtkAlgorithm> job = item->MakeJob(this->MakeJobInputs());
  const nlohmann::json started = item->Settings();
  this->Runner.Start(item, std::move(job), item->Name(),
    [this, item, started](vtkAlgorithm* finished, bool ok, const QString& error) {
      if (this->IndexOf(item) < 0)
      {
        return; // removed meanwhile
      }
      const bool cancelledByUser = this->UserCancelled.erase(item) > 0;
      if (ok)
      {
        this->Errors.erase(item);
        this->Computed[item] = started;
        item->TakeResult(finished);
        this->SampleTimeRange(item);
      }
      else if (cancelledByUser && error.isEmpty() && this->Computed.count(item) > 0)
      {
        item->RevertSettings(this->Computed.at(item));
      }
      else if (!error.isEmpty())
      {
        this->Errors[item] = error;
      }
      Q_EMIT this->ItemFinished(item, ok);
    });
}

namespace
{
/// What an item's range over time depends on: its job's settings (not the
/// display's), its colouring array, and the metric with its parameter
/// values (not t).
std::string TimeRangeSource(const PipelineItem& item, const std::string& metric)
{
  nlohmann::json settings = item.Settings();
  for (const PropertySpec& spec : item.Properties())
  {
    if (spec.Display && spec.Key != "ColorArray")
    {
      settings.erase(spec.Key);
    }
  }
  return settings.dump() + "\n" + metric;
}
}

void StudioDocument::SampleTimeRange(PipelineItem* item)
{
  // Most items do not colour over time: nothing to describe or compare
  // (this runs after every job an item finishes).
  if (!item->ColoursOverTime() || !item->IsVisible() || !this->CurrentMetric->HasDefinition())
  {
    return;
  }
  const std::string source = TimeRangeSource(*item, this->EffectiveMetricText());
  if (!item->NeedsTimeRange(source))
  {
    return;
  }
  // One filter per t, made here on the GUI thread, each with its own metric.
  auto sampler = vtkSmartPointer<TimeRangeSampler>::New();
  sampler->SetArrayName(item->Settings().at("ColorArray").get<std::string>());
  for (int k = 0; k < TimeRangeSampler::NumberOfTimes; ++k)
  {
    vtkNew<vtkRiemannMetric> metric;
    metric->ShallowCopy(this->CurrentMetric);
    if (!metric->SetTime(static_cast<double>(k) / (TimeRangeSampler::NumberOfTimes - 1)))
    {
      return;
    }
    JobInputs inputs = this->MakeJobInputs();
    inputs.Metric = metric;
    sampler->AddJob(item->MakeJob(inputs));
  }
  this->Runner.Start(item->TimeRangeKey(), std::move(sampler), item->Name() + ": colour range over t",
    [this, item, source](vtkAlgorithm* finished, bool ok, const QString&) {
      double range[2];
      if (ok && this->IndexOf(item) >= 0 && TimeRangeSampler::GetRange(finished->GetOutputDataObject(0), range))
      {
        item->SetTimeRange(range, source);
      }
    });
}

void StudioDocument::CancelAll()
{
  for (const auto& item : this->ItemList)
  {
    if (this->Runner.IsRunning(item.get()))
    {
      this->UserCancelled.insert(item.get());
    }
  }
  this->Runner.CancelAll();
}

void StudioDocument::RunAll()
{
  for (const auto& item : this->ItemList)
  {
    this->Run(item.get());
  }
}

QString StudioDocument::ItemError(const PipelineItem* item) const
{
  auto error = this->Errors.find(item);
  return error == this->Errors.end() ? QString() : error->second;
}

void StudioDocument::RunDependents(bool metric, bool scene, bool observer)
{
  for (const auto& item : this->ItemList)
  {
    if (metric || (scene && item->UsesScene()) || (observer && item->FollowsObserver()))
    {
      this->Run(item.get());
    }
  }
}
}
}
