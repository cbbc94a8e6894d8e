#include "PipelineItem.h"

#include "SettingRange.h" // For ShortestNumberText

#include "DeclaredProperties.h"
#include "RiemannIntegrationSettingsDeclaration.h"
#include "RungeKutta.h"

#include "ColorMaps.h"
#include "IntegrationValues.h"
#include "OutputDisplay.h"

#include "vtkNew.h"
#include "vtkRiemannIntegrationSettings.h"

#include "vtkAlgorithm.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkCellData.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace riemann
{
namespace studio
{
namespace
{
bool IsFiniteNumber(const nlohmann::json& value)
{
  return value.is_number() && std::isfinite(value.get<double>());
}

/// "is below 0" / "must be > 0" style text of the allowed range.
QString RangeText(const PropertySpec& spec)
{
  const QString low = spec.MinimumExclusive ? QStringLiteral("> %1") : QStringLiteral(">= %1");
  if (spec.Maximum >= 1e299)
  {
    return low.arg(spec.Minimum);
  }
  if (spec.Minimum <= -1e299)
  {
    return (spec.MaximumExclusive ? QStringLiteral("< %1") : QStringLiteral("<= %1")).arg(spec.Maximum);
  }
  return QStringLiteral("in %1%2, %3%4")
    .arg(spec.MinimumExclusive ? "(" : "[")
    .arg(spec.Minimum)
    .arg(spec.Maximum)
    .arg(spec.MaximumExclusive ? ")" : "]");
}

QString CheckNumber(const PropertySpec& spec, const nlohmann::json& value, bool whole)
{
  if (!IsFiniteNumber(value))
  {
    return QStringLiteral("expected a finite number");
  }
  const double v = value.get<double>();
  if (whole && v != std::floor(v))
  {
    return QStringLiteral("expected a whole number");
  }
  const bool low = spec.MinimumExclusive ? v <= spec.Minimum : v < spec.Minimum;
  const bool high = spec.MaximumExclusive ? v >= spec.Maximum : v > spec.Maximum;
  if (low || high)
  {
    return QStringLiteral("must be %1").arg(RangeText(spec));
  }
  return QString();
}

QString CheckList(const PropertySpec& spec, const nlohmann::json& value, int count, bool whole)
{
  if (!value.is_array() || static_cast<int>(value.size()) != count)
  {
    return QStringLiteral("expected %1 numbers").arg(count);
  }
  bool allZero = true;
  for (int i = 0; i < count; ++i)
  {
    const QString why = CheckNumber(spec, value[i], whole);
    if (!why.isEmpty())
    {
      return QStringLiteral("number %1: %2").arg(i + 1).arg(why);
    }
    allZero = allZero && value[i].get<double>() == 0.0;
  }
  if (spec.NonZero && allZero)
  {
    return QStringLiteral("a direction cannot be (0, 0, 0)");
  }
  if (spec.Type == PropertySpec::Numbers6)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      if (!(value[2 * axis].get<double>() < value[2 * axis + 1].get<double>()))
      {
        return QStringLiteral("bounds must be x0 < x1, y0 < y1, z0 < z1");
      }
    }
  }
  return QString();
}
}

QString CheckPropertyValue(const PropertySpec& spec, const nlohmann::json& value)
{
  switch (spec.Type)
  {
    case PropertySpec::Number:
      return CheckNumber(spec, value, false);
    case PropertySpec::Integer:
      return CheckNumber(spec, value, true);
    case PropertySpec::Vector3:
      return CheckList(spec, value, 3, false);
    case PropertySpec::Numbers6:
      return CheckList(spec, value, 6, false);
    case PropertySpec::Integers3:
      return CheckList(spec, value, 3, true);
    case PropertySpec::Choice:
      if (spec.OpenChoice)
      {
        return value.is_string() && !value.get<std::string>().empty()
          ? QString()
          : QStringLiteral("expected a name");
      }
      if (!value.is_string() ||
        !spec.Choices.contains(QString::fromStdString(value.get<std::string>())))
      {
        return QStringLiteral("expected one of: %1").arg(spec.Choices.join(", "));
      }
      return QString();
    case PropertySpec::Boolean:
      return value.is_boolean() ? QString() : QStringLiteral("expected true or false");
    case PropertySpec::NumberList:
      if (!value.is_array() || value.empty() || value.size() > 1000)
      {
        return QStringLiteral("expected 1 to 1000 numbers");
      }
      return CheckList(spec, value, static_cast<int>(value.size()), false);
    case PropertySpec::PointList:
      if (!value.is_array() || value.size() > 1000)
      {
        return QStringLiteral("expected up to 1000 points");
      }
      for (std::size_t i = 0; i < value.size(); ++i)
      {
        const QString why = CheckList(spec, value[i], 3, false);
        if (!why.isEmpty())
        {
          return QStringLiteral("point %1: %2").arg(i + 1).arg(why);
        }
      }
      return QString();
  }
  return QStringLiteral("unknown kind of setting");
}

