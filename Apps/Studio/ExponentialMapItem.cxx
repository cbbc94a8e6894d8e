// The exponential map at a point: rays and wavefronts (vtkRiemannExponentialMap).
#include "PipelineItems.h"

#include "ColorMaps.h"

#include "vtkRiemannExponentialMap.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"

namespace riemann
{
namespace studio
{
ExponentialMapItem::ExponentialMapItem(const QString& name)
  : PipelineItem(name,
      WithIntegrationDefaults(
        { { "Observer", { 0.0, 0.0, 3.0 } }, { "ConeAxis", { 0.0, 0.0, -1.0 } },
          { "ConeAngle", 35.0 }, { "NumberOfDirections", 600 },
          { "Radii", { 1.25, 2.5, 3.75, 5.0 } }, { "ColorArray", "TransverseJacobian" } },
        "rk4", 5.0))
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
  std::vector<PropertySpec> specs = this->ObserverConeProperties(4);
  PropertySpec radii;
  radii.Key = "Radii";
  radii.Label = "Radii";
  radii.Type = PropertySpec::NumberList;
  radii.Minimum = 0.0;
  radii.MinimumExclusive = true;
  radii.Help = "Arc lengths of the geodesic spheres (wavefronts), e.g. 1, 2.5, 4; those beyond "
               "the length are not reached";
  specs.push_back(radii);
  return this->WithIntegrationAndDisplay(specs);
}

vtkSmartPointer<vtkAlgorithm> ExponentialMapItem::MakeJob(const JobInputs& inputs) const
{
  auto expmap = vtkSmartPointer<vtkRiemannExponentialMap>::New();
  vtkNew<vtkRiemannMetric> metric;
  metric->ShallowCopy(inputs.Metric);
  expmap->SetMetric(metric);
  this->ApplyIntegration(expmap->GetIntegrationSettings());
  this->ApplyObserverCone(expmap.Get());
  for (const nlohmann::json& radius : this->Settings().at("Radii"))
  {
    expmap->AddRadius(radius.get<double>());
  }
  return expmap;
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
  std::vector<std::string> lines{
    var + " = riemann.vtkRiemannExponentialMap()",
    var + ".SetMetric(metric)",
  };
  for (const std::string& line : this->ObserverConePythonLines(var))
  {
    lines.push_back(line);
  }
  for (const nlohmann::json& radius : this->Settings().at("Radii"))
  {
    lines.push_back(var + ".AddRadius(" + PythonNumber(radius.get<double>()) + ")");
  }
  for (const std::string& line : this->IntegrationPythonLines(var))
  {
    lines.push_back(line);
  }
  return lines;
}
}
}
