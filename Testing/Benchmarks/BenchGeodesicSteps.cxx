/**
 * @file BenchGeodesicSteps.cxx
 * @brief Geodesic steps per second on the graph metric of 8 Gaussian bumps
 * with classical RK4: the library against a hand-inlined reference.
 *
 * Every benchmark does the same work per iteration: 64 geodesics of exactly
 * 1000 RK4 steps of arc length 0.01, and reports items_per_second = steps/s.
 *
 * - BM_GeodesicTrace/{drift,no_drift}: riemann::TraceGeodesic, one thread,
 *   one reused GeodesicPath. "drift" is the default options (one extra
 *   metric evaluation per step for the speed drift); "no_drift" sets
 *   RecordSpeedDrift = false, the same work as the hand-inlined loop.
 * - BM_GeodesicTraceAllCores/...: the same on hardware_concurrency threads.
 * - BM_GeodesicHandInlined / BM_GeodesicHandInlinedAllCores: the same
 *   geodesics as a plain C++ loop on arrays (the Gaussians' gradient and
 *   Hessian written out, RK4 written out), storing every point. It is what
 *   the library's abstractions (virtual fields and metric, jets, Eigen,
 *   recording) are measured against.
 * - BM_GeodesicRungeKutta4Step: riemann::RungeKutta4Step alone in a loop (no
 *   recording), to split TraceGeodesic's time into integrator and recording.
 *
 * Before anything is timed, Scene::Get() checks that all variants integrate
 * the same geodesics (same endpoints to 1e-10, exactly 1000 steps each) and
 * aborts otherwise: the ratios are only meaningful for equal work.
 */
#include "EightBumps.h"
#include "GeodesicTrace.h"
#include "HandPacketReference.h"
#include "Integrators.h"
#include "PacketTrace.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>
#include <vector>

