#include "ConjugatePoints.h"

#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace riemann
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

/// The largest move of a phase between two samples that are compared: small
/// enough that matching the phases of the two samples is unambiguous where
/// it matters and that no phase can wind past pi unseen (file comment).
constexpr double LargestPhaseMove = 0.25 * Pi;

/// Interval splits before the search gives up on a geodesic (a phase that
/// keeps moving fast however short the interval: a singular metric).
constexpr int MaximumSplitDepth = 40;

/// x in (-pi, pi].
double Wrap(double x)
{
  x = std::remainder(x, 2.0 * Pi);
  return x <= -Pi ? x + 2.0 * Pi : x;
}

/// A phase's signed angle before the next crossing of pi: > 0 before it,
/// 0 at a conjugate point, < 0 just after (the phases decrease through pi).
double BeforeCrossing(double phase)
{
  return Wrap(phase + Pi);
}

/**
 * The phases of `from` (as BeforeCrossing) and where each went at `to`,
 * continuously: To[k] = From[k] + its move, matching each phase of `to` with
 * one of `from` so that the largest move is the smaller; both sorted by From.
 * When both matchings move little they give the same crossings, so which one
 * is chosen does not change the count (a near tie only happens when the two
 * phases are close).
 */
struct PhaseMoves
{
  std::array<double, 2> From;
  std::array<double, 2> To;
  double LargestMove;
};

PhaseMoves MovePhases(const JacobiSample& from, const JacobiSample& to)
{
  const std::array<double, 2> a = { BeforeCrossing(from.Phases[0]),
    BeforeCrossing(from.Phases[1]) };
  const std::array<double, 2> b = { BeforeCrossing(to.Phases[0]), BeforeCrossing(to.Phases[1]) };
  const std::array<double, 2> straight = { Wrap(b[0] - a[0]), Wrap(b[1] - a[1]) };
  const std::array<double, 2> swapped = { Wrap(b[1] - a[0]), Wrap(b[0] - a[1]) };
  const double straightLargest = std::max(std::abs(straight[0]), std::abs(straight[1]));
  const double swappedLargest = std::max(std::abs(swapped[0]), std::abs(swapped[1]));
  const std::array<double, 2>& move = straightLargest <= swappedLargest ? straight : swapped;
  PhaseMoves moves;
  moves.LargestMove = std::min(straightLargest, swappedLargest);
  const int low = a[0] <= a[1] ? 0 : 1;
  moves.From = { a[low], a[1 - low] };
  moves.To = { a[low] + move[low], a[1 - low] + move[1 - low] };
  return moves;
}

/// Phase `rank` (in the order of MovePhases) at `to`, seen from `from`.
double MovedPhase(const JacobiSample& from, const JacobiSample& to, int rank)
{
  return MovePhases(from, to).To[rank];
}

// The search stops where the integration stops being trustworthy: g(v, v)
// must stay 1 (it drifts, then blows up, where a geodesic runs off through
// a coordinate singularity, e.g. towards the point at infinity of the
// stereographic sphere). Conjugate points are not reported beyond.
bool Trustworthy(const JacobiSample& sample)
{
  return sample.Point.allFinite() && std::isfinite(sample.SpeedDrift) &&
    std::abs(sample.SpeedDrift) <= 1e-4;
}

/**
 * The search along one geodesic, fed the trace's samples one by one
 * (Visit), as the list of named steps of ConjugatePoints.h's file comment:
 * ScanInterval (match, split, count), RefineCrossing (Illinois), then
 * MergeCrossings (multiplicity, index, sheet).
 */
class ConjugateSearch
{
public:
  ConjugateSearch(const Metric& metric, double tolerance, int maximumCount)
    : M(metric)
    , Tolerance(tolerance)
    , MaximumCount(maximumCount)
  {
  }

  /// The trace's next sample; false to stop the trace.
  bool Visit(const JacobiSample& sample)
  {
    if (!this->HaveSeed)
    {
      this->Seed = sample;
      // W = -I exactly at the seed: both phases at pi, not "just before" it.
      this->Seed.Phases[0] = this->Seed.Phases[1] = Pi;
      this->Previous = this->Seed;
      this->HaveSeed = true;
      return true;
    }
    if (!Trustworthy(sample))
    {
      return false;
    }
    const double spacing = sample.ArcLength - this->Previous.ArcLength;
    if (!this->ScanInterval(this->Previous, sample, spacing, 0))
    {
      return false;
    }
    this->Previous = sample;
    return !this->FoundEnough(sample.ArcLength);
  }