PipelineItem::PipelineItem(const QString& name, nlohmann::json defaults, std::vector<OutputLook> looks)
  : OutputLooks(std::move(looks))
  , ItemName(name)
  , Values(std::move(defaults))
{
  // The displays' settings, but those the item gives itself.
  std::vector<std::string> types;
  for (const OutputLook& look : this->OutputLooks)
  {
    types.push_back(look.DataType);
  }
  const nlohmann::json displayDefaults = DisplayDefaults(types);
  for (const auto& entry : displayDefaults.items())
  {
    this->Values.emplace(entry.key(), entry.value());
  }
}

ColorScale PipelineItem::Coloring(const std::string& array, double opacity) const
{
  ColorScale scale;
  scale.Array = array;
  scale.Map = this->Text("ColorMap");
  scale.Opacity = opacity;
  scale.CustomRange = this->Text("ColorRange") == "custom";
  scale.Minimum = this->Number("ColorRangeMinimum");
  scale.Maximum = this->Number("ColorRangeMaximum");
  // Over time: the sampled range once there is one (until then, the data's).
  if (this->Text("ColorRange") == "over time" && !this->TimeRangeFor.empty())
  {
    scale.CustomRange = true;
    scale.Minimum = this->TimeRange[0];
    scale.Maximum = this->TimeRange[1];
  }
  scale.Steps = this->Integer("ColorSteps");
  scale.ScalarBar = this->Values.at("ScalarBar").get<bool>();
  return scale;
}

PipelineItem::~PipelineItem() = default;

bool PipelineItem::ColoursOverTime() const
{
  return this->Text("ColorRange") == "over time" && this->Text("ColorArray") != "Solid";
}

bool PipelineItem::NeedsTimeRange(const std::string& source) const
{
  return this->ColoursOverTime() && source != this->TimeRangeFor;
}

void PipelineItem::SetTimeRange(const double range[2], const std::string& source)
{
  this->TimeRange[0] = range[0];
  this->TimeRange[1] = range[1] > range[0] ? range[1] : range[0] + 1e-12;
  this->TimeRangeFor = source;
  Q_EMIT this->DisplayChanged();
}

void PipelineItem::SetName(const QString& name)
{
  if (name != this->ItemName && !name.trimmed().isEmpty())
  {
    this->ItemName = name.trimmed();
    Q_EMIT this->NameChanged();
  }
}

void PipelineItem::SetVisible(bool visible)
{
  if (visible != this->Visible)
  {
    this->Visible = visible;
    Q_EMIT this->VisibilityChanged();
  }
}

std::vector<PropertySpec> PipelineItem::Properties() const
{
  std::vector<PropertySpec> specs = this->ItemProperties();
  std::vector<std::string> types;
  for (const OutputLook& look : this->OutputLooks)
  {
    types.push_back(look.DataType);
  }
  for (const PropertySpec& spec : DisplayPropertySpecs(types, this->ColorArrays(), this->Text("ColorArray")))
  {
    specs.push_back(spec);
  }
  return specs;
}

std::vector<vtkSmartPointer<vtkDataObject>> PipelineItem::ShownData() const
{
  std::vector<vtkSmartPointer<vtkDataObject>> shown = this->Results;
  shown.resize(this->OutputLooks.size());
  return shown;
}

void PipelineItem::RevertSettings(const nlohmann::json& settings)
{
  if (!settings.is_object() || settings == this->Values)
  {
    return;
  }
  this->Values = settings;
  Q_EMIT this->SettingsChanged(false);
}

QString PipelineItem::ApplySettings(const nlohmann::json& settings)
{
  if (!settings.is_object())
  {
    return QStringLiteral("settings must be a JSON object");
  }
  const std::vector<PropertySpec> specs = this->Properties();
  bool needsRun = false;
  bool changed = false;
  // Check everything first: a bad value leaves every setting as it was. An
  // old key (a declared project alias) is taken as the setting's own.
  nlohmann::json taken = nlohmann::json::object();
  for (const auto& entry : settings.items())
  {
    const QString key = QString::fromStdString(entry.key());
    const PropertySpec* spec = nullptr;
    for (const PropertySpec& candidate : specs)
    {
      spec = candidate.Key == entry.key() || candidate.Aliases.contains(key) ? &candidate : spec;
    }
    if (!spec)
    {
      return QStringLiteral("%1: no such setting for a %2 item")
        .arg(key, QString::fromStdString(this->Kind()));
    }
    const QString why = CheckPropertyValue(*spec, entry.value());
    if (!why.isEmpty())
    {
      return QStringLiteral("%1: %2").arg(spec->Label, why);
    }
    taken[spec->Key] = entry.value();
    if (this->Values.value(spec->Key, nlohmann::json()) != entry.value())
    {
      changed = true;
      needsRun = needsRun || !spec->Display;
    }
  }
  if (!changed)
  {
    return QString();
  }
  for (const auto& entry : taken.items())
  {
    this->Values[entry.key()] = entry.value();
  }
  Q_EMIT this->SettingsChanged(needsRun);
  return QString();
}

