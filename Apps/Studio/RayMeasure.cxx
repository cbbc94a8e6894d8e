#include "RayMeasure.h"

#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cmath>
#include <limits>

namespace riemann
{
namespace studio
{
vtkIdType NearestRayPoint(vtkPolyData* ray, const double point[3])
{
  vtkIdType nearest = -1;
  double best = std::numeric_limits<double>::infinity();
  for (vtkIdType i = 0; ray && i < ray->GetNumberOfPoints(); ++i)
  {
    double x[3];
    ray->GetPoint(i, x);
    const double d = vtkMath::Distance2BetweenPoints(x, point);
    if (d < best)
    {
      best = d;
      nearest = i;
    }
  }
  return nearest;
}

double ArcLengthBetween(vtkPolyData* ray, vtkIdType a, vtkIdType b)
{
  vtkDataArray* arc = ray ? ray->GetPointData()->GetArray("ArcLength") : nullptr;
  const vtkIdType n = ray ? ray->GetNumberOfPoints() : 0;
  if (!arc || a < 0 || b < 0 || a >= n || b >= n)
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return std::abs(arc->GetComponent(b, 0) - arc->GetComponent(a, 0));
}
} // namespace studio
} // namespace riemann
