/**
 * @file DistanceField.h
 * @brief The geodesic distance from one or several seeds on a regular grid:
 * the anisotropic eikonal equation |grad u|_{g^-1} = 1 solved by a
 * semi-Lagrangian (Hopf-Lax) scheme on a 26-point stencil, iterated to its
 * fixed point over blocks in parallel (Documentation/Mathematics.md,
 * "Between two points").
 *
 * The scheme. At a grid point x, with g = g(x),
 *   u(x) = min over y on the stencil's surface S of [ u_I(y) + |x - y|_g ],
 * where S is the boundary of the 3 x 3 x 3 cube of x's neighbours,
 * triangulated into 48 triangles (a face's centre, an edge midpoint, a
 * corner), and u_I is u interpolated linearly on each triangle. The minimum
 * over a triangle, an edge or a vertex has a closed form (the minimum of a
 * linear function plus a norm over a simplex). The scheme is monotone and
 * consistent for any metric (the minimum is over the whole surface, so no
 * stencil needs to be acute), first order: the error is O(h) away from the
 * seeds (measured: Testing/Benchmarks/README.md, BenchDistanceField).
 * Near each seed the distance is the local one, |x - p| in g at their
 * midpoint, within SeedRadius cells (the point source's singularity would
 * otherwise cost accuracy everywhere).
 *
 * The solver. The scheme's fixed point is reached by Gauss-Seidel passes
 * over blocks of 8^3 points (a block is passed over forward and backward
 * until it no longer changes), the blocks touched by a change passed over
 * again, until none changes: the fast iterative method of Jeong and
 * Whitaker (2008) by blocks. Blocks are coloured by the parity of their
 * indices; the blocks of one colour never share a stencil, so they run in
 * parallel (ParallelFor), and the result does not depend on the threads.
 *
 * With every value come the arrival direction (the g-unit velocity, at x,
 * of the minimal geodesic from its seed: x minus the foot of the minimising
 * point of S, g-normalised) and the seed it comes from (the stencil vertex
 * with the largest weight in the minimising simplex): Voronoi regions of
 * the seeds in g.
 */
#ifndef RiemannDistanceField_h
#define RiemannDistanceField_h

#include "Metric.h"
#include "RiemannCommonDistanceExport.h"

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace riemann
{
/// A regular grid: Dimensions points along each axis from Origin, Spacing apart.
struct DistanceGrid
{
  Vec3 Origin = Vec3::Zero();
  Vec3 Spacing = Vec3::Ones();
  std::array<int, 3> Dimensions = { 1, 1, 1 };

  std::size_t NumberOfPoints() const
  {
    return static_cast<std::size_t>(this->Dimensions[0]) * this->Dimensions[1] *
      this->Dimensions[2];
  }
  /// Point index of (i, j, k), i fastest (VTK's order).
  std::size_t Index(int i, int j, int k) const
  {
    return static_cast<std::size_t>(i) +
      static_cast<std::size_t>(this->Dimensions[0]) *
      (static_cast<std::size_t>(j) + static_cast<std::size_t>(this->Dimensions[1]) * k);
  }
  Vec3 Point(int i, int j, int k) const
  {
    return this->Origin + Vec3(i * this->Spacing[0], j * this->Spacing[1], k * this->Spacing[2]);
  }
};

struct DistanceOptions
{
  /// Points within this many cells of a seed take the local distance.
  double SeedRadius = 2.5;
  /// A change of a value below Tolerance * (1 + value) counts as none.
  double Tolerance = 1e-12;
};

struct DistanceFieldResult
{
  /// The distance, +infinity where no seed reaches (the metric fails there).
  std::vector<double> Distance;
  /// ArrivalDirection, 3 per point (zero at a seed and where unreached).
  std::vector<double> ArrivalDirection;
  /// Which seed each point is closest to; -1 where unreached.
  std::vector<int> SeedId;
  /// Point updates and block rounds the solver took.
  long long Updates = 0;
  int Rounds = 0;
};

/// Runs `work(first, last)` over [0, count), on as many threads as it likes.
using DistanceParallelFor =
  std::function<void(std::size_t count, const std::function<void(std::size_t, std::size_t)>& work)>;
/// Told the fraction of the work done (a rough one); returns false to stop.
using DistanceProgress = std::function<bool(double fraction)>;

/// Runs `work` on the calling thread: the default ParallelFor.
RIEMANNCOMMONDISTANCE_EXPORT void SerialFor(
  std::size_t count, const std::function<void(std::size_t, std::size_t)>& work);

/**
 * The distance field of `seeds` on `grid`. Points outside the metric's data
 * (Metric::InsideData: a sampled volume with "outside": "stop") or where g
 * fails are unreached. Throws std::invalid_argument when there is no seed, a
 * seed is not finite, outside the grid's box or outside the data, or the
 * grid has fewer than 2 points along an axis or a spacing that is not
 * positive and finite. Returns false when `progress` asked to stop (the
 * result is then incomplete).
 */
RIEMANNCOMMONDISTANCE_EXPORT bool ComputeDistanceField(const Metric& metric,
  const DistanceGrid& grid, const std::vector<Vec3>& seeds, const DistanceOptions& options,
  DistanceFieldResult& result, const DistanceParallelFor& parallelFor = SerialFor,
  const DistanceProgress& progress = {});
} // namespace riemann

#endif