void PipelineItem::TakeResult(vtkAlgorithm* job)
{
  this->Results.clear();
  for (int port = 0; port < job->GetNumberOfOutputPorts(); ++port)
  {
    vtkDataObject* output = job->GetOutputDataObject(port);
    vtkSmartPointer<vtkDataObject> copy;
    if (output)
    {
      copy.TakeReference(output->NewInstance());
      copy->ShallowCopy(output);
    }
    this->Results.push_back(copy);
  }
  Q_EMIT this->ResultChanged();
}

vtkDataObject* PipelineItem::Result(int port) const
{
  return port >= 0 && port < static_cast<int>(this->Results.size()) ? this->Results[port].Get()
                                                                     : nullptr;
}

QStringList PipelineItem::ColorArrays() const
{
  QStringList names;
  for (const auto& result : this->Results)
  {
    auto* data = vtkDataSet::SafeDownCast(result);
    if (!data)
    {
      continue;
    }
    for (vtkFieldData* arrays : { static_cast<vtkFieldData*>(data->GetPointData()),
           static_cast<vtkFieldData*>(data->GetCellData()) })
    {
      for (int i = 0; i < arrays->GetNumberOfArrays(); ++i)
      {
        const char* name = arrays->GetArrayName(i);
        if (name && !names.contains(name) && arrays->GetArray(i))
        {
          names << name;
        }
      }
    }
  }
  return names;
}

double PipelineItem::Number(const char* key) const
{
  return this->Values.at(key).get<double>();
}

int PipelineItem::Integer(const char* key) const
{
  return static_cast<int>(this->Values.at(key).get<double>());
}

void PipelineItem::Vector(const char* key, double* out, int count) const
{
  const nlohmann::json& values = this->Values.at(key);
  for (int i = 0; i < count; ++i)
  {
    out[i] = values.at(i).get<double>();
  }
}

std::string PipelineItem::Text(const char* key) const
{
  return this->Values.at(key).get<std::string>();
}

void PipelineItem::ApplyIntegration(vtkRiemannIntegrationSettings* settings) const
{
  ApplyIntegrationValues(this->Values, settings);
}

nlohmann::json WithIntegrationDefaults(nlohmann::json own, const char* integrator, double length)
{
  // The declared defaults for curves (vtkRiemannIntegrationSettings's), but
  // the item's integrator and length.
  vtkNew<vtkRiemannIntegrationSettings> defaults;
  defaults->SetIntegratorTypeFromName(integrator);
  defaults->SetMaximumPropagation(length);
  own.update(IntegrationValues(defaults));
  return own;
}

std::vector<PropertySpec> IntegrationPropertySpecs()
{
  // One field per declared setting (vtkRiemannIntegrationSettings.settings.json):
  // the key is the property (projects store it so), the label, help, unit
  // and range are the declaration's, as riemann's options are.
  return DeclaredPropertySpecs(riemann::declared::vtkRiemannIntegrationSettings::Settings);
}

std::vector<std::string> PipelineItem::IntegrationPythonLines(const std::string& var) const
{
  vtkNew<vtkRiemannIntegrationSettings> settings;
  this->ApplyIntegration(settings);
  return IntegrationPython(var + ".GetIntegrationSettings()", settings);
}

std::vector<PropertySpec> PipelineItem::WithIntegration(std::vector<PropertySpec> specs)
{
  for (const PropertySpec& spec : IntegrationPropertySpecs())
  {
    specs.push_back(spec);
  }
  return specs;
}

std::string PythonNumber(double value)
{
  return riemann::ShortestNumberText(value);
}

std::string PythonString(const std::string& text)
{
  return nlohmann::json(text).dump();
}

std::string PythonTuple(const nlohmann::json& values)
{
  std::string text = "(";
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    text += (i ? ", " : "") + PythonNumber(values[i].get<double>());
  }
  return text + ")";
}
}
}
