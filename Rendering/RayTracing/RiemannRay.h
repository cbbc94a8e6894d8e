/**
 * @file RiemannRay.h
 * @brief One ray of the inside view traced on the CPU: the reference for the
 * GPU pass, the ray bundles plotted next to it, and the CPU tracer.
 *
 * A ray starts at the observer with a unit-speed velocity (ObserverCamera) and
 * is integrated in Riemannian arc length with the scene's RaySettings. After
 * each step the segment from the previous point to the new one is intersected
 * with the scene (IntersectSegment); the ray stops at the first hit, at
 * MaximumLength (the last step is shortened to land on it), after
 * MaximumSteps, or where the metric degenerates. The GLSL in
 * vtkRiemannRayTracePass follows the same rules.
 */
#ifndef RiemannRay_h
#define RiemannRay_h

#include "RiemannRenderingRayTracingModule.h" // For export macro
#include "RiemannScene.h"

#include "GeodesicTrace.h" // For TerminationReason
#include "Metric.h"

#include <vector>

namespace riemann
{
struct RayPath
{
  /// Sampled points, from the observer to the hit (or the last step).
  std::vector<Vec3> Points;
  std::vector<double> ArcLength;
  bool Hit = false;
  SceneHit HitInfo;
  /// Arc length at the hit, or at the end of the ray.
  double Length = 0.0;
  /// Velocity at the hit or at the end (dx/ds).
  Vec3 FinalVelocity = Vec3::Zero();
  /// HitSurface, OutOfLength, OutOfSteps, DegenerateMetric, Stagnation, UnexpectedValue.
  int Reason = NotInitialized;
  int Steps = 0;
};

/**
 * Trace one ray from p with unit-speed velocity v. With `recordPath` false
 * only the end state is kept (no allocation).
 */
RIEMANNRENDERINGRAYTRACING_EXPORT void TraceRay(const Metric& metric, const Scene& scene,
  const Vec3& p, const Vec3& v, const RaySettings& settings, RayPath& path, bool recordPath = true);
} // namespace riemann

#endif
