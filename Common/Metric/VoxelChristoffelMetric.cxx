#include "VoxelChristoffelMetric.h"

#include "Christoffel.h"
#include "TensorMetric.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

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
  const auto* tensor = dynamic_cast<const TensorMetric*>(this->Exact.get());
  this->Field = tensor ? dynamic_cast<const SampledTensorField*>(&tensor->GetField()) : nullptr;
  if (!this->Field)
  {
    throw std::invalid_argument(
      "VoxelChristoffelMetric: the metric must be a TensorMetric of a SampledTensorField");
  }
  this->Geometry.Origin = grid.Origin;
  this->Geometry.Spacing = grid.Spacing;
  this->Geometry.Direction = grid.Direction;
  this->Geometry.Dimensions = grid.Dimensions;
  this->WorldToGrid = (grid.Direction * grid.Spacing.asDiagonal()).inverse();
  const std::array<int, 3>& n = grid.Dimensions;
  this->Samples.assign(static_cast<std::size_t>(grid.NumberOfPoints()) * Values, NAN);
  const auto sampleSlices = [&](int firstSlice, int lastSlice)
  {
    float* out = this->Samples.data() +
      static_cast<std::size_t>(Values) * n[0] * n[1] * static_cast<std::size_t>(firstSlice);
    for (int k = firstSlice; k < lastSlice; ++k)
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
            for (int d = 0; d < 3; ++d)
            {
              out[6 + 6 * d + q] = static_cast<float>(dg[d](PairI[q], PairJ[q]));
            }
          }
        }
      }
    }
  };
  // Slices on all cores: the default reading of every sampled metric is made
  // here, a microsecond a voxel (seconds on a whole-brain scan). Each thread
  // writes its own slices, so the samples do not depend on the threads.
  const int threads =
    static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, static_cast<unsigned>(n[2])));
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t)
  {
    workers.emplace_back(sampleSlices, n[2] * t / threads, n[2] * (t + 1) / threads);
  }
  sampleSlices(0, n[2] / threads);
  for (std::thread& worker : workers)
  {
    worker.join();
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

LaneMask VoxelChristoffelMetric::AccelerationPacket(
  const PacketVec3& x, const PacketVec3& v, PacketVec3& a, LaneMask lanes) const
{
  // Step 1: each lane's 24 interpolated numbers (its own 8 voxels: a
  // gather), into a structure of arrays. Lanes not in the box hold g = I,
  // dg = 0: finite values that nobody reads.
  alignas(64) double jet[Values][PacketWidth];
  LaneMask inBox = 0;
  for (int l = 0; l < PacketWidth; ++l)
  {
    float values[Values];
    const bool read = HasLane(lanes, l) && this->Interpolate(x.Lane(l), 0, Values, values);
    inBox |= read ? LaneMask{ 1 } << l : 0;
    for (int q = 0; q < Values; ++q)
    {
      jet[q][l] = read ? values[q] : (q < 3 ? 1.0 : 0.0);
    }
  }

  // Step 2: all lanes at once. The symbols contracted with v twice,
  //   w_k = ((sum_i v^i d_i g) v)_k - 1/2 v^T (d_k g) v,  a = -g^-1 w,
  // with g^-1 w by the adjugate over the determinant (the same
  // quantity as Acceleration(), in another order of operations).
  // Storage order of the six: XX YY ZZ XY YZ XZ.
  alignas(64) double determinant[PacketWidth];
  for (int l = 0; l < PacketWidth; ++l)
  {
    const double xx = jet[0][l], yy = jet[1][l], zz = jet[2][l];
    const double xy = jet[3][l], yz = jet[4][l], xz = jet[5][l];
    const double vx = v.C[0][l], vy = v.C[1][l], vz = v.C[2][l];
    // M = sum_i v^i d_i g (symmetric), and q_k = v^T (d_k g) v.
    double m[6], q[3];
    for (int e = 0; e < 6; ++e)
    {
      m[e] = vx * jet[6 + e][l] + vy * jet[12 + e][l] + vz * jet[18 + e][l];
    }
    for (int k = 0; k < 3; ++k)
    {
      const auto at = [&](int e) { return jet[6 + 6 * k + e][l]; };
      q[k] = vx * (at(0) * vx + 2.0 * (at(3) * vy + at(5) * vz)) +
        vy * (at(1) * vy + 2.0 * at(4) * vz) + vz * at(2) * vz;
    }
    const double wx = m[0] * vx + m[3] * vy + m[5] * vz - 0.5 * q[0];
    const double wy = m[3] * vx + m[1] * vy + m[4] * vz - 0.5 * q[1];
    const double wz = m[5] * vx + m[4] * vy + m[2] * vz - 0.5 * q[2];
    // The adjugate of g (symmetric).
    const double axx = yy * zz - yz * yz, ayy = xx * zz - xz * xz, azz = xx * yy - xy * xy;
    const double axy = xz * yz - xy * zz, ayz = xy * xz - xx * yz, axz = xy * yz - xz * yy;
    determinant[l] = xx * axx + xy * axy + xz * axz;
    const double scale = -1.0 / determinant[l];
    a.C[0][l] = scale * (axx * wx + axy * wy + axz * wz);
    a.C[1][l] = scale * (axy * wx + ayy * wy + ayz * wz);
    a.C[2][l] = scale * (axz * wx + ayz * wy + azz * wz);
    determinant[l] = xx > 0.0 ? determinant[l] : -1.0; // Christoffel()'s test: det > 0, g_xx > 0
  }
  LaneMask defined = 0;
  for (int l = 0; l < PacketWidth; ++l)
  {
    const bool finite =
      std::isfinite(a.C[0][l]) && std::isfinite(a.C[1][l]) && std::isfinite(a.C[2][l]);
    defined |= HasLane(inBox, l) && determinant[l] > 0.0 && finite ? LaneMask{ 1 } << l : 0;
  }

  // Step 3: lanes beyond the box, the wrapped metric's (g = I, or the
  // spline's continuation with "outside": "stop").
  const LaneMask beyond = lanes & ~inBox;
  if (beyond)
  {
    PacketVec3 exact;
    defined |= this->Exact->AccelerationPacket(x, v, exact, beyond) & beyond;
    for (int l = 0; l < PacketWidth; ++l)
    {
      if (HasLane(beyond, l))
      {
        a.SetLane(l, exact.Lane(l));
      }
    }
  }
  return defined & lanes;
}
} // namespace riemann
