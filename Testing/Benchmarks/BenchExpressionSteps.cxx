// Geodesic steps per second with the 8-Gaussian graph metric typed as one
// expression (compiled from GiNaC's symbolic derivatives into a tape) against
// the same metric from the built-in Gaussian provider, in one run.
// Target (issue "Metrics from expressions"): the typed metric at least half as
// fast as the built-in one. BM_EightGaussiansPacket*: the same 16 geodesics
// through the packet engine (TraceGeodesics: the SIMD Gaussian kernel for
// the built-in provider, the packet tape interpreter for the typed one).
#include "GeodesicTrace.h"
#include "MetricDefinition.h"
#include "PacketTrace.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct Bump
{
  double A, X, Y, Z, S;
};
const Bump Bumps[8] = { { 0.9, -1.2, -0.8, 0.3, 0.5 }, { 0.6, 0.7, 1.1, -0.4, 0.55 },
  { -0.5, 1.3, -0.9, 0.8, 0.6 }, { 0.8, -0.3, 0.2, -1.2, 0.7 }, { 0.4, 0.1, -1.4, -0.2, 0.5 },
  { -0.7, -1.1, 1.0, 1.1, 0.45 }, { 1.0, 1.4, 0.4, 0.1, 0.45 }, { 0.3, 0.0, 0.0, 1.4, 0.8 } };

std::string Definition(bool typed)
{
  std::ostringstream s;
  s << std::setprecision(17);
  if (typed)
  {
    s << R"({"type": "graph", "f": ")";
    for (int i = 0; i < 8; ++i)
    {
      const Bump& b = Bumps[i];
      s << (i ? " + " : "") << b.A << "*exp(-((x - (" << b.X << "))^2 + (y - (" << b.Y
        << "))^2 + (z - (" << b.Z << "))^2) / (2*" << b.S << "^2))";
    }
    return s.str() + "\"}";
  }
  s << R"({"type": "graph", "gaussians": [)";
  for (int i = 0; i < 8; ++i)
  {
    const Bump& b = Bumps[i];
    s << (i ? "," : "") << R"({"amplitude": )" << b.A << R"(, "center": [)" << b.X << "," << b.Y
      << "," << b.Z << R"(], "sigma": )" << b.S << "}";
  }
  return s.str() + "]}";
}

/// RK4, step 0.01, length 10, no drift: 1000 steps per geodesic.
riemann::GeodesicOptions BundleOptions()
{
  riemann::GeodesicOptions options;
  options.Integrator = riemann::IntegratorType::RungeKutta4;
  options.Step = 0.01;
  options.MaximumLength = 10.0;
  options.RecordSpeedDrift = false;
  return options;
}

/// 16 geodesics of 1000 RK4 steps each (step 0.01) through the bumps.
void TraceBundle(benchmark::State& state, bool typed)
{
  const auto metric = riemann::ParseMetricDefinition(Definition(typed));
  const riemann::GeodesicOptions options = BundleOptions();
  riemann::GeodesicPath path;
  path.Points.reserve(1100);
  path.Velocities.reserve(1100);
  path.ArcLength.reserve(1100);
  path.SpeedDrift.reserve(1100);
  long long steps = 0;
  for (auto _ : state)
  {
    for (int k = 0; k < 16; ++k)
    {
      const riemann::Vec3 p(-2.5, -1.0 + 0.13 * k, 0.2 - 0.05 * k);
      riemann::Vec3 v;
      riemann::UnitSpeedVelocity(*metric, p, riemann::Vec3(1.0, 0.2, 0.1), v);
      riemann::TraceGeodesic(*metric, p, v, options, path);
      steps += static_cast<long long>(path.Points.size()) - 1;
      benchmark::DoNotOptimize(path.Points.back());
    }
  }
  state.SetItemsProcessed(steps);
}

void BM_EightGaussiansBuiltIn(benchmark::State& state)
{
  TraceBundle(state, false);
}
void BM_EightGaussiansTyped(benchmark::State& state)
{
  TraceBundle(state, true);
}
BENCHMARK(BM_EightGaussiansBuiltIn)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EightGaussiansTyped)->Unit(benchmark::kMillisecond);

/// TraceBundle's 16 geodesics through the packet engine.
void TracePacketBundle(benchmark::State& state, bool typed)
{
  const auto metric = riemann::ParseMetricDefinition(Definition(typed));
  const riemann::GeodesicOptions options = BundleOptions();
  std::vector<riemann::GeodesicSeed> seeds(16);
  for (int k = 0; k < 16; ++k)
  {
    seeds[k].Point = riemann::Vec3(-2.5, -1.0 + 0.13 * k, 0.2 - 0.05 * k);
    riemann::UnitSpeedVelocity(*metric, seeds[k].Point, riemann::Vec3(1.0, 0.2, 0.1), seeds[k].Velocity);
  }
  std::vector<riemann::GeodesicPath> paths(seeds.size());
  long long steps = 0;
  for (auto _ : state)
  {
    riemann::TraceGeodesics(*metric, seeds.data(), seeds.size(), options, paths.data());
    for (const riemann::GeodesicPath& path : paths)
    {
      steps += static_cast<long long>(path.Points.size()) - 1;
    }
    benchmark::DoNotOptimize(paths.back().Points.back());
  }
  state.SetItemsProcessed(steps);
}

void BM_EightGaussiansPacketBuiltIn(benchmark::State& state)
{
  TracePacketBundle(state, false);
}
void BM_EightGaussiansPacketTyped(benchmark::State& state)
{
  TracePacketBundle(state, true);
}
BENCHMARK(BM_EightGaussiansPacketBuiltIn)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EightGaussiansPacketTyped)->Unit(benchmark::kMillisecond);
} // namespace
