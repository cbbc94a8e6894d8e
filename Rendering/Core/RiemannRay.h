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
 * MaximumSteps, where the metric degenerates, or after the step that leaves
 * a sampled metric's data ("outside": "stop"; its segment is still
 * intersected, and the ray is shaded as escaped). The GLSL in
 * vtkRiemannRayTracePass follows the same rules.
 */
#ifndef RiemannRay_h
#define RiemannRay_h

#include "RiemannRenderingCoreExport.h" // For export macro
#include "RiemannSceneIntersection.h"
#include "RiemannScene.h"

#include "GeodesicTrace.h" // For TerminationReason
#include "Integrators.h" // For GeodesicStepper
#include "Metric.h"
#include "PacketKernels.h" // For AdvanceRayPacket

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
  /// HitSurface, OutOfLength, OutOfSteps, OutOfData, DegenerateMetric, Stagnation,
  /// UnexpectedValue.
  int Reason = NotInitialized;
  int Steps = 0;
};

class RayMarcher;

/**
 * RayMarcher::Advance for up to PacketWidth rays at once through the packet
 * engine (PacketKernels.h): the same rules, each ray's step in a SIMD lane;
 * advanced[i] is what rays[i]->Advance(metric) would return. The rays'
 * settings must be alike (one integrator and step); with dp45 (whose step
 * control lives in each ray's stepper) every ray advances alone.
 */
RIEMANNRENDERINGCORE_EXPORT void AdvanceRayPacket(
  const Metric& metric, RayMarcher* const* rays, int count, bool* advanced);

/**
 * The rules of one ray, one step at a time, so that a tracer can advance many
 * rays and intersect their segments together (the CPU tracer's Embree ray
 * streams) while keeping exactly TraceRay's rules:
 * @code
 * RayMarcher ray(settings);
 * ray.Start(p, v);
 * while (ray.Advance(metric))         // false: ended (length, steps, failure)
 * {
 *   SceneHit hit;
 *   if (IntersectSegment(scene, ray.SegmentStart(), ray.SegmentEnd(), hit)) { ray.Hit(hit); break; }
 *   ray.Miss();
 * }
 * @endcode
 */
class RIEMANNRENDERINGCORE_EXPORT RayMarcher
{
public:
  explicit RayMarcher(const RaySettings& settings);

  /// Start a ray at p with unit-speed velocity v.
  void Start(const Vec3& p, const Vec3& v);

  /**
   * Take the next step. True: the segment SegmentStart() -> SegmentEnd() is
   * to be intersected, then Hit() or Miss() called. False: the ray has ended
   * (Reason() says why).
   */
  bool Advance(const Metric& metric);

  Vec3 SegmentStart() const { return this->Previous.head<3>(); }
  Vec3 SegmentEnd() const { return this->State.head<3>(); }

  /// The segment hits: the ray ends there (arc length and velocity linear within the step).
  void Hit(const SceneHit& hit);
  /// The segment hits nothing: the step is accepted.
  void Miss();

  bool Ended() const { return this->Done; }
  bool IsHit() const { return this->DidHit; }
  int Reason() const { return this->Termination; }
  int Steps() const { return this->StepCount; }
  /// Arc length so far, or at the hit.
  double Length() const { return this->ArcLength; }
  /// Position at the end (the hit position for a hit).
  Vec3 Position() const;
  /// Velocity at the end (dx/ds).
  Vec3 Velocity() const;
  const SceneHit& HitInfo() const { return this->LastHit; }

private:
  friend void AdvanceRayPacket(
    const Metric& metric, RayMarcher* const* rays, int count, bool* advanced);
  /// Advance's checks before a step: false (and Done) when the ray ends.
  bool BeginStep(double& remaining);
  /// Advance's checks after a step taken with `status`; `insideData` is
  /// Metric::InsideData at the new point (the next BeginStep ends the ray if not).
  bool EndStep(IntegrationStep::Status status, double taken, bool insideData);

  RaySettings Settings;
  GeodesicStepper Stepper;
  Vec6 State;
  Vec6 Previous;
  double ArcLength = 0.0;
  double Taken = 0.0;
  int StepCount = 0;
  int Termination = NotInitialized;
  bool Done = true;
  bool DidHit = false;
  /// The last step left the metric's data: the ray ends before the next one.
  bool LeftData = false;
  SceneHit LastHit;
  Vec3 HitVelocity = Vec3::Zero();
};

class MeshIntersector;

/**
 * Trace one ray from p with unit-speed velocity v. With `recordPath` false
 * only the end state is kept (no allocation). With `meshes` (the scene's
 * triangle meshes in Embree) each segment is intersected with them too.
 */
RIEMANNRENDERINGCORE_EXPORT void TraceRay(const Metric& metric, const Scene& scene,
  const Vec3& p, const Vec3& v, const RaySettings& settings, RayPath& path, bool recordPath = true,
  const MeshIntersector* meshes = nullptr);

/**
 * TraceRay for `count` rays from p with unit-speed velocities v[i] into
 * paths[i], PacketWidth at a time through the packet engine
 * (AdvanceRayPacket): the same paths, to rounding. Single-threaded.
 */
RIEMANNRENDERINGCORE_EXPORT void TraceRays(const Metric& metric, const Scene& scene, const Vec3& p,
  const Vec3* v, int count, const RaySettings& settings, RayPath* paths, bool recordPath = true,
  const MeshIntersector* meshes = nullptr);
} // namespace riemann

#endif
