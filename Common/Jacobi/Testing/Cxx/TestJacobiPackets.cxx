// Tests of the Jacobi system on the packet engine (JacobiField.h's packet
// TraceJacobiFields, Metric::JacobiAccelerationPacket, ConjugatePoints.h's
// many-direction FindConjugatePoints):
// - every family's packet Jacobi accelerations against the scalar
//   JacobiAccelerations, lane by lane, with masked-out lanes; the Gaussian
//   table's third derivatives against GaussianField's;
// - the packet trace against the scalar one for every family and integrator,
//   with landings, backward seeds, bounds and every termination reason:
//   same samples (points, fields, determinants, phases), same reasons;
// - exact answers through the packet path: on the round sphere of radius 1
//   (curvature 1) every direction's first conjugate point is the double
//   point at arc length pi, and the transverse Jacobian is sin(s)^2.
#include "MetricTestUtilities.h"

#include "ConjugatePoints.h"
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

constexpr double Pi = 3.14159265358979323846;

std::shared_ptr<const ScalarField> ThreeBumps()
{
  return std::make_shared<ScalarFieldSum>(0.1,
    std::vector<std::shared_ptr<const ScalarField>>{
      std::make_shared<GaussianField>(0.8, Vec3(0.3, -0.2, 0.1), Vec3(0.6, 0.5, 0.7)),
      std::make_shared<GaussianField>(-0.5, Vec3(-0.6, 0.4, -0.3), Vec3(0.4, 0.6, 0.5)),
      std::make_shared<GaussianField>(0.6, Vec3(0.1, 0.7, 0.6), Vec3(0.5, 0.5, 0.4)) });
}

/// The test families plus graph and conformal metrics of a Gaussian table.
std::vector<std::pair<std::string, std::shared_ptr<const Metric>>> JacobiMetrics()
{
  auto metrics = Metrics();
  metrics.emplace_back("graph of 3 bumps", std::make_shared<GraphMetric>(ThreeBumps()));
  metrics.emplace_back("conformal 1.5 + 3 bumps",
    std::make_shared<ConformalMetric>(std::make_shared<ScalarFieldSum>(
      1.5, std::vector<std::shared_ptr<const ScalarField>>{ ThreeBumps() })));
  return metrics;
}

/// The unit round sphere in stereographic coordinates: n = 2 / (1 + |x|^2).
std::shared_ptr<const Metric> RoundSphere()
{
  return ParseMetricDefinition(R"json({"type": "conformal", "n": "2/(1 + x^2 + y^2 + z^2)"})json");
}

TEST(JacobiPackets, GaussianTableThirdDerivativesEqualTheScalarField)
{
  const auto field = ThreeBumps();
  const auto points = RandomPoints(2 * PacketWidth, 1.5, 21);
  for (size_t start = 0; start < points.size(); start += PacketWidth)
  {
    PacketVec3 p;
    for (int l = 0; l < PacketWidth; ++l)
    {
      p.SetLane(l, points[start + l]);
    }
    PacketScalarJet packet;
    field->EvaluatePacket(p, ThirdDerivatives, packet, AllLanes);
    for (int l = 0; l < PacketWidth; ++l)
    {
      ScalarJet scalar;
      field->Evaluate(points[start + l], ThirdDerivatives, scalar);
      EXPECT_NEAR(packet.Value[l], scalar.Value, 1e-14);
      EXPECT_LT((packet.Hessian.Lane(l) - scalar.Hessian).cwiseAbs().maxCoeff(), 1e-14);
      for (int e = 0; e < 10; ++e)
      {
        const int(&i)[3] = ThirdEntryIndices[e];
        // Every permutation of the indices holds the same derivative.
        EXPECT_NEAR(packet.Third[e][l], scalar.Third[i[0]](i[1], i[2]), 1e-13) << "entry " << e;
        EXPECT_NEAR(packet.Third[e][l], scalar.Third[i[2]](i[0], i[1]), 1e-13) << "entry " << e;
      }
    }
  }
}

