/**
 * @file JacobiField.h
 * @brief Jacobi fields and conjugate points along a geodesic (MATH.md
 * "Jacobi fields and conjugate points").
 *
 * The geodesic flow x' = v, v' = -Gamma(x)(v, v) is integrated together with
 * its variational (linearised) equations for two Jacobi fields (J_a, DJ_a),
 * a = 0, 1:
 *   X' = V,   V' = -(d_X Gamma)(v, v) - 2 Gamma(x)(v, V),
 * where (d_X Gamma)^m_ij = X^l d_l Gamma^m_ij uses the exact derivatives of
 * the Christoffel symbols (ChristoffelAndDerivatives, Curvature.h). The
 * 18-dimensional system (x, v, X_0, V_0, X_1, V_1) is advanced by any of the
 * three integrators of RungeKutta.h (Euler, RK4, adaptive Dormand-Prince 5(4),
 * whose error control then covers the Jacobi fields too) in arc length (the
 * seed velocity is g-unit, so the parameter is arc length). DJ_a = V_a is the
 * coordinate derivative dJ_a/ds, not the covariant one.
 *
 * Seed: v0 = direction / |direction|_g, and (w_0, w_1) a g-orthonormal basis
 * of the g-orthogonal complement of v0 with vol_g(w_0, w_1, v0) = +1;
 * J_a(0) = 0, DJ_a(0) = w_a. Both fields stay g-orthogonal to the velocity
 * (g(J, v) is affine in s and vanishes with its derivative at s = 0).
 *
 * Transverse frame at each sample: vhat = v / |v|_g; e_0 = the coordinate axis
 * least aligned with vhat, projected g-orthogonally off vhat and g-normalised;
 * e_1 = the g-cross product vhat x_g e_0 (e_1^m = sqrt(det g) g^mi
 * eps_ijk vhat^j e_0^k), so that (e_0, e_1, vhat) is g-orthonormal and
 * positively oriented. Transverse[a][b] = g(J_a, e_b) (= components of the
 * part of J_a orthogonal to v). e_0 may jump between samples when a different
 * axis becomes the least aligned one, which changes Transverse by a rotation
 * only: its singular values and determinant do not depend on that choice.
 *
 * Determinant = sqrt(det g) det[J_0, J_1, v] / |v|_g (the g-volume of J_0, J_1
 * and the unit velocity) = det Transverse: signed, continuous in s, > 0 just
 * after the seed, and zero exactly where the transverse part of
 * d exp_p / dv loses rank, i.e. at conjugate points.
 *
 * Phases (the Maslov phases of the pair of fields): with X = Transverse^T and
 * Y the same matrix of the covariant derivatives DJ_a/ds + Gamma(v, J_a)
 * (columns = fields, rows = frame vectors), the matrix
 * W = (X + iY)(X - iY)^-1 is unitary because the fields span a Lagrangian
 * plane (X^T Y is symmetric: their Wronskian vanishes at the seed). Its two
 * eigenvalues are exp(i Phases[k]). W does not depend on the choice of the
 * transverse frame nor of the basis of fields (only on the plane they span),
 * it is -I at the seed, and it has the eigenvalue -1 exactly where X is
 * singular, with multiplicity the rank drop. Each phase passes pi (mod 2 pi)
 * only decreasing, at speed 2 (the crossing form of a Riemannian Jacobi
 * equation is definite), so conjugate points are counted, not guessed:
 * ConjugatePoints.h tracks the phases continuously.
 */
#ifndef RiemannJacobiField_h
#define RiemannJacobiField_h

