/**
 * @file GeodesicConnector.h
 * @brief Every geodesic from p to q up to a given arc length: the two-point
 * problem, solved by shooting and Newton's method on the exponential map.
 *
 * The exponential map at p sends an initial g-unit direction u and an arc
 * length s to x(s; u). A geodesic from p to q is a root of
 *   F(u, s) = x(s; u) - q.
 * Its derivative is known exactly along the trace: varying u by e w_a (w_a
 * the Jacobi fields' initial variations, g-orthonormal and g-orthogonal to
 * u) moves x(s) by e J_a(s), and varying s moves it by v(s). So the Newton
 * system at (u, s) is
 *   [J_0(s) J_1(s) v(s)] (d_0, d_1, d_s) = q - x(s; u),
 * and the step is u <- normalise_g(u + d_0 w_0 + d_1 w_1), s <- s + d_s.
 * The matrix is singular exactly where q is conjugate to p along the
 * geodesic (det [J_0 J_1 v] = 0 there; JacobiField.h): the step is then the
 * least-squares one (a pseudo-inverse), and the result says that q is
 * conjugate rather than missing the geodesic.
 *
 * The search (Documentation/Mathematics.md, "Between two points"):
 *  1. shooting: geodesics with their Jacobi fields from a Fibonacci grid of
 *     g-unit directions at p (ShootingDirections), each to a little past
 *     the length limit; wherever a geodesic passes q most closely (a local
 *     minimum of the distance to q along it) the linearised Newton step is
 *     computed, and the pass is a candidate when that step changes the
 *     direction by at most two grid spacings (FindConnectionCandidates);
 *  2. Newton from each candidate, with backtracking, to |x(s) - q| below
 *     the tolerance (RefineConnection);
 *  3. each geodesic's Morse index: its conjugate points before q counted
 *     with multiplicity, by the Maslov-phase search of ConjugatePoints.h
 *     (as vtkRiemannConjugateLocus counts them), and whether q itself is
 *     conjugate to p along it (ClassifyConnection);
 *  4. duplicates merged (the same direction and length), sorted by length,
 *     the shortest marked (MergeConnections).
 * Grid directions that sweep a whole family of geodesics to q (q conjugate
 * to p with multiplicity 2, as the antipode of p on a round sphere) give one
 * result each: the family, sampled.
 *
 * The stages are single-threaded; vtkRiemannGeodesicConnector runs stages 1
 * to 3 in parallel over directions and candidates.
 */
#ifndef RiemannGeodesicConnector_h
#define RiemannGeodesicConnector_h

#include "GeodesicTrace.h"
#include "Metric.h"
#include "RiemannCommonJacobiExport.h"

#include <cstddef>
#include <vector>

