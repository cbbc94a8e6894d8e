#include "JacobiField.h"

#include "Curvature.h"

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

bool RungeKutta4(const Metric& metric, Vec18& y, double h)
{
  Vec18 k1, k2, k3, k4;
  if (!JacobiFlow(metric, y, k1) || !JacobiFlow(metric, y + 0.5 * h * k1, k2) ||
    !JacobiFlow(metric, y + 0.5 * h * k2, k3) || !JacobiFlow(metric, y + h * k3, k4))
  {
    return false;
  }
  y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  return y.allFinite();
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
/// with a fixed number of RK4 sub-steps (a smooth function of s).
bool SampleAt(const Metric& metric, const JacobiSample& from, double s, JacobiSample& sample)
{
  constexpr int subSteps = 8;
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
} // namespace

bool TraceJacobiFields(const Metric& metric, const Vec3& p, const Vec3& direction, double step,
  double length, std::vector<JacobiSample>& samples)
{
  samples.clear();
  if (!(step > 0.0) || !(length >= 0.0) || !std::isfinite(length) || !p.allFinite() ||
    !direction.allFinite())
  {
    return false;
  }
  Mat3 g;
  if (!metric.Tensor(p, g))
  {
    return false;
  }
  const Eigen::LLT<Mat3> llt(g);
  if (!g.allFinite() || llt.info() != Eigen::Success)
  {
    return false;
  }
  const Mat3 ginv = llt.solve(Mat3::Identity());
  Vec3 v0, w0, w1;
  if (!TransverseFrame(g, ginv, std::sqrt(g.determinant()), direction, v0, w0, w1))
  {
    return false;
  }
  Vec18 y;
  y << p, v0, Vec3::Zero(), w0, Vec3::Zero(), w1;
  JacobiSample sample;
  if (!FillSample(metric, 0.0, y, sample))
  {
    return false;
  }
  samples.push_back(sample);
  double s = 0.0;
  while (s < length)
  {
    const double h = std::min(step, length - s);
    if (!RungeKutta4(metric, y, h))
    {
      return false;
    }
    // Land exactly on `length` at the last step.
    s = (length - s <= step) ? length : s + h;
    if (!FillSample(metric, s, y, sample))
    {
      return false;
    }
    samples.push_back(sample);
  }
  return true;
}

std::vector<ConjugatePoint> FindConjugatePoints(const Metric& metric, const Vec3& p,
  const Vec3& direction, double step, double length, double tolerance, int maximumCount)
{
  std::vector<ConjugatePoint> points;
  std::vector<JacobiSample> samples;
  TraceJacobiFields(metric, p, direction, step, length, samples);
  tolerance = std::max(tolerance, 1e-14);
  const std::size_t n = samples.size();

  const auto add = [&](const JacobiSample& root)
  {
    if (!points.empty() && root.ArcLength - points.back().ArcLength < 0.5 * step)
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
  };

  // The search stops where the integration stops being trustworthy: g(v, v)
  // must stay 1 (it drifts, then blows up, where a geodesic runs off through
  // a coordinate singularity, e.g. towards the point at infinity of the
  // stereographic sphere). Conjugate points are not reported beyond.
  const auto trustworthy = [&](const JacobiSample& sample)
  {
    const double speed = metric.InnerProduct(sample.Point, sample.Velocity, sample.Velocity);
    return sample.Point.allFinite() && std::isfinite(speed) && std::abs(speed - 1.0) <= 1e-4;
  };

  // Sample 0 is the seed (J = 0): start the search at the interval [1, 2].
  for (std::size_t i = 2; i < n; ++i)
  {
    if (maximumCount > 0 && static_cast<int>(points.size()) >= maximumCount)
    {
      break;
    }
    if (!trustworthy(samples[i]))
    {
      break;
    }
    const JacobiSample& previous = samples[i - 1];
    const JacobiSample& current = samples[i];
    const double d0 = previous.Determinant;
    const double d1 = current.Determinant;
    if (d1 == 0.0 || d0 * d1 < 0.0)
    {
      // Sign change in [s_{i-1}, s_i]: bisection on the determinant.
      double a = previous.ArcLength;
      double b = current.ArcLength;
      double fa = d0;
      JacobiSample middle = current;
      bool ok = true;
      while (b - a > tolerance && d1 != 0.0)
      {
        const double c = 0.5 * (a + b);
        if (!SampleAt(metric, previous, c, middle))
        {
          ok = false;
          break;
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
      JacobiSample root;
      if (ok && SampleAt(metric, previous, 0.5 * (a + b), root))
      {
        add(root);
      }
      continue;
    }
    if (i + 1 < n)
    {
      const double d2 = samples[i + 1].Determinant;
      const bool sameSign =
        (d0 > 0.0 && d1 > 0.0 && d2 > 0.0) || (d0 < 0.0 && d1 < 0.0 && d2 < 0.0);
      if (sameSign && std::abs(d1) < std::abs(d0) && std::abs(d1) <= std::abs(d2))
      {
        // Touching zero candidate: golden-section minimum of the smallest
        // singular value over [s_{i-1}, s_{i+1}].
        constexpr double ratio = 0.6180339887498949;
        double a = previous.ArcLength;
        double b = samples[i + 1].ArcLength;
        JacobiSample left, right;
        double c = b - ratio * (b - a);
        double d = a + ratio * (b - a);
        if (!SampleAt(metric, previous, c, left) || !SampleAt(metric, previous, d, right))
        {
          continue;
        }
        bool ok = true;
        while (b - a > tolerance)
        {
          if (left.SingularValues[1] < right.SingularValues[1])
          {
            b = d;
            d = c;
            right = left;
            c = b - ratio * (b - a);
            ok = SampleAt(metric, previous, c, left);
          }
          else
          {
            a = c;
            c = d;
            left = right;
            d = a + ratio * (b - a);
            ok = SampleAt(metric, previous, d, right);
          }
          if (!ok)
          {
            break;
          }
        }
        JacobiSample root;
        if (ok && SampleAt(metric, previous, 0.5 * (a + b), root) &&
          root.SingularValues[1] <= RankThreshold(metric, root, tolerance))
        {
          add(root);
        }
      }
    }
  }
  return points;
}
} // namespace riemann