namespace
{
using riemann::Vec3;
using riemann::Vec6;

// The 8 bumps (EightBumps.h).
using riemann::bench::Bump;
using riemann::bench::BumpCount;
using riemann::bench::Bumps;

constexpr int SeedCount = 64;
constexpr int StepsPerGeodesic = 1000;
constexpr double Step = 0.01;
// Endpoints of the library and of the reference may differ by rounding only
// (different operation order), amplified along 1000 steps.
constexpr double EndpointTolerance = 1e-10;

/// The bumps as plain arrays (structure of arrays) for the hand-inlined loop.
struct PlainBumps
{
  double Amplitude[BumpCount];
  double Center[3][BumpCount];
  double InverseVariance[3][BumpCount]; // 1 / sigma^2, as GaussianField does
};

struct Seed
{
  Vec3 Point;
  Vec3 Velocity; // unit speed in g
};

// ---------------------------------------------------------------------------
// The hand-inlined reference.

/**
 * Geodesic flow (x, v) -> (v, a) of the graph metric of f = sum of bumps:
 * a = -grad f (v^T H v) / (1 + |grad f|^2), with
 * d_i f = -u_i f and d_i d_j f = (u_i u_j - delta_ij w_i) f per bump
 * (u = w (x - c), w = 1 / sigma^2). No finiteness checks: f is smooth and
 * bounded, so nothing can become degenerate on this metric.
 */
inline void HandFlow(const PlainBumps& b, const double y[6], double flow[6])
{
  double gx = 0, gy = 0, gz = 0;
  double hxx = 0, hyy = 0, hzz = 0, hxy = 0, hxz = 0, hyz = 0;
  for (int k = 0; k < BumpCount; ++k)
  {
    const double dx = y[0] - b.Center[0][k];
    const double dy = y[1] - b.Center[1][k];
    const double dz = y[2] - b.Center[2][k];
    const double ux = b.InverseVariance[0][k] * dx;
    const double uy = b.InverseVariance[1][k] * dy;
    const double uz = b.InverseVariance[2][k] * dz;
    const double f = b.Amplitude[k] * std::exp(-0.5 * (dx * ux + dy * uy + dz * uz));
    gx -= f * ux;
    gy -= f * uy;
    gz -= f * uz;
    // Only the 6 distinct entries of the symmetric Hessian.
    hxx += f * (ux * ux - b.InverseVariance[0][k]);
    hyy += f * (uy * uy - b.InverseVariance[1][k]);
    hzz += f * (uz * uz - b.InverseVariance[2][k]);
    hxy += f * ux * uy;
    hxz += f * ux * uz;
    hyz += f * uy * uz;
  }
  const double vx = y[3], vy = y[4], vz = y[5];
  const double vHv = hxx * vx * vx + hyy * vy * vy + hzz * vz * vz +
    2.0 * (hxy * vx * vy + hxz * vx * vz + hyz * vy * vz);
  const double s = -vHv / (1.0 + gx * gx + gy * gy + gz * gz);
  flow[0] = vx;
  flow[1] = vy;
  flow[2] = vz;
  flow[3] = s * gx;
  flow[4] = s * gy;
  flow[5] = s * gz;
}

/**
 * StepsPerGeodesic classical RK4 steps from the seed, storing the seed and
 * every step's point in `points` (3 * (StepsPerGeodesic + 1) doubles, as
 * TraceGeodesic records StepsPerGeodesic + 1 points). `y` ends as (x, v).
 */
inline void HandTrace(const PlainBumps& b, const Seed& seed, double* points, double y[6])
{
  for (int i = 0; i < 3; ++i)
  {
    y[i] = seed.Point[i];
    y[3 + i] = seed.Velocity[i];
    points[i] = y[i];
  }
  const double h = Step;
  double k1[6], k2[6], k3[6], k4[6], t[6];
  for (int n = 1; n <= StepsPerGeodesic; ++n)
  {
    HandFlow(b, y, k1);
    for (int i = 0; i < 6; ++i)
    {
      t[i] = y[i] + 0.5 * h * k1[i];
    }
    HandFlow(b, t, k2);
    for (int i = 0; i < 6; ++i)
    {
      t[i] = y[i] + 0.5 * h * k2[i];
    }
    HandFlow(b, t, k3);
    for (int i = 0; i < 6; ++i)
    {
      t[i] = y[i] + h * k3[i];
    }
    HandFlow(b, t, k4);
    for (int i = 0; i < 6; ++i)
    {
      y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    points[3 * n] = y[0];
    points[3 * n + 1] = y[1];
    points[3 * n + 2] = y[2];
  }
}

// ---------------------------------------------------------------------------
// The library's integrator without TraceGeodesic's recording.

/// StepsPerGeodesic riemann::RungeKutta4Step calls; false if one fails.
bool StepOnly(const riemann::Metric& metric, const Seed& seed, Vec6& y)
{
  y << seed.Point, seed.Velocity;
  for (int n = 0; n < StepsPerGeodesic; ++n)
  {
    if (!riemann::RungeKutta4Step(metric, y, Step))
    {
      return false;
    }
  }
  return true;
}

// ---------------------------------------------------------------------------
// The shared, verified setup.

[[noreturn]] void Fail(const char* what, int seed, double difference)
{
  std::fprintf(stderr,
    "BenchGeodesicSteps: %s (seed %d, difference %g): not comparing unequal work\n", what, seed,
    difference);
  std::abort();
}

class Scene
{
public:
  std::shared_ptr<const riemann::Metric> Metric;
  PlainBumps Plain;
  std::vector<Seed> Seeds;
  /// The same seeds for the packet engine.
  std::vector<riemann::GeodesicSeed> PacketSeeds;
  /// The bumps for the SIMD hand-written reference.
  riemann_bench::HandBumps Hand;
  /// RK4, step 0.01, MaximumLength = 1000 steps (MaximumSteps is not reached).
  riemann::GeodesicOptions Options;
  /// dp45 over the same length, tolerance 1e-8 (the library's default).
  riemann::GeodesicOptions AdaptiveOptions;
  /// Accepted dp45 steps of all seeds (TraceGeodesic's), for steps/s.
  long long AdaptiveSteps = 0;

  /// Built and verified once, on first use (never inside a timed loop).
  static const Scene& Get()
  {
    static const Scene scene;
    return scene;
  }

private:
  Scene()
  {
    for (int k = 0; k < BumpCount; ++k)
    {
      const Bump& bump = Bumps[k];
      this->Plain.Amplitude[k] = bump.Amplitude;
      this->Hand.Amplitude[k] = bump.Amplitude;
      for (int i = 0; i < 3; ++i)
      {
        this->Plain.Center[i][k] = bump.Center[i];
        this->Plain.InverseVariance[i][k] = 1.0 / (bump.Sigma[i] * bump.Sigma[i]);
        this->Hand.Center[i][k] = bump.Center[i];
        this->Hand.InverseVariance[i][k] = this->Plain.InverseVariance[i][k];
      }
    }
    this->Metric = riemann::bench::GraphOfEightBumps();

    this->Options.Integrator = riemann::IntegratorType::RungeKutta4;
    this->Options.Step = Step;
    this->Options.MaximumLength = StepsPerGeodesic * Step;
    this->Options.MaximumSteps = 10 * StepsPerGeodesic;
    this->Hand.Count = BumpCount;
    this->AdaptiveOptions = this->Options;
    this->AdaptiveOptions.Integrator = riemann::IntegratorType::DormandPrince45;
    this->AdaptiveOptions.Tolerance = 1e-8;

    this->MakeSeeds();
    this->Verify();
  }

  /**
   * Seed i starts 1.2 from bump i % 8 (directions spread by a Fibonacci
   * sphere) and aims slightly off that bump's center, so every geodesic
   * crosses a bump's slope and bends, instead of running straight.
   */
  void MakeSeeds()
  {
    const double goldenAngle = std::acos(-1.0) * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < SeedCount; ++i)
    {
      const Bump& bump = Bumps[i % BumpCount];
      const Vec3 center(bump.Center[0], bump.Center[1], bump.Center[2]);
      const double z = 1.0 - (2.0 * i + 1.0) / SeedCount;
      const double r = std::sqrt(1.0 - z * z);
      const Vec3 out(r * std::cos(goldenAngle * i), r * std::sin(goldenAngle * i), z);
      const Vec3 miss = 0.3 * Vec3(std::sin(1.0 * i), std::cos(0.7 * i), std::sin(1.3 * i));
      Seed seed;
      seed.Point = center + 1.2 * out;
      if (!riemann::UnitSpeedVelocity(
            *this->Metric, seed.Point, center + miss - seed.Point, seed.Velocity))
      {
        Fail("no unit-speed velocity", i, 0.0);
      }
      this->Seeds.push_back(seed);
      this->PacketSeeds.push_back({ seed.Point, seed.Velocity, false });
    }
  }

  /// All variants give the same endpoints after exactly StepsPerGeodesic steps.
  void Verify()
  {
    riemann::GeodesicPath path;
    std::vector<double> points(3 * (StepsPerGeodesic + 1));
    for (int i = 0; i < SeedCount; ++i)
    {
      const Seed& seed = this->Seeds[i];
      riemann::TraceGeodesic(*this->Metric, seed.Point, seed.Velocity, this->Options, path);
      if (path.Reason != riemann::OutOfLength ||
        path.Points.size() != static_cast<size_t>(StepsPerGeodesic + 1))
      {
        Fail("TraceGeodesic did not take exactly StepsPerGeodesic steps", i,
          static_cast<double>(path.Points.size()) - (StepsPerGeodesic + 1));
      }
      const Vec3 ours = path.Points.back();

      double y[6];
      HandTrace(this->Plain, seed, points.data(), y);
      const double handDifference = (ours - Vec3(y[0], y[1], y[2])).cwiseAbs().maxCoeff();
      if (!(handDifference <= EndpointTolerance))
      {
        Fail("TraceGeodesic and the hand-inlined loop disagree", i, handDifference);
      }

      Vec6 stepped;
      if (!StepOnly(*this->Metric, seed, stepped))
      {
        Fail("RungeKutta4Step failed", i, 0.0);
      }
      const double stepDifference = (ours - stepped.head<3>()).cwiseAbs().maxCoeff();
      if (!(stepDifference <= EndpointTolerance))
      {
        Fail("TraceGeodesic and the RungeKutta4Step loop disagree", i, stepDifference);
      }
    }
    this->VerifyPackets();
  }

  /**
   * The packet engine and the SIMD reference give TraceGeodesic's endpoints
   * too, with RK4 and with dp45 (same number of accepted steps); records the
   * dp45 step count for steps/s.
   */
  void VerifyPackets()
  {
    std::vector<riemann::GeodesicPath> packet(SeedCount);
    std::vector<double> handPoints(3 * StepsPerGeodesic * riemann_bench::HandLanes);
    for (const riemann::GeodesicOptions* options : { &this->Options, &this->AdaptiveOptions })
    {
      const bool adaptive = options == &this->AdaptiveOptions;
      riemann::TraceGeodesics(
        *this->Metric, this->PacketSeeds.data(), SeedCount, *options, packet.data());
      for (int first = 0; first < SeedCount; first += riemann_bench::HandLanes)
      {
        riemann_bench::HandState y = HandStart(first);
        long long handSteps[riemann_bench::HandLanes];
        if (adaptive)
        {
          std::vector<std::vector<double>> lanePoints(
            riemann_bench::HandLanes, std::vector<double>(3 * 100000));
          double* pointers[riemann_bench::HandLanes];
          for (int l = 0; l < riemann_bench::HandLanes; ++l)
          {
            pointers[l] = lanePoints[l].data();
          }
          HandDormandPrince45(y, pointers, 100000, handSteps);
        }
        else
        {
          riemann_bench::HandPacketRungeKutta4(
            this->Hand, y, StepsPerGeodesic, Step, handPoints.data());
        }
        for (int l = 0; l < riemann_bench::HandLanes; ++l)
        {
          const int i = first + l;
          riemann::GeodesicPath scalar;
          riemann::TraceGeodesic(
            *this->Metric, this->Seeds[i].Point, this->Seeds[i].Velocity, *options, scalar);
          if (packet[i].Reason != riemann::OutOfLength ||
            packet[i].Points.size() != scalar.Points.size())
          {
            Fail("TraceGeodesics and TraceGeodesic took different steps", i,
              static_cast<double>(packet[i].Points.size()) -
                static_cast<double>(scalar.Points.size()));
          }
          const double packetDifference =
            (packet[i].Points.back() - scalar.Points.back()).cwiseAbs().maxCoeff();
          if (!(packetDifference <= EndpointTolerance))
          {
            Fail("TraceGeodesics and TraceGeodesic disagree", i, packetDifference);
          }
          const Vec3 hand(y.Y[0][l], y.Y[1][l], y.Y[2][l]);
          const double handDifference = (hand - scalar.Points.back()).cwiseAbs().maxCoeff();
          if (!(handDifference <= EndpointTolerance) ||
            (adaptive && handSteps[l] + 1 != static_cast<long long>(scalar.Points.size())))
          {
            Fail("the SIMD reference and TraceGeodesic disagree", i, handDifference);
          }
          if (adaptive)
          {
            this->AdaptiveSteps += handSteps[l];
          }
        }
      }
    }
  }

public:
  /// The 8 seeds from `first` as the reference's state.
  riemann_bench::HandState HandStart(int first) const
  {
    riemann_bench::HandState y;
    for (int l = 0; l < riemann_bench::HandLanes; ++l)
    {
      for (int i = 0; i < 3; ++i)
      {
        y.Y[i][l] = this->Seeds[first + l].Point[i];
        y.Y[3 + i][l] = this->Seeds[first + l].Velocity[i];
      }
    }
    return y;
  }

  /// The reference's dp45 with AdaptiveOptions.
  void HandDormandPrince45(riemann_bench::HandState& y, double* const* points, std::size_t capacity,
    long long* steps) const
  {
    const riemann::GeodesicOptions& o = this->AdaptiveOptions;
    riemann_bench::HandPacketDormandPrince45(this->Hand, y, o.MaximumLength, o.Step, o.Tolerance,
      o.MinimumStep, o.MaximumStep, points, capacity, steps);
  }
};

// ---------------------------------------------------------------------------
// Helpers shared by the benchmarks.

unsigned ThreadCount()
{
  return std::max(1u, std::thread::hardware_concurrency());
}

/**
 * Run work(thread, firstSeed, endSeed) on ThreadCount() threads, seeds split
 * in equal contiguous blocks (every geodesic costs the same 1000 steps).
 * Threads are started per call: ~10-50 us against tens of milliseconds of
 * work, and it is what a caller without a pool (the VTK filter) pays too.
 */
template <typename Work>
void RunOnAllCores(unsigned threadCount, const Work& work)
{
  std::vector<std::thread> threads;
  threads.reserve(threadCount);
  for (unsigned t = 0; t < threadCount; ++t)
  {
    const int begin = static_cast<int>(SeedCount * t / threadCount);
    const int end = static_cast<int>(SeedCount * (t + 1) / threadCount);
    threads.emplace_back([&work, t, begin, end] { work(t, begin, end); });
  }
  for (std::thread& thread : threads)
  {
    thread.join();
  }
}

/**
 * One thread's GeodesicPath on its own cache lines: push_back writes the
 * vectors' end pointers at every step, and two threads' paths side by side in
 * a std::vector would false-share them.
 */
struct alignas(64) ThreadPath
{
  riemann::GeodesicPath Path;
};

/// One thread's hand-inlined output buffer, for the same reason.
struct alignas(64) ThreadPoints
{
  std::vector<double> Points = std::vector<double>(3 * (StepsPerGeodesic + 1));
};

void ReportSteps(benchmark::State& state, unsigned threadCount)
{
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(SeedCount) * StepsPerGeodesic);
  state.counters["threads"] = threadCount;
}

