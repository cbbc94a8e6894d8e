// Geodesics from a seed over a cone of directions (vtkRiemannGeodesicTracer,
// which fans its seed itself: NumberOfDirections, ConeAngle).
#include "PipelineItems.h"

#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "vtkRiemannGeodesicTracerSettingAccess.h"

#include "vtkRiemannGeodesicTracer.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"


namespace riemann
{
namespace studio
{
namespace
{
namespace tracer = riemann::declared::vtkRiemannGeodesicTracer;

/// The tracer's settings of its mask input, which this item does not have.
const std::vector<std::string>& MaskSeedSettings()
{
  static const std::vector<std::string> names{ "SeedsPerVoxel", "SeedDirection", "RandomSeed" };
  return names;
}

/// A new item: the declaration's Fan (a seed left of the origin, 24
/// directions) with the tracer's own integration settings.
nlohmann::json GeodesicsDefaults()
{
  vtkNew<vtkRiemannGeodesicTracer> filter;
  return FilterDefaults(riemann::settings::SettingValues(filter), filter->GetIntegrationSettings(),
    nlohmann::json::object(), MaskSeedSettings(), tracer::Fan::Json);
}

/// Yellow polylines, two pixels wide.
OutputLook GeodesicsLook()
{
  OutputLook look = LookOf("vtkPolyData", { { 1.0, 0.85, 0.2 } }, true);
  look.LineWidth = 2.0;
  return look;
}
}

GeodesicsItem::GeodesicsItem(const QString& name)
  : PipelineItem(name, GeodesicsDefaults(), { GeodesicsLook() })
{
}

std::vector<PropertySpec> GeodesicsItem::ItemProperties() const
{
  return WithIntegration(
    DeclaredPropertySpecs(tracer::Settings, MaskSeedSettings()));
}

vtkSmartPointer<vtkAlgorithm> GeodesicsItem::MakeJob(const JobInputs& inputs) const
{
  return DeclaredJob<vtkRiemannGeodesicTracer>(this->Settings(), inputs);
}

std::vector<std::string> GeodesicsItem::PythonLines(const std::string& var) const
{
  return DeclaredPythonLines<vtkRiemannGeodesicTracer>(this->FilterClass(), var, this->Settings());
}
}
}
