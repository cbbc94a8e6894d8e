// Jacobi fields and conjugate points (JacobiField.h, ConjugatePoints.h) against known answers:
// round spheres (first conjugate point at pi / sqrt(K), multiplicity 2),
// Hadamard manifolds (none), flat pull-backs (linear Jacobi fields).
#include "Curvature.h"
#include "ConjugatePoints.h"
#include "MetricTestUtilities.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

namespace riemann
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

struct Seed
{
  Vec3 Point;
  Vec3 Direction;
};

/// Seeds for the stereographic spheres: directions not radial, so the great
/// circle misses the point at infinity.
std::vector<Seed> SphereSeeds()
{
  return { { Vec3(0.5, 0.0, 0.0), Vec3(0.0, 1.0, 0.0) },
    { Vec3(0.5, 0.0, 0.0), Vec3(0.2, 1.0, 0.5) }, { Vec3(0.1, -0.2, 0.3), Vec3(1.0, 1.0, 0.0) },
    { Vec3(-0.3, 0.4, 0.2), Vec3(0.0, -0.3, 1.0) } };
}

void ExpectRoundSphere(const Metric& metric, double curvature, double step)
{
  // The curvature first, from the metric's own derivatives.
  CurvatureSample sample;
  ASSERT_TRUE(ComputeCurvature(metric, Vec3(0.2, -0.1, 0.3), sample));
  EXPECT_NEAR(sample.SectionalMin, curvature, 1e-9);
  EXPECT_NEAR(sample.SectionalMax, curvature, 1e-9);

  const double first = Pi / std::sqrt(curvature);
  for (const Seed& seed : SphereSeeds())
  {
    // A fixed step decides the accuracy: RK4 at these steps splits the double
    // point by up to about 3e-6 in arc length (measured over 500 directions),
    // so crossings closer than 1e-5 are one point of multiplicity 2.
    const auto points =
      FindConjugatePoints(metric, seed.Point, seed.Direction, step, 2.2 * first, 1e-5, 0);
    ASSERT_EQ(points.size(), 2u) << "seed " << seed.Point.transpose();
    for (int k = 0; k < 2; ++k)
    {
      const double expected = (k + 1) * first;
      std::cout << "K = " << curvature << " seed " << seed.Point.transpose() << " dir "
                << seed.Direction.transpose() << ": conjugate " << k + 1 << " at "
                << points[k].ArcLength << " (error " << points[k].ArcLength - expected
                << "), multiplicity " << points[k].Multiplicity << "\n";
      EXPECT_NEAR(points[k].ArcLength, expected, 1e-6);
      EXPECT_EQ(points[k].Multiplicity, 2);
      EXPECT_EQ(points[k].Index, k + 1);
    }
    if (curvature == 1.0)
    {
      // The first conjugate point of p on the stereographic unit sphere is
      // its antipode -p / |p|^2; the second is p itself.
      const Vec3 antipode = -seed.Point / seed.Point.squaredNorm();
      EXPECT_LT((points[0].Point - antipode).norm(), 1e-6);
    }
    EXPECT_LT((points[1].Point - seed.Point).norm(), 1e-6);
  }
}

TEST(JacobiField, UnitSphereConjugatePointsAtPiAndTwoPi)
{
  const auto metric =
    ParseMetricDefinition(R"json({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})json");
  ExpectRoundSphere(*metric, 1.0, 0.01);
}

TEST(JacobiField, SphereOfCurvatureFourConjugatePointsAtHalfPi)
{
  const auto metric =
    ParseMetricDefinition(R"json({"type":"conformal","n":"1/(1+x^2+y^2+z^2)"})json");
  ExpectRoundSphere(*metric, 4.0, 0.005);
}

