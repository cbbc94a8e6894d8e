#include "DistanceDescent.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace riemann
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

/// The cell of x (its lower corner's indices) and x's place in it (0..1).
bool Locate(const DistanceGrid& grid, const Vec3& x, int cell[3], double t[3])
{
  for (int a = 0; a < 3; ++a)
  {
    const double f = (x[a] - grid.Origin[a]) / grid.Spacing[a];
    const int n = grid.Dimensions[static_cast<std::size_t>(a)];
    if (!(f >= -1e-9 && f <= n - 1 + 1e-9))
    {
      return false;
    }
    cell[a] = std::clamp(static_cast<int>(std::floor(f)), 0, n - 2);
    t[a] = std::clamp(f - cell[a], 0.0, 1.0);
  }
  return true;
}

/// Runs visit(point index, weight) over the 8 corners of x's cell.
template <class Visit>
bool ForEachCorner(const DistanceGrid& grid, const Vec3& x, Visit visit)
{
  int cell[3];
  double t[3];
  if (!Locate(grid, x, cell, t))
  {
    return false;
  }
  for (int c = 0; c < 8; ++c)
  {
    const int di = c & 1, dj = c >> 1 & 1, dk = c >> 2 & 1;
    const double w = (di ? t[0] : 1 - t[0]) * (dj ? t[1] : 1 - t[1]) * (dk ? t[2] : 1 - t[2]);
    visit(grid.Index(cell[0] + di, cell[1] + dj, cell[2] + dk), w);
  }
  return true;
}

/// The arrival direction at x (trilinear over the reached corners), zero if none.
Vec3 DirectionAt(const DistanceGrid& grid, const DistanceFieldResult& field, const Vec3& x)
{
  Vec3 sum = Vec3::Zero();
  ForEachCorner(grid, x,
    [&](std::size_t n, double w)
    {
      sum += w *
        Vec3(field.ArrivalDirection[3 * n], field.ArrivalDirection[3 * n + 1],
          field.ArrivalDirection[3 * n + 2]);
    });
  return sum;
}
} // namespace

double InterpolateDistance(const DistanceGrid& grid, const DistanceFieldResult& field, const Vec3& x)
{
  double value = 0.0;
  if (!ForEachCorner(grid, x, [&](std::size_t n, double w) { value += w * field.Distance[n]; }))
  {
    return Infinity;
  }
  return std::isfinite(value) ? value : Infinity;
}

DistanceDescent DescendToSeed(const DistanceGrid& grid, const DistanceFieldResult& field,
  const std::vector<Vec3>& seeds, const Vec3& x)
{
  DistanceDescent descent;
  descent.Distance = InterpolateDistance(grid, field, x);
  int cell[3];
  double t[3];
  if (!(descent.Distance < Infinity) || !Locate(grid, x, cell, t))
  {
    return descent;
  }
  // The closest seed: the nearest grid point's.
  int nearest[3];
  for (int a = 0; a < 3; ++a)
  {
    nearest[a] = cell[a] + (t[a] >= 0.5 ? 1 : 0);
  }
  descent.Seed = field.SeedId[grid.Index(nearest[0], nearest[1], nearest[2])];
  if (descent.Seed < 0 || descent.Seed >= static_cast<int>(seeds.size()))
  {
    descent.Seed = -1;
    return descent;
  }
  const Vec3& seed = seeds[static_cast<std::size_t>(descent.Seed)];
  const double step = 0.5 * grid.Spacing.minCoeff();
  const double stop = 2.0 * grid.Spacing.maxCoeff();
  // Enough steps to cross the box a few times.
  const double box = (grid.Spacing.cwiseProduct(Vec3(grid.Dimensions[0] - 1,
                       grid.Dimensions[1] - 1, grid.Dimensions[2] - 1)))
                       .norm();
  const int budget = static_cast<int>(std::ceil(4.0 * box / step));
  Vec3 at = x;
  descent.Points.push_back(at);
  for (int n = 0; n < budget; ++n)
  {
    if ((at - seed).norm() <= stop)
    {
      descent.Reached = true;
      break;
    }
    // Midpoint step backwards along the unit (Euclidean) arrival direction.
    const Vec3 first = DirectionAt(grid, field, at);
    if (!(first.norm() > 0))
    {
      break;
    }
    const Vec3 middle = at - 0.5 * step * first.normalized();
    const Vec3 second = DirectionAt(grid, field, middle);
    if (!(second.norm() > 0))
    {
      break;
    }
    at -= step * second.normalized();
    descent.Points.push_back(at);
  }
  descent.Points.push_back(seed);
  return descent;
}
} // namespace riemann
