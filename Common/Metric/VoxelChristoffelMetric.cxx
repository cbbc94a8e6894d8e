#include "VoxelChristoffelMetric.h"

#include "Christoffel.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace riemann
{
namespace
{
constexpr int Values = 24;
/// The index pairs (i, j) of the six independent components of g and of each d_k g, in storage order.
constexpr int PairI[6] = { 0, 1, 2, 0, 1, 0 };
constexpr int PairJ[6] = { 0, 1, 2, 1, 2, 2 };
} // namespace

VoxelChristoffelMetric::VoxelChristoffelMetric(
  std::shared_ptr<const Metric> exact, const SampledTensorGrid& grid)
  : Exact(std::move(exact))
{
  this->Geometry.Origin = grid.Origin;
  this->Geometry.Spacing = grid.Spacing;
  this->Geometry.Direction = grid.Direction;
  this->Geometry.Dimensions = grid.Dimensions;
  this->WorldToGrid = (grid.Direction * grid.Spacing.asDiagonal()).inverse();
  const std::array<int, 3>& n = grid.Dimensions;
  this->Samples.assign(static_cast<std::size_t>(grid.NumberOfPoints()) * Values, NAN);
  float* out = this->Samples.data();
  for (int k = 0; k < n[2]; ++k)
  {
    for (int j = 0; j < n[1]; ++j)
    {
      for (int i = 0; i < n[0]; ++i, out += Values)
      {
        const Vec3 x = grid.Origin +
          grid.Direction * Vec3(i * grid.Spacing[0], j * grid.Spacing[1], k * grid.Spacing[2]);
        Mat3 g;
        Mat3Stack dg;
        // A voxel where the spline fails keeps NaN: steps that read it stop
        // as degenerate, as they would on the exact metric.
        if (!this->Exact->TensorDerivatives(x, g, dg))
        {
          continue;
        }
        for (int q = 0; q < 6; ++q)
        {
          out[q] = static_cast<float>(g(PairI[q], PairJ[q]));
          for (int k = 0; k < 3; ++k)
          {
            out[6 + 6 * k + q] = static_cast<float>(dg[k](PairI[q], PairJ[q]));
          }
        }
      }
    }
  }
}

std::string VoxelChristoffelMetric::Describe() const
{
  return this->Exact->Describe() + " (Christoffel symbols sampled at the voxels)";
}

bool VoxelChristoffelMetric::Interpolate(const Vec3& p, int first, int count, float* values) const
{
  const Vec3 u = this->WorldToGrid * (p - this->Geometry.Origin);
  const std::array<int, 3>& n = this->Geometry.Dimensions;
  int cell[3];
  float t[3];
  for (int a = 0; a < 3; ++a)
  {
    // The box the samples' own field has (SampledTensorField::Inside), to
    // the outer voxels' faces; between an outer voxel and its face, that
    // voxel's values.
    if (!SampledTensorField::WithinFaces(u[a], n[a]))
    {
      return false;
    }
    const double clamped = std::clamp(u[a], 0.0, n[a] - 1.0);
    cell[a] = std::min(static_cast<int>(clamped), n[a] - 2);
    t[a] = static_cast<float>(clamped - cell[a]);
  }
  const long long nx = n[0];
  const long long nxy = nx * n[1];
  const float* base =
    this->Samples.data() + Values * (cell[0] + nx * cell[1] + nxy * cell[2]) + first;
  // The 8 corners' weights and rows, then one contiguous sum per value (vectorised).
  const float s[3] = { 1.0f - t[0], 1.0f - t[1], 1.0f - t[2] };
  const float weight[8] = { s[0] * s[1] * s[2], t[0] * s[1] * s[2], s[0] * t[1] * s[2],
    t[0] * t[1] * s[2], s[0] * s[1] * t[2], t[0] * s[1] * t[2], s[0] * t[1] * t[2],
    t[0] * t[1] * t[2] };
  const float* corner[8] = { base, base + Values, base + Values * nx, base + Values * (nx + 1),
    base + Values * nxy, base + Values * (nxy + 1), base + Values * (nxy + nx),
    base + Values * (nxy + nx + 1) };
  // Corner by corner over contiguous values: the inner loop vectorises.
  for (int v = 0; v < count; ++v)
  {
    values[v] = weight[0] * corner[0][v];
  }
  for (int c = 1; c < 8; ++c)
  {
    const float w = weight[c];
    const float* row = corner[c];
    for (int v = 0; v < count; ++v)
    {
      values[v] += w * row[v];
    }
  }
  return true;
}

bool VoxelChristoffelMetric::Tensor(const Vec3& p, Mat3& g) const
{
  float v[6];
  if (!this->Interpolate(p, 0, 6, v))
  {
    return this->Exact->Tensor(p, g);
  }
  g << v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2];
  // Positive definite, as a convex combination of positive definite samples.
  return g.allFinite() && g(0, 0) > 0.0;
}

bool VoxelChristoffelMetric::Christoffel(const Vec3& p, Mat3Stack& gamma) const
{
  float v[Values];
  if (!this->Interpolate(p, 0, Values, v))
  {
    return this->Exact->Christoffel(p, gamma);
  }
  const auto symmetric = [](const float* c)
  {
    Mat3 m;
    m << c[0], c[3], c[5], c[3], c[1], c[4], c[5], c[4], c[2];
    return m;
  };
  const Mat3 g = symmetric(v);
  const Mat3Stack dg = { symmetric(v + 6), symmetric(v + 12), symmetric(v + 18) };
  // The symbols of the interpolated g and dg, not interpolated symbols: where
  // g jumps by orders of magnitude between voxels (a repaired background
  // voxel next to tissue), g^-1 dg at the small side is huge, and
  // interpolating it threw a geodesic 36 km in one step; this way Gamma
  // stays of the size of dg over the interpolated g.
  const double determinant = g.determinant();
  if (!(determinant > 0.0) || !(g(0, 0) > 0.0))
  {
    return false;
  }
  ChristoffelFromMetricDerivatives(g.inverse(), dg, gamma);
  return gamma[0].allFinite() && gamma[1].allFinite() && gamma[2].allFinite();
}

bool VoxelChristoffelMetric::Acceleration(const Vec3& p, const Vec3& v, Vec3& a) const
{
  Mat3Stack gamma;
  if (!this->Christoffel(p, gamma))
  {
    return false;
  }
  a = ContractChristoffel(gamma, v);
  return a.allFinite();
}
} // namespace riemann
