// The exponential map at a point: rays and wavefronts (vtkRiemannExponentialMap).
#include "PipelineItems.h"

#include "ColorMaps.h"
#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "vtkRiemannExponentialMapSettingAccess.h"

#include "vtkRiemannExponentialMap.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"

namespace riemann
{
namespace studio
{
namespace
{
/// A new filter's settings, coloured by the transverse Jacobian.
nlohmann::json ExponentialMapDefaults()
{
  vtkNew<vtkRiemannExponentialMap> filter;
  return FilterDefaults(riemann::settings::SettingValues(filter), filter->GetIntegrationSettings(),
    { { "ColorArray", "TransverseJacobian" } });
}
}

ExponentialMapItem::ExponentialMapItem(const QString& name)
  : PipelineItem(name, ExponentialMapDefaults())
{
  for (vtkActor* actor : { this->Rays.Get(), this->Wavefronts.Get() })
  {
    vtkNew<vtkPolyDataMapper> mapper;
    actor->SetMapper(mapper);
    this->Assembly->AddPart(actor);
  }
  this->UpdateDisplay();
}

std::vector<PropertySpec> ExponentialMapItem::Properties() const
{
  return this->WithIntegrationAndDisplay(
    DeclaredPropertySpecs(riemann::declared::vtkRiemannExponentialMap::Settings));
}

vtkSmartPointer<vtkAlgorithm> ExponentialMapItem::MakeJob(const JobInputs& inputs) const
{
  return DeclaredJob<vtkRiemannExponentialMap>(this->Settings(), inputs);
}

void ExponentialMapItem::UpdateDisplay()
{
  const std::string array = this->Text("ColorArray");
  const double opacity = this->Number("Opacity");
  const double rayColor[3] = { 0.9, 0.9, 0.9 };
  const double frontColor[3] = { 0.3, 0.7, 1.0 };
  auto* rays = vtkPolyData::SafeDownCast(this->Result(0));
  auto* fronts = vtkPolyData::SafeDownCast(this->Result(1));
  if (rays)
  {
    vtkPolyDataMapper::SafeDownCast(this->Rays->GetMapper())->SetInputData(rays);
  }
  if (fronts)
  {
    vtkPolyDataMapper::SafeDownCast(this->Wavefronts->GetMapper())->SetInputData(fronts);
  }
  // The rays stay faint so the wavefronts read.
  ApplyColoring(this->Rays, rays, this->Coloring(array, 0.35 * opacity), rayColor);
  ApplyColoring(this->Wavefronts, fronts, this->Coloring(array, 0.8 * opacity), frontColor, this->ScalarBar());
  this->Rays->SetVisibility(rays != nullptr);
  this->Wavefronts->SetVisibility(fronts != nullptr);
}

std::vector<std::string> ExponentialMapItem::PythonLines(const std::string& var) const
{
  return DeclaredPythonLines<vtkRiemannExponentialMap>(this->FilterClass(), var, this->Settings());
}
}
}
