// JSON metric definitions: every supported form builds the metric it names,
// and every bad input is refused with a message that says where and why.
// The printed table of bad inputs is part of the foundation issue's note.
#include "DiffeoMetric.h"
#include "GlslSource.h"
#include "MetricGlsl.h"
#include "GraphMetric.h"
#include "MetricDefinition.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdio>

namespace riemann
{
namespace
{
TEST(MetricDefinition, BuildsEveryFamily)
{
  const char* definitions[] = {
    R"json({"type": "euclidean"})json",
    R"json({"type": "graph", "gaussians": [{"amplitude": 1.0, "center": [0,0,0], "sigma": [0.5,0.5,0.5]}]})json",
    R"json({"type": "graph", "gaussians": [{"amplitude": 1, "center": [0,0,0], "sigma": 0.5},
                                       {"amplitude": -0.5, "center": [1,0,0], "sigma": [0.3,0.4,0.5]}]})json",
    R"json({"type": "graph", "quadratic": {"diagonal": [1, 1, -1]}, "name": "saddle"})json",
    R"json({"type": "graph", "quadratic": [{"matrix": [[1,0,0],[0,1,0],[0,0,1]]}, {"linear": [1,0,0]}]})json",
    R"json({"type": "diffeo", "preset": "twist", "rate": 1.0})json",
    R"json({"type": "diffeo", "preset": "bump", "gaussian": {"amplitude": 0.5, "center": [0,0,0], "sigma": 1}, "direction": [1,0,0]})json",
    R"json({"type": "diffeo", "preset": "bump", "gaussian": {"amplitude": 0.3, "center": [0,0,0], "sigma": 1},
        "field": {"matrix": [[0,-1,0],[1,0,0],[0,0,0]], "center": [0,0,0], "offset": [0,0,0]}})json",
    R"json({"type": "diffeo", "compose": [{"preset": "twist"}, {"type": "diffeo", "preset": "identity"},
        {"compose": [{"preset": "twist", "rate": -0.5}]}]})json",
    R"json({"type": "conformal", "gaussians": [{"amplitude": 0.5, "center": [0,0,0], "sigma": 1}]})json",
    R"json({"type": "tensor", "matrix": [[2,0.1,0],[0.1,1,0],[0,0,1]]})json",
  };
  for (const char* text : definitions)
  {
    EXPECT_NO_THROW({
      auto metric = ParseMetricDefinition(text);
      Mat3 g;
      EXPECT_TRUE(metric->Tensor(Vec3(0.1, 0.2, 0.3), g));
    }) << text;
  }
}

TEST(MetricDefinition, BuildsWhatItSays)
{
  auto metric = ParseMetricDefinition(
    R"json({"type": "graph", "gaussians": [{"amplitude": 2.0, "center": [1,0,0], "sigma": 0.5}]})json");
  ASSERT_EQ(metric->FamilyName(), "graph");
  ScalarJet f;
  static_cast<const GraphMetric&>(*metric).GetField().Evaluate(Vec3(1.5, 0, 0), ValueOnly, f);
  EXPECT_NEAR(f.Value, 2.0 * std::exp(-0.5), 1e-15);

  auto twist = ParseMetricDefinition(R"json({"type": "diffeo", "preset": "twist", "rate": 2})json");
  VectorJet jet;
  static_cast<const DiffeoMetric&>(*twist).GetMap().Evaluate(Vec3(1, 0, 0.25), ValueOnly, jet);
  EXPECT_NEAR(jet.Value[0], std::cos(0.5), 1e-15);
  EXPECT_NEAR(jet.Value[1], std::sin(0.5), 1e-15);

  // compose[0] is applied last: twist(bump(p)).
  auto composed = ParseMetricDefinition(R"json({"type": "diffeo", "compose": [
      {"preset": "twist"},
      {"preset": "bump", "gaussian": {"amplitude": 0.5, "center": [0,0,0], "sigma": 1}, "direction": [0,0,1]}]})json");
  static_cast<const DiffeoMetric&>(*composed).GetMap().Evaluate(Vec3(1, 0, 0), ValueOnly, jet);
  const double z = 0.5 * std::exp(-0.5);
  EXPECT_NEAR(jet.Value[0], std::cos(z), 1e-15);
  EXPECT_NEAR(jet.Value[2], z, 1e-15);
}

struct BadInput
{
  const char* What;
  const char* Json;
  const char* Expected; // a substring of the message
};

