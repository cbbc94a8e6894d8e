/**
 * @file BenchConjugatePoints.cxx
 * @brief Conjugate points of 10,000 directions on all cores, directions per
 * second: the library's detection (riemann::FindConjugatePoints, counting
 * Maslov phases) against the old one it replaced
 * (riemann::bench::LegacyFindConjugatePoints, LegacyConjugateSearch.h),
 * both measured in the same run so that their ratio means something.
 *
 * Every benchmark is named BM_ConjugatePoints/<case>_<integrator>_<search>,
 * <search> = new, legacy, or packet: the new search on the packet engine
 * (the many-direction FindConjugatePoints, 8 directions in lock step, in
 * chunks of 32 per thread), with the new search's settings. The metrics are conformal, typed as
 * expressions as a user would; the directions are the Fibonacci lattice of the sphere (as `riemann
 * conjugate --directions 10000`). The adaptive integrator (dp45, Dormand-Prince 5(4)) runs with
 * vtkRiemannConjugateLocus's settings, first step 0.01, steps of at most 0.1; options.Tolerance is
 * the old default 1e-9 for the legacy search and the filter's default cap 1e-6 for the new one,
 * which lowers it itself to tolerance / 100 = 1e-10 (ConjugateIntegrationTolerance). rk4 is
 * fixed-step RK4 at step 0.01 (the CLI default); there the new search's root tolerance is 1e-5, its
 * merge resolution (the step, not the tolerance, decides the accuracy: RK4 splits the round
 * sphere's double point by up to ~3e-6, TestJacobiField.cxx). Cases:
 * - sphere_dp45, sphere_rk4: the unit 3-sphere in stereographic
 *   coordinates (Data/metrics/round-sphere.json, n = 2 / (1 + x^2 + y^2 +
 *   z^2)) seen from (0.2, 0.1, -0.3), up to arc length 4, the first
 *   conjugate point (exactly at pi, multiplicity 2), roots to 1e-8.
 * - sphere10_dp45: the filter's real default workload: the same up to arc
 *   length 10 (its default MaximumPropagation), first point only. The new
 *   search stops tracing once it has that point; the legacy one traces to 10.
 * - squashed_dp45: n = 2 (1 + 0.0005 x^2) / (1 + x^2 + y^2 + z^2) from
 *   (0.1, -0.2, 0.15), up to arc length 6, the first two points (roots to
 *   1e-8): the perturbation splits the sphere's double point into two
 *   simple points, mostly close together (often within one dp45 step), the
 *   case the legacy search gets wrong by design.
 * Counters: directions_per_second (the figure, wall time), threads; found
 * (directions with at least one conjugate point), double (directions whose
 * first point has multiplicity 2); on the spheres max_error (largest
 * |ArcLength - pi| of the first point); on the squashed sphere both_simple
 * (directions with two points of multiplicity 1 reported), missed
 * (directions whose points add up to a multiplicity below 2), and min_gap,
 * max_gap (the range of the distance between the two points where both
 * were reported simple). Directions are handed out to the threads one by one
 * (an atomic counter): their costs differ. The counters are recorded, not
 * asserted: a benchmark does not pass or fail.
 */
#include "ConjugatePoints.h"
#include "DirectionLattice.h"
#include "LegacyConjugateSearch.h"
#include "MetricDefinition.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