namespace riemann
{
struct ConnectOptions
{
  /// Geodesics of arc length up to this are searched.
  double MaximumLength = 10.0;
  /// What |x(s) - q| (coordinate distance) each result reaches.
  double Tolerance = 1e-9;
  /// Directions of the shooting grid.
  int NumberOfDirections = 2000;
  /// Newton iterations of one candidate at most.
  int MaximumIterations = 40;
  /**
   * How geodesics and Jacobi fields are integrated: the integrator, the
   * first step, the step bounds and the step count (MaximumLength is set
   * per trace). With dp45 the shooting uses its Tolerance, and Newton
   * RefinementTolerance(Tolerance) when smaller: the integration error
   * must stay well below what |x(s) - q| is asked to be.
   */
  GeodesicOptions Integration;
};

/// The per-step tolerance of dp45 during Newton, for a connection tolerance.
RIEMANNCOMMONJACOBI_EXPORT double RefinementTolerance(double tolerance);

/// A pass of a shooting geodesic near q: where Newton starts.
struct ConnectionCandidate
{
  /// g-unit initial velocity at p.
  Vec3 Direction = Vec3::Zero();
  double ArcLength = 0.0;
};

/// One geodesic from p to q.
struct ConnectingGeodesic
{
  /// g-unit initial velocity at p.
  Vec3 Direction = Vec3::Zero();
  /// Arc length from p to q.
  double Length = 0.0;
  /// |x(Length) - q| reached (at most the tolerance).
  double Miss = 0.0;
  int Iterations = 0;
  /// Conjugate points of p strictly before q along it, with multiplicity.
  int MorseIndex = 0;
  /// 0, or the multiplicity (1 or 2) of q as a conjugate point of p along
  /// it (the Newton system is singular there).
  int ConjugateMultiplicity = 0;
  /// One of the shortest found (within the tolerance).
  bool Shortest = false;
};

/**
 * `count` g-unit directions at p, evenly spread over the unit sphere of g
 * (a Fibonacci grid in a g-orthonormal frame, its axis towards q). Empty
 * when g is not positive definite at p.
 */
RIEMANNCOMMONJACOBI_EXPORT std::vector<Vec3> ShootingDirections(
  const Metric& metric, const Vec3& p, const Vec3& q, int count);

/**
 * Step 1 for directions[0, count) of a grid of `gridSize` directions (the
 * grid's spacing sets the candidates' window): the candidates their
 * geodesics give, PacketWidth directions in lock step.
 */
RIEMANNCOMMONJACOBI_EXPORT std::vector<ConnectionCandidate> FindConnectionCandidates(
  const Metric& metric, const Vec3& p, const Vec3& q, const Vec3* directions, std::size_t count,
  int gridSize, const ConnectOptions& options);

/**
 * Step 2: Newton from `candidate`. False when it does not reach the
 * tolerance within MaximumIterations, leaves the length limit (with 1% to
 * spare: a root just past it is not one), or its geodesic stops early.
 */
RIEMANNCOMMONJACOBI_EXPORT bool RefineConnection(const Metric& metric, const Vec3& p,
  const Vec3& q, const ConnectionCandidate& candidate, const ConnectOptions& options,
  ConnectingGeodesic& result);

/// Step 3: MorseIndex and ConjugateMultiplicity of `geodesic`.
RIEMANNCOMMONJACOBI_EXPORT void ClassifyConnection(
  const Metric& metric, const Vec3& p, const ConnectOptions& options, ConnectingGeodesic& geodesic);

/**
 * Step 4: the distinct geodesics of `found` no longer than MaximumLength
 * (two are one when their directions differ by less than 1e-6 in g-angle
 * and their lengths by less than 1e-6 (1 + length)), sorted by length, the
 * shortest marked.
 */
RIEMANNCOMMONJACOBI_EXPORT std::vector<ConnectingGeodesic> MergeConnections(
  std::vector<ConnectingGeodesic> found, const ConnectOptions& options);

/// What keeps p and q from being joined, checked before any shooting.
enum class ConnectionProblem
{
  None,
  NotFinite,        ///< p or q is not finite
  StartOutsideData, ///< p is outside the metric's data (Metric::InsideData)
  EndOutsideData,   ///< q is
  SamePoint         ///< |p - q| <= the tolerance
};
RIEMANNCOMMONJACOBI_EXPORT ConnectionProblem CheckConnection(
  const Metric& metric, const Vec3& p, const Vec3& q, const ConnectOptions& options);

/// Steps 1 to 4 on one thread. Throws std::invalid_argument for what
/// CheckConnection refuses, or g not positive definite at p.
RIEMANNCOMMONJACOBI_EXPORT std::vector<ConnectingGeodesic> ConnectPoints(
  const Metric& metric, const Vec3& p, const Vec3& q, const ConnectOptions& options);

/// The geodesic's samples from p to q (TraceGeodesic to its length).
RIEMANNCOMMONJACOBI_EXPORT void TraceConnection(const Metric& metric, const Vec3& p,
  const ConnectingGeodesic& geodesic, const ConnectOptions& options, GeodesicPath& path);
} // namespace riemann

#endif
