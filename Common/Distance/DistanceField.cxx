#include "DistanceField.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace riemann
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
/// Points per block edge: 512 points a block, a few hundred blocks a task.
constexpr int BlockSize = 8;
/// Passes over one block in one round at most (it is passed over again in
/// the next round if it still changes).
constexpr int MaximumPasses = 2 * BlockSize;

/// The 26-point stencil: the neighbours' offsets, and the surface of their
/// cube as 48 triangles and 72 edges (indices into the offsets).
struct Stencil
{
  std::array<std::array<int, 3>, 26> Offsets;
  std::vector<std::array<int, 3>> Triangles;
  std::vector<std::array<int, 2>> Edges;

  Stencil()
  {
    int n = 0;
    for (int c = -1; c <= 1; ++c)
    {
      for (int b = -1; b <= 1; ++b)
      {
        for (int a = -1; a <= 1; ++a)
        {
          if (a != 0 || b != 0 || c != 0)
          {
            this->Offsets[static_cast<std::size_t>(n++)] = { a, b, c };
          }
        }
      }
    }
    // Each face of the cube: its centre, edge midpoints and corners; the
    // triangles (centre, midpoint, corner) around the centre.
    for (int axis = 0; axis < 3; ++axis)
    {
      const int p = (axis + 1) % 3;
      const int q = (axis + 2) % 3;
      for (int side : { -1, 1 })
      {
        std::array<int, 3> centre = { 0, 0, 0 };
        centre[static_cast<std::size_t>(axis)] = side;
        for (int sp : { -1, 1 })
        {
          for (int sq : { -1, 1 })
          {
            std::array<int, 3> alongP = centre;
            alongP[static_cast<std::size_t>(p)] = sp;
            std::array<int, 3> alongQ = centre;
            alongQ[static_cast<std::size_t>(q)] = sq;
            std::array<int, 3> corner = alongP;
            corner[static_cast<std::size_t>(q)] = sq;
            this->AddTriangle(this->Find(centre), this->Find(alongP), this->Find(corner));
            this->AddTriangle(this->Find(centre), this->Find(alongQ), this->Find(corner));
          }
        }
      }
    }
  }

  int Find(const std::array<int, 3>& offset) const
  {
    return static_cast<int>(
      std::find(this->Offsets.begin(), this->Offsets.end(), offset) - this->Offsets.begin());
  }

  void AddTriangle(int a, int b, int c)
  {
    this->Triangles.push_back({ a, b, c });
    for (const std::array<int, 2>& edge :
      { std::array<int, 2>{ a, b }, std::array<int, 2>{ b, c }, std::array<int, 2>{ a, c } })
    {
      const std::array<int, 2> sorted = { std::min(edge[0], edge[1]), std::max(edge[0], edge[1]) };
      if (std::find(this->Edges.begin(), this->Edges.end(), sorted) == this->Edges.end())
      {
        this->Edges.push_back(sorted);
      }
    }
  }
};

const Stencil& TheStencil()
{
  static const Stencil stencil;
  return stencil;
}

/// g at a point, the 6 entries of its upper triangle (xx xy xz yy yz zz).
using Sym3 = std::array<double, 6>;

Vec3 Apply(const Sym3& m, const Vec3& w)
{
  return Vec3(m[0] * w[0] + m[1] * w[1] + m[2] * w[2], m[1] * w[0] + m[3] * w[1] + m[4] * w[2],
    m[2] * w[0] + m[4] * w[1] + m[5] * w[2]);
}

/// The best candidate of one update: value, seed, the foot's offset from x.
struct Candidate
{
  double Value = Infinity;
  int Seed = -1;
  Vec3 Foot = Vec3::Zero();
};

/**
 * The grid, its metric and its values, and the update of one point by the
 * Hopf-Lax formula on the stencil's surface (the file comment of the header).
 */