riemann::GeodesicOptions OptionsWithDrift(const Scene& scene, bool recordSpeedDrift)
{
  riemann::GeodesicOptions options = scene.Options;
  options.RecordSpeedDrift = recordSpeedDrift;
  return options;
}

// ---------------------------------------------------------------------------
// The benchmarks.

void BM_GeodesicTrace(benchmark::State& state, bool recordSpeedDrift)
{
  const Scene& scene = Scene::Get();
  const riemann::GeodesicOptions options = OptionsWithDrift(scene, recordSpeedDrift);
  riemann::GeodesicPath path;
  // One untimed trace grows the path to its final capacity: the timed loop
  // then measures integration and recording, not allocation.
  riemann::TraceGeodesic(
    *scene.Metric, scene.Seeds[0].Point, scene.Seeds[0].Velocity, options, path);
  for (auto _ : state)
  {
    for (const Seed& seed : scene.Seeds)
    {
      riemann::TraceGeodesic(*scene.Metric, seed.Point, seed.Velocity, options, path);
      benchmark::DoNotOptimize(path.Points.back());
    }
  }
  ReportSteps(state, 1);
}
BENCHMARK_CAPTURE(BM_GeodesicTrace, drift, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GeodesicTrace, no_drift, false)->Unit(benchmark::kMillisecond);