TEST(MetricDefinition, RefusesBadInputWithAClearMessage)
{
  const BadInput cases[] = {
    { "malformed JSON", "{\"type\": \"graph\",\n \"gaussians\": [}", "line 2, column" },
    { "not an object", "[1, 2, 3]", "expected a JSON object" },
    { "missing type", R"json({"gaussians": []})json", "missing required key \"type\"" },
    { "unknown type", R"json({"type": "banana"})json", "unknown metric type \"banana\"" },
    { "unknown key", R"json({"type": "graph", "gausians": []})json", "unknown key \"gausians\"" },
    { "expression: unknown symbol", R"json({"type": "graph", "f": "x^2 + q"})json",
      "metric.f: column 7: unknown symbol" },
    { "expression: syntax error", R"json({"type": "graph", "f": "x^2 + * y"})json",
      "metric.f: column " },
    { "expression: unknown function", R"json({"type": "conformal", "n": "1 + erf(x)"})json",
      "metric.n: column 5" },
    { "expression: two components of phi", R"json({"type": "diffeo", "phi": ["x", "y"]})json",
      "metric.phi: expected an array of 3 expressions, got an array of 2" },
    { "expression: error in phi[1]", R"json({"type": "diffeo", "phi": ["x", "y +", "z"]})json",
      "metric.phi[1]: column" },
    { "expression: asymmetric g",
      R"json({"type": "tensor", "g": [["1","x","0"],["0","1","0"],["0","0","1"]]})json",
      "metric.g: g must be symmetric: g[0][1] = \"x\" but g[1][0] = \"0\"" },
    { "expression: g of wrong size", R"json({"type": "tensor", "g": [["1","0"],["0","1"]]})json",
      "metric.g: expected a 3x3 array of expressions" },
    { "parameter not a number",
      R"json({"type": "graph", "parameters": {"a": "big"}, "f": "a*x"})json",
      "metric.parameters.a: expected a number" },
    { "parameter named like a variable",
      R"json({"type": "graph", "parameters": {"x": 1}, "f": "x"})json", "metric.f: " },
    { "empty graph", R"json({"type": "graph"})json", "needs at least one of" },
    { "center of 2",
      R"json({"type": "graph", "gaussians": [{"amplitude": 1, "center": [0,0], "sigma": 1}]})json",
      "metric.gaussians[0].center: expected an array of 3 numbers, got an array of 2" },
    { "string for number",
      R"json({"type": "graph", "gaussians": [{"amplitude": "big", "center": [0,0,0], "sigma": 1}]})json",
      "metric.gaussians[0].amplitude: expected a number (or {\"from\": a, \"to\": b}), got the "
      "string \"big\"" },
    { "negative sigma",
      R"json({"type": "graph", "gaussians": [{"amplitude": 1, "center": [0,0,0], "sigma": [1,-1,1]}]})json",
      "metric.gaussians[0].sigma: every spread must be positive" },
    { "overflowing number", R"json({"type": "diffeo", "preset": "twist", "rate": 1e999})json",
      "number overflow" },
    { "bump not a diffeomorphism",
      R"json({"type": "diffeo", "preset": "bump", "gaussian": {"amplitude": 2, "center": [0,0,0], "sigma": 0.5}, "direction": [1,0,0]})json",
      "is not a diffeomorphism: 1 + grad f . v" },
    { "bump field not a diffeomorphism",
      R"json({"type": "diffeo", "preset": "bump", "gaussian": {"amplitude": -3, "center": [0,0,0], "sigma": 1},
          "field": {"matrix": [[1,0,0],[0,1,0],[0,0,1]]}})json",
      "is not a diffeomorphism: det J" },
    { "bad map inside a composition",
      R"json({"type": "diffeo", "compose": [{"preset": "twist"}, {"preset": "bump", "gaussian": {"amplitude": 5, "center": [0,0,0], "sigma": 1}, "direction": [0,1,0]}]})json",
      "map 1 of the composition" },
    { "graph inside a composition", R"json({"type": "diffeo", "compose": [{"type": "graph"}]})json",
      "metric.compose[0].type" },
    { "bump with both direction and field",
      R"json({"type": "diffeo", "preset": "bump", "gaussian": {"amplitude": 0.1, "center": [0,0,0], "sigma": 1}, "direction": [1,0,0], "field": {"matrix": [[0,0,0],[0,0,0],[0,0,0]]}})json",
      "exactly one of" },
    { "unknown preset", R"json({"type": "diffeo", "preset": "swirl"})json",
      "unknown preset \"swirl\"" },
    { "conformal index not positive",
      R"json({"type": "conformal", "constant": 1, "gaussians": [{"amplitude": -2, "center": [0,0,0], "sigma": 1}]})json",
      "must be positive everywhere" },
    { "tensor not symmetric", R"json({"type": "tensor", "matrix": [[1,2,0],[0,1,0],[0,0,1]]})json",
      "symmetric" },
    { "tensor not positive definite",
      R"json({"type": "tensor", "matrix": [[1,0,0],[0,-1,0],[0,0,1]]})json",
      "not positive definite" },
    { "matrix of wrong shape", R"json({"type": "tensor", "matrix": [[1,0,0],[0,1,0]]})json",
      "metric.matrix: expected a 3x3 matrix" },
  };
  std::printf("\n| bad input | message |\n|---|---|\n");
  for (const BadInput& c : cases)
  {
    std::string message;
    try
    {
      ParseMetricDefinition(c.Json);
      ADD_FAILURE() << c.What << ": accepted";
    }
    catch (const MetricDefinitionError& e)
    {
      message = e.what();
    }
    EXPECT_NE(message.find(c.Expected), std::string::npos)
      << c.What << ": message was: " << message;
    std::printf("| %s | %s |\n", c.What, message.c_str());
  }
}