class Solver
{
public:
  Solver(const Metric& metric, const DistanceGrid& grid, const DistanceOptions& options)
    : TheMetric(metric)
    , Grid(grid)
    , Options(options)
    , Size(grid.NumberOfPoints())
  {
    const Stencil& stencil = TheStencil();
    for (std::size_t v = 0; v < stencil.Offsets.size(); ++v)
    {
      const auto& o = stencil.Offsets[v];
      this->Offsets[v] =
        Vec3(o[0] * grid.Spacing[0], o[1] * grid.Spacing[1], o[2] * grid.Spacing[2]);
    }
    this->Values.assign(this->Size, Infinity);
    this->Seeds.assign(this->Size, -1);
    this->Feet.assign(this->Size, Vec3::Zero());
    this->Fixed.assign(this->Size, 0);
    this->Tensors.resize(this->Size);
    this->Reach.assign(this->Size, 0.0);
    this->Valid.assign(this->Size, 0);
  }

  /// Step 1: g at every point (a point where it fails is never reached),
  /// and the g-distance from the point to its stencil's surface at least.
  void SampleMetric(const DistanceParallelFor& parallelFor)
  {
    const double shortest = this->Grid.Spacing.minCoeff();
    parallelFor(this->Size,
      [this, shortest](std::size_t first, std::size_t last)
      {
        for (std::size_t n = first; n < last; ++n)
        {
          // Where geodesics stop (outside a sampled metric's volume with
          // "outside": "stop") no distance is defined either.
          Mat3 g;
          const Vec3 x = this->PointOf(n);
          if (!this->TheMetric.InsideData(x) || !this->TheMetric.Tensor(x, g) || !g.allFinite())
          {
            continue;
          }
          const Eigen::SelfAdjointEigenSolver<Mat3> eigen(g, Eigen::EigenvaluesOnly);
          const double smallest = eigen.eigenvalues()[0];
          if (!(smallest > 0))
          {
            continue;
          }
          this->Tensors[n] = { g(0, 0), g(0, 1), g(0, 2), g(1, 1), g(1, 2), g(2, 2) };
          // The cube's surface is at least one spacing from its centre.
          this->Reach[n] = std::sqrt(smallest) * shortest;
          this->Valid[n] = 1;
        }
      });
  }

  /// Step 2: the points near the seeds take the local distance and stay.
  void PlaceSeeds(const std::vector<Vec3>& seeds)
  {
    const double radius = this->Options.SeedRadius * this->Grid.Spacing.maxCoeff();
    for (std::size_t s = 0; s < seeds.size(); ++s)
    {
      const Vec3& p = seeds[s];
      int low[3], high[3];
      for (int a = 0; a < 3; ++a)
      {
        const double centre = (p[a] - this->Grid.Origin[a]) / this->Grid.Spacing[a];
        const double reach = radius / this->Grid.Spacing[a];
        low[a] = std::max(0, static_cast<int>(std::floor(centre - reach)));
        high[a] = std::min(this->Grid.Dimensions[static_cast<std::size_t>(a)] - 1,
          static_cast<int>(std::ceil(centre + reach)));
      }
      for (int k = low[2]; k <= high[2]; ++k)
      {
        for (int j = low[1]; j <= high[1]; ++j)
        {
          for (int i = low[0]; i <= high[0]; ++i)
          {
            const std::size_t n = this->Grid.Index(i, j, k);
            const Vec3 x = this->Grid.Point(i, j, k);
            if (!this->Valid[n] || (x - p).norm() > radius)
            {
              continue;
            }
            // |x - p| in g at the midpoint: second order in |x - p|.
            Mat3 g;
            if (!this->TheMetric.Tensor(0.5 * (x + p), g))
            {
              continue;
            }
            const double d = std::sqrt(std::max(0.0, (x - p).dot(g * (x - p))));
            if (d < this->Values[n])
            {
              this->Values[n] = d;
              this->Seeds[n] = static_cast<int>(s);
              this->Feet[n] = p - x;
              this->Fixed[n] = 1;
            }
          }
        }
      }
    }
  }

