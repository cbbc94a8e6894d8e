#include "ImageDataDisplay.h"

#include "vtkAssembly.h"
#include "vtkContourFilter.h"
#include "vtkCutter.h"
#include "vtkDataArray.h"
#include "vtkExtractVOI.h"
#include "vtkImageData.h"
#include "vtkPlane.h"
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
/// The first point array with `components` components ("" when none).
std::string FirstPointArray(vtkImageData* image, int components)
{
  for (int i = 0; i < image->GetPointData()->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = image->GetPointData()->GetArray(i);
    if (array && array->GetNumberOfComponents() == components && array->GetName())
    {
      return array->GetName();
    }
  }
  return std::string();
}

/// `name` when it is a point scalar of `image`, else its first scalar: what contours read.
std::string ScalarOrFirst(vtkImageData* image, const std::string& name)
{
  vtkDataArray* array = image->GetPointData()->GetArray(name.c_str());
  return array && array->GetNumberOfComponents() == 1 ? name : FirstPointArray(image, 1);
}

/// The plane through the grid's centre, moved by `offset` along axis x, y or z.
vtkSmartPointer<vtkPolyData> Slice(vtkImageData* image, const std::string& normal, double offset)
{
  const int axis = normal == "x" ? 0 : normal == "y" ? 1 : 2;
  double bounds[6];
  image->GetBounds(bounds);
  double origin[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  origin[axis] += offset;
  double direction[3] = { 0, 0, 0 };
  direction[axis] = 1.0;
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(origin);
  plane->SetNormal(direction);
  vtkNew<vtkCutter> cutter;
  cutter->SetInputData(image);
  cutter->SetCutFunction(plane);
  cutter->Update();
  return cutter->GetOutput();
}

/// Ellipsoids of the tensor array `tensors` on about 8 points per axis: the unit spheres of g.
vtkSmartPointer<vtkPolyData> TensorGlyphs(vtkImageData* image, const std::string& tensors)
{
  int extent[6];
  image->GetExtent(extent);
  vtkNew<vtkExtractVOI> sample;
  sample->SetInputData(image);
  sample->SetVOI(extent);
  const int rate = std::max(1, (extent[1] - extent[0]) / 8);
  sample->SetSampleRate(rate, rate, rate);
  sample->Update();
  vtkImageData* sampled = sample->GetOutput();
  sampled->GetPointData()->SetActiveTensors(tensors.c_str());
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(8);
  vtkNew<vtkTensorGlyph> glyphs;
  glyphs->SetInputData(sampled);
  glyphs->SetSourceConnection(sphere->GetOutputPort());
  glyphs->ExtractEigenvaluesOn();
  glyphs->ColorGlyphsOff();
  const double* spacing = image->GetSpacing();
  // Semi-axes 1/sqrt(lambda), scaled to a third of the gap between glyphs.
  glyphs->SetScaleFactor(0.35 * rate * std::min({ spacing[0], spacing[1], spacing[2] }));
  glyphs->Update();
  return glyphs->GetOutput();
}

vtkSmartPointer<vtkPolyData> Isosurface(vtkImageData* image, const std::string& array, double value)
{
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(image);
  contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, array.c_str());
  contour->SetValue(0, value);
  contour->ComputeScalarsOff();
  contour->Update();
  return contour->GetOutput();
}

/// `count` level lines of `array` on `slice`, evenly inside the range the whole grid has.
vtkSmartPointer<vtkPolyData> LevelLinesOf(
  vtkPolyData* slice, vtkImageData* image, const std::string& array, int count)
{
  vtkNew<vtkContourFilter> lines;
  lines->SetInputData(slice);
  lines->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, array.c_str());
  double range[2];
  image->GetPointData()->GetArray(array.c_str())->GetRange(range);
  if (range[1] > range[0])
  {
    const double gap = (range[1] - range[0]) / (count + 1);
    lines->GenerateValues(count, range[0] + gap, range[1] - gap);
  }
  lines->ComputeScalarsOff();
  lines->Update();
  return lines->GetOutput();
}

}

