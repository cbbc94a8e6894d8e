/**
 * @file DistanceDescent.h
 * @brief From a point back to its closest seed along a distance field: the
 * minimal geodesic's first guess, by following the arrival directions
 * backwards (the steepest descent of the distance).
 *
 * The minimal geodesic from a seed to x arrives at x with the field's
 * arrival direction; walking backwards along the arrival directions
 * (interpolated trilinearly, a midpoint step of half the smallest spacing)
 * follows it back to its seed, within the field's first-order error. The
 * walk stops when it is within `stop` (coordinates) of the seed, which it
 * then joins. The polyline it gives is the start of Newton's method in
 * vtkRiemannMinimalGeodesics, which makes it a geodesic to round-off
 * (GeodesicConnector.h).
 */
#ifndef RiemannDistanceDescent_h
#define RiemannDistanceDescent_h

#include "DistanceField.h"
#include "RiemannCommonDistanceExport.h"

#include <vector>

namespace riemann
{
struct DistanceDescent
{
  /// From x to the seed (the last point is the seed itself); empty when x
  /// is outside the grid or unreached.
  std::vector<Vec3> Points;
  /// The seed it reached (-1 when none).
  int Seed = -1;
  /// The field's distance at x (interpolated).
  double Distance = 0.0;
  /// Whether the walk reached the seed (not stopped by its step budget).
  bool Reached = false;
};

/// The field's value at any point of the grid's box (trilinear); +infinity
/// outside it or next to an unreached point.
RIEMANNCOMMONDISTANCE_EXPORT double InterpolateDistance(
  const DistanceGrid& grid, const DistanceFieldResult& field, const Vec3& x);

/**
 * Walk from x back to its closest seed (`seeds` as given to
 * ComputeDistanceField) along the field's arrival directions.
 */
RIEMANNCOMMONDISTANCE_EXPORT DistanceDescent DescendToSeed(const DistanceGrid& grid,
  const DistanceFieldResult& field, const std::vector<Vec3>& seeds, const Vec3& x);
} // namespace riemann

#endif
