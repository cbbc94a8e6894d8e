#include "CutLocus.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace riemann
{
namespace
{
Vec3 DirectionAt(const DistanceFieldResult& field, std::size_t n)
{
  return Vec3(field.ArrivalDirection[3 * n], field.ArrivalDirection[3 * n + 1],
    field.ArrivalDirection[3 * n + 2]);
}

/**
 * Where on the edge [x, y] the two fronts meet: u extrapolated from x along
 * its own arrival direction (du = g(v_x, dx)) equals u extrapolated from y
 * along its own. The middle of the edge when they do not cross on it.
 */
Vec3 CrossingPoint(const Metric& metric, const Vec3& x, const Vec3& y, double ux, double uy,
  const Vec3& vx, const Vec3& vy)
{
  const Vec3 edge = y - x;
  Mat3 gx, gy;
  if (!metric.Tensor(x, gx) || !metric.Tensor(y, gy))
  {
    return 0.5 * (x + y);
  }
  // From x: ux + t sx; from y: uy - (1 - t) sy, with s the slopes along the edge.
  const double sx = vx.dot(gx * edge);
  const double sy = vy.dot(gy * edge);
  const double denominator = sx - sy;
  const double t = denominator != 0 ? (uy - sy - ux) / denominator : 0.5;
  return x + std::clamp(std::isfinite(t) ? t : 0.5, 0.0, 1.0) * edge;
}

/// The corners' shared points: cell (i, j, k) spans points i..i+1, ...
class CellCentres
{
public:
  CellCentres(const DistanceGrid& grid, CutLocusSurface& surface)
    : Grid(grid)
    , Surface(surface)
  {
  }
  int Of(int i, int j, int k)
  {
    const std::size_t key = this->Grid.Index(i, j, k);
    const auto found = this->Ids.find(key);
    if (found != this->Ids.end())
    {
      return found->second;
    }
    const int id = static_cast<int>(this->Surface.Points.size());
    this->Surface.Points.push_back(
      this->Grid.Point(i, j, k) + 0.5 * this->Grid.Spacing);
    this->Ids.emplace(key, id);
    return id;
  }

private:
  const DistanceGrid& Grid;
  CutLocusSurface& Surface;
  std::unordered_map<std::size_t, int> Ids;
};
} // namespace

CutLocusSurface ExtractCutLocus(const Metric& metric, const DistanceGrid& grid,
  const DistanceFieldResult& field, const CutLocusOptions& options)
{
  CutLocusSurface surface;
  CellCentres centres(grid, surface);
  const auto& dims = grid.Dimensions;
  for (int axis = 0; axis < 3; ++axis)
  {
    const int p = (axis + 1) % 3;
    const int q = (axis + 2) % 3;
    int step[3] = { 0, 0, 0 };
    step[axis] = 1;
    for (int k = 0; k + step[2] < dims[2]; ++k)
    {
      for (int j = 0; j + step[1] < dims[1]; ++j)
      {
        for (int i = 0; i + step[0] < dims[0]; ++i)
        {
          int at[3] = { i, j, k };
          // An edge on the grid's boundary has fewer than four cells.
          if (at[p] == 0 || at[q] == 0 || at[p] == dims[static_cast<std::size_t>(p)] - 1 ||
            at[q] == dims[static_cast<std::size_t>(q)] - 1)
          {
            continue;
          }
          const std::size_t a = grid.Index(i, j, k);
          const std::size_t b = grid.Index(i + step[0], j + step[1], k + step[2]);
          const double ua = field.Distance[a], ub = field.Distance[b];
          if (!(ua < std::numeric_limits<double>::infinity()) ||
            !(ub < std::numeric_limits<double>::infinity()) || field.SeedId[a] < 0 ||
            field.SeedId[b] < 0)
          {
            continue;
          }
          const Vec3 da = DirectionAt(field, a), db = DirectionAt(field, b);
          if (da.squaredNorm() == 0 || db.squaredNorm() == 0)
          {
            continue; // a seed's own point
          }
          const double angle =
            std::acos(std::clamp(da.normalized().dot(db.normalized()), -1.0, 1.0));
          int kind = 0;
          if (field.SeedId[a] != field.SeedId[b])
          {
            kind = 2;
          }
          else
          {
            // The turn a smooth field makes over the edge: |x - y|_g / u.
            const Vec3 x = grid.Point(i, j, k);
            const Vec3 edge = grid.Point(i + step[0], j + step[1], k + step[2]) - x;
            Mat3 g;
            const double length = metric.Tensor(x + 0.5 * edge, g)
              ? std::sqrt(std::max(0.0, edge.dot(g * edge)))
              : edge.norm();
            const double smooth = options.SmoothFactor * length / std::min(ua, ub);
            kind = angle > options.MinimumAngle && angle > smooth ? 1 : 0;
          }
          if (kind == 0)
          {
            continue;
          }
          // The dual square: the centres of the four cells around the edge,
          // in order around it.
          std::array<int, 4> quad;
          const int corners[4][2] = { { -1, -1 }, { 0, -1 }, { 0, 0 }, { -1, 0 } };
          for (int c = 0; c < 4; ++c)
          {
            int cell[3] = { i, j, k };
            cell[p] += corners[c][0];
            cell[q] += corners[c][1];
            quad[static_cast<std::size_t>(c)] = centres.Of(cell[0], cell[1], cell[2]);
          }
          surface.Quads.push_back(quad);
          surface.Angle.push_back(angle);
          surface.Kind.push_back(kind);
          surface.Distance.push_back(0.5 * (ua + ub));
          surface.Centres.push_back(CrossingPoint(metric, grid.Point(i, j, k),
            grid.Point(i + step[0], j + step[1], k + step[2]), ua, ub, da, db));
        }
      }
    }
  }
  return surface;
}
} // namespace riemann