TEST(JacobiPackets, EveryFamilyJacobiAccelerationsEqualTheScalarOnes)
{
  const auto points = RandomPoints(2 * PacketWidth, 1.2, 31);
  const auto vectors = RandomPoints(10 * PacketWidth, 1.0, 32);
  // Every lane but 2 and 5 in use: those must not be reported.
  const LaneMask lanes = AllLanes & ~((LaneMask{ 1 } << 2) | (LaneMask{ 1 } << 5));
  for (const auto& [name, metric] : JacobiMetrics())
  {
    SCOPED_TRACE(name);
    for (size_t start = 0; start < points.size(); start += PacketWidth)
    {
      PacketJacobiState y, dy;
      for (int l = 0; l < PacketWidth; ++l)
      {
        const size_t k = 5 * (start + l);
        y.X.SetLane(l, points[start + l]);
        y.V.SetLane(l, vectors[k]);
        y.J[0].SetLane(l, vectors[k + 1]);
        y.DJ[0].SetLane(l, vectors[k + 2]);
        y.J[1].SetLane(l, vectors[k + 3]);
        y.DJ[1].SetLane(l, vectors[k + 4]);
      }
      const LaneMask defined = metric->JacobiAccelerationPacket(y, dy, lanes);
      for (int l = 0; l < PacketWidth; ++l)
      {
        if (!HasLane(lanes, l))
        {
          EXPECT_FALSE(HasLane(defined, l)) << "lane " << l;
          continue;
        }
        const Vec3 j[2] = { y.J[0].Lane(l), y.J[1].Lane(l) };
        const Vec3 dj[2] = { y.DJ[0].Lane(l), y.DJ[1].Lane(l) };
        Vec3 a;
        Vec3 variations[2];
        const bool expected =
          JacobiAccelerations(*metric, y.X.Lane(l), y.V.Lane(l), j, dj, a, variations);
        ASSERT_EQ(HasLane(defined, l), expected) << "lane " << l;
        if (!expected)
        {
          continue;
        }
        // The SIMD families use their own closed forms: equal to rounding
        // of the terms (the scalar path goes through g^-1 and d Gamma).
        const double scale =
          std::max({ 1.0, a.norm(), variations[0].norm(), variations[1].norm() });
        EXPECT_LT((dy.V.Lane(l) - a).norm(), 1e-11 * scale) << "lane " << l;
        EXPECT_LT((dy.DJ[0].Lane(l) - variations[0]).norm(), 1e-11 * scale) << "lane " << l;
        EXPECT_LT((dy.DJ[1].Lane(l) - variations[1]).norm(), 1e-11 * scale) << "lane " << l;
      }
    }
  }
}

/// Seeds around the origin, of different directions; every third backward.
std::vector<JacobiSeed> Seeds(int count)
{
  std::vector<JacobiSeed> seeds;
  const auto points = RandomPoints(count, 0.8, 41);
  const auto directions = RandomPoints(count, 1.0, 42);
  for (int i = 0; i < count; ++i)
  {
    JacobiSeed seed;
    seed.Point = points[i];
    seed.Direction = directions[i];
    seed.Backward = i % 3 == 2;
    seeds.push_back(seed);
  }
  return seeds;
}

/// As PathTolerance of TestPacketEngine: rounding for fixed steps, a small
/// multiple of the tolerance for dp45 (its error estimate's rounding moves
/// the next step).
double TraceTolerance(const GeodesicOptions& options)
{
  return options.Integrator == IntegratorType::DormandPrince45 ? 50.0 * options.Tolerance : 1e-9;
}

/// The packet traces must be the scalar ones: same sample counts and
/// reasons, samples equal to `tolerance` (relative to their size).
void ExpectSameTraces(const Metric& metric, const std::vector<JacobiSeed>& seeds,
  const GeodesicOptions& options, const std::vector<double>& landings, double tolerance)
{
  std::vector<JacobiTrace> packet(seeds.size());
  TraceJacobiFields(metric, seeds.data(), seeds.size(), options, packet.data(), landings);
  for (size_t i = 0; i < seeds.size(); ++i)
  {
    JacobiTrace scalar;
    TraceJacobiFields(
      metric, seeds[i].Point, seeds[i].Direction, options, scalar, seeds[i].Backward, landings);
    SCOPED_TRACE("seed " + std::to_string(i));
    ASSERT_EQ(packet[i].Reason, scalar.Reason);
    ASSERT_EQ(packet[i].Samples.size(), scalar.Samples.size());
    for (size_t k = 0; k < scalar.Samples.size(); ++k)
    {
      const JacobiSample& a = packet[i].Samples[k];
      const JacobiSample& b = scalar.Samples[k];
      const double scale = std::max({ 1.0, b.Point.norm(), b.Velocity.norm(), b.J[0].norm(),
        b.J[1].norm(), b.DJ[0].norm(), b.DJ[1].norm() });
      ASSERT_NEAR(a.ArcLength, b.ArcLength, tolerance * scale) << "sample " << k;
      ASSERT_LT((a.Point - b.Point).norm(), tolerance * scale) << "sample " << k;
      ASSERT_LT((a.Velocity - b.Velocity).norm(), tolerance * scale) << "sample " << k;
      for (int f = 0; f < 2; ++f)
      {
        ASSERT_LT((a.J[f] - b.J[f]).norm(), tolerance * scale) << "sample " << k;
        ASSERT_LT((a.DJ[f] - b.DJ[f]).norm(), tolerance * scale) << "sample " << k;
      }
      ASSERT_NEAR(a.Determinant, b.Determinant, tolerance * scale * scale) << "sample " << k;
    }
  }
}

