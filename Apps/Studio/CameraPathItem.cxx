// A flight of the observer through curved space (vtkRiemannCameraPath): the
// path as a tube and, at each frame, a cone along "straight ahead"; File >
// Export Animation flies the inside view along it.
#include "PipelineItems.h"

#include "ColorMaps.h"

#include "PictureSchema.h"
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
nlohmann::json SchemaVector(PictureSettingId id)
{
  const std::array<double, 3>& v = PictureSettingOf(id).Default;
  return { v[0], v[1], v[2] };
}
}

CameraPathItem::CameraPathItem(const QString& name)
  : PipelineItem(name,
      { { "PathType", "geodesic" }, { "Position", SchemaVector(PictureSettingId::Position) },
        { "LookAt", SchemaVector(PictureSettingId::LookAt) },
        { "ViewUp", SchemaVector(PictureSettingId::ViewUp) }, { "Length", 3.0 },
        { "KeyPositions", nlohmann::json::array() }, { "NumberOfFrames", 60 } })
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
  PropertySpec type;
  type.Key = "PathType";
  type.Label = "Path";
  type.Type = PropertySpec::Choice;
  type.Choices = QStringList{ "geodesic", "spline" };
  type.Help = "geodesic: fly straight ahead from Position towards Looks at; spline: through the "
              "key positions (Ctrl+click in the outside view adds one)";

  PropertySpec position;
  position.Key = "Position";
  position.Label = "Position";
  position.Type = PropertySpec::Vector3;
  position.Help = "Where a geodesic flight starts";

  PropertySpec lookAt;
  lookAt.Key = "LookAt";
  lookAt.Label = "Looks at";
  lookAt.Type = PropertySpec::Vector3;
  lookAt.Help = "The direction a geodesic flight takes";

  PropertySpec up;
  up.Key = "ViewUp";
  up.Label = "View up";
  up.Type = PropertySpec::Vector3;
  up.NonZero = true;
  up.Help = "Up at the first frame; then carried along the path by the metric";

  PropertySpec length;
  length.Key = "Length";
  length.Label = "Length";
  length.Minimum = 0.0;
  length.MinimumExclusive = true;
  length.Maximum = 1e6;
  length.Help = "The g-length a geodesic flight covers";

  PropertySpec keys;
  keys.Key = "KeyPositions";
  keys.Label = "Keys";
  keys.Type = PropertySpec::PointList;
  keys.Help = "A spline flight's key positions, in order (Ctrl+click in the outside view adds one)";

  PropertySpec frames;
  frames.Key = "NumberOfFrames";
  frames.Label = "Frames";
  frames.Type = PropertySpec::Integer;
  frames.Minimum = 2;
  frames.Maximum = 100000;
  frames.Help = "Frames of the film (Export Animation uses the count it is given)";

  std::vector<PropertySpec> specs{ type, position, lookAt, up, length, keys, frames };
  for (const PropertySpec& display : this->DisplayProperties())
  {
    specs.push_back(display);
  }
  return specs;
}

vtkSmartPointer<vtkAlgorithm> CameraPathItem::MakeJob(const JobInputs& inputs) const
{
  auto path = vtkSmartPointer<vtkRiemannCameraPath>::New();
  vtkNew<vtkRiemannMetric> metric;
  metric->ShallowCopy(inputs.Metric);
  path->SetMetric(metric);
  this->Configure(path);
  return path;
}

void CameraPathItem::Configure(vtkRiemannCameraPath* path) const
{
  double v[3];
  path->SetPathType(this->Text("PathType") == "spline" ? vtkRiemannCameraPath::SPLINE
                                                       : vtkRiemannCameraPath::GEODESIC);
  this->Vector("Position", v, 3);
  path->SetPosition(v);
  this->Vector("LookAt", v, 3);
  path->SetLookAt(v);
  this->Vector("ViewUp", v, 3);
  path->SetViewUp(v);
  path->SetLength(this->Number("Length"));
  vtkNew<vtkPoints> keys;
  for (const nlohmann::json& key : this->Settings().at("KeyPositions"))
  {
    keys->InsertNextPoint(key[0].get<double>(), key[1].get<double>(), key[2].get<double>());
  }
  path->SetKeyPositions(keys);
  path->SetNumberOfFrames(this->Integer("NumberOfFrames"));
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
  std::vector<std::string> lines{
    var + " = riemann.vtkRiemannCameraPath()",
    var + ".SetMetric(metric)",
    var + ".SetPathTypeTo" + (this->Text("PathType") == "spline" ? "Spline()" : "Geodesic()"),
    var + ".SetPosition" + PythonTuple(settings.at("Position")),
    var + ".SetLookAt" + PythonTuple(settings.at("LookAt")),
    var + ".SetViewUp" + PythonTuple(settings.at("ViewUp")),
    var + ".SetLength(" + PythonNumber(this->Number("Length")) + ")",
    var + ".SetNumberOfFrames(" + std::to_string(this->Integer("NumberOfFrames")) + ")",
  };
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