namespace
{
using riemann::Vec3;

constexpr int DirectionCount = 10000;
constexpr double Pi = 3.14159265358979323846;

/// FindConjugatePoints' signature with GeodesicOptions: the new search and the
/// legacy one are interchangeable behind it.
using Search = std::vector<riemann::ConjugatePoint> (*)(
  const riemann::Metric&, const Vec3&, const Vec3&, const riemann::GeodesicOptions&, double, int);

// The cast picks the GeodesicOptions overload of riemann::FindConjugatePoints.
const Search NewSearch = static_cast<Search>(&riemann::FindConjugatePoints);
const Search LegacySearch = &riemann::bench::LegacyFindConjugatePoints;
/// The many-direction FindConjugatePoints on the packet engine (SearchAllPackets).
const Search PacketSearch = nullptr;

/// One workload of the file comment, with the settings of one of the searches.
struct Workload
{
  /// n(x, y, z) of the conformal metric n^2 delta.
  const char* Factor;
  Vec3 Observer;
  riemann::IntegratorType Integrator;
  /// options.Tolerance (read by dp45 only).
  double IntegrationTolerance;
  double Length;
  /// The root tolerance passed to the search.
  double Tolerance;
  /// The number of points asked for (maximumCount).
  int Wanted;
  /// The round sphere: the first point is exactly at pi (max_error).
  bool RoundSphere;
};

const char* const RoundSphere = "2/(1+x^2+y^2+z^2)";
const char* const SquashedSphere = "2*(1+0.0005*x^2)/(1+x^2+y^2+z^2)";
const Vec3 SphereObserver(0.2, 0.1, -0.3);
const Vec3 SquashedObserver(0.1, -0.2, 0.15);

// dp45 integration tolerances: the old default for the legacy search, the
// filter's cap for the new one (which lowers it to 1e-10 itself).
constexpr double LegacyDp45 = 1e-9;
constexpr double NewDp45 = 1e-6;
// Root tolerances: 1e-8 as the filter's default; the new search at a fixed
// RK4 step merges crossings closer than 1e-5 (the step's accuracy).
constexpr double Roots = 1e-8;
constexpr double NewRk4Roots = 1e-5;

using riemann::IntegratorType;
// (RK4 does not read the integration tolerance: the rk4 pairs differ only in
// their root tolerance.)
const Workload SphereDp45New{ RoundSphere, SphereObserver, IntegratorType::DormandPrince45, NewDp45,
  4.0, Roots, 1, true };
const Workload SphereDp45Legacy{ RoundSphere, SphereObserver, IntegratorType::DormandPrince45,
  LegacyDp45, 4.0, Roots, 1, true };
const Workload SphereRk4New{ RoundSphere, SphereObserver, IntegratorType::RungeKutta4, NewDp45, 4.0,
  NewRk4Roots, 1, true };
const Workload SphereRk4Legacy{ RoundSphere, SphereObserver, IntegratorType::RungeKutta4,
  LegacyDp45, 4.0, Roots, 1, true };
const Workload Sphere10Dp45New{ RoundSphere, SphereObserver, IntegratorType::DormandPrince45,
  NewDp45, 10.0, Roots, 1, true };
const Workload Sphere10Dp45Legacy{ RoundSphere, SphereObserver, IntegratorType::DormandPrince45,
  LegacyDp45, 10.0, Roots, 1, true };
const Workload SquashedDp45New{ SquashedSphere, SquashedObserver, IntegratorType::DormandPrince45,
  NewDp45, 6.0, Roots, 2, false };
const Workload SquashedDp45Legacy{ SquashedSphere, SquashedObserver,
  IntegratorType::DormandPrince45, LegacyDp45, 6.0, Roots, 2, false };

/// What the search reported, summed over directions (the counters).
struct Outcome
{
  int Found = 0;
  int Double = 0;
  int BothSimple = 0;
  int Missed = 0;
  double MaximumError = 0.0;
  double MinimumGap = HUGE_VAL;
  double MaximumGap = 0.0;

  /// One direction's points, `wanted` of them asked for.
  void Add(const std::vector<riemann::ConjugatePoint>& points, int wanted)
  {
    int multiplicity = 0;
    for (const riemann::ConjugatePoint& point : points)
    {
      multiplicity += point.Multiplicity;
    }
    this->Missed += multiplicity < wanted ? 1 : 0;
    if (points.empty())
    {
      return;
    }
    ++this->Found;
    this->Double += points[0].Multiplicity == 2 ? 1 : 0;
    this->MaximumError = std::max(this->MaximumError, std::abs(points[0].ArcLength - Pi));
    if (points.size() >= 2 && points[0].Multiplicity == 1 && points[1].Multiplicity == 1)
    {
      ++this->BothSimple;
      const double gap = points[1].ArcLength - points[0].ArcLength;
      this->MinimumGap = std::min(this->MinimumGap, gap);
      this->MaximumGap = std::max(this->MaximumGap, gap);
    }
  }

  /// Another thread's share.
  void Merge(const Outcome& other)
  {
    this->Found += other.Found;
    this->Double += other.Double;
    this->BothSimple += other.BothSimple;
    this->Missed += other.Missed;
    this->MaximumError = std::max(this->MaximumError, other.MaximumError);
    this->MinimumGap = std::min(this->MinimumGap, other.MinimumGap);
    this->MaximumGap = std::max(this->MaximumGap, other.MaximumGap);
  }
};

/// The GeodesicOptions of a workload: vtkRiemannConjugateLocus's step
/// settings (first step 0.01, at most 0.1; RK4 at 0.01).
riemann::GeodesicOptions OptionsOf(const Workload& workload)
{
  riemann::GeodesicOptions options;
  options.Integrator = workload.Integrator;
  options.Step = 0.01;
  options.Tolerance = workload.IntegrationTolerance;
  options.MaximumStep = 0.1;
  options.MaximumLength = workload.Length;
  return options;
}

/// All directions on all threads, directions taken one at a time.
Outcome SearchAll(const riemann::Metric& metric, const Workload& workload,
  const riemann::GeodesicOptions& options, const std::vector<Vec3>& directions, Search search,
  unsigned threadCount)
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
        const int count = static_cast<int>(directions.size());
        for (int i = next++; i < count; i = next++)
        {
          outcome.Add(search(metric, workload.Observer, directions[i], options, workload.Tolerance,
                        workload.Wanted),
            workload.Wanted);
        }
      });
  }
  for (std::thread& thread : threads)
  {
    thread.join();
  }
  Outcome total;
  for (const Outcome& outcome : outcomes)
  {
    total.Merge(outcome);
  }
  return total;
}