TEST(JacobiPackets, TraceJacobiFieldsEqualsTheScalarTraceForEveryFamilyAndIntegrator)
{
  // 19 seeds: two full packets and a partial one; the box makes lanes end
  // apart (and be refilled), the landings shorten steps lane by lane.
  const auto seeds = Seeds(19);
  const std::vector<double> landings = { 0.25, 0.9, 1.3 };
  for (const auto& [name, metric] : JacobiMetrics())
  {
    for (IntegratorType type :
      { IntegratorType::Euler, IntegratorType::RungeKutta4, IntegratorType::DormandPrince45 })
    {
      SCOPED_TRACE(name + ", " + IntegratorName(type));
      GeodesicOptions options;
      options.Integrator = type;
      options.Step = 0.07;
      options.MaximumLength = 1.5;
      options.Tolerance = 1e-9;
      options.UseBounds = true;
      const double bounds[6] = { -1.3, 1.3, -1.2, 1.2, -1.25, 1.25 };
      std::copy(bounds, bounds + 6, options.Bounds);
      ExpectSameTraces(*metric, seeds, options, landings, TraceTolerance(options));
    }
  }
}

TEST(JacobiPackets, TraceJacobiFieldsStopsForEveryReasonAsTheScalarTrace)
{
  // n = 1 - x vanishes at x = 1 (degenerate metric); a zero direction (not
  // initialized); a seed outside the box (out of domain at once); a NaN
  // point; a small step budget (out of steps); and plain length.
  ConformalMetric vanishing(std::make_shared<QuadraticField>(Mat3::Zero(), Vec3(-1, 0, 0), 1.0));
  std::vector<JacobiSeed> seeds(PacketWidth + 4);
  for (size_t i = 0; i < seeds.size(); ++i)
  {
    seeds[i].Point = Vec3(-0.5, 0.01 * i, 0.0);
    seeds[i].Direction = i % 4 == 0 ? Vec3(1, 0, 0) : Vec3(0, i % 4 == 1 ? 1.0 : 0.0, 1);
  }
  seeds[3].Direction = Vec3::Zero();
  seeds[5].Point = Vec3(0.0, 5.0, 0.0);
  seeds[6].Point = Vec3(std::nan(""), 0.0, 0.0);
  GeodesicOptions options;
  options.Step = 0.1;
  options.MaximumLength = 3.0;
  options.UseBounds = true;
  const double bounds[6] = { -2, 2, -2, 2, -2, 2 };
  std::copy(bounds, bounds + 6, options.Bounds);
  for (IntegratorType type :
    { IntegratorType::Euler, IntegratorType::RungeKutta4, IntegratorType::DormandPrince45 })
  {
    SCOPED_TRACE(IntegratorName(type));
    options.Integrator = type;
    options.MaximumSteps = 100000;
    ExpectSameTraces(vanishing, seeds, options, {}, TraceTolerance(options));
    options.MaximumSteps = 7;
    ExpectSameTraces(vanishing, seeds, options, {}, TraceTolerance(options));
  }
  std::vector<JacobiTrace> traces(seeds.size());
  options.Integrator = IntegratorType::RungeKutta4;
  options.MaximumSteps = 100000;
  TraceJacobiFields(vanishing, seeds.data(), seeds.size(), options, traces.data());
  EXPECT_TRUE(traces[0].Reason == DegenerateMetric || traces[0].Reason == Stagnation);
  EXPECT_EQ(traces[1].Reason, OutOfLength);
  EXPECT_EQ(traces[3].Reason, NotInitialized);
  EXPECT_EQ(traces[5].Reason, OutOfDomain);
  EXPECT_EQ(traces[6].Reason, NotInitialized);
}

