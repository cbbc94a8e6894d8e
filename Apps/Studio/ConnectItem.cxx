// Every geodesic between two points (vtkRiemannGeodesicConnector), shown as
// the picked ray is: tubes, and a ball where they end.
#include "PipelineItems.h"

#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "vtkRiemannGeodesicConnectorSettingAccess.h"

#include "ColorMaps.h"

#include "vtkRiemannGeodesicConnector.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include "vtkPolyData.h"


namespace riemann
{
namespace studio
{
namespace
{
/// A new connector's settings (its own integration defaults: dp45).
nlohmann::json ConnectDefaults()
{
  vtkNew<vtkRiemannGeodesicConnector> filter;
  return FilterDefaults(
    riemann::settings::SettingValues(filter), filter->GetIntegrationSettings(),
    nlohmann::json::object());
}

/// The picked ray's look (OutsideView::ShowPickedRay): magenta tubes, and a magenta ball.
std::vector<OutputLook> ConnectLooks()
{
  const std::array<double, 3> magenta{ { PickedRayColor[0], PickedRayColor[1], PickedRayColor[2] } };
  OutputLook lines = LookOf("vtkPolyData", magenta, true);
  lines.TubeRadius = 0.006;
  OutputLook end = LookOf("vtkPolyData", magenta, false);
  end.FollowsColoring = false;
  return { lines, end };
}
}

ConnectItem::ConnectItem(const QString& name)
  : PipelineItem(name, ConnectDefaults(), ConnectLooks())
{
}

std::vector<PropertySpec> ConnectItem::ItemProperties() const
{
  // Ctrl+click in the outside view picks From, then To (TakePickedPoint).
  return WithIntegration(
    DeclaredPropertySpecs(riemann::declared::vtkRiemannGeodesicConnector::Settings));
}

vtkSmartPointer<vtkAlgorithm> ConnectItem::MakeJob(const JobInputs& inputs) const
{
  return DeclaredJob<vtkRiemannGeodesicConnector>(this->Settings(), inputs);
}

std::vector<vtkSmartPointer<vtkDataObject>> ConnectItem::ShownData() const
{
  vtkSmartPointer<vtkDataObject> result = this->Result(0);
  auto* lines = vtkPolyData::SafeDownCast(result);
  if (!lines || lines->GetNumberOfLines() == 0)
  {
    return { nullptr, nullptr };
  }
  // Sized with the geodesics, as the picked ray with the scene.
  double to[3];
  this->Vector("EndPosition", to, 3);
  return { result, SphereMarker(to, 0.02 * LargestSide(lines)) };
}

std::vector<std::string> ConnectItem::PythonLines(const std::string& var) const
{
  return DeclaredPythonLines<vtkRiemannGeodesicConnector>(this->FilterClass(), var, this->Settings());
}

bool ConnectItem::TakePickedPoint(const double point[3])
{
  // Ctrl+clicks alternate: From, then To.
  const char* key = this->PickTo ? "EndPosition" : "StartPosition";
  this->PickTo = !this->PickTo;
  return this->ApplySettings({ { key, { point[0], point[1], point[2] } } }).isEmpty();
}
}
}