/// All directions on all threads through the many-direction (packet)
/// FindConjugatePoints, in chunks of 32 directions taken one at a time.
Outcome SearchAllPackets(const riemann::Metric& metric, const Workload& workload,
  const riemann::GeodesicOptions& options, const std::vector<Vec3>& directions,
  unsigned threadCount)
{
  constexpr int Chunk = 4 * riemann::PacketWidth;
  std::atomic<int> next(0);
  std::vector<Outcome> outcomes(threadCount);
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < threadCount; ++t)
  {
    threads.emplace_back(
      [&, t]
      {
        std::vector<std::vector<riemann::ConjugatePoint>> found(Chunk);
        const int count = static_cast<int>(directions.size());
        for (int first = Chunk * next++; first < count; first = Chunk * next++)
        {
          const int n = std::min(Chunk, count - first);
          riemann::FindConjugatePoints(metric, workload.Observer, directions.data() + first,
            static_cast<size_t>(n), options, workload.Tolerance, workload.Wanted, found.data());
          for (int i = 0; i < n; ++i)
          {
            outcomes[t].Add(found[static_cast<size_t>(i)], workload.Wanted);
          }
        }
      });
  }
  for (std::thread& thread : threads)
  {
    thread.join();
  }
  Outcome total;
  for (const Outcome& outcome : outcomes)
  {
    total.Merge(outcome);
  }
  return total;
}

void BM_ConjugatePoints(benchmark::State& state, const Workload& workload, Search search)
{
  const auto metric = riemann::ParseMetricDefinition(
    std::string(R"json({"type":"conformal","n":")json") + workload.Factor + "\"}");
  const std::vector<Vec3> directions =
    riemann::FibonacciDirections(DirectionCount, Vec3(0.0, 0.0, 1.0), 180.0);
  const riemann::GeodesicOptions options = OptionsOf(workload);
  const unsigned threadCount = std::max(1u, std::thread::hardware_concurrency());

  Outcome total;
  for (auto _ : state)
  {
    total = search ? SearchAll(*metric, workload, options, directions, search, threadCount)
                   : SearchAllPackets(*metric, workload, options, directions, threadCount);
  }
  state.counters["directions_per_second"] = benchmark::Counter(
    static_cast<double>(DirectionCount) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["found"] = total.Found;
  state.counters["double"] = total.Double;
  if (workload.RoundSphere)
  {
    state.counters["max_error"] = total.MaximumError;
  }
  else
  {
    state.counters["both_simple"] = total.BothSimple;
    state.counters["missed"] = total.Missed;
    state.counters["min_gap"] = total.BothSimple > 0 ? total.MinimumGap : 0.0;
    state.counters["max_gap"] = total.MaximumGap;
  }
  state.counters["threads"] = threadCount;
}
} // namespace

// Real time: the workers' time is what a user waits for. Each new/legacy pair
// is registered together so that they run one after the other.
#define RIEMANN_CONJUGATE_BENCHMARK(name, workload, search)                                        \
  BENCHMARK_CAPTURE(BM_ConjugatePoints, name, workload, search)                                    \
    ->Unit(benchmark::kMillisecond)                                                                \
    ->MeasureProcessCPUTime()                                                                      \
    ->UseRealTime()                                                                                \
    ->Iterations(1)

RIEMANN_CONJUGATE_BENCHMARK(sphere_dp45_packet, SphereDp45New, PacketSearch);
RIEMANN_CONJUGATE_BENCHMARK(sphere_dp45_new, SphereDp45New, NewSearch);
RIEMANN_CONJUGATE_BENCHMARK(sphere_dp45_legacy, SphereDp45Legacy, LegacySearch);
RIEMANN_CONJUGATE_BENCHMARK(sphere_rk4_packet, SphereRk4New, PacketSearch);
RIEMANN_CONJUGATE_BENCHMARK(sphere_rk4_new, SphereRk4New, NewSearch);
RIEMANN_CONJUGATE_BENCHMARK(sphere_rk4_legacy, SphereRk4Legacy, LegacySearch);
RIEMANN_CONJUGATE_BENCHMARK(sphere10_dp45_packet, Sphere10Dp45New, PacketSearch);
RIEMANN_CONJUGATE_BENCHMARK(sphere10_dp45_new, Sphere10Dp45New, NewSearch);
RIEMANN_CONJUGATE_BENCHMARK(sphere10_dp45_legacy, Sphere10Dp45Legacy, LegacySearch);
RIEMANN_CONJUGATE_BENCHMARK(squashed_dp45_packet, SquashedDp45New, PacketSearch);
RIEMANN_CONJUGATE_BENCHMARK(squashed_dp45_new, SquashedDp45New, NewSearch);
RIEMANN_CONJUGATE_BENCHMARK(squashed_dp45_legacy, SquashedDp45Legacy, LegacySearch);
