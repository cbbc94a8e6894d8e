// The old conjugate-point search (LegacyConjugateSearch.h): FindConjugatePoints
// of Common/Metric/JacobiField.cxx at commit 48702d2, step for step, on the
// public API (TraceJacobiFields, ContinueJacobiFields) instead of the old
// file-local integration helpers.
#include "LegacyConjugateSearch.h"

#include "Metric.h"

#include <algorithm>
#include <cmath>

namespace riemann
{
namespace bench
{
namespace
{
/// The sample at arc length s >= from.ArcLength, re-integrated from `from`
/// by RK4 with a number of sub-steps fixed for a search (a smooth function
/// of s): 8 per `interval` (the sample spacing there), at least 8. The old
/// SampleAt; ContinueJacobiFields does the RK4 steps it did itself.
bool SampleAt(
  const Metric& metric, const JacobiSample& from, double s, double interval, JacobiSample& sample)
{
  const int subSteps = std::max(
    8, static_cast<int>(std::ceil(8.0 * (s - from.ArcLength) / std::max(interval, 1e-300) - 1e-9)));
  return ContinueJacobiFields(metric, from, s, subSteps, sample);
}

/// The smallest singular value below which the transverse Jacobian counts as
/// singular: relative to the size of the fields' derivatives, which set the
/// scale of J near a zero.
double RankThreshold(const Metric& metric, const JacobiSample& sample, double tolerance)
{
  const double scale =
    std::sqrt(std::max(0.0, metric.InnerProduct(sample.Point, sample.DJ[0], sample.DJ[0]))) +
    std::sqrt(std::max(0.0, metric.InnerProduct(sample.Point, sample.DJ[1], sample.DJ[1])));
  return std::max(100.0 * tolerance, 1e-6) * scale;
}

/// A sign change of det J in [previous, current]: its zero by bisection to
/// `tolerance`. False when a sample on the way cannot be integrated.
bool BisectDeterminant(const Metric& metric, const JacobiSample& previous,
  const JacobiSample& current, double spacing, double tolerance, JacobiSample& root)
{
  double a = previous.ArcLength;
  double b = current.ArcLength;
  double fa = previous.Determinant;
  JacobiSample middle = current;
  while (b - a > tolerance && current.Determinant != 0.0)
  {
    const double c = 0.5 * (a + b);
    if (!SampleAt(metric, previous, c, spacing, middle))
    {
      return false;
    }
    if (middle.Determinant == 0.0)
    {
      a = b = c;
      break;
    }
    if ((middle.Determinant < 0.0) == (fa < 0.0))
    {
      a = c;
      fa = middle.Determinant;
    }
    else
    {
      b = c;
    }
  }
  return SampleAt(metric, previous, 0.5 * (a + b), spacing, root);
}

/// A touching zero candidate (|det J| dips without a sign change): the
/// golden-section minimum of the smallest singular value over
/// [previous, following], a root when that value is below the rank threshold.
bool MinimiseSingularValue(const Metric& metric, const JacobiSample& previous,
  const JacobiSample& following, double spacing, double tolerance, JacobiSample& root)
{
  constexpr double ratio = 0.6180339887498949;
  double a = previous.ArcLength;
  double b = following.ArcLength;
  JacobiSample left, right;
  double c = b - ratio * (b - a);
  double d = a + ratio * (b - a);
  if (!SampleAt(metric, previous, c, spacing, left) ||
    !SampleAt(metric, previous, d, spacing, right))
  {
    return false;
  }
  while (b - a > tolerance)
  {
    bool ok = true;
    if (left.SingularValues[1] < right.SingularValues[1])
    {
      b = d;
      d = c;
      right = left;
      c = b - ratio * (b - a);
      ok = SampleAt(metric, previous, c, spacing, left);
    }
    else
    {
      a = c;
      c = d;
      left = right;
      d = a + ratio * (b - a);
      ok = SampleAt(metric, previous, d, spacing, right);
    }
    if (!ok)
    {
      return false;
    }
  }
  return SampleAt(metric, previous, 0.5 * (a + b), spacing, root) &&
    root.SingularValues[1] <= RankThreshold(metric, root, tolerance);
}

/// Append `root` as the next conjugate point, unless it is the one just
/// found seen again from the neighbouring interval.
void AddConjugatePoint(const Metric& metric, const JacobiSample& root, double spacing,
  double tolerance, std::vector<ConjugatePoint>& points)
{
  if (!points.empty() && root.ArcLength - points.back().ArcLength < 0.5 * spacing)
  {
    return; // the same conjugate point seen from both neighbouring intervals
  }
  ConjugatePoint point;
  point.ArcLength = root.ArcLength;
  point.Point = root.Point;
  // Rank drop 2 when the other singular value vanishes too. Integration
  // error splits a double zero by about the step's error (1e-6 at RK4 step
  // 0.01 on the unit sphere), while at a simple conjugate point the other
  // singular value is of the size of the fields: compare relative to |DJ|.
  point.Multiplicity = root.SingularValues[0] <=
      1e-3 * RankThreshold(metric, root, tolerance) / std::max(100.0 * tolerance, 1e-6)
    ? 2
    : 1;
  point.Index = static_cast<int>(points.size()) + 1;
  points.push_back(point);
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
} // namespace

// As the old code: trace the Jacobi fields to the end, then over each
// interval of samples BisectDeterminant (a sign change of det J) or
// MinimiseSingularValue (a touching zero), AddConjugatePoint for each root.
std::vector<ConjugatePoint> LegacyFindConjugatePoints(const Metric& metric, const Vec3& p,
  const Vec3& direction, const GeodesicOptions& options, double tolerance, int maximumCount)
{
  std::vector<ConjugatePoint> points;
  JacobiTrace trace;
  TraceJacobiFields(metric, p, direction, options, trace);
  const std::vector<JacobiSample>& samples = trace.Samples;
  tolerance = std::max(tolerance, 1e-14);
  const std::size_t n = samples.size();

  // Sample 0 is the seed (J = 0): start the search at the interval [1, 2].
  for (std::size_t i = 2; i < n; ++i)
  {
    if (maximumCount > 0 && static_cast<int>(points.size()) >= maximumCount)
    {
      break;
    }
    if (!Trustworthy(samples[i]))
    {
      break;
    }
    const JacobiSample& previous = samples[i - 1];
    const JacobiSample& current = samples[i];
    // The sample spacing around the current interval (variable with dp45).
    const double spacing = current.ArcLength - previous.ArcLength;
    const double d0 = previous.Determinant;
    const double d1 = current.Determinant;
    JacobiSample root;
    if (d1 == 0.0 || d0 * d1 < 0.0)
    {
      if (BisectDeterminant(metric, previous, current, spacing, tolerance, root))
      {
        AddConjugatePoint(metric, root, spacing, tolerance, points);
      }
      continue;
    }
    if (i + 1 < n)
    {
      const double d2 = samples[i + 1].Determinant;
      const bool sameSign =
        (d0 > 0.0 && d1 > 0.0 && d2 > 0.0) || (d0 < 0.0 && d1 < 0.0 && d2 < 0.0);
      if (sameSign && std::abs(d1) < std::abs(d0) && std::abs(d1) <= std::abs(d2) &&
        MinimiseSingularValue(metric, previous, samples[i + 1], spacing, tolerance, root))
      {
        AddConjugatePoint(metric, root, spacing, tolerance, points);
      }
    }
  }
  return points;
}
} // namespace bench
} // namespace riemann
