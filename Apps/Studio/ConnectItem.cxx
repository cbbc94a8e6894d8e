// Every geodesic between two points (vtkRiemannGeodesicConnector), drawn as
// the picked ray is: tubes, and a ball where they end.
#include "PipelineItems.h"

#include "DeclaredJob.h"
#include "DeclaredProperties.h"
#include "vtkRiemannGeodesicConnectorSettingAccess.h"

#include "ColorMaps.h"

#include "vtkRiemannGeodesicConnector.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkTubeFilter.h"

#include <algorithm>

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
}

ConnectItem::ConnectItem(const QString& name)
  : PipelineItem(name, ConnectDefaults())
{
  // The picked ray's look (OutsideView::ShowPickedRay): magenta tubes.
  this->Tubes->SetNumberOfSides(8);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(this->Tubes->GetOutputPort());
  this->Lines->SetMapper(mapper);
  this->Lines->GetProperty()->SetColor(PickedRayColor[0], PickedRayColor[1], PickedRayColor[2]);
  this->Assembly->AddPart(this->Lines);
  vtkNew<vtkPolyDataMapper> endMapper;
  endMapper->SetInputConnection(this->End->GetOutputPort());
  this->EndBall->SetMapper(endMapper);
  this->EndBall->GetProperty()->SetColor(PickedRayColor[0], PickedRayColor[1], PickedRayColor[2]);
  this->Assembly->AddPart(this->EndBall);
  this->UpdateDisplay();
}

std::vector<PropertySpec> ConnectItem::Properties() const
{
  // Ctrl+click in the outside view picks From, then To (TakePickedPoint).
  return this->WithIntegrationAndDisplay(
    DeclaredPropertySpecs(riemann::declared::vtkRiemannGeodesicConnector::Settings));
}

vtkSmartPointer<vtkAlgorithm> ConnectItem::MakeJob(const JobInputs& inputs) const
{
  return DeclaredJob<vtkRiemannGeodesicConnector>(this->Settings(), inputs);
}

void ConnectItem::UpdateDisplay()
{
  auto* lines = vtkPolyData::SafeDownCast(this->Result(0));
  double to[3];
  this->Vector("EndPosition", to, 3);
  this->End->SetCenter(to);
  if (lines)
  {
    this->Tubes->SetInputData(lines);
    // Sized with the geodesics, as the picked ray with the scene.
    double bounds[6];
    lines->GetBounds(bounds);
    const double size = std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2],
      bounds[5] - bounds[4], 1.0 });
    this->Tubes->SetRadius(0.006 * size);
    this->End->SetRadius(0.02 * size);
  }
  ApplyColoring(this->Lines, lines, this->Coloring(this->Text("ColorArray"), this->Number("Opacity")),
    PickedRayColor, this->ScalarBar());
  const bool shown = lines && lines->GetNumberOfLines() > 0;
  this->Lines->SetVisibility(shown);
  this->EndBall->SetVisibility(shown);
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