  /// The Hopf-Lax update of point (i, j, k): its candidate, or the current
  /// value when nothing on the stencil improves it.
  Candidate Update(int i, int j, int k, std::size_t n) const
  {
    const Stencil& stencil = TheStencil();
    const Sym3& m = this->Tensors[n];
    const double reach = this->Reach[n];
    Candidate best;
    best.Value = this->Values[n];
    // The neighbours' values, and their offsets' M d and d.M d where finite.
    double u[26];
    Vec3 md[26];
    double c[26];
    double lowest = Infinity;
    for (std::size_t v = 0; v < 26; ++v)
    {
      const auto& o = stencil.Offsets[v];
      const int a = i + o[0], b = j + o[1], cc = k + o[2];
      u[v] = Infinity;
      if (a < 0 || b < 0 || cc < 0 || a >= this->Grid.Dimensions[0] ||
        b >= this->Grid.Dimensions[1] || cc >= this->Grid.Dimensions[2])
      {
        continue;
      }
      const std::size_t neighbour = this->Grid.Index(a, b, cc);
      u[v] = this->Values[neighbour];
      if (u[v] < Infinity)
      {
        md[v] = Apply(m, this->Offsets[v]);
        c[v] = this->Offsets[v].dot(md[v]);
        lowest = std::min(lowest, u[v]);
      }
    }
    if (!(lowest + reach < best.Value))
    {
      return best; // nothing on the stencil can improve it
    }
    const auto seedOf = [&](int v)
    {
      const auto& o = stencil.Offsets[static_cast<std::size_t>(v)];
      return this->Seeds[this->Grid.Index(i + o[0], j + o[1], k + o[2])];
    };
    // Vertices.
    for (int v = 0; v < 26; ++v)
    {
      if (u[v] + reach < best.Value)
      {
        const double value = u[v] + std::sqrt(c[v]);
        if (value < best.Value)
        {
          best = { value, seedOf(v), this->Offsets[v] };
        }
      }
    }
    // Edges: min over t in (0, 1) of u_a + t (u_b - u_a) + |d_a + t e|_g.
    for (const std::array<int, 2>& edge : stencil.Edges)
    {
      const int a = edge[0], b = edge[1];
      if (!(std::min(u[a], u[b]) + reach < best.Value) || u[a] == Infinity || u[b] == Infinity)
      {
        continue;
      }
      const double ab = this->Offsets[a].dot(md[b]);
      const double A = c[b] - 2.0 * ab + c[a];
      const double B = ab - c[a];
      const double k1 = u[b] - u[a];
      if (!(A > 0) || !(k1 * k1 < A))
      {
        continue;
      }
      const double closest = -B / A;
      const double n0 = std::max(0.0, c[a] + B * closest);
      const double norm = std::sqrt(n0 / (1.0 - k1 * k1 / A));
      const double t = closest - norm * k1 / A;
      if (t > 0.0 && t < 1.0)
      {
        const double value = u[a] + k1 * t + norm;
        if (value < best.Value)
        {
          best = { value, seedOf(t < 0.5 ? a : b),
            this->Offsets[a] + t * (this->Offsets[b] - this->Offsets[a]) };
        }
      }
    }
    // Triangles: min over the simplex of u_0 + k.mu + |d_0 + E mu|_g.
    for (const std::array<int, 3>& triangle : stencil.Triangles)
    {
      const int v0 = triangle[0], v1 = triangle[1], v2 = triangle[2];
      if (u[v0] == Infinity || u[v1] == Infinity || u[v2] == Infinity ||
        !(std::min({ u[v0], u[v1], u[v2] }) + reach < best.Value))
      {
        continue;
      }
      const Vec3& d0 = this->Offsets[v0];
      const double d01 = d0.dot(md[v1]);
      const double d02 = d0.dot(md[v2]);
      const double d12 = this->Offsets[v1].dot(md[v2]);
      // A = E^T g E, b = E^T g d_0 with E = [d_1 - d_0, d_2 - d_0].
      const double a11 = c[v1] - 2.0 * d01 + c[v0];
      const double a22 = c[v2] - 2.0 * d02 + c[v0];
      const double a12 = d12 - d01 - d02 + c[v0];
      const double b1 = d01 - c[v0];
      const double b2 = d02 - c[v0];
      const double det = a11 * a22 - a12 * a12;
      if (!(det > 1e-14 * a11 * a22))
      {
        continue;
      }
      // A^-1 applied to b and to k.
      const double k1 = u[v1] - u[v0];
      const double k2 = u[v2] - u[v0];
      const double ib1 = (a22 * b1 - a12 * b2) / det;
      const double ib2 = (a11 * b2 - a12 * b1) / det;
      const double ik1 = (a22 * k1 - a12 * k2) / det;
      const double ik2 = (a11 * k2 - a12 * k1) / det;
      const double s = k1 * ik1 + k2 * ik2;
      if (!(s < 1.0))
      {
        continue;
      }
      const double n0 = std::max(0.0, c[v0] - (b1 * ib1 + b2 * ib2));
      const double norm = std::sqrt(n0 / (1.0 - s));
      const double mu1 = -ib1 - norm * ik1;
      const double mu2 = -ib2 - norm * ik2;
      if (mu1 > 0.0 && mu2 > 0.0 && mu1 + mu2 < 1.0)
      {
        const double value = u[v0] + k1 * mu1 + k2 * mu2 + norm;
        if (value < best.Value)
        {
          const double mu0 = 1.0 - mu1 - mu2;
          const int heaviest = mu0 >= mu1 && mu0 >= mu2 ? v0 : (mu1 >= mu2 ? v1 : v2);
          best = { value, seedOf(heaviest),
            d0 + mu1 * (this->Offsets[v1] - d0) + mu2 * (this->Offsets[v2] - d0) };
        }
      }
    }
    return best;
  }

