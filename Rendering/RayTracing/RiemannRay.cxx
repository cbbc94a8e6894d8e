#include "RiemannRay.h"

#include <algorithm>
#include <cmath>

namespace riemann
{
void TraceRay(const Metric& metric, const Scene& scene, const Vec3& p, const Vec3& v,
  const RaySettings& settings, RayPath& path, bool recordPath)
{
  path.Points.clear();
  path.ArcLength.clear();
  path.Hit = false;
  path.Length = 0.0;
  path.Steps = 0;
  path.FinalVelocity = v;
  Vec6 y;
  y << p, v;
  if (recordPath)
  {
    path.Points.push_back(p);
    path.ArcLength.push_back(0.0);
  }
  GeodesicStepper stepper(settings.Integrator, settings.Step, settings.Tolerance,
    AdaptiveMinimumStepFactor * settings.Step, AdaptiveMaximumStepFactor * settings.Step);
  double s = 0.0;
  for (int n = 0;; ++n)
  {
    const double remaining = settings.MaximumLength - s;
    if (remaining <= 1e-12 * std::max(1.0, settings.MaximumLength))
    {
      path.Reason = OutOfLength;
      break;
    }
    if (n >= settings.MaximumSteps)
    {
      path.Reason = OutOfSteps;
      break;
    }
    const Vec6 previous = y;
    double taken = 0.0;
    const auto status = stepper.Advance(metric, y, remaining, taken);
    if (status != DormandPrince45::Accepted)
    {
      path.Reason = status == DormandPrince45::StepTooSmall ? Stagnation : DegenerateMetric;
      y = previous;
      break;
    }
    if (!y.allFinite())
    {
      path.Reason = UnexpectedValue;
      y = previous;
      break;
    }
    ++path.Steps;
    SceneHit hit;
    if (IntersectSegment(scene, previous.head<3>(), y.head<3>(), hit))
    {
      path.Hit = true;
      path.HitInfo = hit;
      path.Reason = HitSurface;
      // Arc length and velocity at the hit, linear within the step (the
      // segment is the chord the shader intersects too).
      path.Length = s + hit.Fraction * taken;
      path.FinalVelocity = previous.tail<3>() + hit.Fraction * (y.tail<3>() - previous.tail<3>());
      if (recordPath)
      {
        path.Points.push_back(hit.Position);
        path.ArcLength.push_back(path.Length);
      }
      return;
    }
    s += taken;
    if (recordPath)
    {
      path.Points.push_back(y.head<3>());
      path.ArcLength.push_back(s);
    }
  }
  path.Length = s;
  path.FinalVelocity = y.tail<3>();
}
} // namespace riemann
