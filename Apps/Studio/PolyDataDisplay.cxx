#include "PolyDataDisplay.h"

#include "vtkAssembly.h"
#include "vtkConeSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"

#include <algorithm> // std::max

namespace riemann
{
namespace studio
{
PolyDataDisplay::PolyDataDisplay(vtkAssembly* parts)
{
  vtkNew<vtkPolyDataMapper> mapper;
  this->Surface->SetMapper(mapper);
  this->Tubes->SetNumberOfSides(8);
  parts->AddPart(this->Surface);
  // Cones along a vector array: where a camera path's observer looks.
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(12);
  cone->SetHeight(1.0);
  cone->SetRadius(0.3);
  this->HeadingPoints->RandomModeOff();
  this->HeadingPoints->GenerateVerticesOff();
  this->Heading->SetInputConnection(this->HeadingPoints->GetOutputPort());
  this->Heading->SetSourceConnection(cone->GetOutputPort());
  this->Heading->SetVectorModeToUseVector();
  this->Heading->SetScaleModeToDataScalingOff();
  this->Heading->OrientOn();
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(this->Heading->GetOutputPort());
  this->Cones->SetMapper(coneMapper);
  this->Cones->GetProperty()->SetColor(0.95, 0.95, 0.95);
  this->Cones->SetVisibility(false);
  parts->AddPart(this->Cones);
}

void PolyDataDisplay::Show(vtkDataObject* data, const OutputLook& look, const nlohmann::json&,
  ColorScale coloring, vtkScalarBarActor* bar)
{
  auto* poly = vtkPolyData::SafeDownCast(data);
  const bool shown = poly && poly->GetNumberOfCells() > 0;
  auto* mapper = vtkPolyDataMapper::SafeDownCast(this->Surface->GetMapper());
  if (shown && look.TubeRadius > 0.0)
  {
    this->Tubes->SetInputData(poly);
    this->Tubes->SetRadius(look.TubeRadius * LargestSide(poly));
    mapper->SetInputConnection(this->Tubes->GetOutputPort());
  }
  else if (shown)
  {
    mapper->SetInputData(poly);
  }
  vtkProperty* property = this->Surface->GetProperty();
  property->SetLineWidth(static_cast<float>(look.LineWidth));
  property->SetRenderPointsAsSpheres(look.PointSize > 0.0);
  property->SetPointSize(static_cast<float>(look.PointSize > 0.0 ? look.PointSize : 1.0));
  if (!look.FollowsColoring)
  {
    coloring.Array = "Solid";
  }
  coloring.Opacity *= look.OpacityScale;
  ApplyColoring(this->Surface, shown ? poly : nullptr, coloring, look.Solid.data(), bar);
  this->Surface->SetVisibility(shown);

  const bool heading = shown && !look.HeadingArray.empty() &&
    poly->GetPointData()->GetArray(look.HeadingArray.c_str());
  if (heading)
  {
    poly->GetPointData()->SetActiveVectors(look.HeadingArray.c_str());
    // About 16 cones: a dense flight's frames would overlap into a sleeve.
    this->HeadingPoints->SetInputData(poly);
    this->HeadingPoints->SetOnRatio(std::max<vtkIdType>(1, poly->GetNumberOfPoints() / 16));
    this->HeadingPoints->SetMaximumNumberOfPoints(poly->GetNumberOfPoints());
    this->Heading->SetScaleFactor(0.06 * LargestSide(poly));
  }
  this->Cones->SetVisibility(heading);
}
}
}
