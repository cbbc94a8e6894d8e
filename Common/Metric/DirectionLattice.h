/**
 * @file DirectionLattice.h
 * @brief Directions spread evenly over the unit sphere or a cap of it (a
 * Fibonacci lattice): the fans of geodesics of the exponential map and of the
 * conjugate-locus search (vtkRiemannDirectionGrid triangulates them).
 */
#ifndef RiemannDirectionLattice_h
#define RiemannDirectionLattice_h

#include "Jets.h"
#include "RiemannCommonMetricExport.h"

#include <vector>

namespace riemann
{
/**
 * `count` unit vectors over the cap {angle to `axis` <= coneAngle degrees}
 * (coneAngle >= 180: the whole sphere). Heights along the axis are evenly
 * spaced in [cos(coneAngle), 1] at (i + 1/2) / count, so every direction
 * stands for the same solid angle (Archimedes); longitudes advance by the
 * golden angle. Direction i is (z_i, r_i cos(phi_i), r_i sin(phi_i)) in the
 * frame (axis, u, w), u = normalize(axis x (e_x, or e_y when axis is nearly
 * e_x)), w = axis x u. `axis` must be finite and nonzero (it is normalised);
 * returns an empty vector otherwise.
 */
RIEMANNCOMMONMETRIC_EXPORT std::vector<Vec3> FibonacciDirections(
  int count, const Vec3& axis, double coneAngle);
} // namespace riemann

#endif
