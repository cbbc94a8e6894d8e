/**
 * @file BenchConjugatePoints.cxx
 * @brief Conjugate points of 10,000 directions on the round-sphere metric,
 * on all cores: directions per second.
 *
 * The metric is the unit 3-sphere in stereographic coordinates, typed as an
 * expression as a user would (Data/metrics/round-sphere.json:
 * n = 2 / (1 + x^2 + y^2 + z^2)); the observer is (0.2, 0.1, -0.3); the
 * directions are the Fibonacci lattice of the sphere (as `riemann conjugate
 * --directions 10000`). Each direction is searched up to arc length 4 for its
 * first conjugate point (exactly at pi, multiplicity 2), roots refined to 1e-8,
 * with the Jacobi fields integrated by:
 * - BM_ConjugatePoints/rk4: fixed-step RK4, step 0.01 (the CLI default);
 * - BM_ConjugatePoints/dp45: adaptive Dormand-Prince 5(4), tolerance 1e-9,
 *   largest step 0.1.
 * Counters: directions_per_second (the figure), found (directions with a
 * conjugate point), max_error (largest |ArcLength - pi|), double (how many
 * were classified multiplicity 2). Directions are handed out to the threads
 * one by one (an atomic counter): their costs differ.
 */
#include "DirectionLattice.h"
#include "ConjugatePoints.h"
#include "MetricDefinition.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

namespace
{
constexpr int DirectionCount = 10000;
constexpr double Pi = 3.14159265358979323846;

struct Outcome
{
  int Found = 0;
  int Double = 0;
  double MaximumError = 0.0;
};

void BM_ConjugatePoints(benchmark::State& state, riemann::IntegratorType integrator)
{
  const auto metric =
    riemann::ParseMetricDefinition(R"json({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})json");
  const riemann::Vec3 observer(0.2, 0.1, -0.3);
  const std::vector<riemann::Vec3> directions =
    riemann::FibonacciDirections(DirectionCount, riemann::Vec3(0.0, 0.0, 1.0), 180.0);
  riemann::GeodesicOptions options;
  options.Integrator = integrator;
  options.Step = 0.01;
  options.Tolerance = 1e-9;
  options.MaximumStep = 0.1;
  options.MaximumLength = 4.0;
  const unsigned threadCount = std::max(1u, std::thread::hardware_concurrency());

  Outcome total;
  for (auto _ : state)
  {
    std::atomic<int> next(0);
    std::vector<Outcome> outcomes(threadCount);
    std::vector<std::thread> threads;
    for (unsigned t = 0; t < threadCount; ++t)
    {
      threads.emplace_back(
        [&, t]
        {
          Outcome& outcome = outcomes[t];
          for (int i = next++; i < DirectionCount; i = next++)
          {
            const auto points =
              riemann::FindConjugatePoints(*metric, observer, directions[i], options, 1e-8, 1);
            if (!points.empty())
            {
              ++outcome.Found;
              outcome.Double += points[0].Multiplicity == 2 ? 1 : 0;
              outcome.MaximumError =
                std::max(outcome.MaximumError, std::abs(points[0].ArcLength - Pi));
            }
          }
        });
    }
    for (std::thread& thread : threads)
    {
      thread.join();
    }
    total = Outcome();
    for (const Outcome& outcome : outcomes)
    {
      total.Found += outcome.Found;
      total.Double += outcome.Double;
      total.MaximumError = std::max(total.MaximumError, outcome.MaximumError);
    }
  }
  state.counters["directions_per_second"] = benchmark::Counter(
    static_cast<double>(DirectionCount) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["found"] = total.Found;
  state.counters["double"] = total.Double;
  state.counters["max_error"] = total.MaximumError;
  state.counters["threads"] = threadCount;
}
} // namespace

// Real time: the workers' time is what a user waits for.
BENCHMARK_CAPTURE(BM_ConjugatePoints, rk4, riemann::IntegratorType::RungeKutta4)
  ->Unit(benchmark::kMillisecond)
  ->MeasureProcessCPUTime()
  ->UseRealTime()
  ->Iterations(1);
BENCHMARK_CAPTURE(BM_ConjugatePoints, dp45, riemann::IntegratorType::DormandPrince45)
  ->Unit(benchmark::kMillisecond)
  ->MeasureProcessCPUTime()
  ->UseRealTime()
  ->Iterations(1);
