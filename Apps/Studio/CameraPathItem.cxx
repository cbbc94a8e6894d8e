// A flight of the observer through curved space (vtkRiemannCameraPath),
// shown as a tube with cones along "straight ahead" (its Forward array) at
// a few of its frames; File > Export Animation flies the inside view along it.
#include "PipelineItems.h"

#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "SettingValues.h"
#include "vtkRiemannCameraPathSettingAccess.h"

#include "vtkRiemannCameraPath.h"
#include "vtkRiemannMetric.h"

#include "vtkPoints.h"

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

/// A cyan tube, with cones along each frame's Forward: where the observer looks.
OutputLook CameraPathLook()
{
  OutputLook look = LookOf("vtkPolyData", { { 0.3, 0.85, 0.95 } }, true);
  look.TubeRadius = 0.01;
  look.HeadingArray = "Forward";
  return look;
}
}

CameraPathItem::CameraPathItem(const QString& name)
  : PipelineItem(name, CameraPathDefaults(), { CameraPathLook() })
{
}

std::vector<PropertySpec> CameraPathItem::ItemProperties() const
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
