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
#include "GaussianField.h"
#include "GeodesicTrace.h"
#include "GraphMetric.h"
#include "Integrators.h"
#include "ScalarFieldSum.h"

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

constexpr int BumpCount = 8;
constexpr int SeedCount = 64;
constexpr int StepsPerGeodesic = 1000;
constexpr double Step = 0.01;
// Endpoints of the library and of the reference may differ by rounding only
// (different operation order), amplified along 1000 steps.
constexpr double EndpointTolerance = 1e-10;

struct Bump
{
  double Amplitude;
  double Center[3];
  double Sigma[3];
};

// Amplitudes 0.3-1, centers in [-1.5, 1.5]^3, sigmas 0.4-0.8; half of them
// anisotropic, so the Hessians have off-diagonal structure along geodesics.
constexpr Bump Bumps[BumpCount] = {
  { 1.00, { -1.0, -1.0, -0.5 }, { 0.60, 0.60, 0.60 } },
  { 0.70, { 1.2, -0.8, 0.4 }, { 0.50, 0.80, 0.50 } },
  { 0.45, { -0.3, 1.1, 1.0 }, { 0.40, 0.40, 0.70 } },
  { 0.90, { 0.6, 0.5, -1.2 }, { 0.70, 0.50, 0.60 } },
  { 0.30, { -1.4, 0.3, 0.8 }, { 0.80, 0.80, 0.80 } },
  { 0.60, { 1.5, 1.4, 1.3 }, { 0.45, 0.60, 0.75 } },
  { 0.80, { 0.0, -1.5, 1.5 }, { 0.50, 0.50, 0.50 } },
  { 0.55, { 0.2, 0.1, 0.0 }, { 0.80, 0.40, 0.60 } },
};

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
  /// RK4, step 0.01, MaximumLength = 1000 steps (MaximumSteps is not reached).
  riemann::GeodesicOptions Options;

  /// Built and verified once, on first use (never inside a timed loop).
  static const Scene& Get()
  {
    static const Scene scene;
    return scene;
  }

private:
  Scene()
  {
    std::vector<std::shared_ptr<const riemann::ScalarField>> terms;
    for (int k = 0; k < BumpCount; ++k)
    {
      const Bump& bump = Bumps[k];
      const Vec3 center(bump.Center[0], bump.Center[1], bump.Center[2]);
      const Vec3 sigma(bump.Sigma[0], bump.Sigma[1], bump.Sigma[2]);
      terms.push_back(std::make_shared<riemann::GaussianField>(bump.Amplitude, center, sigma));
      this->Plain.Amplitude[k] = bump.Amplitude;
      for (int i = 0; i < 3; ++i)
      {
        this->Plain.Center[i][k] = bump.Center[i];
        this->Plain.InverseVariance[i][k] = 1.0 / (bump.Sigma[i] * bump.Sigma[i]);
      }
    }
    this->Metric = std::make_shared<riemann::GraphMetric>(
      std::make_shared<riemann::ScalarFieldSum>(0.0, std::move(terms)));

    this->Options.Integrator = riemann::IntegratorType::RungeKutta4;
    this->Options.Step = Step;
    this->Options.MaximumLength = StepsPerGeodesic * Step;
    this->Options.MaximumSteps = 10 * StepsPerGeodesic;

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
    }
  }

  /// All variants give the same endpoints after exactly StepsPerGeodesic steps.
  void Verify() const
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
} // namespace
