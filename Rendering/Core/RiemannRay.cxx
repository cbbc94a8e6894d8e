#include "RiemannRay.h"

#include "RiemannSceneIntersection.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace riemann
{
namespace
{
void StartPath(const Vec3& p, bool recordPath, RayPath& path);
void FinishPath(const RayMarcher& ray, bool recordPath, RayPath& path);
}

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
  this->LeftData = false;
  this->LastHit = SceneHit();
}

bool RayMarcher::Advance(const Metric& metric)
{
  double remaining = 0.0;
  if (!this->BeginStep(remaining))
  {
    return false;
  }
  double taken = 0.0;
  const auto status = this->Stepper.Advance(metric, this->State, remaining, taken);
  return this->EndStep(status, taken, metric.InsideData(this->State.head<3>()));
}

bool RayMarcher::BeginStep(double& remaining)
{
  if (this->Done)
  {
    return false;
  }
  if (this->LeftData)
  {
    this->Termination = OutOfData;
    this->Done = true;
    return false;
  }
  remaining = this->Settings.MaximumLength - this->ArcLength;
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
  return true;
}

bool RayMarcher::EndStep(IntegrationStep::Status status, double taken, bool insideData)
{
  this->Taken = taken;
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
  this->LeftData = !insideData;
  return true;
}

void AdvanceRayPacket(const Metric& metric, RayMarcher* const* rays, int count, bool* advanced)
{
  // Step 1: dp45 keeps its step control in each ray's stepper: one by one.
  if (count <= 0)
  {
    return;
  }
  if (rays[0]->Settings.Integrator == IntegratorType::DormandPrince45)
  {
    for (int i = 0; i < count; ++i)
    {
      advanced[i] = rays[i]->Advance(metric);
    }
    return;
  }
  // Step 2: each ray's checks, and its state into a lane.
  PacketState y;
  alignas(64) double h[PacketWidth] = {};
  LaneMask lanes = 0;
  for (int l = 0; l < PacketWidth; ++l)
  {
    double remaining = 0.0;
    const bool stepping = l < count && rays[l]->BeginStep(remaining);
    if (l < count)
    {
      advanced[l] = stepping;
    }
    for (int i = 0; i < 6; ++i)
    {
      // Lanes without a ray hold a finite filler (their copy of lane 0's state is never read).
      y.Component(i)[l] = stepping ? rays[l]->State[i] : 0.0;
    }
    if (stepping)
    {
      h[l] = std::min(rays[l]->Settings.Step, remaining);
      lanes |= LaneMask{ 1 } << l;
    }
  }
  if (lanes == 0)
  {
    return;
  }
  // Step 3: one step of every lane, then each ray's state and checks back.
  const LaneMask stepped = rays[0]->Settings.Integrator == IntegratorType::Euler
    ? EulerPacketStep(metric, y, h, lanes)
    : RungeKutta4PacketStep(metric, y, h, lanes);
  for (int l = 0; l < count; ++l)
  {
    if (!HasLane(lanes, l))
    {
      continue;
    }
    for (int i = 0; i < 6; ++i)
    {
      rays[l]->State[i] = y.Component(i)[l];
    }
    advanced[l] = rays[l]->EndStep(
      HasLane(stepped, l) ? IntegrationStep::Accepted : IntegrationStep::Degenerate, h[l],
      metric.InsideData(rays[l]->State.head<3>()));
  }
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
  StartPath(p, recordPath, path);
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
  FinishPath(ray, recordPath, path);
}

namespace
{
/// An empty path, or the start point alone when the path is recorded.
void StartPath(const Vec3& p, bool recordPath, RayPath& path)
{
  path.Points.clear();
  path.ArcLength.clear();
  if (recordPath)
  {
    path.Points.push_back(p);
    path.ArcLength.push_back(0.0);
  }
}

/// TraceRay's path from a ray that has ended (the points recorded as it went).
void FinishPath(const RayMarcher& ray, bool recordPath, RayPath& path)
{
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
} // namespace

void TraceRays(const Metric& metric, const Scene& scene, const Vec3& p, const Vec3* v, int count,
  const RaySettings& settings, RayPath* paths, bool recordPath, const MeshIntersector* meshes)
{
  for (int first = 0; first < count; first += PacketWidth)
  {
    // Step 1: a packet of rays started at p.
    const int n = std::min(PacketWidth, count - first);
    std::vector<RayMarcher> rays(static_cast<size_t>(n), RayMarcher(settings));
    RayMarcher* live[PacketWidth];
    int liveIndex[PacketWidth];
    int liveCount = 0;
    for (int i = 0; i < n; ++i)
    {
      StartPath(p, recordPath, paths[first + i]);
      rays[static_cast<size_t>(i)].Start(p, v[first + i]);
      live[liveCount] = &rays[static_cast<size_t>(i)];
      liveIndex[liveCount++] = i;
    }
    // Step 2: step the live rays together, intersect each segment, keep
    // those that missed (TraceRay's loop, one lane per ray).
    while (liveCount > 0)
    {
      bool advanced[PacketWidth];
      AdvanceRayPacket(metric, live, liveCount, advanced);
      int kept = 0;
      for (int k = 0; k < liveCount; ++k)
      {
        RayMarcher& ray = *live[k];
        RayPath& path = paths[first + liveIndex[k]];
        if (!advanced[k])
        {
          continue;
        }
        SceneHit hit;
        if (IntersectSceneSegment(scene, meshes, ray.SegmentStart(), ray.SegmentEnd(), hit))
        {
          ray.Hit(hit);
          continue;
        }
        ray.Miss();
        if (recordPath)
        {
          path.Points.push_back(ray.SegmentEnd());
          path.ArcLength.push_back(ray.Length());
        }
        live[kept] = live[k];
        liveIndex[kept++] = liveIndex[k];
      }
      liveCount = kept;
    }
    // Step 3: the ends.
    for (int i = 0; i < n; ++i)
    {
      FinishPath(rays[static_cast<size_t>(i)], recordPath, paths[first + i]);
    }
  }
}
} // namespace riemann
