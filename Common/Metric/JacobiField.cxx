#include "JacobiField.h"

#include "Curvature.h"
#include "RungeKutta.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

namespace riemann
{
namespace
{
/// (x, v, X_0, V_0, X_1, V_1).
using Vec18 = Eigen::Matrix<double, 18, 1>;

/// The geodesic flow and its linearisation at y.
bool JacobiFlow(const Metric& metric, const Vec18& y, Vec18& dy)
{
  Mat3 g;
  Mat3 ginv;
  Mat3Stack gamma;
  std::array<Mat3Stack, 3> dGamma;
  const Vec3 x = y.segment<3>(0);
  const Vec3 v = y.segment<3>(3);
  if (!ChristoffelAndDerivatives(metric, x, g, ginv, gamma, dGamma))
  {
    return false;
  }
  dy.segment<3>(0) = v;
  for (int m = 0; m < 3; ++m)
  {
    dy[3 + m] = -v.dot(gamma[m] * v);
  }
  for (int a = 0; a < 2; ++a)
  {
    const Vec3 bigX = y.segment<3>(6 + 6 * a);
    const Vec3 bigV = y.segment<3>(9 + 6 * a);
    dy.segment<3>(6 + 6 * a) = bigV;
    for (int m = 0; m < 3; ++m)
    {
      // (d_X Gamma)^m_ij v^i v^j + 2 Gamma^m_ij v^i V^j (Gamma symmetric).
      const Mat3 dX = bigX[0] * dGamma[0][m] + bigX[1] * dGamma[1][m] + bigX[2] * dGamma[2][m];
      dy[9 + 6 * a + m] = -v.dot(dX * v) - 2.0 * v.dot(gamma[m] * bigV);
    }
  }
  return dy.allFinite();
}

/// The Jacobi system as a flow for RungeKutta.h's steppers.
struct JacobiSystem
{
  const Metric& M;
  bool operator()(const Vec18& y, Vec18& dy) const { return JacobiFlow(this->M, y, dy); }
};

bool RungeKutta4(const Metric& metric, Vec18& y, double h)
{
  return RungeKutta4StepOf(JacobiSystem{ metric }, y, h) && y.allFinite();
}

/// g-orthonormal, positively oriented (e0, e1, vhat) at a point (file comment of JacobiField.h).
bool TransverseFrame(
  const Mat3& g, const Mat3& ginv, double volume, const Vec3& v, Vec3& vhat, Vec3& e0, Vec3& e1)
{
  const double speed = std::sqrt(v.dot(g * v));
  if (!(speed > 0.0) || !std::isfinite(speed))
  {
    return false;
  }
  vhat = v / speed;
  int best = 0;
  double bestAlignment = HUGE_VAL;
  for (int k = 0; k < 3; ++k)
  {
    const double alignment = std::abs((g * vhat)[k]) / std::sqrt(g(k, k));
    if (alignment < bestAlignment)
    {
      bestAlignment = alignment;
      best = k;
    }
  }
  e0 = Vec3::Unit(best);
  e0 -= e0.dot(g * vhat) * vhat;
  const double norm = std::sqrt(e0.dot(g * e0));
  if (!(norm > 0.0))
  {
    return false;
  }
  e0 /= norm;
  e1 = volume * (ginv * vhat.cross(e0));
  return e1.allFinite();
}

bool FillSample(const Metric& metric, double s, const Vec18& y, JacobiSample& sample)
{
  sample.ArcLength = s;
  sample.Point = y.segment<3>(0);
  sample.Velocity = y.segment<3>(3);
  sample.J[0] = y.segment<3>(6);
  sample.DJ[0] = y.segment<3>(9);
  sample.J[1] = y.segment<3>(12);
  sample.DJ[1] = y.segment<3>(15);
  Mat3 g;
  if (!metric.Tensor(sample.Point, g))
  {
    return false;
  }
  const Eigen::LLT<Mat3> llt(g);
  if (!g.allFinite() || llt.info() != Eigen::Success)
  {
    return false;
  }
  const Mat3 ginv = llt.solve(Mat3::Identity());
  const double volume = std::sqrt(g.determinant());
  sample.SpeedDrift = sample.Velocity.dot(g * sample.Velocity) - 1.0;
  Vec3 vhat, e0, e1;
  if (!TransverseFrame(g, ginv, volume, sample.Velocity, vhat, e0, e1))
  {
    return false;
  }
  Eigen::Matrix2d t;
  for (int a = 0; a < 2; ++a)
  {
    t(a, 0) = sample.J[a].dot(g * e0);
    t(a, 1) = sample.J[a].dot(g * e1);
    sample.Transverse[a][0] = t(a, 0);
    sample.Transverse[a][1] = t(a, 1);
  }
  Mat3 columns;
  columns << sample.J[0], sample.J[1], vhat;
  sample.Determinant = volume * columns.determinant();
  const Eigen::JacobiSVD<Eigen::Matrix2d> svd(t);
  sample.SingularValues[0] = svd.singularValues()[0];
  sample.SingularValues[1] = svd.singularValues()[1];
  return std::isfinite(sample.Determinant);
}

Vec18 StateOf(const JacobiSample& sample)
{
  Vec18 y;
  y << sample.Point, sample.Velocity, sample.J[0], sample.DJ[0], sample.J[1], sample.DJ[1];
  return y;
}

/// The sample at arc length s >= from.ArcLength, re-integrated from `from`
/// by RK4 with a number of sub-steps fixed for a search (a smooth function
/// of s): 8 per `interval` (the sample spacing there), at least 8.
bool SampleAt(
  const Metric& metric, const JacobiSample& from, double s, double interval, JacobiSample& sample)
{
  const int subSteps = std::max(8,
    static_cast<int>(std::ceil(8.0 * (s - from.ArcLength) / std::max(interval, 1e-300) - 1e-9)));
  Vec18 y = StateOf(from);
  const double h = (s - from.ArcLength) / subSteps;
  if (h != 0.0)
  {
    for (int i = 0; i < subSteps; ++i)
    {
      if (!RungeKutta4(metric, y, h))
      {
        return false;
      }
    }
  }
  return FillSample(metric, s, y, sample);
}

double RankThreshold(const Metric& metric, const JacobiSample& sample, double tolerance)
{
  const double scale =
    std::sqrt(std::max(0.0, metric.InnerProduct(sample.Point, sample.DJ[0], sample.DJ[0]))) +
    std::sqrt(std::max(0.0, metric.InnerProduct(sample.Point, sample.DJ[1], sample.DJ[1])));
  return std::max(100.0 * tolerance, 1e-6) * scale;
}

/// TraceJacobiFields' first step: the state (x, v, J0, J0', J1, J1') at the
/// seed: v the unit-speed direction, J = 0 and J' an orthonormal transverse
/// frame. False, with `reason` DegenerateMetric, where g is not a metric
/// (`reason` unchanged for a zero direction).
bool InitialState(const Metric& metric, const Vec3& p, const Vec3& direction, Vec18& y, int& reason)
{
  Mat3 g;
  if (!metric.Tensor(p, g))
  {
    reason = DegenerateMetric;
    return false;
  }
  const Eigen::LLT<Mat3> llt(g);
  if (!g.allFinite() || llt.info() != Eigen::Success)
  {
    reason = DegenerateMetric;
    return false;
  }
  const Mat3 ginv = llt.solve(Mat3::Identity());
  Vec3 v0, w0, w1;
  if (!TransverseFrame(g, ginv, std::sqrt(g.determinant()), direction, v0, w0, w1))
  {
    return false; // zero direction
  }
  y << p, v0, Vec3::Zero(), w0, Vec3::Zero(), w1;
  return true;
}

/// The arc lengths strictly inside (0, length) that the trace must land on, sorted.
std::vector<double> LandingStops(const std::vector<double>& landings, double length)
{
  std::vector<double> stops;
  for (double landing : landings)
  {
    if (landing > 0.0 && landing < length)
    {
      stops.push_back(landing);
    }
  }
  std::sort(stops.begin(), stops.end());
  return stops;
}
} // namespace

void TraceJacobiFields(const Metric& metric, const Vec3& p, const Vec3& direction,
  const GeodesicOptions& options, JacobiTrace& trace, bool backward,
  const std::vector<double>& landings)
{
  trace.Samples.clear();
  trace.Reason = NotInitialized;
  if (!p.allFinite() || !direction.allFinite() || !(options.Step > 0.0) ||
    !(options.MaximumLength >= 0.0) || std::isnan(options.MaximumLength))
  {
    return;
  }
  Vec18 y;
  if (!InitialState(metric, p, backward ? Vec3(-direction) : direction, y, trace.Reason))
  {
    return;
  }
  const double sign = backward ? -1.0 : 1.0;
  JacobiSample sample;
  double s = 0.0;
  const auto record = [&]() -> bool
  {
    if (!FillSample(metric, sign * s, y, sample))
    {
      return false;
    }
    trace.Samples.push_back(sample);
    return true;
  };
  record();
  const auto inside = [&](const Vec3& x)
  {
    return !options.UseBounds ||
      (x[0] >= options.Bounds[0] && x[0] <= options.Bounds[1] && x[1] >= options.Bounds[2] &&
        x[1] <= options.Bounds[3] && x[2] >= options.Bounds[4] && x[2] <= options.Bounds[5]);
  };
  if (!inside(p))
  {
    trace.Reason = OutOfDomain;
    return;
  }

  const std::vector<double> stops = LandingStops(landings, options.MaximumLength);
  std::size_t nextStop = 0;

  FlowStepper<Vec18> stepper(options.Integrator, options.Step, options.Tolerance,
    options.MinimumStep, options.MaximumStep);
  const JacobiSystem system{ metric };
  // Steps shorter than this (relative to the length) count as arriving
  // (TraceGeodesic's rule).
  const double arrival = 1e-12 * std::max(1.0, options.MaximumLength);
  for (long long n = 0;; ++n)
  {
    while (nextStop < stops.size() && stops[nextStop] - s <= arrival)
    {
      ++nextStop;
    }
    const double target = nextStop < stops.size() ? stops[nextStop] : options.MaximumLength;
    const double remaining = target - s;
    if (options.MaximumLength - s <= arrival)
    {
      trace.Reason = OutOfLength;
      return;
    }
    if (n >= options.MaximumSteps)
    {
      trace.Reason = OutOfSteps;
      return;
    }
    double taken = 0.0;
    const auto status = stepper.Advance(system, y, remaining, taken);
    if (status != IntegrationStep::Accepted)
    {
      trace.Reason = status == IntegrationStep::StepTooSmall ? Stagnation : DegenerateMetric;
      return;
    }
    if (!y.allFinite())
    {
      trace.Reason = UnexpectedValue;
      return;
    }
    // Land exactly on a landing or on the length (no rounding drift).
    s = (remaining - taken <= arrival) ? target : s + taken;
    if (!record())
    {
      // The step landed where g is degenerate: not a point of the manifold.
      trace.Reason = DegenerateMetric;
      return;
    }
    if (!inside(y.segment<3>(0)))
    {
      trace.Reason = OutOfDomain;
      return;
    }
  }
}

bool TraceJacobiFields(const Metric& metric, const Vec3& p, const Vec3& direction, double step,
  double length, std::vector<JacobiSample>& samples)
{
  samples.clear();
  if (!(step > 0.0) || !(length >= 0.0) || !std::isfinite(length))
  {
    return false;
  }
  GeodesicOptions options;
  options.Integrator = IntegratorType::RungeKutta4;
  options.Step = step;
  options.MaximumLength = length;
  options.MaximumSteps = static_cast<long long>(std::ceil(length / step)) + 2;
  JacobiTrace trace;
  TraceJacobiFields(metric, p, direction, options, trace);
  samples = std::move(trace.Samples);
  return trace.Reason == OutOfLength;
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

namespace
{
// FindConjugatePoints' steps: the two root searches on an interval of the
// traced samples, and the record of a root found.

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

// FindConjugatePoints as named steps: trace the Jacobi fields, then over
// each interval of samples BisectDeterminant (a sign change of det J) or
// MinimiseSingularValue (a touching zero), AddConjugatePoint for each root.
std::vector<ConjugatePoint> FindConjugatePoints(const Metric& metric, const Vec3& p,
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
} // namespace riemann
