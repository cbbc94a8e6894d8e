#include "DirectionLattice.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace riemann
{
std::vector<Vec3> FibonacciDirections(int count, const Vec3& axis, double coneAngle)
{
  constexpr double pi = 3.14159265358979323846;
  const double norm = axis.norm();
  if (count <= 0 || !axis.allFinite() || !(norm > 0.0))
  {
    return {};
  }
  const Vec3 a = axis / norm;
  const Vec3 helper = std::abs(a[0]) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  const Vec3 u = a.cross(helper).normalized();
  const Vec3 w = a.cross(u);
  const double cosine = coneAngle >= 180.0 ? -1.0 : std::cos(coneAngle * pi / 180.0);
  const double goldenAngle = pi * (3.0 - std::sqrt(5.0));
  std::vector<Vec3> directions(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i)
  {
    const double z = 1.0 - (1.0 - cosine) * (i + 0.5) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = goldenAngle * i;
    directions[i] = z * a + r * std::cos(phi) * u + r * std::sin(phi) * w;
  }
  return directions;
}
} // namespace riemann
