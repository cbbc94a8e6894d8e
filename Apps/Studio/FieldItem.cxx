// A field of the metric on a grid (curvature, volume form or the metric
// tensor), shown as a slice, an isosurface or tensor glyphs.
#include "PipelineItems.h"

#include "ColorMaps.h"
#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "SettingValues.h"
#include "vtkRiemannFieldAlgorithmSettingAccess.h"

#include "vtkRiemannCurvatureField.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannMetricTensorField.h"
#include "vtkRiemannVolumeForm.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkContourFilter.h"
#include "vtkDataArray.h"
#include "vtkExtractVOI.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkTensorGlyph.h"

#include <algorithm>

namespace riemann
{
namespace studio
{
namespace
{
/// The first point array with one component (what contours and default colouring use).
std::string FirstScalarArray(vtkImageData* image)
{
  for (int i = 0; image && i < image->GetPointData()->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = image->GetPointData()->GetArray(i);
    if (array && array->GetNumberOfComponents() == 1 && array->GetName())
    {
      return array->GetName();
    }
  }
  return std::string();
}

/// The grid every field filter samples (declared by vtkRiemannFieldAlgorithm).
namespace grid = riemann::declared::vtkRiemannFieldAlgorithm;

/// A new item: the declared grid, the curvature shown as a slice.
nlohmann::json FieldDefaults()
{
  vtkNew<vtkRiemannCurvatureField> filter;
  nlohmann::json values = DeclaredDefaults(riemann::settings::SettingValues(filter.Get()));
  values.update({ { "Field", "curvature" }, { "Representation", "slice" }, { "SliceNormal", "z" },
    { "SliceOffset", 0.0 }, { "ContourValue", 0.5 }, { "ColorArray", "ScalarCurvature" } });
  return values;
}
}

FieldItem::FieldItem(const QString& name)
  : PipelineItem(name, FieldDefaults())
{
  vtkNew<vtkPolyDataMapper> mapper;
  this->Surface->SetMapper(mapper);
  this->Assembly->AddPart(this->Surface);
  this->UpdateDisplay();
}

std::string FieldItem::FilterClass() const
{
  const std::string field = this->Text("Field");
  return field == "volume-form" ? "vtkRiemannVolumeForm"
    : field == "metric-tensor"  ? "vtkRiemannMetricTensorField"
                                : "vtkRiemannCurvatureField";
}

std::vector<PropertySpec> FieldItem::Properties() const
{
  PropertySpec field;
  field.Key = "Field";
  field.Label = "Field";
  field.Type = PropertySpec::Choice;
  field.Choices = QStringList{ "curvature", "volume-form", "metric-tensor" };
  field.Help = "curvature: scalar, Ricci and sectional curvatures; volume-form: sqrt(det g); "
               "metric-tensor: g and its inverse";

  PropertySpec representation;
  representation.Key = "Representation";
  representation.Label = "Show as";
  representation.Type = PropertySpec::Choice;
  representation.Choices = QStringList{ "slice", "isosurface", "glyphs" };
  representation.Help = "glyphs: ellipsoids of the metric tensor (Field metric-tensor)";
  representation.Display = true;

  PropertySpec contour;
  contour.Key = "ContourValue";
  contour.Label = "Isovalue";
  contour.Help = "Value of the colouring array (or the first scalar) on the isosurface";
  contour.Display = true;

  std::vector<PropertySpec> specs{ field };
  for (const PropertySpec& spec : DeclaredPropertySpecs(grid::Settings))
  {
    specs.push_back(spec);
  }
  specs.push_back(representation);
  for (const PropertySpec& spec : this->SliceProperties())
  {
    specs.push_back(spec);
  }
  specs.push_back(contour);
  for (const PropertySpec& spec : this->DisplayProperties())
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

void FieldItem::UpdateDisplay()
{
  auto* image = vtkImageData::SafeDownCast(this->Result(0));
  this->Surface->SetVisibility(image != nullptr);
  if (!image)
  {
    return;
  }
  std::string array = this->Text("ColorArray");
  if (!image->GetPointData()->GetArray(array.c_str()) && array != "Solid")
  {
    array = FirstScalarArray(image);
  }
  const std::string representation = this->Text("Representation");
  vtkSmartPointer<vtkPolyData> shown;
  if (representation == "glyphs" && image->GetPointData()->GetArray("MetricTensor"))
  {
    // About 8 glyphs per axis, each an ellipsoid with the axes of g.
    int extent[6];
    image->GetExtent(extent);
    vtkNew<vtkExtractVOI> sample;
    sample->SetInputData(image);
    sample->SetVOI(extent);
    const int rate = std::max(1, (extent[1] - extent[0]) / 8);
    sample->SetSampleRate(rate, rate, rate);
    sample->Update();
    vtkImageData* sampled = sample->GetOutput();
    sampled->GetPointData()->SetActiveTensors("MetricTensor");
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(12);
    sphere->SetPhiResolution(8);
    vtkNew<vtkTensorGlyph> glyphs;
    glyphs->SetInputData(sampled);
    glyphs->SetSourceConnection(sphere->GetOutputPort());
    glyphs->ExtractEigenvaluesOn();
    glyphs->ColorGlyphsOff();
    const double* spacing = image->GetSpacing();
    // Unit sphere of g: semi-axes 1/sqrt(lambda); scaled to a third of the gap.
    glyphs->SetScaleFactor(0.35 * rate * std::min({ spacing[0], spacing[1], spacing[2] }));
    glyphs->Update();
    shown = glyphs->GetOutput();
  }
  else if (representation == "isosurface" && !FirstScalarArray(image).empty())
  {
    const std::string contoured =
      image->GetPointData()->GetArray(array.c_str()) &&
        image->GetPointData()->GetArray(array.c_str())->GetNumberOfComponents() == 1
      ? array
      : FirstScalarArray(image);
    vtkNew<vtkContourFilter> contour;
    contour->SetInputData(image);
    contour->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, contoured.c_str());
    contour->SetValue(0, this->Number("ContourValue"));
    contour->ComputeScalarsOff();
    contour->Update();
    shown = contour->GetOutput();
  }
  else
  {
    shown = this->SliceOf(image);
  }
  vtkPolyDataMapper::SafeDownCast(this->Surface->GetMapper())->SetInputData(shown);
  const double white[3] = { 0.9, 0.9, 0.9 };
  ApplyColoring(this->Surface, shown, this->Coloring(array, this->Number("Opacity")), white, this->ScalarBar());
}

std::vector<std::string> FieldItem::PythonLines(const std::string& var) const
{
  return DeclaredPythonLines<vtkRiemannFieldAlgorithm>(this->FilterClass(), var, this->Settings());
}
}
}
