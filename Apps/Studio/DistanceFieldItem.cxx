// The distance from a seed (vtkRiemannDistanceField), shown as a slice
// coloured by distance, its level sets (the wavefronts) and the cut locus
// (vtkRiemannCutLocus, computed from the result for the display).
#include "PipelineItems.h"

#include "ColorMaps.h"

#include "vtkRiemannCutLocus.h"
#include "vtkRiemannDistanceField.h"
#include "vtkRiemannMetric.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkContourFilter.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"

#include <algorithm>

namespace riemann
{
namespace studio
{
DistanceFieldItem::DistanceFieldItem(const QString& name)
  : PipelineItem(name,
      { { "Seed", { -1.5, 0.0, 0.0 } }, { "Bounds", { -2.0, 2.0, -2.0, 2.0, -2.0, 2.0 } },
        { "Dimensions", { 49, 49, 49 } }, { "SliceNormal", "z" }, { "SliceOffset", 0.0 },
        { "NumberOfWavefronts", 20 }, { "ShowCutLocus", true }, { "ColorArray", "Distance" } })
{
  for (vtkActor* actor : { this->Slice.Get(), this->Wavefronts.Get(), this->CutLocus.Get() })
  {
    vtkNew<vtkPolyDataMapper> mapper;
    actor->SetMapper(mapper);
    this->Assembly->AddPart(actor);
  }
  this->Wavefronts->GetProperty()->SetColor(0.05, 0.05, 0.05);
  this->Wavefronts->GetProperty()->SetLineWidth(1.5);
  this->CutLocus->GetProperty()->SetColor(1.0, 1.0, 1.0);
  this->CutLocus->GetProperty()->SetOpacity(0.55);
  vtkNew<vtkPolyDataMapper> seedMapper;
  seedMapper->SetInputConnection(this->Seed->GetOutputPort());
  this->SeedBall->SetMapper(seedMapper);
  this->SeedBall->GetProperty()->SetColor(0.95, 0.3, 0.2);
  this->Assembly->AddPart(this->SeedBall);
  this->UpdateDisplay();
}

std::vector<PropertySpec> DistanceFieldItem::Properties() const
{
  PropertySpec seed;
  seed.Key = "Seed";
  seed.Label = "Seed";
  seed.Type = PropertySpec::Vector3;
  seed.Help = "The point the distance is measured from, inside the bounds (Ctrl+click in the "
              "outside view places it)";

  PropertySpec bounds;
  bounds.Key = "Bounds";
  bounds.Label = "Bounds";
  bounds.Type = PropertySpec::Numbers6;
  bounds.Help = "x0 x1 y0 y1 z0 z1 of the grid";

  PropertySpec dimensions;
  dimensions.Key = "Dimensions";
  dimensions.Label = "Samples";
  dimensions.Type = PropertySpec::Integers3;
  dimensions.Minimum = 2;
  dimensions.Maximum = 512;
  dimensions.Help = "Grid points per axis (first order: the error halves with the spacing, up "
                    "to a logarithm)";

  PropertySpec fronts;
  fronts.Key = "NumberOfWavefronts";
  fronts.Label = "Wavefronts";
  fronts.Type = PropertySpec::Integer;
  fronts.Minimum = 0;
  fronts.Maximum = 200;
  fronts.Help = "Level sets of the distance drawn on the slice";
  fronts.Display = true;

  PropertySpec cut;
  cut.Key = "ShowCutLocus";
  cut.Label = "Cut locus";
  cut.Type = PropertySpec::Boolean;
  cut.Help = "Where two minimal geodesics from the seed meet (vtkRiemannCutLocus)";
  cut.Display = true;

  std::vector<PropertySpec> specs{ seed, bounds, dimensions };
  for (const PropertySpec& spec : this->SliceProperties())
  {
    specs.push_back(spec);
  }
  specs.push_back(fronts);
  specs.push_back(cut);
  for (const PropertySpec& spec : this->DisplayProperties())
  {
    specs.push_back(spec);
  }
  return specs;
}

vtkSmartPointer<vtkAlgorithm> DistanceFieldItem::MakeJob(const JobInputs& inputs) const
{
  auto field = vtkSmartPointer<vtkRiemannDistanceField>::New();
  vtkNew<vtkRiemannMetric> metric;
  metric->ShallowCopy(inputs.Metric);
  field->SetMetric(metric);
  double bounds[6], seed[3];
  this->Vector("Bounds", bounds, 6);
  this->Vector("Seed", seed, 3);
  field->SetBounds(bounds);
  const nlohmann::json& dimensions = this->Settings().at("Dimensions");
  field->SetDimensions(dimensions[0].get<int>(), dimensions[1].get<int>(), dimensions[2].get<int>());
  field->AddSeed(seed);
  return field;
}

void DistanceFieldItem::UpdateDisplay()
{
  double seed[3];
  this->Vector("Seed", seed, 3);
  this->Seed->SetCenter(seed);
  auto* image = vtkImageData::SafeDownCast(this->Result(0));
  const bool shown = image && image->GetPointData()->GetArray("Distance");
  for (vtkActor* actor : { this->Slice.Get(), this->Wavefronts.Get(), this->CutLocus.Get() })
  {
    actor->SetVisibility(shown);
  }
  if (!shown)
  {
    return;
  }
  double bounds[6];
  image->GetBounds(bounds);
  this->Seed->SetRadius(0.015 * (bounds[1] - bounds[0] + bounds[3] - bounds[2] + bounds[5] - bounds[4]));

  // The slice, coloured by the chosen array (Distance by default).
  const vtkSmartPointer<vtkPolyData> slice = this->SliceOf(image);
  vtkPolyDataMapper::SafeDownCast(this->Slice->GetMapper())->SetInputData(slice);
  const double white[3] = { 0.9, 0.9, 0.9 };
  ApplyColoring(this->Slice, slice, this->Coloring(this->Text("ColorArray"), this->Number("Opacity")),
    white, this->ScalarBar());

  // The wavefronts: level sets of the distance on the slice.
  vtkNew<vtkContourFilter> fronts;
  fronts->SetInputData(slice);
  fronts->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Distance");
  double range[2];
  image->GetPointData()->GetArray("Distance")->GetRange(range);
  const int count = this->Integer("NumberOfWavefronts");
  if (count > 0 && range[1] > range[0])
  {
    fronts->GenerateValues(count, range[0] + (range[1] - range[0]) / (count + 1),
      range[1] - (range[1] - range[0]) / (count + 1));
  }
  fronts->ComputeScalarsOff();
  fronts->Update();
  vtkPolyDataMapper::SafeDownCast(this->Wavefronts->GetMapper())->SetInputData(fronts->GetOutput());
  this->Wavefronts->SetVisibility(count > 0);

  // The cut locus, in 3D.
  vtkNew<vtkRiemannCutLocus> cut;
  cut->SetInputData(image);
  cut->Update();
  vtkPolyDataMapper::SafeDownCast(this->CutLocus->GetMapper())->SetInputData(cut->GetOutput());
  vtkPolyDataMapper::SafeDownCast(this->CutLocus->GetMapper())->ScalarVisibilityOff();
  this->CutLocus->SetVisibility(this->Settings().at("ShowCutLocus").get<bool>());
}

std::vector<std::string> DistanceFieldItem::PythonLines(const std::string& var) const
{
  const nlohmann::json& dimensions = this->Settings().at("Dimensions");
  return {
    var + " = riemann.vtkRiemannDistanceField()",
    var + ".SetMetric(metric)",
    var + ".SetBounds" + PythonTuple(this->Settings().at("Bounds")),
    var + ".SetDimensions" + PythonTuple(dimensions),
    var + ".AddSeed" + PythonTuple(this->Settings().at("Seed")),
  };
}

bool DistanceFieldItem::TakePickedPoint(const double point[3])
{
  return this->ApplySettings({ { "Seed", { point[0], point[1], point[2] } } }).isEmpty();
}
}
}
