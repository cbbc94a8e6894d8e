#include "vtkRiemannIntegrationSettings.h"

#include "GeodesicTrace.h"
#include "IntegrationSchema.h"
#include "RungeKutta.h"

#include "vtkObjectFactory.h"

#include <sstream>
#include <utility>

vtkStandardNewMacro(vtkRiemannIntegrationSettings);

vtkRiemannIntegrationSettings::vtkRiemannIntegrationSettings()
{
  const riemann::GeodesicOptions defaults;
  this->IntegratorType = static_cast<int>(defaults.Integrator);
  this->InitialIntegrationStep = defaults.Step;
  this->MinimumIntegrationStep = defaults.MinimumStep;
  this->MaximumIntegrationStep = defaults.MaximumStep;
  this->MaximumError = defaults.Tolerance;
  this->MaximumPropagation = defaults.MaximumLength;
  this->MaximumNumberOfSteps = static_cast<vtkIdType>(defaults.MaximumSteps);
}

bool vtkRiemannIntegrationSettings::SetIntegratorTypeFromName(const char* name)
{
  riemann::IntegratorType type;
  if (!name || !riemann::ParseIntegratorName(name, type))
  {
    return false;
  }
  this->SetIntegratorType(static_cast<int>(type));
  return true;
}

const char* vtkRiemannIntegrationSettings::GetIntegratorTypeAsString() const
{
  return riemann::IntegratorName(static_cast<riemann::IntegratorType>(this->IntegratorType));
}

std::string vtkRiemannIntegrationSettings::CheckSettings() const
{
  // Each property in the range of the integration schema (IntegrationSchema.h),
  // in the schema's order, named as the property.
  using riemann::IntegrationSettingId;
  const std::pair<IntegrationSettingId, double> values[] = {
    { IntegrationSettingId::Integrator, static_cast<double>(this->IntegratorType) },
    { IntegrationSettingId::Step, this->InitialIntegrationStep },
    { IntegrationSettingId::MinimumStep, this->MinimumIntegrationStep },
    { IntegrationSettingId::MaximumStep, this->MaximumIntegrationStep },
    { IntegrationSettingId::Tolerance, this->MaximumError },
    { IntegrationSettingId::Length, this->MaximumPropagation },
    { IntegrationSettingId::MaximumSteps, static_cast<double>(this->MaximumNumberOfSteps) },
  };
  for (const auto& value : values)
  {
    const riemann::IntegrationSetting& setting = riemann::IntegrationSettingOf(value.first);
    std::string error = riemann::CheckIntegrationValue(setting, value.second, setting.Property);
    if (!error.empty())
    {
      return error;
    }
  }
  if (this->MinimumIntegrationStep > this->MaximumIntegrationStep)
  {
    std::ostringstream message;
    message << "MinimumIntegrationStep (" << this->MinimumIntegrationStep
            << ") is above MaximumIntegrationStep (" << this->MaximumIntegrationStep << ")";
    return message.str();
  }
  return std::string();
}

double vtkRiemannIntegrationSettings::GetValue(riemann::IntegrationSettingId id)
{
  using riemann::IntegrationSettingId;
  switch (id)
  {
    case IntegrationSettingId::Integrator:
      return this->IntegratorType;
    case IntegrationSettingId::Step:
      return this->InitialIntegrationStep;
    case IntegrationSettingId::MinimumStep:
      return this->MinimumIntegrationStep;
    case IntegrationSettingId::MaximumStep:
      return this->MaximumIntegrationStep;
    case IntegrationSettingId::Tolerance:
      return this->MaximumError;
    case IntegrationSettingId::Length:
      return this->MaximumPropagation;
    case IntegrationSettingId::MaximumSteps:
      return static_cast<double>(this->MaximumNumberOfSteps);
  }
  return 0.0;
}

void vtkRiemannIntegrationSettings::SetValue(riemann::IntegrationSettingId id, double value)
{
  using riemann::IntegrationSettingId;
  switch (id)
  {
    case IntegrationSettingId::Integrator:
      this->SetIntegratorType(static_cast<int>(value));
      break;
    case IntegrationSettingId::Step:
      this->SetInitialIntegrationStep(value);
      break;
    case IntegrationSettingId::MinimumStep:
      this->SetMinimumIntegrationStep(value);
      break;
    case IntegrationSettingId::MaximumStep:
      this->SetMaximumIntegrationStep(value);
      break;
    case IntegrationSettingId::Tolerance:
      this->SetMaximumError(value);
      break;
    case IntegrationSettingId::Length:
      this->SetMaximumPropagation(value);
      break;
    case IntegrationSettingId::MaximumSteps:
      this->SetMaximumNumberOfSteps(static_cast<vtkIdType>(value));
      break;
  }
}

void vtkRiemannIntegrationSettings::DeepCopy(vtkRiemannIntegrationSettings* other)
{
  if (!other || other == this)
  {
    return;
  }
  this->IntegratorType = other->IntegratorType;
  this->InitialIntegrationStep = other->InitialIntegrationStep;
  this->MinimumIntegrationStep = other->MinimumIntegrationStep;
  this->MaximumIntegrationStep = other->MaximumIntegrationStep;
  this->MaximumError = other->MaximumError;
  this->MaximumPropagation = other->MaximumPropagation;
  this->MaximumNumberOfSteps = other->MaximumNumberOfSteps;
  this->Modified();
}

void vtkRiemannIntegrationSettings::ApplyTo(riemann::GeodesicOptions& options) const
{
  options.Integrator = static_cast<riemann::IntegratorType>(this->IntegratorType);
  options.Step = this->InitialIntegrationStep;
  options.MinimumStep = this->MinimumIntegrationStep;
  options.MaximumStep = this->MaximumIntegrationStep;
  options.Tolerance = this->MaximumError;
  options.MaximumLength = this->MaximumPropagation;
  options.MaximumSteps = this->MaximumNumberOfSteps;
}

bool vtkRiemannIntegrationSettings::Share(
  vtkObject* owner, vtkRiemannIntegrationSettings*& slot, vtkRiemannIntegrationSettings* settings)
{
  // Never null: every consumer always has settings to read.
  if (!settings || settings == slot)
  {
    return false;
  }
  settings->Register(owner);
  if (slot)
  {
    slot->UnRegister(owner);
  }
  slot = settings;
  return true;
}

void vtkRiemannIntegrationSettings::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IntegratorType: " << this->GetIntegratorTypeAsString() << "\n";
  os << indent << "InitialIntegrationStep: " << this->InitialIntegrationStep << "\n";
  os << indent << "MinimumIntegrationStep: " << this->MinimumIntegrationStep << "\n";
  os << indent << "MaximumIntegrationStep: " << this->MaximumIntegrationStep << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "MaximumPropagation: " << this->MaximumPropagation << "\n";
  os << indent << "MaximumNumberOfSteps: " << this->MaximumNumberOfSteps << "\n";
}
