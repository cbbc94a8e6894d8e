/**
 * @file ConjugatePoints.h
 * @brief Conjugate points along a geodesic, found by counting the Maslov
 * phases of the Jacobi fields (JacobiField.h), so that none is stepped over
 * and two close simple points are never merged into one.
 *
 * Along the geodesic, the unitary matrix W(s) of JacobiField.h has two
 * eigenvalues exp(i theta_k(s)). A conjugate point is an arc length where
 * some theta_k passes pi (mod 2 pi), and every such passage is downward at
 * speed 2. So between two samples the number of conjugate points (with
 * multiplicity) is the number of phases that went down through pi: a
 * count, which does not cancel as a sign change of det J does when two
 * simple points fall in one step. The search:
 *  1. traces the Jacobi fields (TraceJacobiFields with the given options)
 *     and, between each two samples, matches the phases of one sample with
 *     those of the next (the matching with the smaller largest move);
 *  2. where a phase moves by more than pi / 4, splits the interval (fields
 *     continued by RK4 from its start) until no phase moves that much: the
 *     step control that makes the count exact;
 *  3. counts the phases that crossed pi in each interval and refines each
 *     crossing by the Illinois method (bracketing false position) on that
 *     phase's distance to pi, until that distance is below 0.2 * tolerance
 *     (the arc length within 0.1 * tolerance, the speed being 2) or the
 *     bracket is shorter than tolerance;
 *  4. merges crossings closer than `tolerance` into one point of
 *     multiplicity 2 (a rank drop of 2: a round sphere's conjugate points);
 *     two simple points farther apart stay two points of multiplicity 1,
 *     in order.
 * The reported arc length is then as accurate as the Jacobi fields: with the
 * adaptive integrator the integration tolerance is lowered to
 * ConjugateIntegrationTolerance(tolerance) so that `tolerance` bounds the
 * error; with a fixed step the step decides (RK4 at step h errs by about
 * h^4 over a few units of length).
 */
#ifndef RiemannConjugatePoints_h
#define RiemannConjugatePoints_h

#include "JacobiField.h"
#include "RiemannCommonJacobiExport.h"

#include <cstddef>
#include <vector>

namespace riemann
{
struct ConjugatePoint
{
  double ArcLength = 0.0;
  Vec3 Point = Vec3::Zero();
  /// 1 or 2: the rank drop of the transverse Jacobian at the point.
  int Multiplicity = 1;
  /// 1 for the first conjugate point along the geodesic, 2 for the next, ...
  int Index = 0;
  /// The caustic sheet of the point: 1 + the number of conjugate points
  /// before it counted with multiplicity (the Morse index of the geodesic
  /// just before it). The k-th sheet is a continuous function of the
  /// direction, unlike Index. A point of multiplicity 2 lies on sheets Sheet
  /// and Sheet + 1 (where the two sheets meet).
  int Sheet = 1;
  /// For multiplicity 1: the g-unit initial variation u at the observer
  /// (g-orthogonal to the direction) whose Jacobi field vanishes here, up to
  /// sign. The caustic sheet has a cusp where the conjugate distance does not
  /// change along u. Zero for multiplicity 2 (every variation vanishes).
  Vec3 KernelDirection = Vec3::Zero();
};

/// The integration tolerance of the adaptive integrator that keeps the
/// arc-length error of the conjugate points within `tolerance`
/// (Testing/Benchmarks/README.md, section BenchConjugatePoints.cxx: measured).
RIEMANNCOMMONJACOBI_EXPORT double ConjugateIntegrationTolerance(double tolerance);

/**
 * Conjugate points of p along the geodesic in `direction`, up to arc length
 * options.MaximumLength (file comment; any integrator; with
 * DormandPrince45 its tolerance is min(options.Tolerance,
 * ConjugateIntegrationTolerance(tolerance))). A geodesic stopped early is
 * searched as far as it got; the search also stops where |g(v, v) - 1|
 * exceeds 1e-4 (the integration is no longer trustworthy there, e.g. a
 * geodesic running off through the point at infinity of stereographic
 * coordinates). At most `maximumCount` points (no limit when <= 0), in order
 * of arc length; the trace stops once they are found.
 */
RIEMANNCOMMONJACOBI_EXPORT std::vector<ConjugatePoint> FindConjugatePoints(const Metric& metric,
  const Vec3& p, const Vec3& direction, const GeodesicOptions& options, double tolerance,
  int maximumCount);

/**
 * FindConjugatePoints from p in each of directions[0, count) into
 * found[0, count), on the packet engine (the packet TraceJacobiFields of
 * JacobiField.h, PacketWidth directions in lock step): the same points as
 * the one-direction form, to rounding. Single-threaded; callers split the
 * directions across threads.
 */
RIEMANNCOMMONJACOBI_EXPORT void FindConjugatePoints(const Metric& metric, const Vec3& p,
  const Vec3* directions, std::size_t count, const GeodesicOptions& options, double tolerance,
  int maximumCount, std::vector<ConjugatePoint>* found);

/// FindConjugatePoints with fixed-step RK4 of `step` up to `length`.
RIEMANNCOMMONJACOBI_EXPORT std::vector<ConjugatePoint> FindConjugatePoints(const Metric& metric,
  const Vec3& p, const Vec3& direction, double step, double length, double tolerance,
  int maximumCount);
} // namespace riemann

#endif
