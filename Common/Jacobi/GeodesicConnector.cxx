#include "GeodesicConnector.h"

#include "ConjugatePoints.h"
#include "DirectionLattice.h"
#include "JacobiField.h"

#include <Eigen/Cholesky>
#include <Eigen/LU> // inverse
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace riemann
{
namespace
{
/// Singular values below this fraction of the largest are left out of the
/// Newton step (the least-squares step where q is conjugate to p).
constexpr double SingularCutoff = 1e-10;

/// The shooting geodesics go this much past the length limit, so that a
/// pass of q just beyond it, whose root lies just within, is not lost.
double ShootingLength(double maximumLength)
{
  return 1.02 * maximumLength + 1e-3;
}

/// The Newton step of the system [J_0 J_1 v] d = q - x (least squares where
/// the matrix is singular).
Vec3 NewtonStep(const Vec3 (&j)[2], const Vec3& velocity, const Vec3& residual)
{
  Mat3 m;
  m.col(0) = j[0];
  m.col(1) = j[1];
  m.col(2) = velocity;
  Eigen::JacobiSVD<Mat3> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  svd.setThreshold(SingularCutoff);
  return svd.solve(residual);
}

/// u + d_0 w_0 + d_1 w_1, g-normalised at p; false where that fails.
bool MoveDirection(const Metric& metric, const Vec3& p, const Vec3& u, const Vec3 (&w)[2],
  double d0, double d1, Vec3& moved)
{
  return UnitSpeedVelocity(metric, p, u + d0 * w[0] + d1 * w[1], moved);
}

/// Closest approach of the chord [a, b] to q: the distance, and where (0..1).
double ChordDistance(const Vec3& a, const Vec3& b, const Vec3& q, double& t)
{
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  t = length2 > 0 ? std::clamp((q - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - q).norm();
}

/**
 * Step 1's visitor: along each lane's geodesic, the local minima of the
 * distance from the chords to q; at each, the linearised Newton step from
 * the nearer sample, kept as a candidate when it moves the direction by at
 * most `window` (g-angle).
 */
class CandidateVisitor : public JacobiVisitor
{
public:
  CandidateVisitor(const Metric& metric, const Vec3& p, const Vec3& q, const Vec3* directions,
    double window, std::vector<ConnectionCandidate>& out)
    : TheMetric(metric)
    , P(p)
    , Q(q)
    , Directions(directions)
    , Window(window)
    , Out(out)
  {
  }

  void Start(int lane, std::size_t) override { this->Lanes[lane] = LaneState(); }

  bool Visit(int lane, std::size_t trace, const JacobiSample& sample) override
  {
    LaneState& state = this->Lanes[lane];
    if (!state.HasPrevious)
    {
      // s = 0: the fields' initial variations are the directions they move.
      state.W[0] = sample.DJ[0];
      state.W[1] = sample.DJ[1];
      state.Previous = sample;
      state.HasPrevious = true;
      state.Distance = (sample.Point - this->Q).norm();
      return true;
    }
    double t = 0.0;
    const double distance = ChordDistance(state.Previous.Point, sample.Point, this->Q, t);
    // A local minimum of the chords' distance: it fell to the last chord
    // and rises on this one.
    if (state.Falling && distance > state.Distance)
    {
      this->Consider(state, trace);
    }
    state.Falling = distance < state.Distance || (state.Falling && distance == state.Distance);
    state.Nearest = t < 0.5 ? state.Previous : sample;
    state.Distance = distance;
    state.Previous = sample;
    return true;
  }

  void End(int lane, std::size_t trace, int) override
  {
    LaneState& state = this->Lanes[lane];
    if (state.HasPrevious && state.Falling)
    {
      this->Consider(state, trace); // it ended still approaching q
    }
  }

private:
  struct LaneState
  {
    bool HasPrevious = false;
    bool Falling = false;
    double Distance = 0.0;
    Vec3 W[2] = { Vec3::Zero(), Vec3::Zero() };
    JacobiSample Previous;
    JacobiSample Nearest;
  };

  void Consider(const LaneState& state, std::size_t trace)
  {
    const JacobiSample& at = state.Nearest;
    const Vec3 step = NewtonStep(at.J, at.Velocity, this->Q - at.Point);
    if (!step.allFinite() || std::hypot(step[0], step[1]) > this->Window)
    {
      return;
    }
    ConnectionCandidate candidate;
    if (MoveDirection(this->TheMetric, this->P, this->Directions[trace], state.W, step[0], step[1],
          candidate.Direction))
    {
      candidate.ArcLength = std::max(at.ArcLength + step[2], 1e-12);
      this->Out.push_back(candidate);
    }
  }

  const Metric& TheMetric;
  Vec3 P;
  Vec3 Q;
  const Vec3* Directions;
  double Window;
  std::vector<ConnectionCandidate>& Out;
  LaneState Lanes[PacketWidth];
};

/// x(s; u) with its Jacobi fields and their initial variations; false when
/// the geodesic stops before s.
bool EndOfGeodesic(const Metric& metric, const Vec3& p, const Vec3& u, double s,
  const GeodesicOptions& options, JacobiSample& end, Vec3 (&w)[2])
{
  GeodesicOptions to = options;
  to.MaximumLength = s;
  bool first = true;
  const int reason = TraceJacobiFields(metric, p, u, to, false, {}, false,
    [&](const JacobiSample& sample)
    {
      if (first)
      {
        w[0] = sample.DJ[0];
        w[1] = sample.DJ[1];
        first = false;
      }
      end = sample;
      return true;
    });
  return reason == OutOfLength && std::abs(end.ArcLength - s) <= 1e-9 * std::max(1.0, s);
}
} // namespace

double RefinementTolerance(double tolerance)
{
  return std::max(1e-14, 1e-3 * tolerance);
}

std::vector<Vec3> ShootingDirections(const Metric& metric, const Vec3& p, const Vec3& q, int count)
{
  Mat3 g;
  if (count < 1 || !metric.Tensor(p, g))
  {
    return {};
  }
  const Eigen::LLT<Mat3> llt(g);
  if (llt.info() != Eigen::Success)
  {
    return {};
  }
  // g = L L^T: d unit in the Euclidean sense <=> L^-T d unit in g.
  const Mat3 lower = llt.matrixL();
  const Mat3 toG = lower.transpose().inverse();
  Vec3 axis = lower.transpose() * (q - p);
  if (!(axis.norm() > 0) || !axis.allFinite())
  {
    axis = Vec3::UnitZ();
  }
  std::vector<Vec3> directions = FibonacciDirections(count, axis, 180.0);
  for (Vec3& d : directions)
  {
    d = toG * d;
  }
  return directions;
}

std::vector<ConnectionCandidate> FindConnectionCandidates(const Metric& metric, const Vec3& p,
  const Vec3& q, const Vec3* directions, std::size_t count, int gridSize,
  const ConnectOptions& options)
{
  std::vector<ConnectionCandidate> candidates;
  if (count == 0)
  {
    return candidates;
  }
  // Each grid direction stands for a cap of 4 pi / N steradians: its
  // spacing is about sqrt(4 pi / N); a pass within two spacings is tried.
  const double spacing = std::sqrt(4.0 * M_PI / std::max(gridSize, 1));
  CandidateVisitor visitor(metric, p, q, directions, 2.0 * spacing, candidates);
  std::vector<JacobiSeed> seeds(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    seeds[i].Point = p;
    seeds[i].Direction = directions[i];
  }
  GeodesicOptions shooting = options.Integration;
  shooting.MaximumLength = ShootingLength(options.MaximumLength);
  TraceJacobiFields(metric, seeds.data(), count, shooting, {}, false, visitor);
  return candidates;
}

bool RefineConnection(const Metric& metric, const Vec3& p, const Vec3& q,
  const ConnectionCandidate& candidate, const ConnectOptions& options, ConnectingGeodesic& result)
{
  GeodesicOptions integration = options.Integration;
  if (integration.Integrator == IntegratorType::DormandPrince45)
  {
    integration.Tolerance =
      std::min(integration.Tolerance, RefinementTolerance(options.Tolerance));
  }
  const double longest = 1.01 * options.MaximumLength + 1e-9;
  Vec3 u;
  if (!UnitSpeedVelocity(metric, p, candidate.Direction, u))
  {
    return false;
  }
  double s = candidate.ArcLength;
  JacobiSample end;
  Vec3 w[2];
  if (!(s > 0 && s <= longest) || !EndOfGeodesic(metric, p, u, s, integration, end, w))
  {
    return false;
  }
  double miss = (end.Point - q).norm();
  for (int iteration = 0; iteration <= options.MaximumIterations; ++iteration)
  {
    if (miss <= options.Tolerance)
    {
      result.Direction = u;
      result.Length = s;
      result.Miss = miss;
      result.Iterations = iteration;
      return true;
    }
    if (iteration == options.MaximumIterations)
    {
      break;
    }
    // Newton's step, halved until the miss decreases (at most 12 times).
    const Vec3 step = NewtonStep(end.J, end.Velocity, q - end.Point);
    if (!step.allFinite())
    {
      return false;
    }
    bool improved = false;
    for (double fraction = 1.0; fraction > 1e-4 && !improved; fraction *= 0.5)
    {
      Vec3 trialU;
      const double trialS = s + fraction * step[2];
      JacobiSample trialEnd;
      Vec3 trialW[2];
      if (!(trialS > 0 && trialS <= longest) ||
        !MoveDirection(metric, p, u, w, fraction * step[0], fraction * step[1], trialU) ||
        !EndOfGeodesic(metric, p, trialU, trialS, integration, trialEnd, trialW))
      {
        continue;
      }
      const double trialMiss = (trialEnd.Point - q).norm();
      if (trialMiss < miss)
      {
        u = trialU;
        s = trialS;
        end = trialEnd;
        w[0] = trialW[0];
        w[1] = trialW[1];
        miss = trialMiss;
        improved = true;
      }
    }
    if (!improved)
    {
      return false;
    }
  }
  return false;
}

void ClassifyConnection(
  const Metric& metric, const Vec3& p, const ConnectOptions& options, ConnectingGeodesic& geodesic)
{
  // Conjugate points to just past q; those within `near` of q are q itself.
  const double near = 1e-6 * std::max(1.0, geodesic.Length);
  GeodesicOptions search = options.Integration;
  search.MaximumLength = geodesic.Length + 2.0 * near;
  const std::vector<ConjugatePoint> points =
    FindConjugatePoints(metric, p, geodesic.Direction, search, 0.1 * near, 0);
  geodesic.MorseIndex = 0;
  geodesic.ConjugateMultiplicity = 0;
  for (const ConjugatePoint& point : points)
  {
    if (point.ArcLength < geodesic.Length - near)
    {
      geodesic.MorseIndex += point.Multiplicity;
    }
    else if (point.ArcLength <= geodesic.Length + near)
    {
      geodesic.ConjugateMultiplicity += point.Multiplicity;
    }
  }
  geodesic.ConjugateMultiplicity = std::min(geodesic.ConjugateMultiplicity, 2);
}

std::vector<ConnectingGeodesic> MergeConnections(
  std::vector<ConnectingGeodesic> found, const ConnectOptions& options)
{
  found.erase(std::remove_if(found.begin(), found.end(),
                [&options](const ConnectingGeodesic& g)
                { return !(g.Length <= options.MaximumLength); }),
    found.end());
  std::sort(found.begin(), found.end(),
    [](const ConnectingGeodesic& a, const ConnectingGeodesic& b) { return a.Length < b.Length; });
  std::vector<ConnectingGeodesic> distinct;
  for (const ConnectingGeodesic& g : found)
  {
    const bool seen = std::any_of(distinct.begin(), distinct.end(),
      [&g](const ConnectingGeodesic& kept)
      {
        // Both directions are g-unit at p: their Euclidean distance in a
        // g-orthonormal frame is the chord of their g-angle; the
        // coordinate difference bounds it within the frame's condition.
        return std::abs(kept.Length - g.Length) < 1e-6 * (1.0 + g.Length) &&
          (kept.Direction - g.Direction).norm() < 1e-6 * kept.Direction.norm();
      });
    if (!seen)
    {
      distinct.push_back(g);
    }
  }
  if (!distinct.empty())
  {
    const double shortest = distinct.front().Length;
    for (ConnectingGeodesic& g : distinct)
    {
      g.Shortest = g.Length - shortest <= options.Tolerance + 1e-9 * shortest;
    }
  }
  return distinct;
}

ConnectionProblem CheckConnection(
  const Metric& metric, const Vec3& p, const Vec3& q, const ConnectOptions& options)
{
  if (!p.allFinite() || !q.allFinite())
  {
    return ConnectionProblem::NotFinite;
  }
  if (!metric.InsideData(p))
  {
    return ConnectionProblem::StartOutsideData;
  }
  if (!metric.InsideData(q))
  {
    return ConnectionProblem::EndOutsideData;
  }
  return (p - q).norm() <= options.Tolerance ? ConnectionProblem::SamePoint : ConnectionProblem::None;
}

std::vector<ConnectingGeodesic> ConnectPoints(
  const Metric& metric, const Vec3& p, const Vec3& q, const ConnectOptions& options)
{
  switch (CheckConnection(metric, p, q, options))
  {
    case ConnectionProblem::NotFinite:
      throw std::invalid_argument("the points must be finite");
    case ConnectionProblem::StartOutsideData:
    case ConnectionProblem::EndOutsideData:
      throw std::invalid_argument("a point is outside the metric's data (geodesics stop there)");
    case ConnectionProblem::SamePoint:
      throw std::invalid_argument("p and q are the same point (within the tolerance)");
    case ConnectionProblem::None:
      break;
  }
  const std::vector<Vec3> directions =
    ShootingDirections(metric, p, q, options.NumberOfDirections);
  if (directions.empty())
  {
    throw std::invalid_argument("the metric is not positive definite at p");
  }
  const std::vector<ConnectionCandidate> candidates = FindConnectionCandidates(
    metric, p, q, directions.data(), directions.size(), options.NumberOfDirections, options);
  std::vector<ConnectingGeodesic> found;
  for (const ConnectionCandidate& candidate : candidates)
  {
    ConnectingGeodesic geodesic;
    if (RefineConnection(metric, p, q, candidate, options, geodesic))
    {
      found.push_back(geodesic);
    }
  }
  std::vector<ConnectingGeodesic> distinct = MergeConnections(std::move(found), options);
  for (ConnectingGeodesic& geodesic : distinct)
  {
    ClassifyConnection(metric, p, options, geodesic);
  }
  return distinct;
}

void TraceConnection(const Metric& metric, const Vec3& p, const ConnectingGeodesic& geodesic,
  const ConnectOptions& options, GeodesicPath& path)
{
  GeodesicOptions trace = options.Integration;
  if (trace.Integrator == IntegratorType::DormandPrince45)
  {
    trace.Tolerance = std::min(trace.Tolerance, RefinementTolerance(options.Tolerance));
  }
  trace.MaximumLength = geodesic.Length;
  TraceGeodesic(metric, p, geodesic.Direction, trace, path);
}
} // namespace riemann
