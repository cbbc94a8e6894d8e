// The two-point problem (GeodesicConnector.h) on metrics with exact answers:
// in a diffeomorphism metric the one geodesic from p to q has length
// |Phi(q) - Phi(p)| and ends on q; on the round 3-sphere (stereographic
// coordinates) p and q are joined by the two arcs of a great circle, of
// lengths d and 2 pi - d (Morse indices 0 and 2: the longer one passes the
// antipode of p, a conjugate point of multiplicity 2), and the antipode of p
// by a whole sphere of geodesics of length pi, all with q conjugate; in the
// Poincare ball (curvature -1, no conjugate points) one geodesic of the
// closed-form length.
#include "GeodesicConnector.h"
#include "MetricTestUtilities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace riemann
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

/// The tolerances the tests state: where each result ends (the connector's
/// own tolerance), and how far its length may be from the exact one (the
/// integration error of dp45 at the refinement tolerance over a few units;
/// measured at most 1.8e-9, on the Poincare ball).
constexpr double EndTolerance = 1e-9;
constexpr double LengthTolerance = 1e-8;

ConnectOptions Options(double length, int directions)
{
  ConnectOptions options;
  options.MaximumLength = length;
  options.Tolerance = EndTolerance;
  options.NumberOfDirections = directions;
  options.Integration.Integrator = IntegratorType::DormandPrince45;
  options.Integration.Step = 0.01;
  options.Integration.Tolerance = 1e-8;
  options.Integration.MaximumStep = 0.1;
  options.Integration.MaximumSteps = 1000000;
  return options;
}

Vec3 MapPoint(const SpaceMap& map, const Vec3& p)
{
  VectorJet jet;
  map.Evaluate(p, 0, jet);
  return jet.Value;
}

/// The round unit 3-sphere in stereographic coordinates (round-sphere.json).
std::shared_ptr<const Metric> RoundSphere()
{
  return ParseMetricDefinition(R"json({"type": "conformal", "n": "2 / (1 + x^2 + y^2 + z^2)"})json");
}

/// The point of the unit sphere in R^4 that x stands for.
Eigen::Vector4d OnSphere(const Vec3& x)
{
  const double r2 = x.squaredNorm();
  Eigen::Vector4d X;
  X << 2.0 * x / (1.0 + r2), (1.0 - r2) / (1.0 + r2);
  return X;
}

double SphereDistance(const Vec3& p, const Vec3& q)
{
  return std::acos(std::clamp(OnSphere(p).dot(OnSphere(q)), -1.0, 1.0));
}

/// The end of the found geodesic (traced again, as the filter draws it).
Vec3 EndOf(const Metric& metric, const Vec3& p, const ConnectingGeodesic& g,
  const ConnectOptions& options)
{
  GeodesicPath path;
  TraceConnection(metric, p, g, options, path);
  return path.Points.back();
}

TEST(GeodesicConnector, DiffeomorphismMetricsHaveOneGeodesicOfTheMappedLength)
{
  const Vec3 p(0.3, -0.2, 0.1);
  const Vec3 q(1.1, 0.6, 0.9);
  for (const auto& [name, map] : testing::MapProviders())
  {
    const DiffeoMetric metric(map);
    const ConnectOptions options = Options(6.0, 400);
    const std::vector<ConnectingGeodesic> found = ConnectPoints(metric, p, q, options);
    ASSERT_EQ(found.size(), 1u) << name;
    const ConnectingGeodesic& g = found[0];
    EXPECT_NEAR(g.Length, (MapPoint(*map, q) - MapPoint(*map, p)).norm(), LengthTolerance) << name;
    EXPECT_LE(g.Miss, EndTolerance) << name;
    EXPECT_LE((EndOf(metric, p, g, options) - q).norm(), 10 * EndTolerance) << name;
    EXPECT_EQ(g.MorseIndex, 0) << name;
    EXPECT_EQ(g.ConjugateMultiplicity, 0) << name;
    EXPECT_TRUE(g.Shortest) << name;
  }
}

