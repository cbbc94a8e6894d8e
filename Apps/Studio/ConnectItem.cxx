// Every geodesic between two points (vtkRiemannGeodesicConnector), drawn as
// the picked ray is: tubes, and a ball where they end.
#include "PipelineItems.h"

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
ConnectItem::ConnectItem(const QString& name)
  : PipelineItem(name,
      WithIntegrationDefaults({ { "StartPosition", { -1.5, 0.2, 0.0 } },
                                { "EndPosition", { 1.5, -0.2, 0.3 } }, { "NumberOfDirections", 2000 },
                                { "Tolerance", 1e-9 } },
        "dp45", 10.0))
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
  PropertySpec from;
  from.Key = "StartPosition";
  from.Label = "From";
  from.Type = PropertySpec::Vector3;
  from.Help = "The point p the geodesics leave (Ctrl+click in the outside view picks it, then To)";

  PropertySpec to;
  to.Key = "EndPosition";
  to.Label = "To";
  to.Type = PropertySpec::Vector3;
  to.Help = "The point q they reach";

  PropertySpec count;
  count.Key = "NumberOfDirections";
  count.Label = "Directions";
  count.Type = PropertySpec::Integer;
  count.Minimum = 1;
  count.Maximum = 1000000;
  count.Help = "Directions of the shooting grid (more finds geodesics that only a narrow pencil "
               "sends past q)";

  PropertySpec tolerance;
  tolerance.Key = "Tolerance";
  tolerance.Label = "Tolerance";
  tolerance.Minimum = vtkRiemannGeodesicConnector::MinimumTolerance;
  tolerance.Maximum = vtkRiemannGeodesicConnector::MaximumTolerance;
  tolerance.Help = "What |end - q| each geodesic reaches";

  return this->WithIntegrationAndDisplay({ from, to, count, tolerance });
}

vtkSmartPointer<vtkAlgorithm> ConnectItem::MakeJob(const JobInputs& inputs) const
{
  auto connector = vtkSmartPointer<vtkRiemannGeodesicConnector>::New();
  vtkNew<vtkRiemannMetric> metric;
  metric->ShallowCopy(inputs.Metric);
  connector->SetMetric(metric);
  this->ApplyIntegration(connector->GetIntegrationSettings());
  double from[3], to[3];
  this->Vector("StartPosition", from, 3);
  this->Vector("EndPosition", to, 3);
  connector->SetStartPosition(from);
  connector->SetEndPosition(to);
  connector->SetNumberOfDirections(this->Integer("NumberOfDirections"));
  connector->SetTolerance(this->Number("Tolerance"));
  return connector;
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
  std::vector<std::string> lines{
    var + " = riemann.vtkRiemannGeodesicConnector()",
    var + ".SetMetric(metric)",
    var + ".SetStartPosition" + PythonTuple(this->Settings().at("StartPosition")),
    var + ".SetEndPosition" + PythonTuple(this->Settings().at("EndPosition")),
    var + ".SetNumberOfDirections(" + std::to_string(this->Integer("NumberOfDirections")) + ")",
    var + ".SetTolerance(" + PythonNumber(this->Number("Tolerance")) + ")",
  };
  for (const std::string& line : this->IntegrationPythonLines(var))
  {
    lines.push_back(line);
  }
  return lines;
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