void BM_GeodesicTraceAllCores(benchmark::State& state, bool recordSpeedDrift)
{
  const Scene& scene = Scene::Get();
  const riemann::GeodesicOptions options = OptionsWithDrift(scene, recordSpeedDrift);
  const unsigned threadCount = ThreadCount();
  std::vector<ThreadPath> paths(threadCount);
  for (ThreadPath& path : paths)
  {
    riemann::TraceGeodesic(
      *scene.Metric, scene.Seeds[0].Point, scene.Seeds[0].Velocity, options, path.Path);
  }
  for (auto _ : state)
  {
    RunOnAllCores(threadCount,
      [&](unsigned t, int begin, int end)
      {
        riemann::GeodesicPath& path = paths[t].Path;
        for (int i = begin; i < end; ++i)
        {
          const Seed& seed = scene.Seeds[i];
          riemann::TraceGeodesic(*scene.Metric, seed.Point, seed.Velocity, options, path);
          benchmark::DoNotOptimize(path.Points.back());
        }
      });
  }
  ReportSteps(state, threadCount);
}
// Real time: the CPU time of the main thread would not count the workers.
// Process CPU time makes the "CPU" column the total over all threads.
BENCHMARK_CAPTURE(BM_GeodesicTraceAllCores, drift, true)
  ->Unit(benchmark::kMillisecond)
  ->MeasureProcessCPUTime()
  ->UseRealTime();