TEST(GeodesicConnector, TheRoundSphereJoinsTwoPointsByBothArcs)
{
  const auto sphere = RoundSphere();
  const Vec3 p(0.4, 0.1, -0.2);
  const Vec3 q(-0.3, 0.5, 0.6);
  const double d = SphereDistance(p, q);
  // Up to 7 (between 2 pi - d and 2 pi + d): exactly the two arcs.
  const std::vector<ConnectingGeodesic> found = ConnectPoints(*sphere, p, q, Options(7.0, 600));
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(found[0].Length, d, LengthTolerance);
  EXPECT_NEAR(found[1].Length, 2 * Pi - d, LengthTolerance);
  EXPECT_EQ(found[0].MorseIndex, 0);
  EXPECT_EQ(found[1].MorseIndex, 2); // the antipode of p, multiplicity 2
  EXPECT_TRUE(found[0].Shortest);
  EXPECT_FALSE(found[1].Shortest);
  EXPECT_EQ(found[0].ConjugateMultiplicity + found[1].ConjugateMultiplicity, 0);
  // The two arcs leave p in opposite directions (one great circle).
  EXPECT_NEAR(found[0].Direction.normalized().dot(found[1].Direction.normalized()), -1.0, 1e-6);
}

TEST(GeodesicConnector, TheAntipodeIsReachedByAWholeSphereOfConjugateGeodesics)
{
  const auto sphere = RoundSphere();
  // (0.5, 0, 0) is (0.8, 0, 0, 0.6) on the sphere; its antipode
  // (-0.8, 0, 0, -0.6) is (-2, 0, 0).
  const Vec3 p(0.5, 0.0, 0.0);
  const Vec3 q(-2.0, 0.0, 0.0);
  ASSERT_NEAR(SphereDistance(p, q), Pi, 1e-15);
  const int directions = 150;
  const std::vector<ConnectingGeodesic> found = ConnectPoints(*sphere, p, q, Options(4.0, directions));
  // Every shooting direction is a geodesic to q (all 150 are found; a
  // direction whose great circle ran through the point at infinity of the
  // coordinates could be lost, so 95% are asked for).
  EXPECT_GE(found.size(), static_cast<std::size_t>(0.95 * directions));
  for (const ConnectingGeodesic& g : found)
  {
    EXPECT_NEAR(g.Length, Pi, LengthTolerance);
    EXPECT_EQ(g.ConjugateMultiplicity, 2);
    EXPECT_EQ(g.MorseIndex, 0);
    EXPECT_TRUE(g.Shortest);
  }
}

TEST(GeodesicConnector, ThePoincareBallHasOneGeodesicOfTheHyperbolicDistance)
{
  const auto ball =
    ParseMetricDefinition(R"json({"type": "conformal", "n": "2 / (1 - x^2 - y^2 - z^2)"})json");
  const Vec3 p(0.2, -0.3, 0.1);
  const Vec3 q(-0.4, 0.35, 0.3);
  const double exact = std::acosh(
    1.0 + 2.0 * (p - q).squaredNorm() / ((1.0 - p.squaredNorm()) * (1.0 - q.squaredNorm())));
  const std::vector<ConnectingGeodesic> found = ConnectPoints(*ball, p, q, Options(8.0, 400));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0].Length, exact, LengthTolerance);
  EXPECT_EQ(found[0].MorseIndex, 0);
}

TEST(GeodesicConnector, RefusesWhatHasNoAnswer)
{
  const EuclideanMetric flat;
  const ConnectOptions options = Options(5.0, 50);
  EXPECT_THROW(ConnectPoints(flat, Vec3(1, 2, 3), Vec3(1, 2, 3), options), std::invalid_argument);
  EXPECT_THROW(ConnectPoints(flat, Vec3(1, NAN, 3), Vec3(1, 2, 3), options), std::invalid_argument);
  // Too far for the length limit: no geodesic, not an error.
  EXPECT_TRUE(ConnectPoints(flat, Vec3(0, 0, 0), Vec3(6, 0, 0), options).empty());
  const std::vector<ConnectingGeodesic> one = ConnectPoints(flat, Vec3(0, 0, 0), Vec3(3, 4, 0), options);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NEAR(one[0].Length, 5.0, 1e-12);
}
} // namespace
} // namespace riemann
