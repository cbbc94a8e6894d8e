#include "vtkRiemannIntegrationSettings.h"

#include "GeodesicTrace.h"
#include "RungeKutta.h"

#include "vtkObjectFactory.h"

#include <cmath>
#include <sstream>

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

namespace
{
/// "" when `value` is finite and > 0, else the sentence naming `name`.
std::string CheckPositive(const char* name, double value)
{
  if (std::isfinite(value) && value > 0.0)
  {
    return std::string();
  }
  std::ostringstream message;
  message << name << " is " << value << ": expected a finite number > 0";
  return message.str();
}
} // namespace

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
  for (const auto& setting : {
         std::make_pair("InitialIntegrationStep", this->InitialIntegrationStep),
         std::make_pair("MinimumIntegrationStep", this->MinimumIntegrationStep),
         std::make_pair("MaximumIntegrationStep", this->MaximumIntegrationStep),
         std::make_pair("MaximumError", this->MaximumError),
         std::make_pair("MaximumPropagation", this->MaximumPropagation),
       })
  {
    std::string error = CheckPositive(setting.first, setting.second);
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
  if (this->MaximumNumberOfSteps < 1)
  {
    std::ostringstream message;
    message << "MaximumNumberOfSteps is " << this->MaximumNumberOfSteps << ": expected at least 1";
    return message.str();
  }
  return std::string();
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