BENCHMARK_CAPTURE(BM_GeodesicTraceAllCores, no_drift, false)
  ->Unit(benchmark::kMillisecond)
  ->MeasureProcessCPUTime()
  ->UseRealTime();

void BM_GeodesicHandInlined(benchmark::State& state)
{
  const Scene& scene = Scene::Get();
  std::vector<double> points(3 * (StepsPerGeodesic + 1));
  double y[6];
  for (auto _ : state)
  {
    for (const Seed& seed : scene.Seeds)
    {
      HandTrace(scene.Plain, seed, points.data(), y);
      // The stored points are never read: keep the compiler from dropping them.
      benchmark::DoNotOptimize(points.data());
      benchmark::ClobberMemory();
    }
  }
  ReportSteps(state, 1);
}
BENCHMARK(BM_GeodesicHandInlined)->Unit(benchmark::kMillisecond);

void BM_GeodesicHandInlinedAllCores(benchmark::State& state)
{
  const Scene& scene = Scene::Get();
  const unsigned threadCount = ThreadCount();
  std::vector<ThreadPoints> buffers(threadCount);
  for (auto _ : state)
  {
    RunOnAllCores(threadCount,
      [&](unsigned t, int begin, int end)
      {
        double* points = buffers[t].Points.data();
        double y[6];
        for (int i = begin; i < end; ++i)
        {
          HandTrace(scene.Plain, scene.Seeds[i], points, y);
          benchmark::DoNotOptimize(points);
          benchmark::ClobberMemory();
        }
      });
  }
  ReportSteps(state, threadCount);
}
BENCHMARK(BM_GeodesicHandInlinedAllCores)
  ->Unit(benchmark::kMillisecond)
  ->MeasureProcessCPUTime()
  ->UseRealTime();

