// Metrics typed as expressions against the built-in providers they spell
// out (to 1e-12), and geodesics of an expression diffeomorphism against the
// exact Phi^-1 reference. Christoffel symbols of expression metrics against
// the general formula run in TestChristoffel (testing::Metrics() includes them).
#include "DiffeoMetric.h"
#include "GeodesicTrace.h"
#include "GlslSource.h"
#include "MetricGlsl.h"
#include "MetricDefinition.h"
#include "MetricTestUtilities.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace riemann
{
namespace
{
struct Gaussian8
{
  double A, X, Y, Z, S;
};

const Gaussian8 EightGaussians[8] = { { 0.9, -1.2, -0.8, 0.3, 0.5 }, { 0.6, 0.7, 1.1, -0.4, 0.55 },
  { -0.5, 1.3, -0.9, 0.8, 0.6 }, { 0.8, -0.3, 0.2, -1.2, 0.7 }, { 0.4, 0.1, -1.4, -0.2, 0.5 },
  { -0.7, -1.1, 1.0, 1.1, 0.45 }, { 1.0, 1.4, 0.4, 0.1, 0.45 }, { 0.3, 0.0, 0.0, 1.4, 0.8 } };

std::string BuiltInEightGaussians()
{
  std::ostringstream s;
  s << std::setprecision(17) << R"({"type": "graph", "gaussians": [)";
  for (int i = 0; i < 8; ++i)
  {
    const Gaussian8& g = EightGaussians[i];
    s << (i ? "," : "") << R"({"amplitude": )" << g.A << R"(, "center": [)" << g.X << "," << g.Y
      << "," << g.Z << R"(], "sigma": )" << g.S << "}";
  }
  return s.str() + "]}";
}

std::string TypedEightGaussians()
{
  std::ostringstream s;
  s << std::setprecision(17) << R"({"type": "graph", "f": ")";
  for (int i = 0; i < 8; ++i)
  {
    const Gaussian8& g = EightGaussians[i];
    s << (i ? " + " : "") << g.A << "*exp(-((x - (" << g.X << "))^2 + (y - (" << g.Y
      << "))^2 + (z - (" << g.Z << "))^2) / (2*" << g.S << "^2))";
  }
  return s.str() + "\"}";
}

void ExpectSameMetric(const Metric& a, const Metric& b, const char* what)
{
  for (const Vec3& p : testing::RandomPoints(100, 2.0, 31))
  {
    Mat3 ga, gb;
    ASSERT_TRUE(a.Tensor(p, ga));
    ASSERT_TRUE(b.Tensor(p, gb));
    EXPECT_LT((ga - gb).cwiseAbs().maxCoeff(), 1e-12) << what << " g at " << p.transpose();
    Mat3Stack ca, cb;
    ASSERT_TRUE(a.Christoffel(p, ca));
    ASSERT_TRUE(b.Christoffel(p, cb));
    for (int m = 0; m < 3; ++m)
    {
      EXPECT_LT((ca[m] - cb[m]).cwiseAbs().maxCoeff(), 1e-12) << what << " Gamma^" << m;
    }
  }
}

void ExpectSameGeodesic(
  const Metric& a, const Metric& b, const Vec3& p, const Vec3& d, const char* what)
{
  GeodesicOptions options;
  options.Step = 0.01;
  options.MaximumLength = 4.0;
  Vec3 va, vb;
  ASSERT_TRUE(UnitSpeedVelocity(a, p, d, va));
  ASSERT_TRUE(UnitSpeedVelocity(b, p, d, vb));
  GeodesicPath pa, pb;
  TraceGeodesic(a, p, va, options, pa);
  TraceGeodesic(b, p, vb, options, pb);
  ASSERT_EQ(pa.Points.size(), pb.Points.size()) << what;
  double worst = 0;
  for (size_t i = 0; i < pa.Points.size(); ++i)
  {
    worst = std::max(worst, (pa.Points[i] - pb.Points[i]).norm());
  }
  std::printf("%s: geodesic of 400 RK4 steps, max |typed - built-in| = %.2e\n", what, worst);
  EXPECT_LT(worst, 1e-12) << what;
}

TEST(ExpressionMetrics, EightGaussiansTypedEqualBuiltIn)
{
  const auto builtIn = ParseMetricDefinition(BuiltInEightGaussians());
  const auto typed = ParseMetricDefinition(TypedEightGaussians());
  ExpectSameMetric(*builtIn, *typed, "8 Gaussians");
  ExpectSameGeodesic(*builtIn, *typed, Vec3(-2, -0.5, 0.1), Vec3(1, 0.3, 0.05), "8 Gaussians");
}

TEST(ExpressionMetrics, TwistTypedEqualsPreset)
{
  const auto preset =
    ParseMetricDefinition(R"({"type": "diffeo", "preset": "twist", "rate": 0.8})");
  const auto typed = ParseMetricDefinition(R"({"type": "diffeo", "parameters": {"k": 0.8},
      "phi": ["cos(k*z)*x - sin(k*z)*y", "sin(k*z)*x + cos(k*z)*y", "z"]})");
  ExpectSameMetric(*preset, *typed, "twist");
  ExpectSameGeodesic(*preset, *typed, Vec3(1, 0, -1), Vec3(0.3, 1, 0.5), "twist");
}

