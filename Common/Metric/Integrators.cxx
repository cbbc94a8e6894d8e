#include "Integrators.h"

#include <algorithm>
#include <cmath>

namespace riemann
{
const char* IntegratorName(IntegratorType type)
{
  switch (type)
  {
    case IntegratorType::Euler:
      return "euler";
    case IntegratorType::RungeKutta4:
      return "rk4";
    case IntegratorType::DormandPrince45:
      return "dp45";
  }
  return "unknown";
}

bool ParseIntegratorName(const std::string& name, IntegratorType& type)
{
  for (IntegratorType t :
    { IntegratorType::Euler, IntegratorType::RungeKutta4, IntegratorType::DormandPrince45 })
  {
    if (name == IntegratorName(t))
    {
      type = t;
      return true;
    }
  }
  return false;
}

bool EulerStep(const Metric& metric, Vec6& y, double h)
{
  Vec6 dy;
  if (!GeodesicFlow(metric, y, dy))
  {
    return false;
  }
  y += h * dy;
  return true;
}

bool RungeKutta4Step(const Metric& metric, Vec6& y, double h)
{
  Vec6 k1, k2, k3, k4;
  if (!GeodesicFlow(metric, y, k1) || !GeodesicFlow(metric, y + (0.5 * h) * k1, k2) ||
    !GeodesicFlow(metric, y + (0.5 * h) * k2, k3) || !GeodesicFlow(metric, y + h * k3, k4))
  {
    return false;
  }
  y += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  return true;
}

GeodesicStepper::GeodesicStepper(
  IntegratorType type, double step, double tolerance, double minimumStep, double maximumStep)
  : Type(type)
  , InitialStep(step)
  , Step(step)
  , Adaptive(tolerance, minimumStep, maximumStep)
{
}

void GeodesicStepper::Reset()
{
  this->Step = this->InitialStep;
  this->Adaptive.Reset();
}

DormandPrince45::StepStatus GeodesicStepper::Advance(
  const Metric& metric, Vec6& y, double limit, double& taken)
{
  switch (this->Type)
  {
    case IntegratorType::Euler:
      taken = std::min(this->Step, limit);
      return EulerStep(metric, y, taken) ? DormandPrince45::Accepted : DormandPrince45::Degenerate;
    case IntegratorType::RungeKutta4:
      taken = std::min(this->Step, limit);
      return RungeKutta4Step(metric, y, taken) ? DormandPrince45::Accepted
                                               : DormandPrince45::Degenerate;
    case IntegratorType::DormandPrince45:
      return this->Adaptive.Step(metric, y, this->Step, limit, taken);
  }
  return DormandPrince45::Degenerate;
}

DormandPrince45::DormandPrince45(double tolerance, double minimumStep, double maximumStep)
  : Tolerance(tolerance)
  , MinimumStep(minimumStep)
  , MaximumStep(maximumStep)
{
}

DormandPrince45::StepStatus DormandPrince45::Step(
  const Metric& metric, Vec6& y, double& h, double limit, double& taken)
{
  // Butcher tableau of Dormand-Prince 5(4); e = b5 - b4 gives the error estimate.
  constexpr double a21 = 1.0 / 5.0;
  constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
  constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
  constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0,
                   a54 = -212.0 / 729.0;
  constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0,
                   a64 = 49.0 / 176.0, a65 = -5103.0 / 18656.0;
  constexpr double b1 = 35.0 / 384.0, b3 = 500.0 / 1113.0, b4 = 125.0 / 192.0,
                   b5 = -2187.0 / 6784.0, b6 = 11.0 / 84.0;
  constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0,
                   e5 = -17253.0 / 339200.0, e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;

  if (!this->HaveCachedDerivative)
  {
    if (!GeodesicFlow(metric, y, this->CachedDerivative))
    {
      return Degenerate;
    }
    this->HaveCachedDerivative = true;
  }
  h = std::min(std::max(h, this->MinimumStep), this->MaximumStep);
  const Vec6& k1 = this->CachedDerivative;
  Vec6 k2, k3, k4, k5, k6, k7, next;
  for (;;)
  {
    const bool lastStep = h >= limit;
    const double step = lastStep ? limit : h;
    const bool stagesDefined = GeodesicFlow(metric, y + step * (a21 * k1), k2) &&
      GeodesicFlow(metric, y + step * (a31 * k1 + a32 * k2), k3) &&
      GeodesicFlow(metric, y + step * (a41 * k1 + a42 * k2 + a43 * k3), k4) &&
      GeodesicFlow(metric, y + step * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4), k5) &&
      GeodesicFlow(metric, y + step * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5), k6);
    double error = HUGE_VAL;
    bool degenerate = !stagesDefined;
    if (stagesDefined)
    {
      next = y + step * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
      degenerate = !GeodesicFlow(metric, next, k7);
      if (!degenerate)
      {
        const Vec6 estimate = step * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
        // RMS of the error scaled by a mixed absolute/relative tolerance (Hairer).
        const Vec6 scale = Vec6::Constant(this->Tolerance) +
          this->Tolerance * y.cwiseAbs().cwiseMax(next.cwiseAbs());
        error = std::sqrt(estimate.cwiseQuotient(scale).squaredNorm() / 6.0);
      }
    }

    if (error <= 1.0)
    {
      y = next;
      this->CachedDerivative = k7;
      taken = step;
      // Grow at most 5x, shrink at most 5x, with the usual 0.9 safety factor.
      const double factor =
        error > 0 ? std::min(5.0, std::max(0.2, 0.9 * std::pow(error, -0.2))) : 5.0;
      if (!lastStep || factor < 1.0)
      {
        h = std::min(std::max(step * factor, this->MinimumStep), this->MaximumStep);
      }
      return Accepted;
    }
    if (step <= this->MinimumStep)
    {
      // A stage still hits a degenerate point at the smallest step: report it
      // as such rather than as an accuracy failure.
      return degenerate ? Degenerate : StepTooSmall;
    }
    h = std::max(this->MinimumStep,
      step * (std::isfinite(error) ? std::max(0.2, 0.9 * std::pow(error, -0.2)) : 0.25));
  }
}
} // namespace riemann