void BM_GeodesicRungeKutta4Step(benchmark::State& state)
{
  const Scene& scene = Scene::Get();
  Vec6 y;
  for (auto _ : state)
  {
    for (const Seed& seed : scene.Seeds)
    {
      if (!StepOnly(*scene.Metric, seed, y))
      {
        state.SkipWithError("RungeKutta4Step failed");
        return;
      }
      benchmark::DoNotOptimize(y);
    }
  }
  ReportSteps(state, 1);
}
BENCHMARK(BM_GeodesicRungeKutta4Step)->Unit(benchmark::kMillisecond);
// ---------------------------------------------------------------------------
// The packet engine against the SIMD hand-written reference and today's
// scalar tracer, RK4 and dp45 (items_per_second = accepted steps/s).

const riemann::GeodesicOptions& OptionsFor(const Scene& scene, bool adaptive, bool drift)
{
  static thread_local riemann::GeodesicOptions options;
  options = adaptive ? scene.AdaptiveOptions : scene.Options;
  options.RecordSpeedDrift = drift;
  return options;
}

long long StepsOf(const Scene& scene, bool adaptive)
{
  return adaptive ? scene.AdaptiveSteps : static_cast<long long>(SeedCount) * StepsPerGeodesic;
}

void ReportStepsOf(benchmark::State& state, const Scene& scene, bool adaptive, unsigned threads)
{
  state.SetItemsProcessed(state.iterations() * StepsOf(scene, adaptive));
  state.counters["threads"] = threads;
}