TEST(JacobiField, SphereTimesLineHasSimpleConjugatePoints)
{
  // S^2 x R (stereographic unit sphere in (x, y), flat z): along a geodesic
  // whose S^2 part has speed c, one transverse field is sin(c s) and the other
  // linear, so the conjugate points are simple (sign changes of the
  // determinant) at s = k pi / c.
  const auto metric = ParseMetricDefinition(R"json({"type":"tensor","g":[
    ["4/(1+x^2+y^2)^2","0","0"],["0","4/(1+x^2+y^2)^2","0"],["0","0","1"]]})json");
  for (const double slope : { 0.0, 0.5 })
  {
    // At (0.5, 0, 0) the S^2 factor of g is 4 / 1.25^2: direction (0, 1, slope)
    // has S^2 part of g-length 2 / 1.25 and z part slope.
    const double sphere = 2.0 / 1.25;
    const double speed = std::sqrt(sphere * sphere + slope * slope);
    const double sphereSpeed = sphere / speed;
    const auto points = FindConjugatePoints(
      *metric, Vec3(0.5, 0.0, 0.0), Vec3(0.0, 1.0, slope), 0.01, 2.2 * Pi / sphereSpeed, 1e-10, 0);
    ASSERT_EQ(points.size(), 2u) << "slope " << slope;
    for (int k = 0; k < 2; ++k)
    {
      const double expected = (k + 1) * Pi / sphereSpeed;
      std::cout << "S^2 x R slope " << slope << ": conjugate " << k + 1 << " at "
                << points[k].ArcLength << " (error " << points[k].ArcLength - expected
                << "), multiplicity " << points[k].Multiplicity << "\n";
      EXPECT_NEAR(points[k].ArcLength, expected, 1e-6);
      EXPECT_EQ(points[k].Multiplicity, 1);
    }
  }
}

TEST(JacobiField, UnitSphereFieldsAreSines)
{
  // On the unit sphere J_a(s) = sin(s) E_a with E_a parallel and g-unit.
  const auto metric =
    ParseMetricDefinition(R"json({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})json");
  std::vector<JacobiSample> samples;
  ASSERT_TRUE(
    TraceJacobiFields(*metric, Vec3(0.5, 0.0, 0.0), Vec3(0.2, 1.0, 0.5), 0.005, 6.0, samples));
  double worst = 0.0;
  for (const JacobiSample& s : samples)
  {
    for (int a = 0; a < 2; ++a)
    {
      const double norm = std::sqrt(metric->InnerProduct(s.Point, s.J[a], s.J[a]));
      worst = std::max(worst, std::abs(norm - std::abs(std::sin(s.ArcLength))));
      EXPECT_NEAR(metric->InnerProduct(s.Point, s.J[a], s.Velocity), 0.0, 1e-9);
    }
    EXPECT_NEAR(s.Determinant, std::pow(std::sin(s.ArcLength), 2), 1e-7);
  }
  std::cout << "unit sphere: max | |J|_g - |sin s| | = " << worst << "\n";
  EXPECT_LT(worst, 1e-7);
}

TEST(JacobiField, HadamardManifoldsHaveNoConjugatePoints)
{
  const auto ball =
    ParseMetricDefinition(R"json({"type":"conformal","n":"2/(1-x^2-y^2-z^2)"})json");
  const std::vector<Seed> ballSeeds = { { Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0) },
    { Vec3(0.2, -0.1, 0.1), Vec3(0.3, 1.0, -0.4) },
    { Vec3(-0.15, 0.2, -0.1), Vec3(-1.0, 0.2, 0.7) } };
  for (const Seed& seed : ballSeeds)
  {
    std::vector<JacobiSample> samples;
    ASSERT_TRUE(TraceJacobiFields(*ball, seed.Point, seed.Direction, 0.01, 4.0, samples));
    // K = -1: |J|_g = sinh(s).
    const JacobiSample& last = samples.back();
    EXPECT_NEAR(
      std::sqrt(ball->InnerProduct(last.Point, last.J[0], last.J[0])) / std::sinh(4.0), 1.0, 1e-6);
    EXPECT_TRUE(FindConjugatePoints(*ball, seed.Point, seed.Direction, 0.01, 4.0, 1e-9, 0).empty());
  }

  const std::vector<std::pair<std::string, std::shared_ptr<const Metric>>> flat = {
    { "twist", std::make_shared<DiffeoMetric>(std::make_shared<TwistMap>(1.0)) },
    { "two-bump composition", std::make_shared<DiffeoMetric>(testing::TwoBumpComposition()) }
  };
  const std::vector<Seed> seeds = { { Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0) },
    { Vec3(0.3, -0.2, 0.1), Vec3(0.2, 1.0, 0.5) },
    { Vec3(-0.5, 0.4, -0.3), Vec3(0.0, 0.3, -1.0) } };
  for (const auto& [name, metric] : flat)
  {
    for (const Seed& seed : seeds)
    {
      std::vector<JacobiSample> samples;
      EXPECT_TRUE(TraceJacobiFields(*metric, seed.Point, seed.Direction, 0.01, 10.0, samples))
        << name;
      EXPECT_TRUE(
        FindConjugatePoints(*metric, seed.Point, seed.Direction, 0.01, 10.0, 1e-9, 0).empty())
        << name;
    }
  }
}

