#include "ColorMaps.h"

#include "vtkActor.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkProperty.h"

#include <algorithm>

namespace riemann
{
namespace studio
{
namespace
{
/// Control points (x in [0, 1], r, g, b) of each map.
struct ControlPoint
{
  double X, R, G, B;
};

std::vector<ControlPoint> ControlPoints(const std::string& name)
{
  if (name == "viridis")
  {
    return { { 0.0, 0.267, 0.005, 0.329 }, { 0.25, 0.230, 0.322, 0.546 },
      { 0.5, 0.128, 0.567, 0.551 }, { 0.75, 0.369, 0.789, 0.383 }, { 1.0, 0.993, 0.906, 0.144 } };
  }
  if (name == "rainbow")
  {
    return { { 0.0, 0.0, 0.0, 1.0 }, { 0.25, 0.0, 1.0, 1.0 }, { 0.5, 0.0, 1.0, 0.0 },
      { 0.75, 1.0, 1.0, 0.0 }, { 1.0, 1.0, 0.0, 0.0 } };
  }
  if (name == "grayscale")
  {
    return { { 0.0, 0.0, 0.0, 0.0 }, { 1.0, 1.0, 1.0, 1.0 } };
  }
  // Moreland's cool to warm (ParaView's default), diverging in Msh space.
  return { { 0.0, 0.230, 0.299, 0.754 }, { 0.5, 0.865, 0.865, 0.865 },
    { 1.0, 0.706, 0.016, 0.150 } };
}
}

QStringList ColorMapNames()
{
  return { "cool-to-warm", "viridis", "rainbow", "grayscale" };
}

void ApplyColoring(vtkActor* actor, vtkDataSet* data, const std::string& array,
  const std::string& map, double opacity, const double solid[3])
{
  vtkMapper* mapper = actor->GetMapper();
  actor->GetProperty()->SetOpacity(opacity);
  actor->GetProperty()->SetColor(solid[0], solid[1], solid[2]);
  vtkDataArray* values = nullptr;
  bool onPoints = true;
  if (data && array != "Solid")
  {
    values = data->GetPointData()->GetArray(array.c_str());
    if (!values)
    {
      values = data->GetCellData()->GetArray(array.c_str());
      onPoints = false;
    }
  }
  if (!values)
  {
    mapper->ScalarVisibilityOff();
    return;
  }
  const int component = values->GetNumberOfComponents() == 1 ? 0 : -1;
  double range[2];
  values->GetRange(range, component);
  if (!(range[0] < range[1]))
  {
    range[1] = range[0] + 1.0;
  }
  // A diverging map is centred on zero when the values change sign
  // (positive and negative curvature read as warm and cool).
  if (map == "cool-to-warm" && range[0] < 0.0 && range[1] > 0.0)
  {
    const double m = std::max(-range[0], range[1]);
    range[0] = -m;
    range[1] = m;
  }
  vtkNew<vtkColorTransferFunction> colors;
  colors->SetColorSpace(map == "cool-to-warm" ? VTK_CTF_DIVERGING : VTK_CTF_RGB);
  for (const ControlPoint& point : ControlPoints(map))
  {
    colors->AddRGBPoint(range[0] + point.X * (range[1] - range[0]), point.R, point.G, point.B);
  }
  if (component < 0)
  {
    colors->SetVectorModeToMagnitude();
  }
  mapper->ScalarVisibilityOn();
  mapper->SetLookupTable(colors);
  mapper->SetColorModeToMapScalars();
  mapper->SetScalarMode(onPoints ? VTK_SCALAR_MODE_USE_POINT_FIELD_DATA
                                 : VTK_SCALAR_MODE_USE_CELL_FIELD_DATA);
  mapper->SelectColorArray(array.c_str());
  mapper->SetScalarRange(range);
  mapper->UseLookupTableScalarRangeOn();
}
}
}
