// Tests of the packet engine (Packet.h, PacketKernels.h, PacketTrace.h):
// - every family's AccelerationPacket and TensorPacket against the scalar
//   Acceleration and Tensor, lane by lane, to rounding (SIMD providers) or
//   exactly (the lane-by-lane default), with masked-out and degenerate lanes;
// - the Gaussian table kernel against GaussianField::Accumulate;
// - TraceGeodesics against TraceGeodesic for many seeds of different lengths
//   (lanes that finish at different steps and are refilled), every integrator
//   and every termination reason;
// - exact answers through the packet path: straight lines in flat metrics,
//   conserved g(v, v) on the 8-Gaussian graph metric.
#include "MetricTestUtilities.h"

#include "Expression.h"
#include "PacketTrace.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace riemann
{
namespace
{
using testing::Metrics;
using testing::RandomPoints;

/// The benchmark's 8 Gaussian bumps (Testing/Benchmarks), summed.
std::shared_ptr<const ScalarField> EightBumps()
{
  std::vector<std::shared_ptr<const ScalarField>> bumps;
  const double table[8][7] = {
    { 1.00, -1.0, -1.0, -0.5, 0.60, 0.60, 0.60 },
    { 0.70, 1.2, -0.8, 0.4, 0.50, 0.80, 0.50 },
    { 0.45, -0.3, 1.1, 1.0, 0.40, 0.40, 0.70 },
    { 0.90, 0.6, 0.5, -1.2, 0.70, 0.50, 0.60 },
    { 0.30, -1.4, 0.3, 0.8, 0.80, 0.80, 0.80 },
    { 0.60, 1.5, 1.4, 1.3, 0.45, 0.60, 0.75 },
    { 0.80, 0.0, -1.5, 1.5, 0.50, 0.50, 0.50 },
    { 0.55, 0.2, 0.1, 0.0, 0.80, 0.40, 0.60 },
  };
  for (const auto& b : table)
  {
    bumps.push_back(
      std::make_shared<GaussianField>(b[0], Vec3(b[1], b[2], b[3]), Vec3(b[4], b[5], b[6])));
  }
  return std::make_shared<ScalarFieldSum>(0.0, bumps);
}

/// Relative difference, with `floor` as the scale of values near zero.
double RelativeDifference(double a, double b, double floor = 1.0)
{
  return std::abs(a - b) / std::max({ std::abs(a), std::abs(b), floor });
}

TEST(PacketEngine, RunsOnANamedSimdTarget)
{
  const std::string target = PacketTargetName();
  std::cout << "packet kernels run on " << target << "\n";
  EXPECT_FALSE(target.empty());
  EXPECT_NE(target, "Unknown");
}

TEST(PacketEngine, GaussianTableEqualsTheScalarField)
{
  const auto sum = EightBumps();
  const auto points = RandomPoints(4 * PacketWidth, 2.5, 7);
  for (int order = ValueOnly; order <= SecondDerivatives; ++order)
  {
    for (size_t start = 0; start < points.size(); start += PacketWidth)
    {
      PacketVec3 p;
      for (int l = 0; l < PacketWidth; ++l)
      {
        p.SetLane(l, points[start + l]);
      }
      PacketScalarJet packet;
      sum->EvaluatePacket(p, order, packet, AllLanes);
      for (int l = 0; l < PacketWidth; ++l)
      {
        ScalarJet scalar;
        sum->Evaluate(points[start + l], order, scalar);
        EXPECT_LT(RelativeDifference(packet.Value[l], scalar.Value), 1e-14);
        for (int i = 0; order >= FirstDerivatives && i < 3; ++i)
        {
          EXPECT_LT(RelativeDifference(packet.Gradient[i][l], scalar.Gradient[i]), 1e-14);
        }
        if (order >= SecondDerivatives)
        {
          EXPECT_LT((packet.Hessian.Lane(l) - scalar.Hessian).cwiseAbs().maxCoeff(),
            1e-14 * std::max(1.0, scalar.Hessian.cwiseAbs().maxCoeff()));
        }
      }
    }
  }
}

TEST(PacketEngine, TapeOnPacketsEqualsTheScalarTapeForEveryFunction)
{
  // Every instruction of the tape, with lanes inside and outside the ranges
  // of Highway's vector functions (large sines, logs of negatives, exps that
  // overflow): each lane must equal the scalar interpreter's (or both NaN).
  const std::vector<std::string> sources = {
    "a*exp(-(x^2 + 2*y^2)/2) + sin(x*y) - cos(z) + tan(0.3*x) + sqrt(1 + y^2)",
    "log(x) + pow(abs(y) + 1, z) + sinh(x) * cosh(y) + tanh(z) + atan2(x*y, 1 + z^2) + atan2(y, x)",
    "abs(x - y) * x^3 + 1/(1 + x^2) + exp(x)*y*z + (x + y)*(y + z)*(z + x)*(x*y + 1)",
    // Sums read only by their exponential (ExpLin), one overflowing at x = 800.
    "exp(x - 2*y + 1) + exp(-(x - 1)^2 - (y + 2)^2 / 3)",
  };
  const CompiledExpressions compiled(sources, { "a" }, SecondDerivatives);
  const double a = 0.7;
  const double points[PacketWidth][3] = { { 0.3, -0.2, 0.5 }, { -1.5, 2.0, -0.7 },
    { 50000.0, 1.1, 0.2 }, { 800.0, 0.3, 1.0 }, { -2.0, -3.0, 0.25 }, { 1e-3, 4.0, -2.0 },
    { 0.0, 0.0, 0.0 }, { 2.5, -0.5, 3.0 } };
  PacketVec3 p;
  for (int l = 0; l < PacketWidth; ++l)
  {
    p.SetLane(l, Vec3(points[l][0], points[l][1], points[l][2]));
  }
  const int outputs = compiled.GetNumberOfOutputs();
  std::vector<double> packet(static_cast<size_t>(outputs) * PacketWidth);
  compiled.EvaluatePacket(p, 0.0, &a, packet.data(), SecondDerivatives);
  int compared = 0;
  for (int l = 0; l < PacketWidth; ++l)
  {
    std::vector<double> scalar(static_cast<size_t>(outputs));
    compiled.Evaluate(points[l], 0.0, &a, scalar.data(), SecondDerivatives);
    for (int o = 0; o < outputs; ++o)
    {
      const double ours = packet[static_cast<size_t>(o) * PacketWidth + l];
      if (std::isnan(scalar[o]))
      {
        EXPECT_TRUE(std::isnan(ours)) << "lane " << l << " output " << o;
        continue;
      }
      if (std::isinf(scalar[o]))
      {
        EXPECT_EQ(ours, scalar[o]) << "lane " << l << " output " << o;
        continue;
      }
      EXPECT_LT(RelativeDifference(ours, scalar[o]), 1e-12)
        << "lane " << l << " output " << o << ": " << ours << " vs " << scalar[o];
      ++compared;
    }
  }
  EXPECT_GT(compared, outputs * PacketWidth / 2);
}

TEST(PacketEngine, EveryFamilyAccelerationAndTensorEqualTheScalarOnes)
{
  auto metrics = Metrics();
  metrics.emplace_back("graph of 8 bumps", std::make_shared<GraphMetric>(EightBumps()));
  const auto points = RandomPoints(2 * PacketWidth, 1.5, 11);
  const auto velocities = RandomPoints(2 * PacketWidth, 1.0, 12);
  // Every other lane in use: the others must not be reported.
  const LaneMask lanes = 0x55u & AllLanes;
  for (const auto& [name, metric] : metrics)
  {
    SCOPED_TRACE(name);
    for (size_t start = 0; start < points.size(); start += PacketWidth)
    {
      PacketVec3 x, v, a;
      for (int l = 0; l < PacketWidth; ++l)
      {
        x.SetLane(l, points[start + l]);
        v.SetLane(l, velocities[start + l]);
      }
      const LaneMask accelerated = metric->AccelerationPacket(x, v, a, lanes);
      PacketSym3 g;
      const LaneMask tensors = metric->TensorPacket(x, g, lanes);
      for (int l = 0; l < PacketWidth; ++l)
      {
        Vec3 expected;
        Mat3 expectedG;
        const bool defined =
          metric->Acceleration(points[start + l], velocities[start + l], expected);
        const bool tensorDefined = metric->Tensor(points[start + l], expectedG);
        if (!HasLane(lanes, l))
        {
          EXPECT_FALSE(HasLane(accelerated, l) || HasLane(tensors, l)) << "lane " << l;
          continue;
        }
        ASSERT_EQ(HasLane(accelerated, l), defined) << "lane " << l;
        ASSERT_EQ(HasLane(tensors, l), tensorDefined) << "lane " << l;
        EXPECT_LT((a.Lane(l) - expected).norm(), 1e-13 * std::max(1.0, expected.norm()))
          << "lane " << l;
        EXPECT_LT((g.Lane(l) - expectedG).norm(), 1e-13 * std::max(1.0, expectedG.norm()))
          << "lane " << l;
      }
    }
  }
}

TEST(PacketEngine, DegenerateLanesAreReportedAloneInTheirPacket)
{
  // n = 1 - x vanishes at x = 1: lanes beyond it are undefined, the others not.
  ConformalMetric vanishing(std::make_shared<QuadraticField>(Mat3::Zero(), Vec3(-1, 0, 0), 1.0));
  ConformalMetric vanishingSum(std::make_shared<ScalarFieldSum>(1.0,
    std::vector<std::shared_ptr<const ScalarField>>{
      std::make_shared<GaussianField>(-2.0, Vec3(2, 0, 0), Vec3(0.3, 0.3, 0.3)) }));
  for (const ConformalMetric* metric : { &vanishing, &vanishingSum })
  {
    PacketVec3 x, v, a;
    for (int l = 0; l < PacketWidth; ++l)
    {
      x.SetLane(l, Vec3(0.3 * l, 0.1, 0.0));
      v.SetLane(l, Vec3(1, 0, 0));
    }
    const LaneMask defined = metric->AccelerationPacket(x, v, a, AllLanes);
    for (int l = 0; l < PacketWidth; ++l)
    {
      Vec3 expected;
      EXPECT_EQ(HasLane(defined, l), metric->Acceleration(x.Lane(l), v.Lane(l), expected))
        << metric->Describe() << " lane " << l;
    }
    EXPECT_NE(defined, 0u);
    EXPECT_NE(defined, AllLanes);
  }
}

/// Seeds around the origin, of different directions; every third backward.
std::vector<GeodesicSeed> Seeds(const Metric& metric, int count)
{
  std::vector<GeodesicSeed> seeds;
  const auto points = RandomPoints(count, 1.0, 3);
  const auto directions = RandomPoints(count, 1.0, 4);
  for (int i = 0; i < count; ++i)
  {
    GeodesicSeed seed;
    seed.Point = points[i];
    if (!UnitSpeedVelocity(metric, points[i], directions[i], seed.Velocity))
    {
      seed.Velocity = directions[i];
    }
    seed.Backward = i % 3 == 2;
    seeds.push_back(seed);
  }
  return seeds;
}

/**
 * How far the packet path may be from the scalar one. Fixed steps: rounding
 * only (fused multiply-adds, Highway's exp within 1 ulp), grown along the
 * path. dp45: the same accepted and rejected steps, but its error estimate
 * is a difference of nearly equal stages, so rounding moves it (and the
 * next step size) by ~1e-11 relative, and the paths then differ by the
 * order of the local error, a small multiple of the tolerance.
 */
double PathTolerance(const GeodesicOptions& options)
{
  return options.Integrator == IntegratorType::DormandPrince45 ? 50.0 * options.Tolerance : 1e-10;
}

/// TraceGeodesics must give TraceGeodesic's paths: same lengths and reasons,
/// points equal to `tolerance` (relative to the path's extent).
void ExpectSamePaths(const Metric& metric, const std::vector<GeodesicSeed>& seeds,
  const GeodesicOptions& options, double tolerance)
{
  std::vector<GeodesicPath> packet(seeds.size());
  TraceGeodesics(metric, seeds.data(), seeds.size(), options, packet.data());
  int compared = 0;
  for (size_t i = 0; i < seeds.size(); ++i)
  {
    GeodesicPath scalar;
    TraceGeodesic(metric, seeds[i].Point, seeds[i].Velocity, options, scalar, seeds[i].Backward);
    SCOPED_TRACE("seed " + std::to_string(i));
    ASSERT_EQ(packet[i].Reason, scalar.Reason);
    ASSERT_EQ(packet[i].Points.size(), scalar.Points.size());
    for (size_t k = 0; k < scalar.Points.size(); ++k)
    {
      const double scale = std::max(1.0, scalar.Points[k].norm());
      ASSERT_LT((packet[i].Points[k] - scalar.Points[k]).norm(), tolerance * scale)
        << "point " << k;
      ASSERT_LT((packet[i].Velocities[k] - scalar.Velocities[k]).norm(),
        tolerance * std::max(1.0, scalar.Velocities[k].norm()));
      ASSERT_NEAR(packet[i].ArcLength[k], scalar.ArcLength[k], tolerance * scale);
      ASSERT_NEAR(packet[i].SpeedDrift[k], scalar.SpeedDrift[k], tolerance);
    }
    ++compared;
  }
  EXPECT_EQ(compared, static_cast<int>(seeds.size()));
}

TEST(PacketEngine, TraceGeodesicsEqualsTraceGeodesicForEveryFamilyAndIntegrator)
{
  auto metrics = Metrics();
  metrics.emplace_back("graph of 8 bumps", std::make_shared<GraphMetric>(EightBumps()));
  for (const auto& [name, metric] : metrics)
  {
    // 21 seeds: two full packets and a partial one.
    const auto seeds = Seeds(*metric, 21);
    for (IntegratorType type :
      { IntegratorType::Euler, IntegratorType::RungeKutta4, IntegratorType::DormandPrince45 })
    {
      SCOPED_TRACE(name + ", " + IntegratorName(type));
      GeodesicOptions options;
      options.Integrator = type;
      options.Step = 0.05;
      options.MaximumLength = 2.0;
      options.Tolerance = 1e-9;
      // Different seeds leave the box at different steps: lanes finish
      // apart and are refilled.
      options.UseBounds = true;
      const double bounds[6] = { -1.6, 1.6, -1.4, 1.4, -1.5, 1.5 };
      std::copy(bounds, bounds + 6, options.Bounds);
      ExpectSamePaths(*metric, seeds, options, PathTolerance(options));
    }
  }
}

TEST(PacketEngine, TraceGeodesicsStopsForEveryReasonAsTheScalarTracer)
{
  GeodesicOptions options;
  options.Step = 0.1;
  options.MaximumLength = 10.0;
  // n = 1 - x reaches zero at x = 1 (degenerate), a zero direction (not
  // initialized), a short step budget (out of steps) and plain length.
  ConformalMetric vanishing(std::make_shared<QuadraticField>(Mat3::Zero(), Vec3(-1, 0, 0), 1.0));
  std::vector<GeodesicSeed> seeds(PacketWidth + 3);
  for (size_t i = 0; i < seeds.size(); ++i)
  {
    seeds[i].Point = Vec3(-0.5, 0.01 * i, 0.0);
    seeds[i].Velocity = i % 4 == 0 ? Vec3(1, 0, 0) : Vec3(0, i % 4 == 1 ? 1.0 : 0.0, 1);
  }
  seeds[3].Velocity = Vec3::Zero();
  for (IntegratorType type :
    { IntegratorType::Euler, IntegratorType::RungeKutta4, IntegratorType::DormandPrince45 })
  {
    SCOPED_TRACE(IntegratorName(type));
    options.Integrator = type;
    options.MaximumSteps = 100000;
    ExpectSamePaths(vanishing, seeds, options, PathTolerance(options));
    options.MaximumSteps = 7;
    ExpectSamePaths(vanishing, seeds, options, PathTolerance(options));
  }
  std::vector<GeodesicPath> paths(seeds.size());
  options.Integrator = IntegratorType::RungeKutta4;
  options.MaximumSteps = 100000;
  TraceGeodesics(vanishing, seeds.data(), seeds.size(), options, paths.data());
  EXPECT_TRUE(paths[0].Reason == DegenerateMetric || paths[0].Reason == Stagnation);
  EXPECT_EQ(paths[3].Reason, NotInitialized);
  EXPECT_EQ(paths[1].Reason, OutOfLength);
}

TEST(PacketEngine, FlatMetricsGiveStraightLines)
{
  // g = I + b b^T (the graph of a linear function) is constant: geodesics
  // are straight lines at constant coordinate speed, exactly.
  GraphMetric linear(std::make_shared<QuadraticField>(Mat3::Zero(), Vec3(0.5, -0.3, 0.2), 0.0));
  EuclideanMetric flat;
  for (const Metric* metric :
    { static_cast<const Metric*>(&linear), static_cast<const Metric*>(&flat) })
  {
    const auto seeds = Seeds(*metric, 19);
    std::vector<GeodesicPath> paths(seeds.size());
    GeodesicOptions options;
    options.Integrator = IntegratorType::DormandPrince45;
    options.MaximumLength = 3.0;
    TraceGeodesics(*metric, seeds.data(), seeds.size(), options, paths.data());
    for (size_t i = 0; i < seeds.size(); ++i)
    {
      ASSERT_EQ(paths[i].Reason, OutOfLength);
      const double sign = seeds[i].Backward ? -1.0 : 1.0;
      const double speed =
        std::sqrt(metric->InnerProduct(seeds[i].Point, seeds[i].Velocity, seeds[i].Velocity));
      const Vec3 exact = seeds[i].Point + sign * 3.0 / speed * seeds[i].Velocity;
      EXPECT_LT((paths[i].Points.back() - exact).norm(), 1e-12)
        << metric->Describe() << " seed " << i;
    }
  }
}

TEST(PacketEngine, SpeedIsConservedOnTheEightBumpGraph)
{
  GraphMetric metric(EightBumps());
  const auto seeds = Seeds(metric, 40);
  std::vector<GeodesicPath> paths(seeds.size());
  GeodesicOptions options;
  options.Integrator = IntegratorType::DormandPrince45;
  options.Tolerance = 1e-10;
  options.MaximumLength = 6.0;
  TraceGeodesics(metric, seeds.data(), seeds.size(), options, paths.data());
  double worst = 0.0;
  for (const GeodesicPath& path : paths)
  {
    ASSERT_EQ(path.Reason, OutOfLength);
    for (double drift : path.SpeedDrift)
    {
      worst = std::max(worst, std::abs(drift));
    }
  }
  // g(v, v) is a first integral of the geodesic flow.
  EXPECT_LT(worst, 1e-8);
}
} // namespace
} // namespace riemann