/// Today's scalar path (TraceGeodesic per seed), for dp45 (RK4: BM_GeodesicTrace).
void BM_GeodesicTraceAdaptive(benchmark::State& state, bool drift)
{
  const Scene& scene = Scene::Get();
  const riemann::GeodesicOptions options = OptionsFor(scene, true, drift);
  riemann::GeodesicPath path;
  for (auto _ : state)
  {
    for (const Seed& seed : scene.Seeds)
    {
      riemann::TraceGeodesic(*scene.Metric, seed.Point, seed.Velocity, options, path);
      benchmark::DoNotOptimize(path.Points.back());
    }
  }
  ReportStepsOf(state, scene, true, 1);
}
BENCHMARK_CAPTURE(BM_GeodesicTraceAdaptive, dp45_no_drift, false)->Unit(benchmark::kMillisecond);

/// The library's packet engine: TraceGeodesics over the 64 seeds.
void BM_GeodesicPacketTrace(benchmark::State& state, bool adaptive, bool drift)
{
  const Scene& scene = Scene::Get();
  const riemann::GeodesicOptions options = OptionsFor(scene, adaptive, drift);
  std::vector<riemann::GeodesicPath> paths(SeedCount);
  riemann::TraceGeodesics(
    *scene.Metric, scene.PacketSeeds.data(), SeedCount, options, paths.data());
  for (auto _ : state)
  {
    riemann::TraceGeodesics(
      *scene.Metric, scene.PacketSeeds.data(), SeedCount, options, paths.data());
    benchmark::DoNotOptimize(paths.back().Points.back());
  }
  ReportStepsOf(state, scene, adaptive, 1);
}
BENCHMARK_CAPTURE(BM_GeodesicPacketTrace, rk4_drift, false, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GeodesicPacketTrace, rk4_no_drift, false, false)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GeodesicPacketTrace, dp45_no_drift, true, false)
  ->Unit(benchmark::kMillisecond);

void BM_GeodesicPacketTraceAllCores(benchmark::State& state, bool adaptive, bool drift)
{
  const Scene& scene = Scene::Get();
  const riemann::GeodesicOptions options = OptionsFor(scene, adaptive, drift);
  const unsigned threadCount = ThreadCount();
  std::vector<riemann::GeodesicPath> paths(SeedCount);
  riemann::TraceGeodesics(
    *scene.Metric, scene.PacketSeeds.data(), SeedCount, options, paths.data());
  for (auto _ : state)
  {
    RunOnAllCores(threadCount,
      [&](unsigned, int begin, int end)
      {
        riemann::TraceGeodesics(*scene.Metric, scene.PacketSeeds.data() + begin,
          static_cast<size_t>(end - begin), options, paths.data() + begin);
      });
    benchmark::DoNotOptimize(paths.back().Points.back());
  }
  ReportStepsOf(state, scene, adaptive, threadCount);
}
BENCHMARK_CAPTURE(BM_GeodesicPacketTraceAllCores, rk4_no_drift, false, false)
  ->Unit(benchmark::kMillisecond)
  ->MeasureProcessCPUTime()
  ->UseRealTime();
