/**
 * @file Integrators.h
 * @brief One step of the geodesic flow x' = v, v' = -Gamma(x)(v, v) (MATH.md)
 * with forward Euler (the paper's), classical RK4, or adaptive
 * Dormand-Prince 5(4) with error control.
 *
 * The steppers work on the first-order phase state (x, v) in fixed-size
 * Eigen vectors: no allocation, no shared mutable state, so any number of
 * geodesics can be integrated concurrently with one Metric.
 */
#ifndef RiemannIntegrators_h
#define RiemannIntegrators_h

#include "Metric.h"

namespace riemann
{
/// Public numbering (JSON, CLI, VTK ivars): do not reorder.
enum class IntegratorType : int
{
  Euler = 0,
  RungeKutta4 = 1,
  DormandPrince45 = 2
};

/// "euler", "rk4", "dp45".
RIEMANNCOMMONMETRIC_EXPORT const char* IntegratorName(IntegratorType type);
/// Parses "euler", "rk4" or "dp45"; false for anything else.
RIEMANNCOMMONMETRIC_EXPORT bool ParseIntegratorName(const std::string& name, IntegratorType& type);

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

/**
 * @class DormandPrince45
 * @brief Adaptive embedded Runge-Kutta 5(4) (Dormand & Prince 1980) with the
 * first-same-as-last cache, standard step-size control, and a mixed
 * absolute/relative tolerance on (x, v).
 */
class RIEMANNCOMMONMETRIC_EXPORT DormandPrince45
{
public:
  enum StepStatus
  {
    Accepted,
    /// The error could not be brought under tolerance above the minimum step.
    StepTooSmall,
    /// The metric is degenerate at a stage point.
    Degenerate
  };

  DormandPrince45(double tolerance, double minimumStep, double maximumStep);

  /// Forget the cached derivative (call when starting a new geodesic).
  void Reset() { this->HaveCachedDerivative = false; }

  /**
   * Advance y by one accepted step of length at most `limit`, trying `h`
   * first. On return `taken` is the step used and `h` the suggested next step.
   */
  StepStatus Step(const Metric& metric, Vec6& y, double& h, double limit, double& taken);

private:
  double Tolerance;
  double MinimumStep;
  double MaximumStep;
  bool HaveCachedDerivative = false;
  Vec6 CachedDerivative;
};
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
  IntegratorType Type;
  double InitialStep;
  double Step;
  DormandPrince45 Adaptive;
};
} // namespace riemann

#endif
