/**
 * @file GeodesicTrace.h
 * @brief Trace one geodesic of a Metric from a point and a direction: the
 * VTK-free core of vtkRiemannGeodesicTracer and `riemann trace`.
 */
#ifndef RiemannGeodesicTrace_h
#define RiemannGeodesicTrace_h

#include "Integrators.h"
#include "RiemannCommonMetricExport.h"

#include <vector>

namespace riemann
{
/**
 * Why a geodesic stopped. 1-6 are vtkStreamTracer's ReasonForTermination
 * codes (7 is its count of fixed reasons); 8 and up are ours.
 */
enum TerminationReason : int
{
  OutOfDomain = 1,
  NotInitialized = 2,
  UnexpectedValue = 3,
  OutOfLength = 4,
  OutOfSteps = 5,
  Stagnation = 6,
  DegenerateMetric = 8,
  HitSurface = 9,
  /// Left the volume of a sampled metric with "outside": "stop" (Metric::InsideData).
  OutOfData = 10,
  /// Tractography (TractStops.h): reached a voxel where the stop mask is 0,
  StoppedByMask = 11,
  /// reached fractional anisotropy below the threshold,
  LowAnisotropy = 12,
  /// turned more sharply than the largest angle per mm between steps.
  SharpTurn = 13,
  /// A step would have outrun its own speed (StepOutranItsSpeed): the metric
  /// changes faster than the step resolves, so the step is refused.
  OutranStep = 14
};

/// The largest TerminationReason code (for tables of counts by reason).
constexpr int LastTerminationReason = OutranStep;

/**
 * A rule that ends geodesics at some points of space (tractography's stop
 * mask and anisotropy threshold: TractStopRules). Consulted at every point
 * of a path, the seed included; must be safe to call from several threads.
 */
class RIEMANNCOMMONMETRIC_EXPORT StopCondition
{
public:
  virtual ~StopCondition() = default;
  /// The TerminationReason for stopping at x, or 0 to go on.
  virtual int ReasonToStop(const Vec3& x) const = 0;
};

/// A short English name for a TerminationReason ("out of length", ...).
RIEMANNCOMMONMETRIC_EXPORT const char* TerminationReasonName(int reason);

/**
 * How a geodesic is integrated. Plain defaults: the same as the declared
 * ones of vtkRiemannIntegrationSettings (vtkRiemannIntegrationSettings.settings.json),
 * which CommonMetric.GeodesicOptions.DefaultsAreTheDeclaredOnes checks.
 */
struct GeodesicOptions
{
  IntegratorType Integrator = IntegratorType::RungeKutta4;
  /// Step in Riemannian arc length (the initial step for dp45).
  double Step = 0.01;
  /// Bounds of the adaptive step (dp45 only).
  double MinimumStep = 1e-7;
  double MaximumStep = 0.5;
  /// Mixed absolute/relative error tolerance per step (dp45 only).
  double Tolerance = 1e-8;
  /// Riemannian arc length at which the geodesic stops.
  double MaximumLength = 10.0;
  long long MaximumSteps = 100000;
  /// Stop when leaving [x0,x1]x[y0,y1]x[z0,z1] (only if UseBounds).
  bool UseBounds = false;
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  /// Record g(v,v)/g(v0,v0) - 1 at every point (one metric evaluation per step).
  bool RecordSpeedDrift = true;
  /// Also stop where this says (not owned; null: no such rule).
  const StopCondition* Stop = nullptr;
};

/// x within options.Bounds, or true when !options.UseBounds.
inline bool InsideBounds(const GeodesicOptions& options, const Vec3& x)
{
  return !options.UseBounds ||
    (x[0] >= options.Bounds[0] && x[0] <= options.Bounds[1] && x[1] >= options.Bounds[2] &&
      x[1] <= options.Bounds[3] && x[2] >= options.Bounds[4] && x[2] <= options.Bounds[5]);
}

/**
 * Why a geodesic at x stops before stepping on, or 0: OutOfDomain outside
 * options.Bounds, OutOfData outside the metric's data, else options.Stop's
 * reason.
 */
inline int ReasonToStopAt(const Metric& metric, const GeodesicOptions& options, const Vec3& x)
{
  if (!InsideBounds(options, x))
  {
    return OutOfDomain;
  }
  if (!metric.InsideData(x))
  {
    return OutOfData;
  }
  return options.Stop ? options.Stop->ReasonToStop(x) : 0;
}

/**
 * How much longer than its nominal length a step's chord may be:
 * StepOutranItsSpeed's bound. An RK4 step's chord is the step times the mean
 * of its stages' velocities, which stays within a few percent of the start's
 * wherever the step resolves the metric; twice it means the stages saw a
 * velocity the start does not (near a nearly degenerate tensor of a
 * sharpened or adjugate metric, one step of 0.5 mm went 31 m).
 */
constexpr double MaximumChordToStepRatio = 2.0;

/**
 * The sampled geodesic. ArcLength is the signed Riemannian arc length from
 * the seed (negative for a backward geodesic, as vtkStreamTracer's
 * IntegrationTime); Velocities are the coordinate velocities dx/ds.
 */
struct RIEMANNCOMMONMETRIC_EXPORT GeodesicPath
{
  std::vector<Vec3> Points;
  std::vector<Vec3> Velocities;
  std::vector<double> ArcLength;
  std::vector<double> SpeedDrift;
  int Reason = NotInitialized;

  /// Empty the path but keep its capacity, so reuse does not allocate.
  void Clear();
};

/**
 * Whether a step from the path's last point to `x` outran its speed: its
 * chord is longer than MaximumChordToStepRatio times its nominal Euclidean
 * length, the start's coordinate speed |dx/ds| times `arcLength`, the step's
 * Riemannian length. Both tracers refuse such a step (OutranStep) and do not
 * record its point.
 */
RIEMANNCOMMONMETRIC_EXPORT bool StepOutranItsSpeed(
  const GeodesicPath& path, const Vec3& x, double arcLength);

/**
 * End `path` on the face of the metric's data (Metric::InsideData) that its
 * last step crossed: from the last recorded point (inside) towards the
 * step's end (x, velocity, arc length, drift; outside), the point of the
 * chord where it leaves the data, found by bisection to 1e-12 of the chord,
 * with velocity, arc length and drift interpolated along it. Appended unless
 * it is the last point itself; the Reason becomes OutOfData. So a traced
 * tract ends on the volume's faces, as MRtrix's and DIPY's do, not a step
 * beyond them.
 */
RIEMANNCOMMONMETRIC_EXPORT void EndOnTheDataFace(const Metric& metric, GeodesicPath& path,
  const Vec3& x, const Vec3& velocity, double arcLength, double drift);

/**
 * Scale `direction` to unit speed in g at p: v = d / sqrt(g_p(d, d)).
 * False when the direction is zero or not finite, or g is degenerate at p.
 */
RIEMANNCOMMONMETRIC_EXPORT bool UnitSpeedVelocity(
  const Metric& metric, const Vec3& p, const Vec3& direction, Vec3& velocity);

/**
 * Integrate the geodesic from p with initial velocity v (any nonzero speed;
 * lengths and steps are in arc length, ArcLength is parameter times the
 * initial speed) until a termination reason occurs. With `backward` the
 * geodesic follows -v and ArcLength is negative.
 */
RIEMANNCOMMONMETRIC_EXPORT void TraceGeodesic(const Metric& metric, const Vec3& p, const Vec3& v,
  const GeodesicOptions& options, GeodesicPath& path, bool backward = false);
} // namespace riemann

#endif
