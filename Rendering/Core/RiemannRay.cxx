#include "RiemannRay.h"

#include "RiemannSceneIntersection.h"

#include <algorithm>
#include <cmath>

namespace riemann
{
RayMarcher::RayMarcher(const RaySettings& settings)
  : Settings(settings)
  , Stepper(settings.Integrator, settings.Step, settings.Tolerance,
      AdaptiveMinimumStepFactor * settings.Step, AdaptiveMaximumStepFactor * settings.Step)
{
  this->State.setZero();
  this->Previous.setZero();
}

void RayMarcher::Start(const Vec3& p, const Vec3& v)
{
  this->State << p, v;
  this->Previous = this->State;
  this->Stepper.Reset();
  this->ArcLength = 0.0;
  this->Taken = 0.0;
  this->StepCount = 0;
  this->Termination = NotInitialized;
  this->Done = false;
  this->DidHit = false;
  this->LastHit = SceneHit();
}

bool RayMarcher::Advance(const Metric& metric)
{
  if (this->Done)
  {
    return false;
  }
  const double remaining = this->Settings.MaximumLength - this->ArcLength;
  if (remaining <= 1e-12 * std::max(1.0, this->Settings.MaximumLength))
  {
    this->Termination = OutOfLength;
    this->Done = true;
    return false;
  }
  if (this->StepCount >= this->Settings.MaximumSteps)
  {
    this->Termination = OutOfSteps;
    this->Done = true;
    return false;
  }
  this->Previous = this->State;
  this->Taken = 0.0;
  const auto status = this->Stepper.Advance(metric, this->State, remaining, this->Taken);
  if (status != DormandPrince45::Accepted)
  {
    this->Termination = status == DormandPrince45::StepTooSmall ? Stagnation : DegenerateMetric;
    this->State = this->Previous;
    this->Done = true;
    return false;
  }
  if (!this->State.allFinite())
  {
    this->Termination = UnexpectedValue;
    this->State = this->Previous;
    this->Done = true;
    return false;
  }
  ++this->StepCount;
  return true;
}

void RayMarcher::Hit(const SceneHit& hit)
{
  this->DidHit = true;
  this->LastHit = hit;
  this->Termination = HitSurface;
  this->Done = true;
  // Arc length and velocity at the hit, linear within the step (the segment
  // is the chord the shader intersects too).
  this->ArcLength += hit.Fraction * this->Taken;
  this->HitVelocity =
    this->Previous.tail<3>() + hit.Fraction * (this->State.tail<3>() - this->Previous.tail<3>());
}

void RayMarcher::Miss()
{
  this->ArcLength += this->Taken;
}

Vec3 RayMarcher::Position() const
{
  return this->DidHit ? this->LastHit.Position : Vec3(this->State.head<3>());
}

Vec3 RayMarcher::Velocity() const
{
  return this->DidHit ? this->HitVelocity : Vec3(this->State.tail<3>());
}

void TraceRay(const Metric& metric, const Scene& scene, const Vec3& p, const Vec3& v,
  const RaySettings& settings, RayPath& path, bool recordPath, const MeshIntersector* meshes)
{
  path.Points.clear();
  path.ArcLength.clear();
  if (recordPath)
  {
    path.Points.push_back(p);
    path.ArcLength.push_back(0.0);
  }
  RayMarcher ray(settings);
  ray.Start(p, v);
  while (ray.Advance(metric))
  {
    SceneHit hit;
    if (IntersectSceneSegment(scene, meshes, ray.SegmentStart(), ray.SegmentEnd(), hit))
    {
      ray.Hit(hit);
      break;
    }
    ray.Miss();
    if (recordPath)
    {
      path.Points.push_back(ray.SegmentEnd());
      path.ArcLength.push_back(ray.Length());
    }
  }
  path.Hit = ray.IsHit();
  path.HitInfo = ray.HitInfo();
  path.Reason = ray.Reason();
  path.Steps = ray.Steps();
  path.Length = ray.Length();
  path.FinalVelocity = ray.Velocity();
  if (recordPath && path.Hit)
  {
    path.Points.push_back(path.HitInfo.Position);
    path.ArcLength.push_back(path.Length);
  }
}
} // namespace riemann