  /// Passes over block (bx, by, bz), forward and backward, until it no
  /// longer changes; whether anything changed, and how many updates.
  bool ProcessBlock(int bx, int by, int bz, long long& updates)
  {
    const int i0 = bx * BlockSize, j0 = by * BlockSize, k0 = bz * BlockSize;
    const int i1 = std::min(i0 + BlockSize, this->Grid.Dimensions[0]);
    const int j1 = std::min(j0 + BlockSize, this->Grid.Dimensions[1]);
    const int k1 = std::min(k0 + BlockSize, this->Grid.Dimensions[2]);
    bool changed = false;
    for (int pass = 0; pass < MaximumPasses; ++pass)
    {
      bool changedThisPass = false;
      const bool forward = pass % 2 == 0;
      for (int kk = 0; kk < k1 - k0; ++kk)
      {
        const int k = forward ? k0 + kk : k1 - 1 - kk;
        for (int jj = 0; jj < j1 - j0; ++jj)
        {
          const int j = forward ? j0 + jj : j1 - 1 - jj;
          for (int ii = 0; ii < i1 - i0; ++ii)
          {
            const int i = forward ? i0 + ii : i1 - 1 - ii;
            const std::size_t n = this->Grid.Index(i, j, k);
            if (this->Fixed[n] || !this->Valid[n])
            {
              continue;
            }
            ++updates;
            const Candidate candidate = this->Update(i, j, k, n);
            const double old = this->Values[n];
            if (candidate.Value < old &&
              !(old - candidate.Value <= this->Options.Tolerance * (1.0 + candidate.Value)))
            {
              changedThisPass = true;
            }
            if (candidate.Value < old)
            {
              this->Values[n] = candidate.Value;
              this->Seeds[n] = candidate.Seed;
              this->Feet[n] = candidate.Foot;
            }
          }
        }
      }
      changed = changed || changedThisPass;
      if (!changedThisPass)
      {
        break;
      }
    }
    return changed;
  }

