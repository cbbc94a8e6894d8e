// Conjugate points and caustic sheets of a point (vtkRiemannConjugateLocus).
#include "PipelineItems.h"

#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "vtkRiemannConjugateLocusSettingAccess.h"

#include "vtkRiemannConjugateLocus.h"
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
/// A new filter's settings (adaptive: its error follows Tolerance / 100,
/// MaximumError only caps it), coloured by arc length.
nlohmann::json ConjugateLocusDefaults()
{
  vtkNew<vtkRiemannConjugateLocus> filter;
  return FilterDefaults(riemann::settings::SettingValues(filter), filter->GetIntegrationSettings(),
    { { "ColorArray", "ArcLength" } });
}

/// Red points (as spheres, with the legend) and orange caustic sheets.
std::vector<OutputLook> ConjugateLocusLooks()
{
  OutputLook points = LookOf("vtkPolyData", { { 1.0, 0.4, 0.3 } }, true);
  points.PointSize = 4.0;
  OutputLook caustics = LookOf("vtkPolyData", { { 1.0, 0.6, 0.2 } }, false);
  caustics.OpacityScale = 0.7;
  return { points, caustics };
}
}

ConjugateLocusItem::ConjugateLocusItem(const QString& name)
  : PipelineItem(name, ConjugateLocusDefaults(), ConjugateLocusLooks())
{
}

std::vector<PropertySpec> ConjugateLocusItem::ItemProperties() const
{
  return WithIntegration(
    DeclaredPropertySpecs(riemann::declared::vtkRiemannConjugateLocus::Settings));
}

vtkSmartPointer<vtkAlgorithm> ConjugateLocusItem::MakeJob(const JobInputs& inputs) const
{
  return DeclaredJob<vtkRiemannConjugateLocus>(this->Settings(), inputs);
}

std::vector<std::string> ConjugateLocusItem::PythonLines(const std::string& var) const
{
  return DeclaredPythonLines<vtkRiemannConjugateLocus>(this->FilterClass(), var, this->Settings());
}
}
}
