/**
 * @file BenchSampledAcceleration.cxx
 * @brief The geodesic acceleration of a sampled metric read at the voxels
 * ("christoffel": "voxels", VoxelChristoffelMetric), what every RK4 stage
 * of tractography evaluates: lane by lane (Metric::AccelerationPacket's
 * default, one Christoffel() per lane: the 27 symbols from g^-1), against
 * VoxelChristoffelMetric::AccelerationPacket (the 8 lanes' gathers, then
 * one contraction for all lanes), in one run, on one core. For reference,
 * the exact spline ("christoffel": "spline") lane by lane.
 *
 * Named BM_SampledAcceleration/<reading>_<lanes|packet>; a 64^3 volume of a
 * fibre field turning in space, 4096 random points inside and velocities.
 * Counter items_per_second = accelerations per second.
 *
 *   build/bin/RiemannBenchmarks --benchmark_filter=SampledAcceleration
 */
#include "SampledTensorSamples.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

namespace
{
using riemann::Mat3;
using riemann::Vec3;

/// A 64^3 tensor volume on [-2, 2]^3: prolate tensors along a direction turning with x and y.
std::shared_ptr<const riemann::Metric> FibreVolume(bool atVoxels)
{
  riemann::SampledTensorGrid grid;
  const int n = 64;
  const double h = 4.0 / (n - 1);
  grid.Dimensions = { n, n, n };
  grid.Spacing = Vec3::Constant(h);
  grid.Origin = Vec3::Constant(-2.0);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const Vec3 x = grid.Origin + h * Vec3(i, j, k);
        const double angle = 0.6 * std::sin(x[0]) + 0.4 * std::cos(1.3 * x[1]);
        const Vec3 u = Vec3(std::cos(angle), std::sin(angle), 0.2 * std::sin(x[2])).normalized();
        const Mat3 g = 0.4 * Mat3::Identity() + 1.4 * (Mat3::Identity() - u * u.transpose());
        for (double c : { g(0, 0), g(1, 1), g(2, 2), g(0, 1), g(1, 2), g(0, 2) })
        {
          grid.Components.push_back(c);
        }
      }
  riemann::SampledTensorOptions options;
  options.ChristoffelAtVoxels = atVoxels;
  return riemann::MakeSampledTensorMetric(std::move(grid), options);
}

void BM_SampledAcceleration(benchmark::State& state, bool atVoxels, bool packet)
{
  const std::shared_ptr<const riemann::Metric> metric = FibreVolume(atVoxels);
  constexpr int Packets = 512;
  std::vector<riemann::PacketVec3> x(Packets), v(Packets);
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> inside(-1.9, 1.9), speed(-1.0, 1.0);
  for (int p = 0; p < Packets; ++p)
  {
    for (int l = 0; l < riemann::PacketWidth; ++l)
    {
      x[p].SetLane(l, Vec3(inside(generator), inside(generator), inside(generator)));
      v[p].SetLane(l, Vec3(speed(generator), speed(generator), speed(generator)));
    }
  }
  riemann::PacketVec3 a;
  for (auto _ : state)
  {
    for (int p = 0; p < Packets; ++p)
    {
      const riemann::LaneMask defined = packet
        ? metric->AccelerationPacket(x[p], v[p], a, riemann::AllLanes)
        : metric->riemann::Metric::AccelerationPacket(x[p], v[p], a, riemann::AllLanes);
      benchmark::DoNotOptimize(defined);
      benchmark::DoNotOptimize(a);
    }
  }
  state.SetItemsProcessed(state.iterations() * Packets * riemann::PacketWidth);
}
} // namespace

BENCHMARK_CAPTURE(BM_SampledAcceleration, voxels_lanes, true, false)
  ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SampledAcceleration, voxels_packet, true, true)
  ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SampledAcceleration, spline_lanes, false, false)
  ->Unit(benchmark::kMicrosecond);