TEST(JacobiField, FlatFieldsAreLinear)
{
  const std::vector<std::pair<std::string, std::shared_ptr<const Metric>>> flat = {
    { "twist", std::make_shared<DiffeoMetric>(std::make_shared<TwistMap>(1.0)) },
    { "two-bump composition", std::make_shared<DiffeoMetric>(testing::TwoBumpComposition()) }
  };
  for (const auto& [name, metric] : flat)
  {
    std::vector<JacobiSample> samples;
    ASSERT_TRUE(
      TraceJacobiFields(*metric, Vec3(0.3, -0.2, 0.1), Vec3(0.2, 1.0, 0.5), 0.0025, 3.0, samples));
    double worstNorm = 0.0, worstNormal = 0.0, worstCross = 0.0, worstDeterminant = 0.0;
    for (const JacobiSample& s : samples)
    {
      for (int a = 0; a < 2; ++a)
      {
        const double norm = std::sqrt(metric->InnerProduct(s.Point, s.J[a], s.J[a]));
        worstNorm = std::max(worstNorm, std::abs(norm - s.ArcLength));
        worstNormal =
          std::max(worstNormal, std::abs(metric->InnerProduct(s.Point, s.J[a], s.Velocity)));
      }
      worstCross = std::max(worstCross, std::abs(metric->InnerProduct(s.Point, s.J[0], s.J[1])));
      worstDeterminant =
        std::max(worstDeterminant, std::abs(s.Determinant - s.ArcLength * s.ArcLength));
    }
    std::cout << name << ": max | |J|_g - s | = " << worstNorm
              << ", max |g(J, v)| = " << worstNormal << ", max |g(J0, J1)| = " << worstCross
              << ", max |det - s^2| = " << worstDeterminant << "\n";
    EXPECT_LT(worstNorm, 1e-9) << name;
    EXPECT_LT(worstNormal, 1e-9) << name;
    EXPECT_LT(worstCross, 1e-9) << name;
    EXPECT_LT(worstDeterminant, 1e-8) << name;
  }
}

/// max over the samples of |det - sin^2 s| on the unit sphere.
double WorstSphereDeterminantError(const JacobiTrace& trace)
{
  double worst = 0.0;
  for (const JacobiSample& s : trace.Samples)
  {
    worst = std::max(worst, std::abs(s.Determinant - std::pow(std::sin(s.ArcLength), 2)));
    worst = std::max(worst, std::abs(s.SingularValues[0] - std::abs(std::sin(s.ArcLength))));
    worst = std::max(worst, std::abs(s.SingularValues[1] - std::abs(std::sin(s.ArcLength))));
  }
  return worst;
}

TEST(JacobiField, EveryIntegratorConvergesToTheSphereSolution)
{
  // det Transverse = sin^2 s and both singular values |sin s| on the unit
  // sphere, up to s = 3 (past the maximum of sin).
  const auto metric =
    ParseMetricDefinition(R"json({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})json");
  const Vec3 p(0.5, 0.0, 0.0);
  const Vec3 direction(0.2, 1.0, 0.5);
  GeodesicOptions options;
  options.MaximumLength = 3.0;
  const auto errorAt = [&](IntegratorType integrator, double step)
  {
    options.Integrator = integrator;
    options.Step = step;
    JacobiTrace trace;
    TraceJacobiFields(*metric, p, direction, options, trace);
    EXPECT_EQ(trace.Reason, OutOfLength);
    EXPECT_DOUBLE_EQ(trace.Samples.back().ArcLength, 3.0);
    return WorstSphereDeterminantError(trace);
  };
  // Halving the step divides the error by 2^order.
  const double euler1 = errorAt(IntegratorType::Euler, 0.004);
  const double euler2 = errorAt(IntegratorType::Euler, 0.002);
  const double rk1 = errorAt(IntegratorType::RungeKutta4, 0.04);
  const double rk2 = errorAt(IntegratorType::RungeKutta4, 0.02);
  std::cout << "unit sphere det/singular values: Euler " << euler1 << " -> " << euler2
            << " (order " << std::log2(euler1 / euler2) << "), RK4 " << rk1 << " -> " << rk2
            << " (order " << std::log2(rk1 / rk2) << ")\n";
  EXPECT_LT(euler2, 0.05);
  EXPECT_NEAR(std::log2(euler1 / euler2), 1.0, 0.15);
  EXPECT_LT(rk2, 1e-6);
  EXPECT_NEAR(std::log2(rk1 / rk2), 4.0, 0.3);

  // The adaptive integrator's error control covers the Jacobi fields.
  options.Integrator = IntegratorType::DormandPrince45;
  options.Step = 0.01;
  for (const double tolerance : { 1e-6, 1e-9 })
  {
    options.Tolerance = tolerance;
    JacobiTrace trace;
    TraceJacobiFields(*metric, p, direction, options, trace);
    EXPECT_EQ(trace.Reason, OutOfLength);
    const double error = WorstSphereDeterminantError(trace);
    std::cout << "dp45 tolerance " << tolerance << ": " << trace.Samples.size() - 1
              << " steps, error " << error << "\n";
    EXPECT_LT(error, 100.0 * tolerance);
  }
}

