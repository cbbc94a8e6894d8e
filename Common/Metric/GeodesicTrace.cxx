#include "GeodesicTrace.h"

#include <algorithm>
#include <cmath>

namespace riemann
{
const char* TerminationReasonName(int reason)
{
  switch (reason)
  {
    case OutOfDomain:
      return "left the domain";
    case NotInitialized:
      return "not initialized";
    case UnexpectedValue:
      return "unexpected (non-finite) value";
    case OutOfLength:
      return "reached the maximum length";
    case OutOfSteps:
      return "reached the maximum number of steps";
    case Stagnation:
      return "step size underflow (tolerance not reachable)";
    case DegenerateMetric:
      return "degenerate metric";
    case HitSurface:
      return "hit a surface";
    case OutOfData:
      return "left the sampled data";
    case StoppedByMask:
      return "left the stop mask";
    case LowAnisotropy:
      return "fell below the anisotropy threshold";
    case SharpTurn:
      return "turned too sharply";
    case OutranStep:
      return "outran its step (the metric changes faster than the step resolves)";
    default:
      return "unknown";
  }
}

void GeodesicPath::Clear()
{
  this->Points.clear();
  this->Velocities.clear();
  this->ArcLength.clear();
  this->SpeedDrift.clear();
  this->Reason = NotInitialized;
}

bool StepOutranItsSpeed(const GeodesicPath& path, const Vec3& x, double arcLength)
{
  const double nominal = path.Velocities.back().norm() * std::abs(arcLength);
  return !((x - path.Points.back()).norm() <= MaximumChordToStepRatio * nominal);
}

void EndOnTheDataFace(const Metric& metric, GeodesicPath& path, const Vec3& x,
  const Vec3& velocity, double arcLength, double drift)
{
  path.Reason = OutOfData;
  const Vec3 inside = path.Points.back();
  // Bisection on the chord: `low` is inside, `high` outside; 40 halvings
  // leave 1e-12 of the chord (a step of 0.5 mm: 5e-13 mm).
  double low = 0.0;
  double high = 1.0;
  for (int i = 0; i < 40; ++i)
  {
    const double middle = 0.5 * (low + high);
    (metric.InsideData(inside + middle * (x - inside)) ? low : high) = middle;
  }
  if (low == 0.0)
  {
    return; // the last point is on the face already
  }
  const auto along = [low](const auto& from, const auto& to) { return from + low * (to - from); };
  path.Points.push_back(along(inside, x));
  path.Velocities.push_back(along(path.Velocities.back(), velocity));
  path.ArcLength.push_back(along(path.ArcLength.back(), arcLength));
  path.SpeedDrift.push_back(along(path.SpeedDrift.back(), drift));
}

bool UnitSpeedVelocity(const Metric& metric, const Vec3& p, const Vec3& direction, Vec3& velocity)
{
  const double squaredSpeed = metric.InnerProduct(p, direction, direction);
  if (!direction.allFinite() || !(squaredSpeed > 0) || !std::isfinite(squaredSpeed))
  {
    return false;
  }
  velocity = direction / std::sqrt(squaredSpeed);
  return true;
}

void TraceGeodesic(const Metric& metric, const Vec3& p, const Vec3& v,
  const GeodesicOptions& options, GeodesicPath& path, bool backward)
{
  path.Clear();
  const double initialSquaredSpeed = metric.InnerProduct(p, v, v);
  if (!p.allFinite() || !v.allFinite() || !std::isfinite(initialSquaredSpeed) ||
    !(initialSquaredSpeed > 0))
  {
    path.Reason = std::isfinite(initialSquaredSpeed) || !p.allFinite() || !v.allFinite()
      ? NotInitialized
      : DegenerateMetric;
    return;
  }
  const double sign = backward ? -1.0 : 1.0;
  const double speed = std::sqrt(initialSquaredSpeed);
  // Work in the curve parameter tau (arc length = speed * tau).
  const double parameterEnd = options.MaximumLength / speed;
  const double step = options.Step / speed;

  Vec6 y;
  y << p, sign * v;
  double tau = 0.0;
  auto record = [&](double drift)
  {
    path.Points.push_back(y.head<3>());
    path.Velocities.push_back(y.tail<3>() * (sign / speed));
    path.ArcLength.push_back(sign * speed * tau);
    path.SpeedDrift.push_back(drift);
  };
  record(0.0);
  if (const int stop = ReasonToStopAt(metric, options, p))
  {
    path.Reason = stop;
    return;
  }

  GeodesicStepper stepper(options.Integrator, step, options.Tolerance, options.MinimumStep / speed,
    options.MaximumStep / speed);
  // Steps shorter than this (relative to the length) count as arriving.
  const double arrival = 1e-12 * std::max(1.0, parameterEnd);
  for (long long n = 0;; ++n)
  {
    const double remaining = parameterEnd - tau;
    if (remaining <= arrival)
    {
      path.Reason = OutOfLength;
      return;
    }
    if (n >= options.MaximumSteps)
    {
      path.Reason = OutOfSteps;
      return;
    }
    double taken = 0.0;
    const auto status = stepper.Advance(metric, y, remaining, taken);
    if (status != DormandPrince45::Accepted)
    {
      path.Reason = status == DormandPrince45::StepTooSmall ? Stagnation : DegenerateMetric;
      return;
    }
    if (!y.allFinite())
    {
      path.Reason = UnexpectedValue;
      return;
    }
    if (StepOutranItsSpeed(path, y.head<3>(), speed * taken))
    {
      path.Reason = OutranStep;
      return;
    }
    tau += taken;
    double drift = 0.0;
    if (options.RecordSpeedDrift)
    {
      const Vec3 velocity = y.tail<3>();
      const double squaredSpeed = metric.InnerProduct(y.head<3>(), velocity, velocity);
      if (!std::isfinite(squaredSpeed))
      {
        // The step landed where g is degenerate (e.g. jumped past n = 0):
        // the point is not on the manifold, so it is not recorded.
        path.Reason = DegenerateMetric;
        return;
      }
      drift = squaredSpeed / initialSquaredSpeed - 1.0;
    }
    const int stop = ReasonToStopAt(metric, options, y.head<3>());
    if (stop == OutOfData)
    {
      EndOnTheDataFace(
        metric, path, y.head<3>(), y.tail<3>() * (sign / speed), sign * speed * tau, drift);
      return;
    }
    record(drift);
    if (stop)
    {
      path.Reason = stop;
      return;
    }
  }
}
} // namespace riemann