TEST(JacobiPackets, RoundSphereFieldsAndConjugatePointsAreExact)
{
  // Curvature 1: the transverse Jacobian of unit-speed geodesics is
  // sin(s)^2 (both fields sin(s) times a parallel unit vector), and every
  // direction's first conjugate point is a double point at s = pi.
  const auto sphere = RoundSphere();
  const Vec3 observer(0.2, -0.1, 0.15);
  const auto directions = RandomPoints(3 * PacketWidth + 3, 1.0, 51);
  std::vector<JacobiSeed> seeds;
  for (const Vec3& direction : directions)
  {
    seeds.push_back({ observer, direction, false });
  }
  GeodesicOptions options;
  options.Integrator = IntegratorType::DormandPrince45;
  options.Tolerance = 1e-11;
  options.MaximumStep = 0.1;
  options.MaximumLength = 3.0;
  options.MaximumSteps = 1000000;
  std::vector<JacobiTrace> traces(seeds.size());
  TraceJacobiFields(*sphere, seeds.data(), seeds.size(), options, traces.data(), { 1.0, 2.0 });
  for (size_t i = 0; i < traces.size(); ++i)
  {
    ASSERT_EQ(traces[i].Reason, OutOfLength) << "direction " << i;
    int landed = 0;
    for (const JacobiSample& sample : traces[i].Samples)
    {
      const double expected = std::sin(sample.ArcLength) * std::sin(sample.ArcLength);
      ASSERT_NEAR(sample.Determinant, expected, 1e-8) << "direction " << i;
      ASSERT_LT(std::abs(sample.SpeedDrift), 1e-9) << "direction " << i;
      landed += sample.ArcLength == 1.0 || sample.ArcLength == 2.0 ? 1 : 0;
    }
    EXPECT_EQ(landed, 2) << "direction " << i << " lands exactly on both landings";
  }

  options.MaximumLength = 4.0;
  std::vector<std::vector<ConjugatePoint>> found(directions.size());
  FindConjugatePoints(
    *sphere, observer, directions.data(), directions.size(), options, 1e-8, 2, found.data());
  for (size_t i = 0; i < directions.size(); ++i)
  {
    ASSERT_EQ(found[i].size(), 1u) << "direction " << i;
    EXPECT_NEAR(found[i][0].ArcLength, Pi, 1e-7) << "direction " << i;
    EXPECT_EQ(found[i][0].Multiplicity, 2) << "direction " << i;
    // The one-direction search gives the same point.
    const auto scalar = FindConjugatePoints(*sphere, observer, directions[i], options, 1e-8, 2);
    ASSERT_EQ(scalar.size(), 1u);
    EXPECT_NEAR(found[i][0].ArcLength, scalar[0].ArcLength, 1e-9) << "direction " << i;
    EXPECT_LT((found[i][0].Point - scalar[0].Point).norm(), 1e-8) << "direction " << i;
  }
}

TEST(JacobiPackets, ConjugatePointsOfManyDirectionsEqualTheOneDirectionSearch)
{
  // A metric without symmetry: the graph of three bumps, made strong enough
  // to focus (simple conjugate points at various distances, or none).
  auto field = std::make_shared<ScalarFieldSum>(0.0,
    std::vector<std::shared_ptr<const ScalarField>>{
      std::make_shared<GaussianField>(2.5, Vec3(1.0, 0.0, 0.0), Vec3(0.5, 0.5, 0.5)),
      std::make_shared<GaussianField>(-1.5, Vec3(1.2, 0.8, 0.3), Vec3(0.4, 0.6, 0.5)) });
  const GraphMetric metric(field);
  const Vec3 observer(-1.0, 0.05, 0.0);
  std::vector<Vec3> directions;
  for (int i = 0; i < 21; ++i)
  {
    directions.emplace_back(1.0, 0.04 * (i - 10), 0.02 * (i % 5));
  }
  GeodesicOptions options;
  options.Integrator = IntegratorType::DormandPrince45;
  options.Tolerance = 1e-9;
  options.MaximumStep = 0.1;
  options.MaximumLength = 6.0;
  options.MaximumSteps = 1000000;
  std::vector<std::vector<ConjugatePoint>> found(directions.size());
  FindConjugatePoints(
    metric, observer, directions.data(), directions.size(), options, 1e-8, 0, found.data());
  int points = 0;
  for (size_t i = 0; i < directions.size(); ++i)
  {
    const auto scalar = FindConjugatePoints(metric, observer, directions[i], options, 1e-8, 0);
    ASSERT_EQ(found[i].size(), scalar.size()) << "direction " << i;
    for (size_t k = 0; k < scalar.size(); ++k)
    {
      EXPECT_NEAR(found[i][k].ArcLength, scalar[k].ArcLength, 1e-7) << "direction " << i;
      EXPECT_EQ(found[i][k].Multiplicity, scalar[k].Multiplicity) << "direction " << i;
      EXPECT_EQ(found[i][k].Index, scalar[k].Index);
      ++points;
    }
  }
  std::cout << points << " conjugate points over " << directions.size() << " directions\n";
  EXPECT_GT(points, 5) << "the bumps must focus some geodesics";
}
} // namespace
} // namespace riemann