#include "GeodesicTrace.h"
#include "Metric.h"
#include "RiemannCommonJacobiExport.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace riemann
{
struct JacobiSample
{
  double ArcLength = 0.0;
  Vec3 Point = Vec3::Zero();
  Vec3 Velocity = Vec3::Zero();
  /// The two transverse Jacobi fields J_a(s) (J_a(0) = 0) and dJ_a/ds.
  Vec3 J[2] = { Vec3::Zero(), Vec3::Zero() };
  Vec3 DJ[2] = { Vec3::Zero(), Vec3::Zero() };
  /// Transverse[a][b] = g(J_a, e_b) in the g-orthonormal transverse frame
  /// (e_0, e_1) of the file comment.
  double Transverse[2][2] = { { 0.0, 0.0 }, { 0.0, 0.0 } };
  /// sqrt(det g) det[J_0, J_1, v] / |v|_g = det Transverse (signed).
  double Determinant = 0.0;
  /// Singular values of Transverse, largest first.
  double SingularValues[2] = { 0.0, 0.0 };
  /// The Maslov phases in (-pi, pi] (file comment): pi at the seed and at
  /// every conjugate point, unordered. Computed only when asked for
  /// (`withPhases`: the conjugate-point search; the other consumers do not
  /// pay for them), else 0.
  double Phases[2] = { 0.0, 0.0 };
  /// g(v, v) - 1 (the seed velocity is g-unit): monitors the integration error.
  double SpeedDrift = 0.0;
};

/**
 * The Jacobi system's accelerations at x with velocity v and the variations
 * (j[k], dj[k]): a = -Gamma(v, v) and variations[k] = -(d_{j[k]} Gamma)(v, v)
 * - 2 Gamma(v, dj[k]), from ChristoffelAndDerivatives. False where the metric
 * refuses second derivatives, is degenerate, or a value is not finite.
 */
RIEMANNCOMMONJACOBI_EXPORT bool JacobiAccelerations(const Metric& metric, const Vec3& x,
  const Vec3& v, const Vec3 (&j)[2], const Vec3 (&dj)[2], Vec3& a, Vec3 (&variations)[2]);

/// A geodesic with its Jacobi fields, sampled at every step (and at s = 0).
struct JacobiTrace
{
  std::vector<JacobiSample> Samples;
  /// Why it stopped (GeodesicTrace.h's TerminationReason).
  int Reason = NotInitialized;
};

/**
 * Trace the geodesic from p in `direction` (any nonzero vector; it is
 * g-normalised) with its two transverse Jacobi fields, under the same
 * options and stopping rules as TraceGeodesic (integrator, step, tolerance
 * and step bounds of dp45, MaximumLength, MaximumSteps, Bounds); samples at
 * s = 0 and after every step. With `backward` the geodesic follows
 * -direction and ArcLength is negative. `landings` (arc lengths > 0, any
 * order) are distances the integration lands on exactly, by shortening the
 * step before each: the exponential map's wavefronts are sampled there
 * without interpolation. RecordSpeedDrift is ignored (always recorded: the
 * metric is evaluated at every sample anyway).
 */
RIEMANNCOMMONJACOBI_EXPORT void TraceJacobiFields(const Metric& metric, const Vec3& p,
  const Vec3& direction, const GeodesicOptions& options, JacobiTrace& trace, bool backward = false,
  const std::vector<double>& landings = {});

/**
 * TraceJacobiFields handing each sample to `visit` as soon as it is computed
 * (s = 0 first) instead of storing them; `visit` returns false to stop the
 * trace there (the conjugate-point search stops after the points it wants).
 * With `withPhases` the samples carry their Maslov phases. Returns the
 * TerminationReason, or 0 when `visit` stopped it.
 */
RIEMANNCOMMONJACOBI_EXPORT int TraceJacobiFields(const Metric& metric, const Vec3& p,
  const Vec3& direction, const GeodesicOptions& options, bool backward,
  const std::vector<double>& landings, bool withPhases,
  const std::function<bool(const JacobiSample&)>& visit);

/**
 * Continue the fields from `from` (a sample of a forward trace) to arc length
 * s >= from.ArcLength by `subSteps` equal RK4 steps (the root searches use it:
 * a fixed number of steps makes the result a smooth function of s), with the
 * Maslov phases when `withPhases`. False where the metric is degenerate on
 * the way.
 */
RIEMANNCOMMONJACOBI_EXPORT bool ContinueJacobiFields(const Metric& metric, const JacobiSample& from,
  double s, int subSteps, JacobiSample& sample, bool withPhases = false);

/// Where a trace of TraceJacobiFields' packet form starts: its p, direction and backward.
struct JacobiSeed
{
  Vec3 Point = Vec3::Zero();
  Vec3 Direction = Vec3::Zero();
  bool Backward = false;
};

/**
 * @class JacobiVisitor
 * @brief What the packet form of TraceJacobiFields hands its samples to.
 * Each trace runs on one lane of the packet from Start to End; lanes are
 * reused, so a visitor that keeps state per trace may keep it per lane.
 * Calls come from the thread that runs TraceJacobiFields.
 */
class RIEMANNCOMMONJACOBI_EXPORT JacobiVisitor
{
public:
  virtual ~JacobiVisitor() = default;
  /// Trace `trace` (seeds[trace]) starts on lane `lane`.
  virtual void Start(int lane, std::size_t trace)
  {
    (void)lane;
    (void)trace;
  }
  /// Its next sample (s = 0 first); false stops it.
  virtual bool Visit(int lane, std::size_t trace, const JacobiSample& sample) = 0;
  /// It ended: its TerminationReason, or 0 when Visit stopped it.
  virtual void End(int lane, std::size_t trace, int reason)
  {
    (void)lane;
    (void)trace;
    (void)reason;
  }
};

/**
 * TraceJacobiFields (the visitor form above) for seeds[0, count),
 * PacketWidth at a time on the packet engine (PacketTrace.h): the Jacobi
 * system of every lane steps in lock step, each lane with its own step
 * control and stopping rules, and a finished lane takes the next seed. The
 * samples and reasons equal the scalar form's to rounding. Single-threaded;
 * callers split their seeds across threads.
 */
RIEMANNCOMMONJACOBI_EXPORT void TraceJacobiFields(const Metric& metric, const JacobiSeed* seeds,
  std::size_t count, const GeodesicOptions& options, const std::vector<double>& landings,
  bool withPhases, JacobiVisitor& visitor);

/// The packet form into traces[0, count) (every sample kept, no phases).
RIEMANNCOMMONJACOBI_EXPORT void TraceJacobiFields(const Metric& metric, const JacobiSeed* seeds,
  std::size_t count, const GeodesicOptions& options, JacobiTrace* traces,
  const std::vector<double>& landings = {});

/**
 * The fixed-step RK4 shorthand: trace with step `step` up to `length` (the
 * last step is shortened to land on it). `samples` receives s = 0 and every
 * step. Returns false (samples holding what was reached) for invalid
 * arguments, or where the metric refuses second derivatives or becomes
 * degenerate before `length`.
 */
RIEMANNCOMMONJACOBI_EXPORT bool TraceJacobiFields(const Metric& metric, const Vec3& p,
  const Vec3& direction, double step, double length, std::vector<JacobiSample>& samples);

} // namespace riemann

#endif