TEST(JacobiField, AdaptiveSearchFindsTheSphereConjugatePoints)
{
  const auto metric =
    ParseMetricDefinition(R"json({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})json");
  GeodesicOptions options;
  options.Integrator = IntegratorType::DormandPrince45;
  options.Step = 0.01;
  options.Tolerance = 1e-10;
  options.MaximumStep = 0.1;
  options.MaximumLength = 2.2 * Pi;
  for (const Seed& seed : SphereSeeds())
  {
    const auto points = FindConjugatePoints(*metric, seed.Point, seed.Direction, options, 1e-10, 0);
    ASSERT_EQ(points.size(), 2u) << "seed " << seed.Point.transpose();
    for (int k = 0; k < 2; ++k)
    {
      EXPECT_NEAR(points[k].ArcLength, (k + 1) * Pi, 1e-6);
      EXPECT_EQ(points[k].Multiplicity, 2);
    }
  }
}

TEST(JacobiField, LandsOnRequestedDistancesAndTracesBackward)
{
  const auto metric =
    ParseMetricDefinition(R"json({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})json");
  GeodesicOptions options;
  options.Step = 0.03;
  options.MaximumLength = 2.0;
  for (const IntegratorType integrator :
    { IntegratorType::Euler, IntegratorType::RungeKutta4, IntegratorType::DormandPrince45 })
  {
    options.Integrator = integrator;
    JacobiTrace trace;
    TraceJacobiFields(*metric, Vec3(0.1, 0.2, 0.0), Vec3(1.0, 0.0, 0.3), options, trace, true,
      { 1.0, 0.5, 1.234, 5.0 });
    ASSERT_EQ(trace.Reason, OutOfLength) << IntegratorName(integrator);
    for (const double landing : { -0.5, -1.0, -1.234, -2.0 })
    {
      const auto found = std::find_if(trace.Samples.begin(), trace.Samples.end(),
        [&](const JacobiSample& s) { return s.ArcLength == landing; });
      EXPECT_NE(found, trace.Samples.end()) << IntegratorName(integrator) << " " << landing;
    }
    // Arc length decreases strictly; the determinant is sin^2 |s| backward too.
    for (std::size_t i = 1; i < trace.Samples.size(); ++i)
    {
      EXPECT_LT(trace.Samples[i].ArcLength, trace.Samples[i - 1].ArcLength);
    }
    EXPECT_NEAR(trace.Samples.back().Determinant, std::pow(std::sin(2.0), 2),
      integrator == IntegratorType::Euler ? 0.05 : 1e-6);
  }
}

TEST(JacobiField, StopsLikeTheGeodesicTracer)
{
  // Same options, same stopping rules: bounds and steps.
  const auto metric = ParseMetricDefinition(R"json({"type":"euclidean"})json");
  GeodesicOptions options;
  options.Step = 0.1;
  options.MaximumLength = 10.0;
  options.UseBounds = true;
  const double bounds[6] = { -1, 1, -1, 1, -1, 1 };
  std::copy(bounds, bounds + 6, options.Bounds);
  JacobiTrace trace;
  TraceJacobiFields(*metric, Vec3::Zero(), Vec3(1.0, 0.0, 0.0), options, trace);
  GeodesicPath path;
  TraceGeodesic(*metric, Vec3::Zero(), Vec3(1.0, 0.0, 0.0), options, path);
  EXPECT_EQ(trace.Reason, OutOfDomain);
  EXPECT_EQ(trace.Reason, path.Reason);
  EXPECT_EQ(trace.Samples.size(), path.Points.size());
  options.UseBounds = false;
  options.MaximumSteps = 7;
  TraceJacobiFields(*metric, Vec3::Zero(), Vec3(1.0, 0.0, 0.0), options, trace);
  EXPECT_EQ(trace.Reason, OutOfSteps);
  EXPECT_EQ(trace.Samples.size(), 8u);
  TraceJacobiFields(*metric, Vec3::Zero(), Vec3::Zero(), options, trace);
  EXPECT_EQ(trace.Reason, NotInitialized);
}
} // namespace
} // namespace riemann
