// Conjugate points and caustic sheets of a point (vtkRiemannConjugateLocus).
#include "PipelineItems.h"

#include "IntegrationSchema.h"

#include "ColorMaps.h"

#include "vtkRiemannConjugateLocus.h"
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
ConjugateLocusItem::ConjugateLocusItem(const QString& name)
  : PipelineItem(name,
      // Adaptive, as the filter: its error follows Tolerance (Tolerance /
      // 100), MaximumError only caps it.
      WithIntegrationDefaults(
        { { "Observer", { 0.0, 0.0, 2.0 } }, { "ConeAxis", { 0.0, 0.0, -1.0 } },
          { "ConeAngle", 30.0 }, { "NumberOfDirections", 800 },
          { "MaximumNumberOfConjugatePoints", 2 }, { "Tolerance", 1e-8 },
          { "MaximumIntegrationStep", 0.1 }, { "ColorArray", "ArcLength" } },
        "dp45", 6.0))
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
  std::vector<PropertySpec> specs = this->ObserverConeProperties(4);
  PropertySpec maximum;
  maximum.Key = "MaximumNumberOfConjugatePoints";
  maximum.Label = "Points per geodesic";
  maximum.Type = PropertySpec::Integer;
  maximum.Minimum = 1;
  maximum.Maximum = 100;
  specs.push_back(maximum);

  PropertySpec tolerance;
  tolerance.Key = "Tolerance";
  tolerance.Label = "Tolerance";
  tolerance.Minimum = 1e-15;
  tolerance.Maximum = 1.0;
  tolerance.Help = "Arc-length accuracy of each conjugate point, and the resolution: two "
                   "closer than this are one point of multiplicity 2 (the integration error "
                   "follows it)";
  specs.push_back(tolerance);

  PropertySpec largestStep;
  largestStep.Key = "MaximumIntegrationStep";
  largestStep.Label = "Largest step";
  // The integration schema's range of the setting, as everywhere else.
  const riemann::IntegrationSetting& maximumStep =
    riemann::IntegrationSettingOf(riemann::IntegrationSettingId::MaximumStep);
  largestStep.Minimum = maximumStep.Minimum;
  largestStep.MinimumExclusive = maximumStep.MinimumExclusive;
  largestStep.Maximum = maximumStep.Maximum;
  largestStep.Help = "Largest step of dp45 (conjugate points are counted, so no step can jump "
                     "over one)";
  specs.push_back(largestStep);
  return this->WithIntegrationAndDisplay(specs);
}

vtkSmartPointer<vtkAlgorithm> ConjugateLocusItem::MakeJob(const JobInputs& inputs) const
{
  auto locus = vtkSmartPointer<vtkRiemannConjugateLocus>::New();
  vtkNew<vtkRiemannMetric> metric;
  metric->ShallowCopy(inputs.Metric);
  locus->SetMetric(metric);
  this->ApplyIntegration(locus->GetIntegrationSettings());
  locus->GetIntegrationSettings()->SetMaximumIntegrationStep(
    this->Number("MaximumIntegrationStep"));
  this->ApplyObserverCone(locus.Get());
  locus->SetMaximumNumberOfConjugatePoints(this->Integer("MaximumNumberOfConjugatePoints"));
  locus->SetTolerance(this->Number("Tolerance"));
  return locus;
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
  std::vector<std::string> lines{
    var + " = riemann.vtkRiemannConjugateLocus()",
    var + ".SetMetric(metric)",
  };
  for (const std::string& line : this->ObserverConePythonLines(var))
  {
    lines.push_back(line);
  }
  lines.push_back(var + ".SetMaximumNumberOfConjugatePoints(" +
    std::to_string(this->Integer("MaximumNumberOfConjugatePoints")) + ")");
  lines.push_back(var + ".SetTolerance(" + PythonNumber(this->Number("Tolerance")) + ")");
  for (const std::string& line : this->IntegrationPythonLines(var))
  {
    lines.push_back(line);
  }
  lines.push_back(var + ".GetIntegrationSettings().SetMaximumIntegrationStep(" +
    PythonNumber(this->Number("MaximumIntegrationStep")) + ")");
  return lines;
}
}
}