TEST(MetricDefinition, FileErrorsNameTheFile)
{
  try
  {
    LoadMetricDefinitionFile("/nonexistent/metric.json");
    ADD_FAILURE() << "accepted a missing file";
  }
  catch (const MetricDefinitionError& e)
  {
    EXPECT_NE(
      std::string(e.what()).find("/nonexistent/metric.json: the metric file does not exist"), std::string::npos);
  }
}
} // namespace
} // namespace riemann

namespace riemann
{
namespace
{
TEST(MetricDefinition, AnimatedNumbersFollowTime)
{
  const std::string text =
    R"json({"type": "graph", "gaussians": [{"amplitude": {"from": 0, "to": 2},
      "center": {"from": [0,0,0], "to": [1,0,0]}, "sigma": 0.5}]})json";
  for (double t : { 0.0, 0.25, 1.0 })
  {
    const auto metric = ParseMetricDefinition(text, t);
    ScalarJet f;
    const Vec3 center(t, 0, 0);
    static_cast<const GraphMetric&>(*metric).GetField().Evaluate(center, ValueOnly, f);
    EXPECT_NEAR(f.Value, 2.0 * t, 1e-15) << "t = " << t;
  }
  // The structure, hence the shader source, is the same at every time.
  EXPECT_EQ(EmitMetricGlsl(*ParseMetricDefinition(text, 0.0)).Source,
    EmitMetricGlsl(*ParseMetricDefinition(text, 0.7)).Source);
  // Validation runs at the requested time: this bump folds only late.
  const std::string folding = R"json({"type": "diffeo", "preset": "bump", "gaussian":
      {"amplitude": {"from": 0.5, "to": 3}, "center": [0,0,0], "sigma": 0.5}, "direction": [1,0,0]})json";
  EXPECT_NO_THROW(ParseMetricDefinition(folding, 0.0));
  EXPECT_THROW(ParseMetricDefinition(folding, 1.0), MetricDefinitionError);
  EXPECT_THROW(
    ParseMetricDefinition(R"json({"type": "graph", "gaussians": [{"amplitude": {"from": 0},
      "center": [0,0,0], "sigma": 1}]})json"),
    MetricDefinitionError);
}
} // namespace
} // namespace riemann

TEST(MetricDefinition, ManyGaussiansValidateByTheirGradientBound)
{
  // A graph metric of Gaussians is positive definite wherever grad f is
  // finite: validated from the bumps' gradient bounds, so thousands of
  // bumps (a point cloud's worth) load (sampling around every bump cost
  // O(N^2): over 100 s for 1600). The bound must be right: g at points
  // near every bump is finite and positive definite.
  std::string json = R"({"type": "graph", "gaussians": [)";
  const int count = 3000;
  for (int k = 0; k < count; ++k)
  {
    char bump[160];
    std::snprintf(bump, sizeof(bump),
      R"(%s{"amplitude": %g, "center": [%g, %g, %g], "sigma": [%g, %g, %g]})", k ? ", " : "",
      (k % 2 ? -1.0 : 1.0) * (0.5 + 0.001 * k), std::sin(k) * 3, std::cos(1.3 * k) * 3,
      std::sin(0.7 * k) * 3, 0.1 + 0.0001 * k, 0.2, 0.15);
    json += bump;
  }
  json += "]}";
  const auto metric = riemann::ParseMetricDefinition(json); // throws when not valid
  ASSERT_TRUE(metric);
  EXPECT_EQ(metric->Validate(), "");
  for (int k = 0; k < count; k += 97)
  {
    const riemann::Vec3 near(std::sin(k) * 3 + 0.1, std::cos(1.3 * k) * 3, std::sin(0.7 * k) * 3);
    riemann::Mat3 g;
    ASSERT_TRUE(metric->Tensor(near, g));
    EXPECT_TRUE(g.allFinite());
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<riemann::Mat3>(g, Eigen::EigenvaluesOnly).eigenvalues().minCoeff(), 0.999);
  }

  // A bound that overflows (amplitude 1e300, spread 1e-10) falls back to
  // sampling, which finds where g is not finite.
  const std::string wild = R"({"type": "graph", "gaussians": [{"amplitude": 1e300,
    "center": [0, 0, 0], "sigma": [1e-10, 1e-10, 1e-10]}]})";
  try
  {
    riemann::ParseMetricDefinition(wild);
    FAIL() << "an overflowing bump was accepted";
  }
  catch (const std::exception& e)
  {
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos) << e.what();
  }
}
