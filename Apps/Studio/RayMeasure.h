/**
 * @file RayMeasure.h
 * @brief Measuring along the picked ray (issue 32): the ray's point nearest
 * to a picked point, and the arc length between two of its points (its
 * `ArcLength` point data: length in the metric, what the ray travelled).
 */
#ifndef RiemannStudioRayMeasure_h
#define RiemannStudioRayMeasure_h

#include "vtkType.h"

class vtkPolyData;

namespace riemann
{
namespace studio
{
/// The index of `ray`'s point nearest to `point` (Euclidean), -1 when it has none.
vtkIdType NearestRayPoint(vtkPolyData* ray, const double point[3]);

/// |s(b) - s(a)| from `ray`'s ArcLength point data (NaN without it or for bad indices).
double ArcLengthBetween(vtkPolyData* ray, vtkIdType a, vtkIdType b);
} // namespace studio
} // namespace riemann

#endif
