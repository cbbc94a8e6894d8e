// Geodesics from a seed over a cone of directions (vtkRiemannGeodesicTracer,
// which fans its seed itself: NumberOfDirections, ConeAngle).
#include "PipelineItems.h"

#include "ColorMaps.h"
#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "vtkRiemannGeodesicTracerSettingAccess.h"

#include "vtkRiemannGeodesicTracer.h"
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
}

GeodesicsItem::GeodesicsItem(const QString& name)
  : PipelineItem(name, GeodesicsDefaults())
{
  vtkNew<vtkPolyDataMapper> mapper;
  this->Lines->SetMapper(mapper);
  this->Lines->GetProperty()->SetLineWidth(2.0);
  this->Assembly->AddPart(this->Lines);
  this->UpdateDisplay();
}

std::vector<PropertySpec> GeodesicsItem::Properties() const
{
  return this->WithIntegrationAndDisplay(
    DeclaredPropertySpecs(tracer::Settings, MaskSeedSettings()));
}

vtkSmartPointer<vtkAlgorithm> GeodesicsItem::MakeJob(const JobInputs& inputs) const
{
  return DeclaredJob<vtkRiemannGeodesicTracer>(this->Settings(), inputs);
}

void GeodesicsItem::UpdateDisplay()
{
  auto* lines = vtkPolyData::SafeDownCast(this->Result(0));
  auto* mapper = vtkPolyDataMapper::SafeDownCast(this->Lines->GetMapper());
  if (lines)
  {
    mapper->SetInputData(lines);
  }
  const double yellow[3] = { 1.0, 0.85, 0.2 };
  ApplyColoring(this->Lines, lines, this->Coloring(this->Text("ColorArray"), this->Number("Opacity")),
    yellow, this->ScalarBar());
  this->Lines->SetVisibility(lines != nullptr);
}

std::vector<std::string> GeodesicsItem::PythonLines(const std::string& var) const
{
  return DeclaredPythonLines<vtkRiemannGeodesicTracer>(this->FilterClass(), var, this->Settings());
}
}
}
