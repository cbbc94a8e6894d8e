/**
 * @file BenchJacobiSteps.cxx
 * @brief The Jacobi system (a geodesic with its two transverse Jacobi
 * fields, JacobiField.h: what the exponential map, the conjugate locus and
 * the tracer's Jacobians integrate), Jacobi steps per second on one core:
 * the scalar TraceJacobiFields one direction at a time against its packet
 * form (PacketWidth directions in lock step), measured in the same run.
 *
 * Named BM_JacobiTrace/<metric>_<integrator>_<scalar|packet>. 64 directions
 * from one observer, fixed-step RK4 at 0.01 up to arc length 10 (1,000
 * steps each, every sample kept as the exponential map keeps them), or
 * dp45 at tolerance 1e-9 (steps counted from the traces). Metrics:
 * - graph8: the graph of the 8 Gaussian bumps of BenchGeodesicSteps.cxx,
 *   built-in providers (the SIMD graph kernel, third-order Gaussian table);
 * - sphere: the round sphere as a typed conformal expression
 *   (n = 2 / (1 + |x|^2)): the SIMD conformal kernel on the packet tape;
 * - nil: a typed tensor metric (Nil): no SIMD form, the lane-by-lane
 *   default, which shows what the packet bookkeeping costs by itself.
 * Counter items_per_second = Jacobi steps per second.
 */
#include "DirectionLattice.h"
#include "EightBumps.h"
#include "JacobiField.h"
#include "MetricDefinition.h"

#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

namespace
{
using riemann::Vec3;

constexpr int DirectionCount = 64;

std::shared_ptr<const riemann::Metric> MetricNamed(const std::string& name)
{
  if (name == "graph8")
  {
    return riemann::bench::GraphOfEightBumps();
  }
  if (name == "sphere")
  {
    return riemann::ParseMetricDefinition(
      R"json({"type": "conformal", "n": "2/(1 + x^2 + y^2 + z^2)"})json");
  }
  return riemann::ParseMetricDefinition(
    R"json({"type": "tensor", "g": [["1", "0", "0"], ["0", "1 + x^2", "-x"], ["0", "-x", "1"]]})json");
}

riemann::GeodesicOptions OptionsFor(bool adaptive)
{
  riemann::GeodesicOptions options;
  options.Integrator =
    adaptive ? riemann::IntegratorType::DormandPrince45 : riemann::IntegratorType::RungeKutta4;
  options.Step = 0.01;
  options.Tolerance = 1e-9;
  options.MaximumStep = 0.1;
  options.MaximumLength = 10.0;
  options.MaximumSteps = 10000000;
  return options;
}

std::vector<riemann::JacobiSeed> Seeds()
{
  std::vector<riemann::JacobiSeed> seeds;
  for (const Vec3& direction :
    riemann::FibonacciDirections(DirectionCount, Vec3(0.0, 0.0, 1.0), 180.0))
  {
    seeds.push_back({ Vec3(0.1, -0.2, 0.05), direction, false });
  }
  return seeds;
}

void BM_JacobiTrace(
  benchmark::State& state, const std::string& metricName, bool adaptive, bool packet)
{
  const auto metric = MetricNamed(metricName);
  const riemann::GeodesicOptions options = OptionsFor(adaptive);
  const std::vector<riemann::JacobiSeed> seeds = Seeds();
  std::vector<riemann::JacobiTrace> traces(seeds.size());
  const auto traceAll = [&]
  {
    if (packet)
    {
      riemann::TraceJacobiFields(*metric, seeds.data(), seeds.size(), options, traces.data());
      return;
    }
    for (size_t i = 0; i < seeds.size(); ++i)
    {
      riemann::TraceJacobiFields(*metric, seeds[i].Point, seeds[i].Direction, options, traces[i]);
    }
  };
  traceAll(); // grows the traces to their final capacity
  long long steps = 0;
  for (const riemann::JacobiTrace& trace : traces)
  {
    steps += static_cast<long long>(trace.Samples.size()) - 1;
  }
  for (auto _ : state)
  {
    traceAll();
    benchmark::DoNotOptimize(traces.back().Samples.back());
  }
  state.SetItemsProcessed(state.iterations() * steps);
}

#define RIEMANN_JACOBI_BENCHMARK(name, metric, adaptive, packet)                                   \
  BENCHMARK_CAPTURE(BM_JacobiTrace, name, std::string(metric), adaptive, packet)                   \
    ->Unit(benchmark::kMillisecond)

RIEMANN_JACOBI_BENCHMARK(graph8_rk4_scalar, "graph8", false, false);
RIEMANN_JACOBI_BENCHMARK(graph8_rk4_packet, "graph8", false, true);
RIEMANN_JACOBI_BENCHMARK(graph8_dp45_scalar, "graph8", true, false);
RIEMANN_JACOBI_BENCHMARK(graph8_dp45_packet, "graph8", true, true);
RIEMANN_JACOBI_BENCHMARK(sphere_rk4_scalar, "sphere", false, false);
RIEMANN_JACOBI_BENCHMARK(sphere_rk4_packet, "sphere", false, true);
RIEMANN_JACOBI_BENCHMARK(nil_rk4_scalar, "nil", false, false);
RIEMANN_JACOBI_BENCHMARK(nil_rk4_packet, "nil", false, true);
} // namespace
