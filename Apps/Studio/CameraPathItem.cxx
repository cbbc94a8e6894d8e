// A flight of the observer through curved space (vtkRiemannCameraPath): the
// path as a tube and, at each frame, a cone along "straight ahead"; File >
// Export Animation flies the inside view along it.
#include "PipelineItems.h"

#include "ColorMaps.h"
#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "SettingValues.h"
#include "vtkRiemannCameraPathSettingAccess.h"

#include "vtkRiemannCameraPath.h"
#include "vtkRiemannMetric.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkConeSource.h"
#include "vtkGlyph3D.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkTubeFilter.h"

#include <algorithm>

namespace riemann
{
namespace studio
{
namespace
{
namespace cameraPath = riemann::declared::vtkRiemannCameraPath;

/// A new item: the declared flight (from the inside view's default camera)
/// and no key positions yet.
nlohmann::json CameraPathDefaults()
{
  vtkNew<vtkRiemannCameraPath> filter;
  nlohmann::json values = DeclaredDefaults(riemann::settings::SettingValues(filter));
  values["KeyPositions"] = nlohmann::json::array();
  return values;
}
}

CameraPathItem::CameraPathItem(const QString& name)
  : PipelineItem(name, CameraPathDefaults())
{
  this->Tubes->SetNumberOfSides(8);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(this->Tubes->GetOutputPort());
  this->Path->SetMapper(mapper);
  this->Assembly->AddPart(this->Path);
  // Cones along each frame's Forward: where the observer looks.
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(12);
  cone->SetHeight(1.0);
  cone->SetRadius(0.3);
  this->Heading->SetSourceConnection(cone->GetOutputPort());
  this->Heading->SetVectorModeToUseVector();
  this->Heading->SetScaleModeToDataScalingOff();
  this->Heading->OrientOn();
  vtkNew<vtkPolyDataMapper> headingMapper;
  headingMapper->SetInputConnection(this->Heading->GetOutputPort());
  this->Cones->SetMapper(headingMapper);
  this->Cones->GetProperty()->SetColor(0.95, 0.95, 0.95);
  this->Assembly->AddPart(this->Cones);
  this->UpdateDisplay();
}

std::vector<PropertySpec> CameraPathItem::Properties() const
{
  // The key positions are the spline's input points, not a property of the
  // filter (SetKeyPositions takes vtkPoints): the item's own field.
  PropertySpec keys;
  keys.Key = "KeyPositions";
  keys.Label = "Keys";
  keys.Type = PropertySpec::PointList;
  keys.Help = "A spline flight's key positions, in order (Ctrl+click in the outside view adds one)";

  std::vector<PropertySpec> specs = DeclaredPropertySpecs(cameraPath::Settings);
  const auto afterLength = std::find_if(specs.begin(), specs.end(),
    [](const PropertySpec& spec) { return spec.Key == "Length"; });
  specs.insert(afterLength == specs.end() ? specs.end() : afterLength + 1, keys);
  for (const PropertySpec& display : this->DisplayProperties())
  {
    specs.push_back(display);
  }
  return specs;
}

vtkSmartPointer<vtkAlgorithm> CameraPathItem::MakeJob(const JobInputs& inputs) const
{
  auto path = DeclaredJob<vtkRiemannCameraPath>(this->Settings(), inputs);
  this->SetKeyPositions(path);
  return path;
}

void CameraPathItem::Configure(vtkRiemannCameraPath* path) const
{
  riemann::settings::ApplySettings(path, this->Settings());
  this->SetKeyPositions(path);
}

void CameraPathItem::SetKeyPositions(vtkRiemannCameraPath* path) const
{
  // Input points, not a declared setting (Settings.md).
  vtkNew<vtkPoints> keys;
  for (const nlohmann::json& key : this->Settings().at("KeyPositions"))
  {
    keys->InsertNextPoint(key[0].get<double>(), key[1].get<double>(), key[2].get<double>());
  }
  path->SetKeyPositions(keys);
}

void CameraPathItem::UpdateDisplay()
{
  auto* path = vtkPolyData::SafeDownCast(this->Result(0));
  const bool shown = path && path->GetNumberOfPoints() > 1;
  if (shown)
  {
    this->Tubes->SetInputData(path);
    path->GetPointData()->SetActiveVectors("Forward");
    this->Heading->SetInputData(path);
    double bounds[6];
    path->GetBounds(bounds);
    const double size =
      std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1.0 });
    this->Tubes->SetRadius(0.01 * size);
    this->Heading->SetScaleFactor(0.06 * size);
  }
  const double cyan[3] = { 0.3, 0.85, 0.95 };
  ApplyColoring(this->Path, path, this->Coloring(this->Text("ColorArray"), this->Number("Opacity")),
    cyan, this->ScalarBar());
  this->Path->SetVisibility(shown);
  this->Cones->SetVisibility(shown);
}

std::vector<std::string> CameraPathItem::PythonLines(const std::string& var) const
{
  const nlohmann::json& settings = this->Settings();
  std::vector<std::string> lines =
    DeclaredPythonLines<vtkRiemannCameraPath>(this->FilterClass(), var, settings);
  if (!settings.at("KeyPositions").empty())
  {
    lines.push_back(var + "_keys = vtkPoints()");
    for (const nlohmann::json& key : settings.at("KeyPositions"))
    {
      lines.push_back(var + "_keys.InsertNextPoint" + PythonTuple(key));
    }
    lines.push_back(var + ".SetKeyPositions(" + var + "_keys)");
  }
  return lines;
}

bool CameraPathItem::TakePickedPoint(const double point[3])
{
  // Each Ctrl+click adds a key: the flight becomes a spline through them.
  nlohmann::json keys = this->Settings().at("KeyPositions");
  keys.push_back({ point[0], point[1], point[2] });
  return this->ApplySettings({ { "KeyPositions", keys }, { "PathType", "spline" } }).isEmpty();
}
}
}