  /// The conjugate points found, crossings closer than the tolerance merged.
  std::vector<ConjugatePoint> Points() const
  {
    std::vector<ConjugatePoint> points = this->MergeCrossings();
    if (this->MaximumCount > 0 && static_cast<int>(points.size()) > this->MaximumCount)
    {
      points.resize(static_cast<size_t>(this->MaximumCount));
    }
    return points;
  }

private:
  /// Count and refine the crossings in [a, b], splitting it while a phase
  /// moves by more than LargestPhaseMove. False to stop the search.
  bool ScanInterval(const JacobiSample& a, const JacobiSample& b, double spacing, int depth)
  {
    const PhaseMoves moves = MovePhases(a, b);
    if (moves.LargestMove > LargestPhaseMove)
    {
      JacobiSample middle;
      if (depth >= MaximumSplitDepth ||
        !this->Continue(a, 0.5 * (a.ArcLength + b.ArcLength), spacing, middle))
      {
        return false;
      }
      return this->ScanInterval(a, middle, spacing, depth + 1) &&
        this->ScanInterval(middle, b, spacing, depth + 1);
    }
    // The lower phase crosses first: ranks in order give crossings in order.
    for (int rank = 0; rank < 2; ++rank)
    {
      if (moves.From[rank] > 0.0 && moves.To[rank] <= 0.0)
      {
        JacobiSample root;
        if (!this->RefineCrossing(a, b, rank, moves.From[rank], moves.To[rank], spacing, root))
        {
          return false;
        }
        this->Crossings.push_back(root);
      }
    }
    return true;
  }

  /**
   * The arc length in [a, b] where phase `rank` crosses pi, by the Illinois
   * method on its BeforeCrossing value f (f(a) = before > 0 >= f(b) =
   * after; f decreases at speed 2 there).
   */
  bool RefineCrossing(const JacobiSample& a, const JacobiSample& b, int rank, double before,
    double after, double spacing, JacobiSample& root) const
  {
    root = b;
    if (after == 0.0)
    {
      return true;
    }
    double lo = a.ArcLength;
    double hi = b.ArcLength;
    double fLo = before;
    double fHi = after;
    int retained = 0; // -1: lo was kept twice in a row, +1: hi
    for (int iteration = 0; iteration < 200 && hi - lo > this->Tolerance; ++iteration)
    {
      double s = lo + (hi - lo) * fLo / (fLo - fHi);
      if (!(s > lo && s < hi))
      {
        s = 0.5 * (lo + hi);
      }
      JacobiSample trial;
      if (!this->Continue(a, s, spacing, trial))
      {
        return false;
      }
      const double f = MovedPhase(a, trial, rank);
      root = trial;
      if (std::abs(f) <= 0.2 * this->Tolerance)
      {
        return true;
      }
      if (f > 0.0)
      {
        lo = s;
        fLo = f;
        fHi = retained == 1 ? 0.5 * fHi : fHi;
        retained = 1;
      }
      else
      {
        hi = s;
        fHi = f;
        fLo = retained == -1 ? 0.5 * fLo : fLo;
        retained = -1;
      }
    }
    return true;
  }

  /// The fields at s from the sample `from` (8 RK4 steps per trace interval).
  bool Continue(const JacobiSample& from, double s, double spacing, JacobiSample& sample) const
  {
    const int subSteps = std::max(8,
      static_cast<int>(std::ceil(8.0 * (s - from.ArcLength) / std::max(spacing, 1e-300) - 1e-9)));
    return ContinueJacobiFields(this->M, from, s, subSteps, sample, true);
  }

  /// Enough points found (and the last one cannot merge with a later crossing).
  bool FoundEnough(double arcLength) const
  {
    return this->MaximumCount > 0 && !this->Crossings.empty() &&
      arcLength > this->Crossings.back().ArcLength + this->Tolerance &&
      this->CountPoints() >= this->MaximumCount;
  }

  /// How many points MergeCrossings makes, without making them (it runs
  /// after every sample once crossings are found).
  int CountPoints() const
  {
    int count = 0;
    for (size_t i = 0; i < this->Crossings.size(); ++i, ++count)
    {
      if (i + 1 < this->Crossings.size() && this->Merges(i))
      {
        ++i;
      }
    }
    return count;
  }

  /// Crossing i and the next are one point of multiplicity 2.
  bool Merges(size_t i) const
  {
    return this->Crossings[i + 1].ArcLength - this->Crossings[i].ArcLength <= this->Tolerance;
  }

  /// Crossings closer than the tolerance are one point of multiplicity 2.
  std::vector<ConjugatePoint> MergeCrossings() const
  {
    std::vector<ConjugatePoint> points;
    int sheet = 1;
    for (size_t i = 0; i < this->Crossings.size(); ++i)
    {
      const JacobiSample& root = this->Crossings[i];
      ConjugatePoint point;
      point.Index = static_cast<int>(points.size()) + 1;
      point.Sheet = sheet;
      if (i + 1 < this->Crossings.size() && this->Merges(i))
      {
        const JacobiSample& next = this->Crossings[i + 1];
        point.ArcLength = 0.5 * (root.ArcLength + next.ArcLength);
        point.Point = 0.5 * (root.Point + next.Point);
        point.Multiplicity = 2;
        ++i;
      }
      else
      {
        point.ArcLength = root.ArcLength;
        point.Point = root.Point;
        point.KernelDirection = this->KernelDirection(root);
      }
      sheet += point.Multiplicity;
      points.push_back(point);
    }
    return points;
  }

