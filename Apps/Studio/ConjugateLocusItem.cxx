// Conjugate points and caustic sheets of a point (vtkRiemannConjugateLocus).
#include "PipelineItems.h"

#include "ColorMaps.h"
#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "vtkRiemannConjugateLocusSettingAccess.h"

#include "vtkRiemannConjugateLocus.h"
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
/// A new filter's settings (adaptive: its error follows Tolerance / 100,
/// MaximumError only caps it), coloured by arc length.
nlohmann::json ConjugateLocusDefaults()
{
  vtkNew<vtkRiemannConjugateLocus> filter;
  return FilterDefaults(riemann::settings::SettingValues(filter), filter->GetIntegrationSettings(),
    { { "ColorArray", "ArcLength" } });
}
}

ConjugateLocusItem::ConjugateLocusItem(const QString& name)
  : PipelineItem(name, ConjugateLocusDefaults())
{
  for (vtkActor* actor : { this->Points.Get(), this->Caustics.Get() })
  {
    vtkNew<vtkPolyDataMapper> mapper;
    actor->SetMapper(mapper);
    this->Assembly->AddPart(actor);
  }
  this->Points->GetProperty()->SetPointSize(4.0);
  this->Points->GetProperty()->SetRenderPointsAsSpheres(true);
  this->UpdateDisplay();
}

std::vector<PropertySpec> ConjugateLocusItem::Properties() const
{
  return this->WithIntegrationAndDisplay(
    DeclaredPropertySpecs(riemann::declared::vtkRiemannConjugateLocus::Settings));
}

vtkSmartPointer<vtkAlgorithm> ConjugateLocusItem::MakeJob(const JobInputs& inputs) const
{
  return DeclaredJob<vtkRiemannConjugateLocus>(this->Settings(), inputs);
}

void ConjugateLocusItem::UpdateDisplay()
{
  const std::string array = this->Text("ColorArray");
  const double opacity = this->Number("Opacity");
  const double pointColor[3] = { 1.0, 0.4, 0.3 };
  const double causticColor[3] = { 1.0, 0.6, 0.2 };
  auto* points = vtkPolyData::SafeDownCast(this->Result(0));
  auto* caustics = vtkPolyData::SafeDownCast(this->Result(1));
  if (points)
  {
    vtkPolyDataMapper::SafeDownCast(this->Points->GetMapper())->SetInputData(points);
  }
  if (caustics)
  {
    vtkPolyDataMapper::SafeDownCast(this->Caustics->GetMapper())->SetInputData(caustics);
  }
  ApplyColoring(this->Points, points, this->Coloring(array, opacity), pointColor, this->ScalarBar());
  ApplyColoring(this->Caustics, caustics, this->Coloring(array, 0.7 * opacity), causticColor);
  this->Points->SetVisibility(points != nullptr);
  this->Caustics->SetVisibility(caustics != nullptr);
}

std::vector<std::string> ConjugateLocusItem::PythonLines(const std::string& var) const
{
  return DeclaredPythonLines<vtkRiemannConjugateLocus>(this->FilterClass(), var, this->Settings());
}
}
}
