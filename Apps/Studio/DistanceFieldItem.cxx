// The distance from a seed (vtkRiemannDistanceField), which the view shows
// as a slice coloured by distance with its level lines (the wavefronts:
// ImageDataDisplay), the cut locus (vtkRiemannCutLocus, computed from the
// result for the view, its declared settings redrawing only) and a marker
// at the seed.
#include "PipelineItems.h"

#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "SettingValues.h"
#include "vtkRiemannCutLocusSettingAccess.h"
#include "vtkRiemannDistanceFieldSettingAccess.h"

#include "vtkRiemannCutLocus.h"
#include "vtkRiemannDistanceField.h"
#include "vtkRiemannMetric.h"

#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"


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
  values.update({ { "Seed", { -1.5, 0.0, 0.0 } }, { "NumberOfContours", 20 }, { "ShowCutLocus", true },
    { "ColorArray", "Distance" } });
  return values;
}

/// The grid (with the legend), the cut locus (translucent white) and the seed (a red ball).
std::vector<OutputLook> DistanceFieldLooks()
{
  OutputLook cut = LookOf("vtkPolyData", { { 1.0, 1.0, 1.0 } }, false);
  cut.FollowsColoring = false;
  cut.OpacityScale = 0.55;
  OutputLook seed = LookOf("vtkPolyData", { { 0.95, 0.3, 0.2 } }, false);
  seed.FollowsColoring = false;
  return { LookOf("vtkImageData", { { 0.9, 0.9, 0.9 } }, true), cut, seed };
}
}

DistanceFieldItem::DistanceFieldItem(const QString& name)
  : PipelineItem(name, DistanceFieldDefaults(), DistanceFieldLooks())
{
}

std::vector<PropertySpec> DistanceFieldItem::ItemProperties() const
{
  PropertySpec seed;
  seed.Key = "Seed";
  seed.Label = "Seed";
  seed.Type = PropertySpec::Vector3;
  seed.Help = "The point the distance is measured from, inside the bounds (Ctrl+click in the "
              "outside view places it)";

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
  specs.push_back(cut);
  // The cut locus is computed from the shown field: its settings only redraw.
  for (PropertySpec spec : DeclaredPropertySpecs(cutlocus::Settings))
  {
    spec.Display = true;
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

std::vector<vtkSmartPointer<vtkDataObject>> DistanceFieldItem::ShownData() const
{
  vtkSmartPointer<vtkDataObject> grid = this->Result(0);
  auto* image = vtkImageData::SafeDownCast(grid);
  if (!image || !image->GetPointData()->GetArray("Distance"))
  {
    return { nullptr, nullptr, nullptr };
  }
  vtkSmartPointer<vtkDataObject> cutLocus =
    this->Settings().at("ShowCutLocus").get<bool>() ? this->CutLocusOf(image) : nullptr;
  double seed[3], bounds[6];
  this->Vector("Seed", seed, 3);
  image->GetBounds(bounds);
  const double radius = 0.015 * (bounds[1] - bounds[0] + bounds[3] - bounds[2] + bounds[5] - bounds[4]);
  return { grid, cutLocus, SphereMarker(seed, radius) };
}

vtkDataObject* DistanceFieldItem::CutLocusOf(vtkImageData* grid) const
{
  nlohmann::json settings = nlohmann::json::object();
  for (const riemann::SettingDeclaration& setting : cutlocus::Settings)
  {
    settings[setting.Name] = this->Settings().at(setting.Name);
  }
  if (!this->CutLocus || this->CutLocusGrid != grid || this->CutLocusSettings != settings)
  {
    vtkNew<vtkRiemannCutLocus> cut;
    riemann::settings::ApplySettings(cut, settings);
    cut->SetInputData(grid);
    cut->Update();
    this->CutLocus = cut->GetOutput();
    this->CutLocusGrid = grid;
    this->CutLocusSettings = std::move(settings);
  }
  return this->CutLocus;
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