  /// The initial variation whose Jacobi field vanishes at `root`: the left
  /// null vector c of Transverse (sum_a c_a J_a = 0 there), as sum_a c_a DJ_a(0).
  Vec3 KernelDirection(const JacobiSample& root) const
  {
    Eigen::Matrix2d transverse;
    transverse << root.Transverse[0][0], root.Transverse[0][1], root.Transverse[1][0],
      root.Transverse[1][1];
    const Eigen::JacobiSVD<Eigen::Matrix2d> svd(transverse, Eigen::ComputeFullU);
    const Eigen::Vector2d c = svd.matrixU().col(1);
    return c[0] * this->Seed.DJ[0] + c[1] * this->Seed.DJ[1];
  }

  const Metric& M;
  double Tolerance;
  int MaximumCount;
  bool HaveSeed = false;
  JacobiSample Seed;
  JacobiSample Previous;
  /// Every phase crossing found, in order of arc length.
  std::vector<JacobiSample> Crossings;
};

/// One ConjugateSearch per lane of the packet Jacobi trace.
class PacketSearch : public JacobiVisitor
{
public:
  PacketSearch(
    const Metric& metric, double tolerance, int maximumCount, std::vector<ConjugatePoint>* found)
    : M(metric)
    , Tolerance(tolerance)
    , MaximumCount(maximumCount)
    , Found(found)
  {
  }
  void Start(int lane, std::size_t) override
  {
    this->Searches[lane].emplace(this->M, this->Tolerance, this->MaximumCount);
  }
  bool Visit(int lane, std::size_t, const JacobiSample& sample) override
  {
    return this->Searches[lane]->Visit(sample);
  }
  void End(int lane, std::size_t trace, int) override
  {
    this->Found[trace] = this->Searches[lane]->Points();
    this->Searches[lane].reset();
  }

private:
  const Metric& M;
  double Tolerance;
  int MaximumCount;
  std::vector<ConjugatePoint>* Found;
  std::optional<ConjugateSearch> Searches[PacketWidth];
};

/// The options the search integrates with: dp45's tolerance follows the search's.
GeodesicOptions SearchOptions(const GeodesicOptions& options, double tolerance)
{
  GeodesicOptions searchOptions = options;
  if (searchOptions.Integrator == IntegratorType::DormandPrince45)
  {
    searchOptions.Tolerance =
      std::min(searchOptions.Tolerance, ConjugateIntegrationTolerance(tolerance));
  }
  return searchOptions;
}
} // namespace

double ConjugateIntegrationTolerance(double tolerance)
{
  return 0.01 * tolerance;
}

std::vector<ConjugatePoint> FindConjugatePoints(const Metric& metric, const Vec3& p,
  const Vec3& direction, const GeodesicOptions& options, double tolerance, int maximumCount)
{
  tolerance = std::max(tolerance, 1e-14);
  ConjugateSearch search(metric, tolerance, maximumCount);
  TraceJacobiFields(metric, p, direction, SearchOptions(options, tolerance), false, {}, true,
    [&search](const JacobiSample& sample) { return search.Visit(sample); });
  return search.Points();
}

void FindConjugatePoints(const Metric& metric, const Vec3& p, const Vec3* directions,
  std::size_t count, const GeodesicOptions& options, double tolerance, int maximumCount,
  std::vector<ConjugatePoint>* found)
{
  tolerance = std::max(tolerance, 1e-14);
  std::vector<JacobiSeed> seeds(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    seeds[i].Point = p;
    seeds[i].Direction = directions[i];
    found[i].clear();
  }
  PacketSearch search(metric, tolerance, maximumCount, found);
  TraceJacobiFields(
    metric, seeds.data(), count, SearchOptions(options, tolerance), {}, true, search);
}

std::vector<ConjugatePoint> FindConjugatePoints(const Metric& metric, const Vec3& p,
  const Vec3& direction, double step, double length, double tolerance, int maximumCount)
{
  if (!(step > 0.0) || !(length >= 0.0) || !std::isfinite(length))
  {
    return {};
  }
  GeodesicOptions options;
  options.Integrator = IntegratorType::RungeKutta4;
  options.Step = step;
  options.MaximumLength = length;
  options.MaximumSteps = static_cast<long long>(std::ceil(length / step)) + 2;
  return FindConjugatePoints(metric, p, direction, options, tolerance, maximumCount);
}
} // namespace riemann
