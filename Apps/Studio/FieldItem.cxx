// A field of the metric on a grid (curvature, volume form or the metric
// tensor); the view shows the grid as a slice, an isosurface or tensor
// glyphs (ImageDataDisplay).
#include "PipelineItems.h"

#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "SettingValues.h"
#include "vtkRiemannFieldAlgorithmSettingAccess.h"

#include "vtkRiemannCurvatureField.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannMetricTensorField.h"
#include "vtkRiemannVolumeForm.h"



namespace riemann
{
namespace studio
{
namespace
{
/// The grid every field filter samples (declared by vtkRiemannFieldAlgorithm).
namespace grid = riemann::declared::vtkRiemannFieldAlgorithm;

/// A new item: the declared grid, the curvature shown as a slice.
nlohmann::json FieldDefaults()
{
  vtkNew<vtkRiemannCurvatureField> filter;
  nlohmann::json values = DeclaredDefaults(riemann::settings::SettingValues(filter.Get()));
  values.update({ { "Field", "curvature" }, { "ColorArray", "ScalarCurvature" } });
  return values;
}
}

FieldItem::FieldItem(const QString& name)
  : PipelineItem(name, FieldDefaults(), { LookOf("vtkImageData", { { 0.9, 0.9, 0.9 } }, true) })
{
}

std::string FieldItem::FilterClass() const
{
  const std::string field = this->Text("Field");
  return field == "volume-form" ? "vtkRiemannVolumeForm"
    : field == "metric-tensor"  ? "vtkRiemannMetricTensorField"
                                : "vtkRiemannCurvatureField";
}

std::vector<PropertySpec> FieldItem::ItemProperties() const
{
  PropertySpec field;
  field.Key = "Field";
  field.Label = "Field";
  field.Type = PropertySpec::Choice;
  field.Choices = QStringList{ "curvature", "volume-form", "metric-tensor" };
  field.Help = "curvature: scalar, Ricci and sectional curvatures; volume-form: sqrt(det g); "
               "metric-tensor: g and its inverse";

  std::vector<PropertySpec> specs{ field };
  for (const PropertySpec& spec : DeclaredPropertySpecs(grid::Settings))
  {
    specs.push_back(spec);
  }
  return specs;
}

vtkSmartPointer<vtkAlgorithm> FieldItem::MakeJob(const JobInputs& inputs) const
{
  // Three filters, one declaration: their base class's (the grid).
  const std::string field = this->Text("Field");
  if (field == "volume-form")
  {
    return DeclaredJob<vtkRiemannVolumeForm, vtkRiemannFieldAlgorithm>(this->Settings(), inputs);
  }
  if (field == "metric-tensor")
  {
    return DeclaredJob<vtkRiemannMetricTensorField, vtkRiemannFieldAlgorithm>(this->Settings(), inputs);
  }
  return DeclaredJob<vtkRiemannCurvatureField, vtkRiemannFieldAlgorithm>(this->Settings(), inputs);
}

std::vector<std::string> FieldItem::PythonLines(const std::string& var) const
{
  return DeclaredPythonLines<vtkRiemannFieldAlgorithm>(this->FilterClass(), var, this->Settings());
}
}
}