ImageDataDisplay::ImageDataDisplay(vtkAssembly* parts)
{
  for (vtkActor* actor : { this->Surface.Get(), this->LevelLines.Get() })
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->ScalarVisibilityOff();
    actor->SetMapper(mapper);
    actor->SetVisibility(false);
    parts->AddPart(actor);
  }
  this->LevelLines->GetProperty()->SetColor(0.05, 0.05, 0.05);
  this->LevelLines->GetProperty()->SetLineWidth(1.5);
}

std::vector<PropertySpec> ImageDataDisplay::Properties()
{
  PropertySpec representation = DisplaySpec("Representation", "Show as", PropertySpec::Choice,
    "slice",
    "slice: a plane through the grid; isosurface: where the colouring array (or the first scalar) "
    "has the isovalue; glyphs: ellipsoids of a tensor array (a field's MetricTensor)");
  representation.Choices = QStringList{ "slice", "isosurface", "glyphs" };
  PropertySpec normal = DisplaySpec(
    "SliceNormal", "Slice normal", PropertySpec::Choice, "z", "The slice's normal axis");
  normal.Choices = QStringList{ "x", "y", "z" };
  PropertySpec offset = DisplaySpec("SliceOffset", "Slice offset", PropertySpec::Number, 0.0,
    "Distance of the slice from the grid's centre along its normal");
  PropertySpec contour = DisplaySpec("ContourValue", "Isovalue", PropertySpec::Number, 0.5,
    "Value of the colouring array (or the first scalar) on the isosurface");
  PropertySpec levels = DisplaySpec("NumberOfContours", "Level lines", PropertySpec::Integer, 0,
    "Level lines of the colouring array (or the first scalar) drawn on the slice: a distance's "
    "wavefronts");
  levels.Minimum = 0;
  levels.Maximum = 200;
  // A distance field's projects before displays were the view's.
  levels.Aliases = QStringList{ "NumberOfWavefronts" };
  return { representation, normal, offset, contour, levels };
}

void ImageDataDisplay::Show(vtkDataObject* data, const OutputLook& look,
  const nlohmann::json& settings, ColorScale coloring, vtkScalarBarActor* bar)
{
  auto* image = vtkImageData::SafeDownCast(data);
  const bool shown = image && image->GetNumberOfPoints() > 0;
  if (!shown)
  {
    ApplyColoring(this->Surface, nullptr, coloring, look.Solid.data(), bar);
    this->Surface->SetVisibility(false);
    this->LevelLines->SetVisibility(false);
    return;
  }
  // An array the grid lacks colours by its first scalar (a field whose kind changed).
  if (coloring.Array != "Solid" && !image->GetPointData()->GetArray(coloring.Array.c_str()))
  {
    coloring.Array = FirstPointArray(image, 1);
  }
  const std::string scalar = ScalarOrFirst(image, coloring.Array);
  const std::string representation = settings.value("Representation", "slice");
  const std::string tensors = image->GetPointData()->GetArray("MetricTensor")
    ? std::string("MetricTensor")
    : FirstPointArray(image, 9);
  vtkSmartPointer<vtkPolyData> slice;
  vtkSmartPointer<vtkPolyData> surface;
  if (representation == "glyphs" && !tensors.empty())
  {
    surface = TensorGlyphs(image, tensors);
  }
  else if (representation == "isosurface" && !scalar.empty())
  {
    surface = Isosurface(image, scalar, settings.value("ContourValue", 0.5));
  }
  else
  {
    slice = Slice(image, settings.value("SliceNormal", "z"), settings.value("SliceOffset", 0.0));
    surface = slice;
  }
  vtkPolyDataMapper::SafeDownCast(this->Surface->GetMapper())->SetInputData(surface);
  coloring.Opacity *= look.OpacityScale;
  ApplyColoring(this->Surface, surface, coloring, look.Solid.data(), bar);
  this->Surface->SetVisibility(true);

  const int levels = settings.value("NumberOfContours", 0);
  const bool lined = slice && levels > 0 && !scalar.empty();
  if (lined)
  {
    vtkPolyDataMapper::SafeDownCast(this->LevelLines->GetMapper())
      ->SetInputData(LevelLinesOf(slice, image, scalar, levels));
  }
  this->LevelLines->SetVisibility(lined);
}
}
}
