#include "CameraPath.h"

#include "RungeKutta.h"

#include <unsupported/Eigen/Splines>

#include <algorithm>
#include <cmath>

namespace riemann
{
namespace
{
using Spline3 = Eigen::Spline<double, 3>;

/// A path's state: its own (position and velocity, or spline parameter),
/// then the transported up and right.
template <int N>
using PathState = Eigen::Matrix<double, N, 1>;

/// Gamma(a, b)^m = Gamma^m_ij a^i b^j.
Vec3 Contract(const Mat3Stack& gamma, const Vec3& a, const Vec3& b)
{
  return Vec3(a.dot(gamma[0] * b), a.dot(gamma[1] * b), a.dot(gamma[2] * b));
}

void CheckSettings(const CameraPathSettings& settings)
{
  if (settings.Frames < 1)
  {
    throw CameraPathError("a camera path needs at least 1 frame");
  }
  if (!(settings.Step > 0) || !std::isfinite(settings.Step))
  {
    throw CameraPathError("the camera path's step must be positive and finite");
  }
  if (settings.Kind == CameraPathKind::Geodesic &&
    (!(settings.Length > 0) || !std::isfinite(settings.Length)))
  {
    throw CameraPathError("a geodesic camera path's length must be positive and finite");
  }
  if (settings.Kind == CameraPathKind::Spline)
  {
    if (settings.Keys.size() < 2)
    {
      throw CameraPathError("a spline camera path needs at least 2 key positions");
    }
    for (size_t k = 0; k < settings.Keys.size(); ++k)
    {
      if (!settings.Keys[k].allFinite())
      {
        throw CameraPathError("key position " + std::to_string(k + 1) + " is not finite");
      }
      if (k > 0 && (settings.Keys[k] - settings.Keys[k - 1]).norm() == 0.0)
      {
        throw CameraPathError("key positions " + std::to_string(k) + " and " +
          std::to_string(k + 1) + " coincide");
      }
    }
  }
}

/// The g-orthonormal frame at the start, as the observer's camera makes it.
ObserverCamera StartFrame(const Metric& metric, const CameraSettings& start)
{
  try
  {
    return ObserverCamera(metric, start);
  }
  catch (const std::runtime_error& e)
  {
    throw CameraPathError(std::string("the camera path's first frame: ") + e.what());
  }
}

/**
 * Steps `y` from arc length `from` to `to` by RK4 in at most `step` long
 * steps; throws where the flow is undefined.
 */
template <class State, class Flow>
void Advance(const Flow& flow, State& y, double from, double to, double step)
{
  const int steps = std::max(1, static_cast<int>(std::ceil((to - from) / step - 1e-9)));
  const double h = (to - from) / steps;
  for (int k = 0; k < steps; ++k)
  {
    if (!RungeKutta4StepOf(flow, y, h))
    {
      throw CameraPathError("the metric is degenerate on the camera path near arc length " +
        std::to_string(from + k * h));
    }
  }
}

bool Report(const std::function<bool(double)>& progress, int frame, int frames)
{
  return !progress || progress(static_cast<double>(frame + 1) / frames);
}

/**
 * The frames of a flight of g-length `length`: `y` advanced by `flow` from
 * one frame's arc length to the next (evenly spaced), `frameOf(y)` read at
 * each; progress after each frame.
 */
template <class State, class Flow, class FrameOf>
std::vector<CameraFrame> Fly(const Flow& flow, State y, double length,
  const CameraPathSettings& settings, const FrameOf& frameOf,
  const std::function<bool(double)>& progress)
{
  std::vector<CameraFrame> frames;
  const int count = settings.Frames;
  for (int k = 0; k < count; ++k)
  {
    const double s = count > 1 ? length * k / (count - 1) : 0.0;
    if (k > 0)
    {
      Advance(flow, y, frames.back().ArcLength, s, settings.Step);
    }
    CameraFrame frame = frameOf(y);
    frame.ArcLength = s;
    frames.push_back(frame);
    if (!Report(progress, k, count))
    {
      throw CameraPathError("cancelled");
    }
  }
  return frames;
}

/// Along the geodesic: y = (x, v, up, right), all parallel-transported.
std::vector<CameraFrame> GeodesicFlight(const Metric& metric, const CameraPathSettings& settings,
  const std::function<bool(double)>& progress)
{
  using State = PathState<12>;
  const ObserverCamera start = StartFrame(metric, settings.Start);
  State y;
  y << settings.Start.Position, start.GetForward(), start.GetUp(), start.GetRight();
  const auto flow = [&metric](const State& s, State& ds) {
    const Vec3 v = s.segment<3>(3);
    Mat3Stack gamma;
    if (!metric.Christoffel(s.segment<3>(0), gamma))
    {
      return false;
    }
    ds.segment<3>(0) = v;
    ds.segment<3>(3) = -Contract(gamma, v, v);
    ds.segment<3>(6) = -Contract(gamma, v, s.segment<3>(6));
    ds.segment<3>(9) = -Contract(gamma, v, s.segment<3>(9));
    return ds.allFinite();
  };
  const auto frameOf = [](const State& at) {
    CameraFrame frame;
    frame.Position = at.segment<3>(0);
    frame.Forward = at.segment<3>(3);
    frame.Up = at.segment<3>(6);
    frame.Right = at.segment<3>(9);
    return frame;
  };
  return Fly(flow, y, settings.Length, settings, frameOf, progress);
}

/// The spline's point, tangent c' and c'' at u, clamped to [0, 1].
struct SplinePoint
{
  Vec3 Point;
  Vec3 Tangent;
  Vec3 Curvature;
};

SplinePoint Evaluate(const Spline3& spline, double u)
{
  const Eigen::Matrix<double, 3, 3> d = spline.derivatives(std::clamp(u, 0.0, 1.0), 2);
  return { d.col(0), d.col(1), d.col(2) };
}

/// |c'(u)|_g, the arc length's rate; NaN where the metric is degenerate.
double Speed(const Metric& metric, const Spline3& spline, double u)
{
  const SplinePoint c = Evaluate(spline, u);
  return std::sqrt(metric.InnerProduct(c.Point, c.Tangent, c.Tangent));
}

/// The spline's g-length: ds/du = |c'|_g integrated by RK4 on a fine grid.
double SplineLength(const Metric& metric, const Spline3& spline, size_t keys)
{
  // Simpson's rule on 256 intervals per key span: smooth integrand, error far
  // below the frames' spacing.
  const int intervals = static_cast<int>(256 * keys);
  const double h = 1.0 / intervals;
  double sum = Speed(metric, spline, 0.0) + Speed(metric, spline, 1.0);
  for (int i = 1; i < intervals; ++i)
  {
    sum += (i % 2 ? 4.0 : 2.0) * Speed(metric, spline, i * h);
  }
  const double length = sum * h / 3.0;
  if (!(length > 0) || !std::isfinite(length))
  {
    throw CameraPathError("the metric is degenerate on the spline camera path");
  }
  return length;
}

/**
 * Along the spline, in g-arc length s: y = (u, up, right) with du/ds =
 * 1/|c'|_g and up, right Fermi-Walker transported; forward is the unit
 * tangent T = c'/|c'|_g.
 */
std::vector<CameraFrame> SplineFlight(const Metric& metric, const CameraPathSettings& settings,
  const std::function<bool(double)>& progress)
{
  using State = PathState<7>;
  Eigen::Matrix<double, 3, Eigen::Dynamic> keys(3, settings.Keys.size());
  for (size_t k = 0; k < settings.Keys.size(); ++k)
  {
    keys.col(static_cast<Eigen::Index>(k)) = settings.Keys[k];
  }
  const Eigen::DenseIndex degree = std::min<Eigen::DenseIndex>(3, keys.cols() - 1);
  const Spline3 spline = Eigen::SplineFitting<Spline3>::Interpolate(keys, degree);
  const double length = SplineLength(metric, spline, settings.Keys.size());

  const SplinePoint first = Evaluate(spline, 0.0);
  CameraSettings start = settings.Start;
  start.Position = first.Point;
  start.LookAt = first.Point + first.Tangent;
  const ObserverCamera frame0 = StartFrame(metric, start);
  State y;
  y << 0.0, frame0.GetUp(), frame0.GetRight();

  // At u: the point, g, the symbols, the unit tangent T and A = D_s T,
  // with D_u c' = c'' + Gamma(c', c').
  struct Tangent
  {
    Vec3 Point, T, A;
    Mat3 G;
    Mat3Stack Gamma;
    double Speed = 0.0;
  };
  const auto tangent = [&](double u, Tangent& at) {
    const SplinePoint c = Evaluate(spline, u);
    Mat3& g = at.G;
    Mat3Stack& gamma = at.Gamma;
    Vec3& t = at.T;
    Vec3& a = at.A;
    double& speed = at.Speed;
    if (!metric.Tensor(c.Point, g) || !metric.Christoffel(c.Point, gamma))
    {
      return false;
    }
    speed = std::sqrt(c.Tangent.dot(g * c.Tangent));
    t = c.Tangent / speed;
    const Vec3 dc = c.Curvature + Contract(gamma, c.Tangent, c.Tangent);
    // D_u T = (D_u c' - g(D_u c', T) T) / |c'|, and D_s = D_u / |c'|.
    a = (dc - dc.dot(g * t) * t) / (speed * speed);
    at.Point = c.Point;
    return std::isfinite(speed) && speed > 0 && a.allFinite();
  };
  const auto flow = [&](const State& s, State& ds) {
    Tangent at;
    if (!tangent(s(0), at))
    {
      return false;
    }
    ds(0) = 1.0 / at.Speed;
    for (int i : { 1, 4 })
    {
      const Vec3 x = s.segment<3>(i);
      // Fermi-Walker: D_s X = g(X, T) A - g(X, A) T; dX/ds = D_s X - Gamma(T, X).
      ds.segment<3>(i) =
        x.dot(at.G * at.T) * at.A - x.dot(at.G * at.A) * at.T - Contract(at.Gamma, at.T, x);
    }
    return ds.allFinite();
  };

  const auto frameOf = [&tangent](const State& at) {
    Tangent here;
    if (!tangent(at(0), here))
    {
      throw CameraPathError("the metric is degenerate on the spline camera path");
    }
    CameraFrame frame;
    frame.Position = here.Point;
    frame.Forward = here.T;
    frame.Up = at.segment<3>(1);
    frame.Right = at.segment<3>(4);
    return frame;
  };
  return Fly(flow, y, length, settings, frameOf, progress);
}
} // namespace

const char* CameraPathKindName(CameraPathKind kind)
{
  return kind == CameraPathKind::Spline ? "spline" : "geodesic";
}

std::vector<CameraFrame> ComputeCameraPath(const Metric& metric,
  const CameraPathSettings& settings, const std::function<bool(double)>& progress)
{
  CheckSettings(settings);
  return settings.Kind == CameraPathKind::Spline ? SplineFlight(metric, settings, progress)
                                                 : GeodesicFlight(metric, settings, progress);
}

CameraSettings CameraSettingsOf(const CameraFrame& frame, const CameraSettings& base)
{
  CameraSettings settings = base;
  settings.Position = frame.Position;
  settings.LookAt = frame.Position + frame.Forward;
  settings.ViewUp = frame.Up;
  return settings;
}
} // namespace riemann
