// Geodesics from a seed over a cone of directions (vtkRiemannGeodesicTracer).
#include "PipelineItems.h"

#include "ColorMaps.h"

#include "vtkRiemannDirectionGrid.h"
#include "vtkRiemannGeodesicTracer.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"

namespace riemann
{
namespace studio
{
namespace
{
/// The seeds: NumberOfDirections points at the start position whose
/// "Direction" vectors are vtkRiemannDirectionGrid's cone of directions.
vtkSmartPointer<vtkPolyData> MakeSeeds(
  const double position[3], const double axis[3], double angle, int count)
{
  vtkNew<vtkRiemannDirectionGrid> grid;
  grid->SetNumberOfDirections(count);
  grid->SetConeAxis(axis[0], axis[1], axis[2]);
  grid->SetConeAngle(angle);
  grid->Update();
  vtkPoints* directions = grid->GetOutput()->GetPoints();
  auto seeds = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  auto direction = vtkSmartPointer<vtkDataArray>::Take(directions->GetData()->NewInstance());
  direction->DeepCopy(directions->GetData());
  direction->SetName("Direction");
  points->SetNumberOfPoints(direction->GetNumberOfTuples());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->SetPoint(i, position);
  }
  seeds->SetPoints(points);
  seeds->GetPointData()->AddArray(direction);
  return seeds;
}
}

GeodesicsItem::GeodesicsItem(const QString& name)
  : PipelineItem(name,
      WithIntegrationDefaults(
        { { "StartPosition", { -3.0, 0.0, 0.0 } }, { "ConeAxis", { 1.0, 0.0, 0.0 } },
          { "ConeAngle", 15.0 }, { "NumberOfDirections", 24 },
          { "IntegrationDirection", "forward" } },
        "rk4", 7.0))
{
  vtkNew<vtkPolyDataMapper> mapper;
  this->Lines->SetMapper(mapper);
  this->Lines->GetProperty()->SetLineWidth(2.0);
  this->Assembly->AddPart(this->Lines);
  this->UpdateDisplay();
}

std::vector<PropertySpec> GeodesicsItem::Properties() const
{
  PropertySpec seed;
  seed.Key = "StartPosition";
  seed.Label = "Seed";
  seed.Type = PropertySpec::Vector3;
  seed.Help = "Where every geodesic starts";

  PropertySpec axis;
  axis.Key = "ConeAxis";
  axis.Label = "Direction";
  axis.Type = PropertySpec::Vector3;
  axis.NonZero = true;
  axis.Help = "Axis of the cone of initial directions (coordinates; normalised in g)";

  PropertySpec cone;
  cone.Key = "ConeAngle";
  cone.Label = "Cone angle";
  cone.Minimum = 0.0;
  cone.Maximum = 180.0;
  cone.Help = "Half-angle of the cone in degrees (180: all directions)";

  PropertySpec count;
  count.Key = "NumberOfDirections";
  count.Label = "Directions";
  count.Type = PropertySpec::Integer;
  count.Minimum = 1;
  count.Maximum = 100000;
  count.Help = "Number of geodesics (1: along the axis only)";

  PropertySpec direction;
  direction.Key = "IntegrationDirection";
  direction.Label = "Integrate";
  direction.Type = PropertySpec::Choice;
  direction.Choices = QStringList{ "forward", "backward", "both" };

  return this->WithIntegrationAndDisplay({ seed, axis, cone, count, direction });
}

vtkSmartPointer<vtkAlgorithm> GeodesicsItem::MakeJob(const JobInputs& inputs) const
{
  auto tracer = vtkSmartPointer<vtkRiemannGeodesicTracer>::New();
  vtkNew<vtkRiemannMetric> metric;
  metric->ShallowCopy(inputs.Metric);
  tracer->SetMetric(metric);
  this->ApplyIntegration(tracer->GetIntegrationSettings());
  const std::string direction = this->Text("IntegrationDirection");
  tracer->SetIntegrationDirection(direction == "backward" ? vtkRiemannGeodesicTracer::BACKWARD
      : direction == "both"                              ? vtkRiemannGeodesicTracer::BOTH
                                                         : vtkRiemannGeodesicTracer::FORWARD);
  double position[3], axis[3];
  this->Vector("StartPosition", position, 3);
  this->Vector("ConeAxis", axis, 3);
  tracer->SetStartPosition(position);
  tracer->SetStartDirection(axis);
  const int count = this->Integer("NumberOfDirections");
  if (count > 1)
  {
    tracer->SetInputData(MakeSeeds(position, axis, this->Number("ConeAngle"), count));
  }
  return tracer;
}

void GeodesicsItem::UpdateDisplay()
{
  auto* lines = vtkPolyData::SafeDownCast(this->Result(0));
  auto* mapper = vtkPolyDataMapper::SafeDownCast(this->Lines->GetMapper());
  if (lines)
  {
    mapper->SetInputData(lines);
  }
  const double yellow[3] = { 1.0, 0.85, 0.2 };
  ApplyColoring(this->Lines, lines, this->Coloring(this->Text("ColorArray"), this->Number("Opacity")),
    yellow, this->ScalarBar());
  this->Lines->SetVisibility(lines != nullptr);
}

std::vector<std::string> GeodesicsItem::PythonLines(const std::string& var) const
{
  const std::string direction = this->Text("IntegrationDirection");
  std::vector<std::string> lines{
    var + " = riemann.vtkRiemannGeodesicTracer()",
    var + ".SetMetric(metric)",
    var + ".SetStartPosition" + PythonTuple(this->Settings().at("StartPosition")),
    var + ".SetStartDirection" + PythonTuple(this->Settings().at("ConeAxis")),
    var + ".SetIntegrationDirectionTo" +
      (direction == "both" ? "Both()" : direction == "backward" ? "Backward()" : "Forward()"),
  };
  if (this->Integer("NumberOfDirections") > 1)
  {
    lines.push_back(var + ".SetInputData(seeds_from_cone(" +
      PythonTuple(this->Settings().at("StartPosition")) + ", " +
      PythonTuple(this->Settings().at("ConeAxis")) + ", " +
      PythonNumber(this->Number("ConeAngle")) + ", " +
      std::to_string(this->Integer("NumberOfDirections")) + "))");
  }
  for (const std::string& line : this->IntegrationPythonLines(var))
  {
    lines.push_back(line);
  }
  return lines;
}
}
}
