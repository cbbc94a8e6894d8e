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
  // The renderers' word before the vocabulary was unified (deprecated).
  if (name == "adaptive")
  {
    type = IntegratorType::DormandPrince45;
    return true;
  }
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
  return EulerStepOf(
    [&metric](const Vec6& state, Vec6& dy) { return GeodesicFlow(metric, state, dy); }, y, h);
}

bool RungeKutta4Step(const Metric& metric, Vec6& y, double h)
{
  return RungeKutta4StepOf(
    [&metric](const Vec6& state, Vec6& dy) { return GeodesicFlow(metric, state, dy); }, y, h);
}

GeodesicStepper::GeodesicStepper(
  IntegratorType type, double step, double tolerance, double minimumStep, double maximumStep)
  : Stepper(type, step, tolerance, minimumStep, maximumStep)
{
}

void GeodesicStepper::Reset()
{
  this->Stepper.Reset();
}

DormandPrince45::StepStatus GeodesicStepper::Advance(
  const Metric& metric, Vec6& y, double limit, double& taken)
{
  return this->Stepper.Advance(
    [&metric](const Vec6& state, Vec6& dy) { return GeodesicFlow(metric, state, dy); }, y, limit,
    taken);
}
} // namespace riemann
