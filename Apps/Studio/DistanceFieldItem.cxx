// The distance from a seed (vtkRiemannDistanceField), shown as a slice
// coloured by distance, its level sets (the wavefronts) and the cut locus
// (vtkRiemannCutLocus, computed from the result for the display, with its
// declared settings as the item's display settings).
#include "PipelineItems.h"

#include "ColorMaps.h"
#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "SettingValues.h"
#include "vtkRiemannCutLocusSettingAccess.h"
#include "vtkRiemannDistanceFieldSettingAccess.h"

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
namespace
{
namespace distance = riemann::declared::vtkRiemannDistanceField;
namespace cutlocus = riemann::declared::vtkRiemannCutLocus;

/// A new item: the declared grid, seed radius and cut locus settings, one
/// seed left of the middle.
nlohmann::json DistanceFieldDefaults()
{
  vtkNew<vtkRiemannDistanceField> filter;
  vtkNew<vtkRiemannCutLocus> cut;
  nlohmann::json values = DeclaredDefaults(riemann::settings::SettingValues(filter));
  values.update(DeclaredDefaults(riemann::settings::SettingValues(cut)));
  values.update({ { "Seed", { -1.5, 0.0, 0.0 } }, { "SliceNormal", "z" }, { "SliceOffset", 0.0 },
    { "NumberOfWavefronts", 20 }, { "ShowCutLocus", true }, { "ColorArray", "Distance" } });
  return values;
}
}

DistanceFieldItem::DistanceFieldItem(const QString& name)
  : PipelineItem(name, DistanceFieldDefaults())
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

  std::vector<PropertySpec> specs{ seed };
  for (const PropertySpec& spec : DeclaredPropertySpecs(distance::Settings))
  {
    specs.push_back(spec);
  }
  for (const PropertySpec& spec : this->SliceProperties())
  {
    specs.push_back(spec);
  }
  specs.push_back(fronts);
  specs.push_back(cut);
  // The cut locus is computed from the shown field: its settings only redraw.
  for (PropertySpec spec : DeclaredPropertySpecs(cutlocus::Settings))
  {
    spec.Display = true;
    specs.push_back(spec);
  }
  for (const PropertySpec& spec : this->DisplayProperties())
  {
    specs.push_back(spec);
  }
  return specs;
}

vtkSmartPointer<vtkAlgorithm> DistanceFieldItem::MakeJob(const JobInputs& inputs) const
{
  // The seed is an input point, not a declared setting (Settings.md).
  auto field = DeclaredJob<vtkRiemannDistanceField>(this->Settings(), inputs);
  double seed[3];
  this->Vector("Seed", seed, 3);
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
  riemann::settings::ApplySettings(cut, this->Settings());
  cut->SetInputData(image);
  cut->Update();
  vtkPolyDataMapper::SafeDownCast(this->CutLocus->GetMapper())->SetInputData(cut->GetOutput());
  vtkPolyDataMapper::SafeDownCast(this->CutLocus->GetMapper())->ScalarVisibilityOff();
  this->CutLocus->SetVisibility(this->Settings().at("ShowCutLocus").get<bool>());
}

std::vector<std::string> DistanceFieldItem::PythonLines(const std::string& var) const
{
  std::vector<std::string> lines =
    DeclaredPythonLines<vtkRiemannDistanceField>(this->FilterClass(), var, this->Settings());
  lines.push_back(var + ".AddSeed" + PythonTuple(this->Settings().at("Seed")));
  if (this->Settings().at("ShowCutLocus").get<bool>())
  {
    // The cut locus as the view draws it, kept as an item of its own.
    const std::string cut = var + "_cut_locus";
    lines.push_back(cut + " = riemann.vtkRiemannCutLocus()");
    lines.push_back(cut + ".SetInputConnection(" + var + ".GetOutputPort())");
    for (const std::string& line : riemann::SettingPythonLines(cutlocus::Settings, cut, this->Settings()))
    {
      lines.push_back(line);
    }
    lines.push_back(cut + ".Update()");
    lines.push_back("items[" + PythonString(this->Name().toStdString() + " cut locus") + "] = " + cut);
  }
  return lines;
}

bool DistanceFieldItem::TakePickedPoint(const double point[3])
{
  return this->ApplySettings({ { "Seed", { point[0], point[1], point[2] } } }).isEmpty();
}
}
}