TEST(ExpressionMetrics, TypedDiffeomorphismGeodesicsAreExact)
{
  // A bump translation typed as Phi; its geodesics are Phi^-1 of lines.
  const auto metric = ParseMetricDefinition(R"json({"type": "diffeo", "parameters": {"a": 0.4},
      "phi": ["x + a*exp(-(x^2 + y^2 + z^2))", "y + 0.3*a*exp(-((x-0.5)^2 + y^2 + z^2))", "z"]})json");
  const auto& diffeo = static_cast<const DiffeoMetric&>(*metric);
  const Vec3 p(-1.5, -0.3, 0.2);
  Vec3 v;
  ASSERT_TRUE(UnitSpeedVelocity(*metric, p, Vec3(1, 0.3, 0.1), v));
  for (double h : { 0.02, 0.01 })
  {
    GeodesicOptions options;
    options.Step = h;
    options.MaximumLength = 5.0;
    GeodesicPath path;
    TraceGeodesic(*metric, p, v, options, path);
    ASSERT_EQ(path.Reason, OutOfLength);
    Vec3 exact;
    ASSERT_TRUE(diffeo.ExactGeodesic(p, v, 5.0, exact));
    const double error = (path.Points.back() - exact).norm();
    std::printf("typed bump diffeomorphism, RK4 h = %g: endpoint error %.2e\n", h, error);
    EXPECT_LT(error, h == 0.02 ? 1e-6 : 1e-7);
  }
}

TEST(ExpressionMetrics, SameStructureSameShader)
{
  // Parameters are uniforms: a new value keeps the GLSL source.
  const std::string a =
    R"json({"type": "graph", "parameters": {"a": 1.0}, "f": "a*exp(-x^2-y^2-z^2)"})json";
  const std::string b =
    R"json({"type": "graph", "parameters": {"a": 2.5}, "f": "a*exp(-x^2-y^2-z^2)"})json";
  const MetricGlsl ga = EmitMetricGlsl(*ParseMetricDefinition(a));
  const MetricGlsl gb = EmitMetricGlsl(*ParseMetricDefinition(b));
  EXPECT_EQ(ga.Source, gb.Source);
  ASSERT_EQ(ga.Uniforms.size(), gb.Uniforms.size());
  ASSERT_EQ(ga.Uniforms[0].Name, gb.Uniforms[0].Name);
  EXPECT_EQ(ga.Uniforms[0].Values[0], 1.0);
  EXPECT_EQ(gb.Uniforms[0].Values[0], 2.5);
}

TEST(ExpressionMetrics, DegenerateWhereItDegeneratesNotRefused)
{
  // The Poincare ball is only a metric inside the unit ball: accepted, and a
  // geodesic leaving the ball stops with DegenerateMetric.
  const auto ball =
    ParseMetricDefinition(R"json({"type": "conformal", "n": "2/(1 - x^2 - y^2 - z^2)"})json");
  Mat3 g;
  EXPECT_TRUE(ball->Tensor(Vec3(0.1, 0.2, 0.3), g));
  EXPECT_FALSE(ball->Tensor(Vec3(1.5, 0, 0), g));
  GeodesicOptions options;
  options.MaximumLength = 20.0;
  GeodesicPath path;
  TraceGeodesic(*ball, Vec3(0.5, 0, 0), Vec3(-1.0, 0, 0), options, path);
  EXPECT_EQ(path.Reason, OutOfLength) << "hyperbolic space is complete inside the ball";
  const auto notDefinite = ParseMetricDefinition(R"({"type": "tensor", "g":
      [["1", "0", "0"], ["0", "1 - x", "0"], ["0", "0", "1"]]})");
  TraceGeodesic(*notDefinite, Vec3::Zero(), Vec3(1, 0, 0), options, path);
  EXPECT_EQ(path.Reason, DegenerateMetric);
  EXPECT_LT(path.Points.back()[0], 1.0);
}
} // namespace
} // namespace riemann

namespace riemann
{
namespace
{
TEST(ExpressionMetrics, NewParameterValuesReuseTheCompiledTape)
{
  // Re-reading a typed definition with other parameter values (or at another
  // time) compiles nothing: parsing is then much faster than the first time.
  const std::string text = R"json({"type": "graph", "parameters": {"a": {"from": 0.5, "to": 1.5}},
      "f": "a*exp(-(x^2+y^2+z^2)/2)*sin(3*x)*cos(2*y + z) + 0.1*x^3*y^2*z"})json";
  const auto first = ParseMetricDefinition(text, 0.0); // holds the compiled tape
  const auto start = std::chrono::steady_clock::now();
  for (int frame = 1; frame <= 20; ++frame)
  {
    const auto metric = ParseMetricDefinition(text, frame / 20.0);
    ScalarJet f;
    static_cast<const GraphMetric&>(*metric).GetField().Evaluate(Vec3(0.3, 0, 0), ValueOnly, f);
    const double a = 0.5 + frame / 20.0;
    EXPECT_NEAR(f.Value, a * std::exp(-0.045) * std::sin(0.9) + 0.0, 1e-12);
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("20 re-parses with new parameter values: %.1f ms in all\n", 1e3 * seconds);
}
} // namespace
} // namespace riemann
