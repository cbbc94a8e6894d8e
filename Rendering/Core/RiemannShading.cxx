#include "RiemannShading.h"

#include "GeodesicTrace.h" // TerminationReason
#include "RiemannSceneIntersection.h"

#include <Eigen/LU> // inverse

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace riemann
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
}

Vec3 FailureColor()
{
  return Vec3(1.0, 0.0, 1.0);
}

bool IsFailure(int reason)
{
  return reason == DegenerateMetric || reason == Stagnation || reason == UnexpectedValue;
}

Vec3 EnvironmentMap::Lookup(const Vec3& direction, const Vec3& background) const
{
  const double length = direction.norm();
  if (this->Empty() || !(length > 0))
  {
    return background;
  }
  const Vec3 d = direction / length;
  const double u = 0.5 + std::atan2(d.x(), -d.z()) / (2.0 * Pi);
  const double t = 0.5 - std::asin(std::clamp(d.y(), -1.0, 1.0)) / Pi;
  // Bilinear between texel centres, as GL_LINEAR: Repeat in u, ClampToEdge in t.
  const double x = u * this->Width - 0.5;
  const double y = t * this->Height - 0.5;
  const double x0 = std::floor(x);
  const double y0 = std::floor(y);
  const double fx = x - x0;
  const double fy = y - y0;
  auto texel = [this](long column, long row)
  {
    column %= this->Width;
    if (column < 0)
    {
      column += this->Width;
    }
    row = std::clamp<long>(row, 0, this->Height - 1);
    const float* p = &this->Rgb[3 * (static_cast<std::size_t>(row) * this->Width + column)];
    return Vec3(p[0], p[1], p[2]);
  };
  const long c0 = static_cast<long>(x0);
  const long r0 = static_cast<long>(y0);
  return (1 - fy) * ((1 - fx) * texel(c0, r0) + fx * texel(c0 + 1, r0)) +
    fy * ((1 - fx) * texel(c0, r0 + 1) + fx * texel(c0 + 1, r0 + 1));
}

void EnvironmentMap::SetImage(const Image& image)
{
  if (image.Width <= 0 || image.Height <= 0 || image.Channels <= 0 ||
    image.Pixels.size() <
      static_cast<std::size_t>(image.Width) * image.Height * static_cast<std::size_t>(image.Channels))
  {
    throw std::invalid_argument("EnvironmentMap::SetImage: an image without pixels (" +
      std::to_string(image.Width) + " x " + std::to_string(image.Height) + " x " +
      std::to_string(image.Channels) + ", " + std::to_string(image.Pixels.size()) + " values)");
  }
  this->Width = image.Width;
  this->Height = image.Height;
  this->Rgb.resize(static_cast<std::size_t>(this->Width) * this->Height * 3);
  for (std::size_t i = 0, n = static_cast<std::size_t>(this->Width) * this->Height; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      // Grey images repeat their one channel; two-channel ones are grey + alpha.
      this->Rgb[3 * i + c] = image.Pixels[i * image.Channels + (image.Channels >= 3 ? c : 0)];
    }
  }
}

double ObserverCosine(const Metric& metric, const Vec3& p, const Vec3& nu, const Vec3& v)
{
  Mat3 g;
  if (!metric.Tensor(p, g))
  {
    return 1.0;
  }
  const double vv = v.dot(g * v);
  const double nn = nu.dot(g.inverse() * nu);
  if (!(vv > 0.0) || !(nn > 0.0))
  {
    return 1.0;
  }
  return std::clamp(std::abs(nu.dot(v)) / std::sqrt(nn * vv), 0.0, 1.0);
}

Vec3 ShadeRay(const Metric& metric, const Scene& scene, bool isHit, const SceneHit& hit,
  int reason, double length, const Vec3& velocity, const EnvironmentMap* environment)
{
  if (isHit)
  {
    Vec3 color = SurfaceColor(scene, hit);
    if (scene.ObserverLight)
    {
      color *= ObserverCosine(metric, hit.Position, hit.Normal, velocity);
    }
    const double fog = 1.0 - std::exp(-scene.FogDensity * length);
    return color + fog * (scene.FogColor - color);
  }
  if (IsFailure(reason))
  {
    return FailureColor();
  }
  return environment ? environment->Lookup(velocity, scene.Background) : scene.Background;
}

Vec3 SurfaceColor(const Scene& scene, const SceneHit& hit)
{
  if (hit.Object < 0 || hit.Object >= static_cast<int>(scene.Objects.size()))
  {
    return Vec3::Zero();
  }
  const SceneObject& object = scene.Objects[hit.Object];
  if (object.Type == ObjectType::Mesh && object.Mesh >= 0 &&
    object.Mesh < static_cast<int>(scene.Meshes.size()) && hit.Primitive >= 0)
  {
    const TriangleMesh& mesh = *scene.Meshes[object.Mesh];
    if (!mesh.Colors.empty() && static_cast<std::size_t>(hit.Primitive) < mesh.NumberOfTriangles())
    {
      const unsigned int* corner = &mesh.Triangles[3 * static_cast<std::size_t>(hit.Primitive)];
      const double w[3] = { 1.0 - hit.U - hit.V, hit.U, hit.V };
      Vec3 color = Vec3::Zero();
      for (int k = 0; k < 3; ++k)
      {
        const float* c = &mesh.Colors[3 * static_cast<std::size_t>(corner[k])];
        color += w[k] * Vec3(c[0], c[1], c[2]);
      }
      return color.cwiseMax(0.0).cwiseMin(1.0);
    }
  }
  const Material& material = object.Surface;
  switch (material.Type)
  {
    case MaterialType::Position:
    {
      Vec3 color;
      for (int axis = 0; axis < 3; ++axis)
      {
        const double lo = material.Bounds[2 * axis];
        const double width = material.Bounds[2 * axis + 1] - lo;
        color[axis] = width > 0 ? std::clamp((hit.Position[axis] - lo) / width, 0.0, 1.0) : 0.5;
      }
      return color;
    }
    case MaterialType::Solid:
      return material.Color;
    case MaterialType::Checker:
    {
      const double size = material.Size > 0 ? material.Size : 1.0;
      const double normalLength = hit.Normal.norm();
      const Vec3 inward = normalLength > 0 ? Vec3(-hit.Normal / normalLength) : Vec3(Vec3::Zero());
      const Vec3 q = hit.Position + (1e-6 * size) * inward;
      const double cells =
        std::floor(q.x() / size) + std::floor(q.y() / size) + std::floor(q.z() / size);
      return std::fmod(std::abs(cells), 2.0) == 0 ? material.Color : material.Color2;
    }
  }
  return Vec3::Zero();
}
} // namespace riemann
