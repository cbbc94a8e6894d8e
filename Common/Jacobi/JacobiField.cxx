#include "JacobiField.h"
#include "JacobiFieldInternals.h"

#include "Curvature.h"
#include "RungeKutta.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <complex>

namespace riemann
{
namespace
{
/// The geodesic flow and its linearisation at y.
bool JacobiFlow(const Metric& metric, const Vec18& y, Vec18& dy)
{
  const Vec3 fields[2] = { y.segment<3>(6), y.segment<3>(12) };
  const Vec3 derivatives[2] = { y.segment<3>(9), y.segment<3>(15) };
  Vec3 a;
  Vec3 variations[2];
  if (!JacobiAccelerations(
        metric, y.segment<3>(0), y.segment<3>(3), fields, derivatives, a, variations))
  {
    return false;
  }
  dy << y.segment<3>(3), a, derivatives[0], variations[0], derivatives[1], variations[1];
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

/**
 * sample.Phases: the eigenvalue angles of W = (X + iY)(X - iY)^-1 (file
 * comment of JacobiField.h), X and Y the fields and their covariant
 * derivatives in the frame (e0, e1), columns = fields.
 */
bool MaslovPhases(
  const Metric& metric, const Mat3& g, const Vec3& e0, const Vec3& e1, JacobiSample& sample)
{
  Mat3Stack gamma;
  if (!metric.Christoffel(sample.Point, gamma))
  {
    return false;
  }
  // [X; Y] as a 4x2 real matrix; its columns are orthonormalised first (W
  // depends only on the plane they span): keeps W accurate where the fields
  // grow or shrink a lot.
  Eigen::Matrix<double, 4, 2> frame;
  for (int a = 0; a < 2; ++a)
  {
    Vec3 covariant = sample.DJ[a];
    for (int m = 0; m < 3; ++m)
    {
      covariant[m] += sample.Velocity.dot(gamma[m] * sample.J[a]);
    }
    frame(0, a) = sample.J[a].dot(g * e0);
    frame(1, a) = sample.J[a].dot(g * e1);
    frame(2, a) = covariant.dot(g * e0);
    frame(3, a) = covariant.dot(g * e1);
  }
  const Eigen::HouseholderQR<Eigen::Matrix<double, 4, 2>> qr(frame);
  const Eigen::Matrix<double, 4, 2> q = qr.householderQ() * Eigen::Matrix<double, 4, 2>::Identity();
  using Complex = std::complex<double>;
  Eigen::Matrix2cd plus, minus;
  for (int r = 0; r < 2; ++r)
  {
    for (int c = 0; c < 2; ++c)
    {
      plus(r, c) = Complex(q(r, c), q(2 + r, c));
      minus(r, c) = Complex(q(r, c), -q(2 + r, c));
    }
  }
  const Eigen::Matrix2cd w = plus * minus.inverse();
  // Eigenvalues of the 2x2 matrix without cancellation near a double
  // eigenvalue (a round sphere's W is a multiple of I): the discriminant is
  // ((w00 - w11) / 2)^2 + w01 w10, not tr^2 / 4 - det.
  const Complex half = 0.5 * (w(0, 0) + w(1, 1));
  const Complex gap = 0.5 * (w(0, 0) - w(1, 1));
  const Complex root = std::sqrt(gap * gap + w(0, 1) * w(1, 0));
  sample.Phases[0] = std::arg(half + root);
  sample.Phases[1] = std::arg(half - root);
  return std::isfinite(sample.Phases[0]) && std::isfinite(sample.Phases[1]);
}

Vec18 StateOf(const JacobiSample& sample)
{
  Vec18 y;
  y << sample.Point, sample.Velocity, sample.J[0], sample.DJ[0], sample.J[1], sample.DJ[1];
  return y;
}

} // namespace

namespace jacobi_detail
{
/// The sample of state y at arc length s; with `withPhases`, its Maslov phases too.
bool FillSample(
  const Metric& metric, double s, const Vec18& y, JacobiSample& sample, bool withPhases)
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
  return std::isfinite(sample.Determinant) &&
    (!withPhases || MaslovPhases(metric, g, e0, e1, sample));
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
} // namespace jacobi_detail

bool JacobiAccelerations(const Metric& metric, const Vec3& x, const Vec3& v, const Vec3 (&j)[2],
  const Vec3 (&dj)[2], Vec3& a, Vec3 (&variations)[2])
{
  Mat3 g;
  Mat3 ginv;
  Mat3Stack gamma;
  std::array<Mat3Stack, 3> dGamma;
  if (!ChristoffelAndDerivatives(metric, x, g, ginv, gamma, dGamma))
  {
    return false;
  }
  for (int m = 0; m < 3; ++m)
  {
    a[m] = -v.dot(gamma[m] * v);
  }
  for (int k = 0; k < 2; ++k)
  {
    for (int m = 0; m < 3; ++m)
    {
      // (d_X Gamma)^m_ij v^i v^j + 2 Gamma^m_ij v^i V^j (Gamma symmetric).
      const Mat3 dX = j[k][0] * dGamma[0][m] + j[k][1] * dGamma[1][m] + j[k][2] * dGamma[2][m];
      variations[k][m] = -v.dot(dX * v) - 2.0 * v.dot(gamma[m] * dj[k]);
    }
  }
  return a.allFinite() && variations[0].allFinite() && variations[1].allFinite();
}

int TraceJacobiFields(const Metric& metric, const Vec3& p, const Vec3& direction,
  const GeodesicOptions& options, bool backward, const std::vector<double>& landings,
  bool withPhases, const std::function<bool(const JacobiSample&)>& visit)
{
  if (!p.allFinite() || !direction.allFinite() || !(options.Step > 0.0) ||
    !(options.MaximumLength >= 0.0) || std::isnan(options.MaximumLength))
  {
    return NotInitialized;
  }
  Vec18 y;
  int reason = NotInitialized;
  if (!jacobi_detail::InitialState(metric, p, backward ? Vec3(-direction) : direction, y, reason))
  {
    return reason;
  }
  const double sign = backward ? -1.0 : 1.0;
  JacobiSample sample;
  double s = 0.0;
  constexpr int stoppedByVisitor = 0;
  // The sample at s; false when g is degenerate there.
  const auto fill = [&]() -> bool
  { return jacobi_detail::FillSample(metric, sign * s, y, sample, withPhases); };
  if (fill() && !visit(sample))
  {
    return stoppedByVisitor;
  }
  if (const int stop = ReasonToStopAt(metric, options, p))
  {
    return stop;
  }

  const std::vector<double> stops = jacobi_detail::LandingStops(landings, options.MaximumLength);
  std::size_t nextStop = 0;

  FlowStepper<Vec18> stepper(
    options.Integrator, options.Step, options.Tolerance, options.MinimumStep, options.MaximumStep);
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
      return OutOfLength;
    }
    if (n >= options.MaximumSteps)
    {
      return OutOfSteps;
    }
    double taken = 0.0;
    const auto status = stepper.Advance(system, y, remaining, taken);
    if (status != IntegrationStep::Accepted)
    {
      return status == IntegrationStep::StepTooSmall ? Stagnation : DegenerateMetric;
    }
    if (!y.allFinite())
    {
      return UnexpectedValue;
    }
    // Land exactly on a landing or on the length (no rounding drift).
    s = (remaining - taken <= arrival) ? target : s + taken;
    if (!fill())
    {
      // The step landed where g is degenerate: not a point of the manifold.
      return DegenerateMetric;
    }
    if (!visit(sample))
    {
      return stoppedByVisitor;
    }
    if (const int stop = ReasonToStopAt(metric, options, y.segment<3>(0)))
    {
      return stop;
    }
  }
}

void TraceJacobiFields(const Metric& metric, const Vec3& p, const Vec3& direction,
  const GeodesicOptions& options, JacobiTrace& trace, bool backward,
  const std::vector<double>& landings)
{
  trace.Samples.clear();
  trace.Reason = TraceJacobiFields(metric, p, direction, options, backward, landings, false,
    [&trace](const JacobiSample& sample)
    {
      trace.Samples.push_back(sample);
      return true;
    });
}

bool ContinueJacobiFields(const Metric& metric, const JacobiSample& from, double s, int subSteps,
  JacobiSample& sample, bool withPhases)
{
  if (!(s >= from.ArcLength) || subSteps < 1)
  {
    return false;
  }
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
  return jacobi_detail::FillSample(metric, s, y, sample, withPhases);
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

} // namespace riemann
