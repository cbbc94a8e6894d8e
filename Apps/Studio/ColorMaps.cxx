#include "ColorMaps.h"

#include "vtkActor.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkLookupTable.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkProperty.h"
#include "vtkScalarBarActor.h"
#include "vtkSmartPointer.h"

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
  // Samples of matplotlib's perceptual maps (van der Walt and Smith;
  // cividis: Nunez, Anderton and Renslow 2018) at ninths, linear between.
  if (name == "viridis")
  {
    return { { 0.0, 0.267, 0.005, 0.329 }, { 0.125, 0.283, 0.141, 0.458 },
      { 0.25, 0.254, 0.265, 0.530 }, { 0.375, 0.207, 0.372, 0.553 }, { 0.5, 0.164, 0.471, 0.558 },
      { 0.625, 0.128, 0.567, 0.551 }, { 0.75, 0.135, 0.659, 0.518 }, { 0.875, 0.478, 0.821, 0.318 },
      { 1.0, 0.993, 0.906, 0.144 } };
  }
  if (name == "cividis")
  {
    return { { 0.0, 0.000, 0.135, 0.305 }, { 0.125, 0.070, 0.200, 0.420 },
      { 0.25, 0.251, 0.284, 0.422 }, { 0.375, 0.360, 0.362, 0.429 }, { 0.5, 0.468, 0.446, 0.446 },
      { 0.625, 0.585, 0.533, 0.434 }, { 0.75, 0.706, 0.624, 0.404 }, { 0.875, 0.835, 0.722, 0.345 },
      { 1.0, 0.995, 0.903, 0.208 } };
  }
  if (name == "magma")
  {
    return { { 0.0, 0.001, 0.000, 0.014 }, { 0.125, 0.112, 0.066, 0.290 },
      { 0.25, 0.316, 0.071, 0.485 }, { 0.375, 0.512, 0.141, 0.506 }, { 0.5, 0.716, 0.215, 0.475 },
      { 0.625, 0.904, 0.312, 0.387 }, { 0.75, 0.987, 0.535, 0.382 }, { 0.875, 0.996, 0.769, 0.526 },
      { 1.0, 0.987, 0.991, 0.750 } };
  }
  if (name == "vtk-rainbow")
  {
    // vtkLookupTable's default: hue 0.667 (blue) to 0 (red) at full saturation.
    return { { 0.0, 0.0, 0.0, 1.0 }, { 0.25, 0.0, 1.0, 1.0 }, { 0.5, 0.0, 1.0, 0.0 },
      { 0.75, 1.0, 1.0, 0.0 }, { 1.0, 1.0, 0.0, 0.0 } };
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
  return { "viridis", "cividis", "magma", "cool-to-warm", "grayscale", "vtk-rainbow", "rainbow" };
}

vtkDataArray* ColoringArray(vtkDataSet* data, const std::string& name, bool* onPoints)
{
  vtkDataArray* values = nullptr;
  bool points = true;
  if (data && name != "Solid")
  {
    values = data->GetPointData()->GetArray(name.c_str());
    if (!values)
    {
      values = data->GetCellData()->GetArray(name.c_str());
      points = false;
    }
  }
  if (onPoints)
  {
    *onPoints = points;
  }
  return values;
}

void ColoringRange(vtkDataArray* values, double range[2])
{
  values->GetRange(range, values->GetNumberOfComponents() == 1 ? 0 : -1);
}

void ApplyColoring(vtkActor* actor, vtkDataSet* data, const ColorScale& scale, const double solid[3],
  vtkScalarBarActor* bar)
{
  vtkMapper* mapper = actor->GetMapper();
  actor->GetProperty()->SetOpacity(scale.Opacity);
  actor->GetProperty()->SetColor(solid[0], solid[1], solid[2]);
  const std::string& array = scale.Array;
  const std::string& map = scale.Map;
  bool onPoints = true;
  vtkDataArray* values = ColoringArray(data, array, &onPoints);
  if (bar)
  {
    bar->SetVisibility(values != nullptr && scale.ScalarBar);
  }
  if (!values)
  {
    mapper->ScalarVisibilityOff();
    return;
  }
  double range[2] = { scale.Minimum, scale.Maximum };
  if (!scale.CustomRange)
  {
    ColoringRange(values, range);
    // A diverging map is centred on zero when the values change sign
    // (positive and negative curvature read as warm and cool).
    if (map == "cool-to-warm" && range[0] < 0.0 && range[1] > 0.0)
    {
      const double m = std::max(-range[0], range[1]);
      range[0] = -m;
      range[1] = m;
    }
  }
  if (!(range[0] < range[1]))
  {
    range[1] = range[0] + 1.0;
  }
  vtkNew<vtkColorTransferFunction> colors;
  colors->SetColorSpace(map == "cool-to-warm" ? VTK_CTF_DIVERGING : VTK_CTF_RGB);
  for (const ControlPoint& point : ControlPoints(map))
  {
    colors->AddRGBPoint(range[0] + point.X * (range[1] - range[0]), point.R, point.G, point.B);
  }
  vtkSmartPointer<vtkScalarsToColors> lookup = colors.Get();
  if (scale.Steps >= 2)
  {
    // N discrete colours: the map at the centres of N equal bins.
    auto table = vtkSmartPointer<vtkLookupTable>::New();
    table->SetNumberOfTableValues(scale.Steps);
    table->SetTableRange(range);
    for (int k = 0; k < scale.Steps; ++k)
    {
      double rgb[3];
      colors->GetColor(range[0] + (k + 0.5) / scale.Steps * (range[1] - range[0]), rgb);
      table->SetTableValue(k, rgb[0], rgb[1], rgb[2], 1.0);
    }
    lookup = table;
  }
  if (values->GetNumberOfComponents() != 1)
  {
    lookup->SetVectorModeToMagnitude();
  }
  mapper->ScalarVisibilityOn();
  mapper->SetLookupTable(lookup);
  mapper->SetColorModeToMapScalars();
  mapper->SetScalarMode(onPoints ? VTK_SCALAR_MODE_USE_POINT_FIELD_DATA
                                 : VTK_SCALAR_MODE_USE_CELL_FIELD_DATA);
  mapper->SelectColorArray(array.c_str());
  mapper->SetScalarRange(range);
  mapper->UseLookupTableScalarRangeOn();
  if (bar)
  {
    bar->SetLookupTable(lookup);
    bar->SetTitle(array.c_str());
    bar->SetMaximumNumberOfColors(scale.Steps >= 2 ? scale.Steps : 256);
  }
}
}
}
