/**
 * @file Integrators.h
 * @brief One step of the geodesic flow x' = v, v' = -Gamma(x)(v, v) (MATH.md)
 * with forward Euler (the paper's), classical RK4, or adaptive
 * Dormand-Prince 5(4) with error control.
 *
 * The steppers work on the first-order phase state (x, v) in fixed-size
 * Eigen vectors: no allocation, no shared mutable state, so any number of
 * geodesics can be integrated concurrently with one Metric. The integrators
 * themselves are the templates of RungeKutta.h, shared with the Jacobi
 * system (JacobiField.h).
 */
#ifndef RiemannIntegrators_h
#define RiemannIntegrators_h

#include "Metric.h"
#include "RungeKutta.h"
#include "RiemannCommonMetricExport.h"

namespace riemann
{
using Vec6 = Eigen::Matrix<double, 6, 1>;

/// The geodesic flow's vector field at y = (x, v): (v, a(x, v)).
inline bool GeodesicFlow(const Metric& metric, const Vec6& y, Vec6& dy)
{
  Vec3 a;
  if (!metric.Acceleration(y.head<3>(), y.tail<3>(), a))
  {
    return false;
  }
  dy.head<3>() = y.tail<3>();
  dy.tail<3>() = a;
  return true;
}

/// y <- y + h f(y). False (y unchanged) where the metric is degenerate.
RIEMANNCOMMONMETRIC_EXPORT bool EulerStep(const Metric& metric, Vec6& y, double h);

/// Classical fourth-order Runge-Kutta. False (y unchanged) where degenerate.
RIEMANNCOMMONMETRIC_EXPORT bool RungeKutta4Step(const Metric& metric, Vec6& y, double h);

/// Adaptive Dormand-Prince 5(4) on the geodesic flow's state; its
/// StepStatus values (DormandPrince45::Accepted, ...) are every stepper's.
using DormandPrince45 = DormandPrince45Of<Vec6>;

/**
 * @class GeodesicStepper
 * @brief One integrator behind one interface: fixed-step Euler or RK4, or
 * adaptive Dormand-Prince 5(4). Used by every tracer (geodesic polylines,
 * rays of the inside view) so they step identically.
 */
class RIEMANNCOMMONMETRIC_EXPORT GeodesicStepper
{
public:
  /// `step` is the fixed step, or the initial one for DormandPrince45.
  GeodesicStepper(
    IntegratorType type, double step, double tolerance, double minimumStep, double maximumStep);

  /// Start a new geodesic (forgets the adaptive step's cached state).
  void Reset();

  /**
   * Advance y by one step of at most `limit`; `taken` is the step used.
   * Fixed-step methods return Accepted or Degenerate.
   */
  DormandPrince45::StepStatus Advance(const Metric& metric, Vec6& y, double limit, double& taken);

private:
  FlowStepper<Vec6> Stepper;
};
} // namespace riemann

#endif