  /// Step 3: rounds over the active blocks, colour by colour, until no
  /// block changes. False when `progress` asked to stop.
  bool Iterate(const DistanceParallelFor& parallelFor, const DistanceProgress& progress,
    DistanceFieldResult& result)
  {
    int blocks[3];
    for (int a = 0; a < 3; ++a)
    {
      blocks[a] = (this->Grid.Dimensions[static_cast<std::size_t>(a)] + BlockSize - 1) / BlockSize;
    }
    const std::size_t count = static_cast<std::size_t>(blocks[0]) * blocks[1] * blocks[2];
    const auto blockIndex = [&](int x, int y, int z)
    { return static_cast<std::size_t>(x) + static_cast<std::size_t>(blocks[0]) * (y + static_cast<std::size_t>(blocks[1]) * z); };
    std::vector<unsigned char> active(count, 0), changed(count, 0), reached(count, 0);
    std::vector<long long> updates(count, 0);
    // The blocks of the seeds' points, and their neighbours, start.
    const auto activateAround = [&](int x, int y, int z)
    {
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
          {
            const int a = x + dx, b = y + dy, c = z + dz;
            if (a >= 0 && b >= 0 && c >= 0 && a < blocks[0] && b < blocks[1] && c < blocks[2])
            {
              active[blockIndex(a, b, c)] = 1;
            }
          }
    };
    for (int k = 0; k < this->Grid.Dimensions[2]; ++k)
      for (int j = 0; j < this->Grid.Dimensions[1]; ++j)
        for (int i = 0; i < this->Grid.Dimensions[0]; ++i)
          if (this->Fixed[this->Grid.Index(i, j, k)])
          {
            activateAround(i / BlockSize, j / BlockSize, k / BlockSize);
          }
    std::vector<std::size_t> list;
    for (;;)
    {
      bool any = false;
      std::fill(changed.begin(), changed.end(), 0);
      for (int colour = 0; colour < 8; ++colour)
      {
        list.clear();
        for (int z = colour >> 2 & 1; z < blocks[2]; z += 2)
          for (int y = colour >> 1 & 1; y < blocks[1]; y += 2)
            for (int x = colour & 1; x < blocks[0]; x += 2)
              if (active[blockIndex(x, y, z)])
              {
                list.push_back(blockIndex(x, y, z));
              }
        parallelFor(list.size(),
          [&](std::size_t first, std::size_t last)
          {
            for (std::size_t l = first; l < last; ++l)
            {
              const std::size_t b = list[l];
              const int x = static_cast<int>(b % blocks[0]);
              const int y = static_cast<int>(b / blocks[0] % blocks[1]);
              const int z = static_cast<int>(b / (static_cast<std::size_t>(blocks[0]) * blocks[1]));
              changed[b] = this->ProcessBlock(x, y, z, updates[b]) ? 1 : 0;
              reached[b] = 1;
            }
          });
      }
      ++result.Rounds;
      std::fill(active.begin(), active.end(), 0);
      for (int z = 0; z < blocks[2]; ++z)
        for (int y = 0; y < blocks[1]; ++y)
          for (int x = 0; x < blocks[0]; ++x)
            if (changed[blockIndex(x, y, z)])
            {
              any = true;
              activateAround(x, y, z);
            }
      if (progress)
      {
        std::size_t settled = 0;
        for (std::size_t b = 0; b < count; ++b)
        {
          settled += reached[b] && !active[b] ? 1 : 0;
        }
        if (!progress(static_cast<double>(settled) / count))
        {
          return false;
        }
      }
      if (!any)
      {
        break;
      }
    }
    for (long long n : updates)
    {
      result.Updates += n;
    }
    return true;
  }

