// JSON metric definitions: every supported form builds the metric it names,
// and every bad input is refused with a message that says where and why.
// The printed table of bad inputs is part of the foundation issue's note.
#include "DiffeoMetric.h"
#include "GlslSource.h"
#include "GraphMetric.h"
#include "MetricDefinition.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace riemann
{
namespace
{
TEST(MetricDefinition, BuildsEveryFamily)
{
  const char* definitions[] = {
    R"({"type": "euclidean"})",
    R"({"type": "graph", "gaussians": [{"amplitude": 1.0, "center": [0,0,0], "sigma": [0.5,0.5,0.5]}]})",
    R"({"type": "graph", "gaussians": [{"amplitude": 1, "center": [0,0,0], "sigma": 0.5},
                                       {"amplitude": -0.5, "center": [1,0,0], "sigma": [0.3,0.4,0.5]}]})",
    R"({"type": "graph", "quadratic": {"diagonal": [1, 1, -1]}, "name": "saddle"})",
    R"({"type": "graph", "quadratic": [{"matrix": [[1,0,0],[0,1,0],[0,0,1]]}, {"linear": [1,0,0]}]})",
    R"({"type": "diffeo", "preset": "twist", "rate": 1.0})",
    R"({"type": "diffeo", "preset": "bump", "gaussian": {"amplitude": 0.5, "center": [0,0,0], "sigma": 1}, "direction": [1,0,0]})",
    R"({"type": "diffeo", "preset": "bump", "gaussian": {"amplitude": 0.3, "center": [0,0,0], "sigma": 1},
        "field": {"matrix": [[0,-1,0],[1,0,0],[0,0,0]], "center": [0,0,0], "offset": [0,0,0]}})",
    R"({"type": "diffeo", "compose": [{"preset": "twist"}, {"type": "diffeo", "preset": "identity"},
        {"compose": [{"preset": "twist", "rate": -0.5}]}]})",
    R"({"type": "conformal", "gaussians": [{"amplitude": 0.5, "center": [0,0,0], "sigma": 1}]})",
    R"({"type": "tensor", "matrix": [[2,0.1,0],[0.1,1,0],[0,0,1]]})",
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
    R"({"type": "graph", "gaussians": [{"amplitude": 2.0, "center": [1,0,0], "sigma": 0.5}]})");
  ASSERT_EQ(metric->FamilyName(), "graph");
  ScalarJet f;
  static_cast<const GraphMetric&>(*metric).GetField().Evaluate(Vec3(1.5, 0, 0), ValueOnly, f);
  EXPECT_NEAR(f.Value, 2.0 * std::exp(-0.5), 1e-15);

  auto twist = ParseMetricDefinition(R"({"type": "diffeo", "preset": "twist", "rate": 2})");
  VectorJet jet;
  static_cast<const DiffeoMetric&>(*twist).GetMap().Evaluate(Vec3(1, 0, 0.25), ValueOnly, jet);
  EXPECT_NEAR(jet.Value[0], std::cos(0.5), 1e-15);
  EXPECT_NEAR(jet.Value[1], std::sin(0.5), 1e-15);

  // compose[0] is applied last: twist(bump(p)).
  auto composed = ParseMetricDefinition(R"({"type": "diffeo", "compose": [
      {"preset": "twist"},
      {"preset": "bump", "gaussian": {"amplitude": 0.5, "center": [0,0,0], "sigma": 1}, "direction": [0,0,1]}]})");
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
    { "missing type", R"({"gaussians": []})", "missing required key \"type\"" },
    { "unknown type", R"({"type": "banana"})", "unknown metric type \"banana\"" },
    { "unknown key", R"({"type": "graph", "gausians": []})", "unknown key \"gausians\"" },
    { "expression (later issue)", R"({"type": "graph", "f": "x^2"})", "not yet supported" },
    { "expression phi", R"({"type": "diffeo", "phi": ["x","y","z"]})", "not yet supported" },
    { "empty graph", R"({"type": "graph"})", "needs at least one of" },
    { "center of 2",
      R"({"type": "graph", "gaussians": [{"amplitude": 1, "center": [0,0], "sigma": 1}]})",
      "metric.gaussians[0].center: expected an array of 3 numbers, got an array of 2" },
    { "string for number",
      R"({"type": "graph", "gaussians": [{"amplitude": "big", "center": [0,0,0], "sigma": 1}]})",
      "metric.gaussians[0].amplitude: expected a number (or {\"from\": a, \"to\": b}), got the string \"big\"" },
    { "negative sigma",
      R"({"type": "graph", "gaussians": [{"amplitude": 1, "center": [0,0,0], "sigma": [1,-1,1]}]})",
      "metric.gaussians[0].sigma: every spread must be positive" },
    { "overflowing number", R"({"type": "diffeo", "preset": "twist", "rate": 1e999})",
      "number overflow" },
    { "bump not a diffeomorphism",
      R"({"type": "diffeo", "preset": "bump", "gaussian": {"amplitude": 2, "center": [0,0,0], "sigma": 0.5}, "direction": [1,0,0]})",
      "is not a diffeomorphism: 1 + grad f . v" },
    { "bump field not a diffeomorphism",
      R"({"type": "diffeo", "preset": "bump", "gaussian": {"amplitude": -3, "center": [0,0,0], "sigma": 1},
          "field": {"matrix": [[1,0,0],[0,1,0],[0,0,1]]}})",
      "is not a diffeomorphism: det J" },
    { "bad map inside a composition",
      R"({"type": "diffeo", "compose": [{"preset": "twist"}, {"preset": "bump", "gaussian": {"amplitude": 5, "center": [0,0,0], "sigma": 1}, "direction": [0,1,0]}]})",
      "map 1 of the composition" },
    { "graph inside a composition", R"({"type": "diffeo", "compose": [{"type": "graph"}]})",
      "metric.compose[0].type" },
    { "bump with both direction and field",
      R"({"type": "diffeo", "preset": "bump", "gaussian": {"amplitude": 0.1, "center": [0,0,0], "sigma": 1}, "direction": [1,0,0], "field": {"matrix": [[0,0,0],[0,0,0],[0,0,0]]}})",
      "exactly one of" },
    { "unknown preset", R"({"type": "diffeo", "preset": "swirl"})", "unknown preset \"swirl\"" },
    { "conformal index not positive",
      R"({"type": "conformal", "constant": 1, "gaussians": [{"amplitude": -2, "center": [0,0,0], "sigma": 1}]})",
      "must be positive everywhere" },
    { "tensor not symmetric", R"({"type": "tensor", "matrix": [[1,2,0],[0,1,0],[0,0,1]]})",
      "symmetric" },
    { "tensor not positive definite", R"({"type": "tensor", "matrix": [[1,0,0],[0,-1,0],[0,0,1]]})",
      "not positive definite" },
    { "matrix of wrong shape", R"({"type": "tensor", "matrix": [[1,0,0],[0,1,0]]})",
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
      std::string(e.what()).find("/nonexistent/metric.json: cannot open"), std::string::npos);
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
  const std::string text = R"({"type": "graph", "gaussians": [{"amplitude": {"from": 0, "to": 2},
      "center": {"from": [0,0,0], "to": [1,0,0]}, "sigma": 0.5}]})";
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
  const std::string folding = R"({"type": "diffeo", "preset": "bump", "gaussian":
      {"amplitude": {"from": 0.5, "to": 3}, "center": [0,0,0], "sigma": 0.5}, "direction": [1,0,0]})";
  EXPECT_NO_THROW(ParseMetricDefinition(folding, 0.0));
  EXPECT_THROW(ParseMetricDefinition(folding, 1.0), MetricDefinitionError);
  EXPECT_THROW(ParseMetricDefinition(R"({"type": "graph", "gaussians": [{"amplitude": {"from": 0},
      "center": [0,0,0], "sigma": 1}]})"), MetricDefinitionError);
}
} // namespace
} // namespace riemann
