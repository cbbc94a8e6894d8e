/**
 * @file RungeKutta.h
 * @brief The three integrators (forward Euler, classical RK4, adaptive
 * Dormand-Prince 5(4)) for any first-order system y' = F(y) in a fixed-size
 * Eigen vector: the geodesic flow (x, v) in 6 dimensions (Integrators.h) and
 * the geodesic flow with two Jacobi fields in 18 (JacobiField.h) step with
 * the same code, so "every integrator" means the same thing for both.
 *
 * A flow is any callable `bool flow(const State& y, State& dy)` returning
 * false where F is undefined (a degenerate metric). Header-only templates:
 * the flow is inlined into the stages.
 */
#ifndef RiemannRungeKutta_h
#define RiemannRungeKutta_h

#include "DormandPrinceTableau.h"
#include "RiemannCommonMetricExport.h"

#include <algorithm>
#include <cmath>
#include <string>

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
/// Parses "euler", "rk4" or "dp45" ("adaptive": dp45, deprecated); false for anything else.
RIEMANNCOMMONMETRIC_EXPORT bool ParseIntegratorName(const std::string& name, IntegratorType& type);

/// The outcome of one step, shared by every state size.
struct IntegrationStep
{
  enum Status
  {
    Accepted,
    /// The error could not be brought under tolerance above the minimum step.
    StepTooSmall,
    /// The flow is undefined (a degenerate metric) at a stage point.
    Degenerate
  };
};

/// y <- y + h F(y). False (y unchanged) where F is undefined.
template <class State, class Flow>
bool EulerStepOf(const Flow& flow, State& y, double h)
{
  State dy;
  if (!flow(y, dy))
  {
    return false;
  }
  y += h * dy;
  return true;
}

/// Classical fourth-order Runge-Kutta. False (y unchanged) where F is undefined.
template <class State, class Flow>
bool RungeKutta4StepOf(const Flow& flow, State& y, double h)
{
  State k1, k2, k3, k4;
  if (!flow(y, k1) || !flow(y + (0.5 * h) * k1, k2) || !flow(y + (0.5 * h) * k2, k3) ||
    !flow(y + h * k3, k4))
  {
    return false;
  }
  y += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  return true;
}

/**
 * Dormand-Prince 5(4) (Dormand & Prince 1980) with the first-same-as-last
 * cache, standard step-size control, and the RMS of the error over all
 * components scaled by a mixed absolute/relative tolerance (Hairer).
 */
template <class State>
class DormandPrince45Of : public IntegrationStep
{
public:
  using StepStatus = IntegrationStep::Status;

  DormandPrince45Of(double tolerance, double minimumStep, double maximumStep)
    : Tolerance(tolerance)
    , MinimumStep(minimumStep)
    , MaximumStep(maximumStep)
  {
  }

  /// Forget the cached derivative (call when starting a new curve).
  void Reset() { this->HaveCachedDerivative = false; }

  /**
   * Advance y by one accepted step of length at most `limit`, trying `h`
   * first. On return `taken` is the step used and `h` the suggested next step.
   */
  template <class Flow>
  StepStatus Step(const Flow& flow, State& y, double& h, double limit, double& taken)
  {
    // The Butcher tableau of Dormand-Prince 5(4) (DormandPrinceTableau.h).
    using namespace riemann::dormand_prince;

    if (!this->HaveCachedDerivative)
    {
      if (!flow(y, this->CachedDerivative))
      {
        return IntegrationStep::Degenerate;
      }
      this->HaveCachedDerivative = true;
    }
    h = std::min(std::max(h, this->MinimumStep), this->MaximumStep);
    const State& k1 = this->CachedDerivative;
    State k2, k3, k4, k5, k6, k7, next;
    for (;;)
    {
      const bool lastStep = h >= limit;
      const double step = lastStep ? limit : h;
      const bool stagesDefined = flow(y + step * (a21 * k1), k2) &&
        flow(y + step * (a31 * k1 + a32 * k2), k3) &&
        flow(y + step * (a41 * k1 + a42 * k2 + a43 * k3), k4) &&
        flow(y + step * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4), k5) &&
        flow(y + step * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5), k6);
      double error = HUGE_VAL;
      bool degenerate = !stagesDefined;
      if (stagesDefined)
      {
        next = y + step * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
        degenerate = !flow(next, k7);
        if (!degenerate)
        {
          const State estimate =
            step * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
          const State scale = State::Constant(this->Tolerance) +
            this->Tolerance * y.cwiseAbs().cwiseMax(next.cwiseAbs());
          error = std::sqrt(
            estimate.cwiseQuotient(scale).squaredNorm() / static_cast<double>(State::RowsAtCompileTime));
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
        return IntegrationStep::Accepted;
      }
      if (step <= this->MinimumStep)
      {
        // A stage still hits a degenerate point at the smallest step: report
        // it as such rather than as an accuracy failure.
        return degenerate ? IntegrationStep::Degenerate : IntegrationStep::StepTooSmall;
      }
      h = std::max(this->MinimumStep,
        step * (std::isfinite(error) ? std::max(0.2, 0.9 * std::pow(error, -0.2)) : 0.25));
    }
  }

private:
  double Tolerance;
  double MinimumStep;
  double MaximumStep;
  bool HaveCachedDerivative = false;
  State CachedDerivative;
};

/**
 * One of the three integrators behind one interface, for any flow:
 * GeodesicStepper is FlowStepper<Vec6> on the geodesic flow.
 */
template <class State>
class FlowStepper
{
public:
  /// `step` is the fixed step, or the initial one for DormandPrince45.
  FlowStepper(
    IntegratorType type, double step, double tolerance, double minimumStep, double maximumStep)
    : Type(type)
    , InitialStep(step)
    , Step(step)
    , Adaptive(tolerance, minimumStep, maximumStep)
  {
  }

  /// Start a new curve (forgets the adaptive step's cached state).
  void Reset()
  {
    this->Step = this->InitialStep;
    this->Adaptive.Reset();
  }

  /**
   * Advance y by one step of at most `limit`; `taken` is the step used.
   * Fixed-step methods return Accepted or Degenerate.
   */
  template <class Flow>
  IntegrationStep::Status Advance(const Flow& flow, State& y, double limit, double& taken)
  {
    switch (this->Type)
    {
      case IntegratorType::Euler:
        taken = std::min(this->Step, limit);
        return EulerStepOf(flow, y, taken) ? IntegrationStep::Accepted
                                           : IntegrationStep::Degenerate;
      case IntegratorType::RungeKutta4:
        taken = std::min(this->Step, limit);
        return RungeKutta4StepOf(flow, y, taken) ? IntegrationStep::Accepted
                                                 : IntegrationStep::Degenerate;
      case IntegratorType::DormandPrince45:
        return this->Adaptive.Step(flow, y, this->Step, limit, taken);
    }
    return IntegrationStep::Degenerate;
  }

private:
  IntegratorType Type;
  double InitialStep;
  double Step;
  DormandPrince45Of<State> Adaptive;
};
} // namespace riemann

#endif
