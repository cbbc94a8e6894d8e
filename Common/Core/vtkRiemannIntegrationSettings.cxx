#include "vtkRiemannIntegrationSettings.h"

#include "GeodesicTrace.h"
#include "vtkRiemannIntegrationSettingsSettingAccess.h"
#include "RungeKutta.h"

#include "vtkObjectFactory.h"

#include <sstream>
#include <utility>

vtkStandardNewMacro(vtkRiemannIntegrationSettings);

vtkRiemannIntegrationSettings::vtkRiemannIntegrationSettings()
{
  namespace declared = riemann::declared::vtkRiemannIntegrationSettings;
  this->IntegratorType = declared::Default::IntegratorType;
  this->InitialIntegrationStep = declared::Default::InitialIntegrationStep;
  this->MinimumIntegrationStep = declared::Default::MinimumIntegrationStep;
  this->MaximumIntegrationStep = declared::Default::MaximumIntegrationStep;
  this->MaximumError = declared::Default::MaximumError;
  this->MaximumPropagation = declared::Default::MaximumPropagation;
  this->MaximumNumberOfSteps = static_cast<vtkIdType>(declared::Default::MaximumNumberOfSteps);
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
  // Each property in its declared range, in the declaration's order, named as the property.
  std::string error = riemann::CheckSettingValues(riemann::declared::vtkRiemannIntegrationSettings::Settings,
    riemann::settings::SettingValues(const_cast<vtkRiemannIntegrationSettings*>(this)));
  if (!error.empty())
  {
    return error;
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
