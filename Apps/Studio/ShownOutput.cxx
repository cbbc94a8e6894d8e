#include "ShownOutput.h"

#include "vtkPolyData.h"
#include "vtkSphereSource.h"

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
