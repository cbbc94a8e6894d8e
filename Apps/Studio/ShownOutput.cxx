#include "ShownOutput.h"

#include "vtkPolyData.h"
#include "vtkDataSet.h"
#include "vtkSphereSource.h"

#include <algorithm>

namespace riemann
{
namespace studio
{
OutputLook LookOf(const std::string& dataType, const std::array<double, 3>& solid, bool legend)
{
  OutputLook look;
  look.DataType = dataType;
  look.Solid = solid;
  look.Legend = legend;
  return look;
}

double LargestSide(vtkDataSet* data)
{
  double bounds[6];
  data->GetBounds(bounds);
  return std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1.0 });
}

vtkSmartPointer<vtkPolyData> SphereMarker(const double center[3], double radius)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(center[0], center[1], center[2]);
  sphere->SetRadius(radius);
  sphere->Update();
  return sphere->GetOutput();
}
}
}