BENCHMARK_CAPTURE(BM_GeodesicPacketTraceAllCores, dp45_no_drift, true, false)
  ->Unit(benchmark::kMillisecond)
  ->MeasureProcessCPUTime()
  ->UseRealTime();

/// The SIMD hand-written reference over seeds [begin, end) (whole packets).
void HandPackets(const Scene& scene, bool adaptive, int begin, int end, std::vector<double>& buffer)
{
  constexpr int W = riemann_bench::HandLanes;
  const size_t perLane = buffer.size() / W;
  for (int first = begin; first < end; first += W)
  {
    riemann_bench::HandState y = scene.HandStart(first);
    if (adaptive)
    {
      double* pointers[W];
      for (int l = 0; l < W; ++l)
      {
        pointers[l] = buffer.data() + l * perLane;
      }
      long long steps[W];
      scene.HandDormandPrince45(y, pointers, perLane / 3, steps);
    }
    else
    {
      riemann_bench::HandPacketRungeKutta4(scene.Hand, y, StepsPerGeodesic, Step, buffer.data());
    }
    benchmark::DoNotOptimize(buffer.data());
    benchmark::ClobberMemory();
  }
}

void BM_GeodesicHandPacket(benchmark::State& state, bool adaptive)
{
  const Scene& scene = Scene::Get();
  std::vector<double> buffer(3 * 20000 * riemann_bench::HandLanes);
  for (auto _ : state)
  {
    HandPackets(scene, adaptive, 0, SeedCount, buffer);
  }
  ReportStepsOf(state, scene, adaptive, 1);
  state.SetLabel(riemann_bench::HandPacketTargetName());
}
BENCHMARK_CAPTURE(BM_GeodesicHandPacket, rk4, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GeodesicHandPacket, dp45, true)->Unit(benchmark::kMillisecond);

void BM_GeodesicHandPacketAllCores(benchmark::State& state, bool adaptive)
{
  const Scene& scene = Scene::Get();
  const unsigned threadCount = ThreadCount();
  std::vector<std::vector<double>> buffers(
    threadCount, std::vector<double>(3 * 20000 * riemann_bench::HandLanes));
  for (auto _ : state)
  {
    RunOnAllCores(threadCount,
      [&](unsigned t, int begin, int end)
      { HandPackets(scene, adaptive, begin, end, buffers[t]); });
  }
  ReportStepsOf(state, scene, adaptive, threadCount);
}
BENCHMARK_CAPTURE(BM_GeodesicHandPacketAllCores, rk4, false)
  ->Unit(benchmark::kMillisecond)
  ->MeasureProcessCPUTime()
  ->UseRealTime();
BENCHMARK_CAPTURE(BM_GeodesicHandPacketAllCores, dp45, true)
  ->Unit(benchmark::kMillisecond)
  ->MeasureProcessCPUTime()
  ->UseRealTime();

void BM_GeodesicTraceAdaptiveAllCores(benchmark::State& state)
{
  const Scene& scene = Scene::Get();
  const riemann::GeodesicOptions options = OptionsFor(scene, true, false);
  const unsigned threadCount = ThreadCount();
  std::vector<ThreadPath> paths(threadCount);
  for (auto _ : state)
  {
    RunOnAllCores(threadCount,
      [&](unsigned t, int begin, int end)
      {
        for (int i = begin; i < end; ++i)
        {
          const Seed& seed = scene.Seeds[i];
          riemann::TraceGeodesic(*scene.Metric, seed.Point, seed.Velocity, options, paths[t].Path);
          benchmark::DoNotOptimize(paths[t].Path.Points.back());
        }
      });
  }
  ReportStepsOf(state, scene, true, threadCount);
}
BENCHMARK(BM_GeodesicTraceAdaptiveAllCores)
  ->Unit(benchmark::kMillisecond)
  ->MeasureProcessCPUTime()
  ->UseRealTime();
} // namespace
