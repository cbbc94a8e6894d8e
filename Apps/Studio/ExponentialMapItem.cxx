// The exponential map at a point: rays and wavefronts (vtkRiemannExponentialMap).
#include "PipelineItems.h"

#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "vtkRiemannExponentialMapSettingAccess.h"

#include "vtkRiemannExponentialMap.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include "vtkNew.h"
#include "vtkPolyData.h"

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

/// The rays faint and grey, so that the wavefronts (blue, with the legend) read.
std::vector<OutputLook> ExponentialMapLooks()
{
  OutputLook rays = LookOf("vtkPolyData", { { 0.9, 0.9, 0.9 } }, false);
  rays.OpacityScale = 0.35;
  OutputLook fronts = LookOf("vtkPolyData", { { 0.3, 0.7, 1.0 } }, true);
  fronts.OpacityScale = 0.8;
  return { rays, fronts };
}
}

ExponentialMapItem::ExponentialMapItem(const QString& name)
  : PipelineItem(name, ExponentialMapDefaults(), ExponentialMapLooks())
{
}

std::vector<PropertySpec> ExponentialMapItem::ItemProperties() const
{
  return WithIntegration(
    DeclaredPropertySpecs(riemann::declared::vtkRiemannExponentialMap::Settings));
}

vtkSmartPointer<vtkAlgorithm> ExponentialMapItem::MakeJob(const JobInputs& inputs) const
{
  return DeclaredJob<vtkRiemannExponentialMap>(this->Settings(), inputs);
}

std::vector<std::string> ExponentialMapItem::PythonLines(const std::string& var) const
{
  return DeclaredPythonLines<vtkRiemannExponentialMap>(this->FilterClass(), var, this->Settings());
}
}
}