  /// Step 4: the values, arrival directions and seeds, as the result.
  void Fill(DistanceFieldResult& result) const
  {
    result.Distance = this->Values;
    result.SeedId = this->Seeds;
    result.ArrivalDirection.assign(3 * this->Size, 0.0);
    for (std::size_t n = 0; n < this->Size; ++n)
    {
      // The geodesic arrives from the foot: x - foot, g-normalised at x.
      const Vec3 w = -this->Feet[n];
      const double norm = std::sqrt(std::max(0.0, w.dot(Apply(this->Tensors[n], w))));
      if (this->Values[n] < Infinity && norm > 0)
      {
        for (int a = 0; a < 3; ++a)
        {
          result.ArrivalDirection[3 * n + static_cast<std::size_t>(a)] = w[a] / norm;
        }
      }
    }
  }

private:
  Vec3 PointOf(std::size_t n) const
  {
    const std::size_t nx = static_cast<std::size_t>(this->Grid.Dimensions[0]);
    const std::size_t ny = static_cast<std::size_t>(this->Grid.Dimensions[1]);
    return this->Grid.Point(static_cast<int>(n % nx), static_cast<int>(n / nx % ny),
      static_cast<int>(n / (nx * ny)));
  }

  const Metric& TheMetric;
  const DistanceGrid& Grid;
  DistanceOptions Options;
  std::size_t Size;
  Vec3 Offsets[26];
  std::vector<double> Values;
  std::vector<int> Seeds;
  std::vector<Vec3> Feet;
  std::vector<unsigned char> Fixed;
  std::vector<Sym3> Tensors;
  std::vector<double> Reach;
  std::vector<unsigned char> Valid;
};

void CheckArguments(const Metric& metric, const DistanceGrid& grid, const std::vector<Vec3>& seeds)
{
  for (int a = 0; a < 3; ++a)
  {
    if (grid.Dimensions[static_cast<std::size_t>(a)] < 2)
    {
      throw std::invalid_argument("the grid needs at least 2 points along each axis");
    }
    if (!(grid.Spacing[a] > 0) || !std::isfinite(grid.Spacing[a]) || !std::isfinite(grid.Origin[a]))
    {
      throw std::invalid_argument("the grid's spacing must be positive and finite");
    }
  }
  if (seeds.empty())
  {
    throw std::invalid_argument("no seed: the distance is measured from at least one point");
  }
  for (std::size_t s = 0; s < seeds.size(); ++s)
  {
    const Vec3& p = seeds[s];
    for (int a = 0; a < 3; ++a)
    {
      const double end = grid.Origin[a] + (grid.Dimensions[static_cast<std::size_t>(a)] - 1) * grid.Spacing[a];
      if (!std::isfinite(p[a]) || p[a] < grid.Origin[a] || p[a] > end)
      {
        throw std::invalid_argument("seed " + std::to_string(s) + " is not inside the grid's bounds");
      }
    }
    if (!metric.InsideData(p))
    {
      throw std::invalid_argument("seed " + std::to_string(s) +
        " is outside the metric's data (geodesics stop there)");
    }
  }
}
} // namespace

void SerialFor(std::size_t count, const std::function<void(std::size_t, std::size_t)>& work)
{
  if (count > 0)
  {
    work(0, count);
  }
}

// ComputeDistanceField as named steps: CheckArguments -> SampleMetric ->
// PlaceSeeds -> Iterate -> Fill.
bool ComputeDistanceField(const Metric& metric, const DistanceGrid& grid,
  const std::vector<Vec3>& seeds, const DistanceOptions& options, DistanceFieldResult& result,
  const DistanceParallelFor& parallelFor, const DistanceProgress& progress)
{
  CheckArguments(metric, grid, seeds);
  result = DistanceFieldResult();
  Solver solver(metric, grid, options);
  solver.SampleMetric(parallelFor);
  solver.PlaceSeeds(seeds);
  if (!solver.Iterate(parallelFor, progress, result))
  {
    return false;
  }
  solver.Fill(result);
  return true;
}
} // namespace riemann
