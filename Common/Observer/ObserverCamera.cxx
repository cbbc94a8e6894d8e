#include "ObserverCamera.h"

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>

namespace riemann
{
std::string CheckCameraView(const Vec3& position, const Vec3& lookAt, const Vec3& viewUp)
{
  // In coordinates: the same test as the g-frame's below, up to the metric
  // (a camera the app or a project accepts is one every metric frames).
  const Vec3 forward = lookAt - position;
  const double length = forward.norm();
  if (!(length > 0) || !std::isfinite(length))
  {
    return "the camera is at the point it looks at";
  }
  if (!(forward.cross(viewUp).norm() > 1e-9 * length * viewUp.norm()))
  {
    return "the view up is along the view direction";
  }
  return std::string();
}

ObserverCamera::ObserverCamera(const Metric& metric, const CameraSettings& settings)
  : Settings(settings)
{
  Mat3 g;
  if (!metric.Tensor(settings.Position, g) || !settings.Position.allFinite())
  {
    throw std::runtime_error("the metric is degenerate at the observer");
  }
  auto dot = [&g](const Vec3& a, const Vec3& b) { return a.dot(g * b); };
  auto normalized = [&dot](const Vec3& a) { return Vec3(a / std::sqrt(dot(a, a))); };

  const Vec3 view = settings.LookAt - settings.Position;
  if (!(view.norm() > 0))
  {
    throw std::runtime_error("the camera position and its focal point coincide");
  }
  // Gram-Schmidt in g: forward, then up, then right (view x up, right-handed).
  this->Forward = normalized(view);
  Vec3 up = settings.ViewUp - dot(settings.ViewUp, this->Forward) * this->Forward;
  if (!(std::sqrt(dot(up, up)) > 1e-9 * std::sqrt(dot(settings.ViewUp, settings.ViewUp))))
  {
    throw std::runtime_error("the view up is zero or parallel to the view direction");
  }
  this->Up = normalized(up);
  Vec3 right = view.cross(settings.ViewUp);
  right -= dot(right, this->Forward) * this->Forward + dot(right, this->Up) * this->Up;
  this->Right = normalized(right);
}

Vec3 ObserverCamera::Direction(double x, double y, double aspect) const
{
  if (this->Settings.Mode == Projection::Equirectangular)
  {
    const double longitude = x * M_PI;
    const double latitude = y * M_PI_2;
    return std::cos(latitude) *
      (std::cos(longitude) * this->Forward + std::sin(longitude) * this->Right) +
      std::sin(latitude) * this->Up;
  }
  const double t = std::tan(0.5 * this->Settings.ViewAngle * M_PI / 180.0);
  const double a = x * t * aspect;
  const double b = y * t;
  // The frame is g-orthonormal, so |d|_g^2 = 1 + a^2 + b^2.
  return (this->Forward + a * this->Right + b * this->Up) / std::sqrt(1.0 + a * a + b * b);
}

Vec3 ObserverCamera::PixelDirection(int column, int row, int width, int height) const
{
  const double x = (2.0 * column + 1.0) / width - 1.0;
  const double y = (2.0 * row + 1.0) / height - 1.0;
  return this->Direction(x, y, static_cast<double>(width) / height);
}
} // namespace riemann
