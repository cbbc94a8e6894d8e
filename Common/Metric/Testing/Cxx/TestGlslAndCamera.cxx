// GLSL emission (structure in the source, numbers in uniforms) and the
// observer camera (g-orthonormal frame, unit-speed pixel rays). The GLSL's
// numerical agreement with the CPU families is checked by the rendering
// module's tests, which run it on the GPU (llvmpipe).
#include "GlslSource.h"
#include "MetricGlsl.h"
#include "MetricDefinition.h"
#include "MetricTestUtilities.h"
#include "ObserverCamera.h"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <set>

namespace riemann
{
namespace
{
TEST(Glsl, EveryBuiltInFamilyEmitsBothFunctions)
{
  for (const auto& [name, metric] : testing::Metrics())
  {
    if (name == "tensor forwarding graph")
    {
      continue; // a general tensor field: checked below to be refused
    }
    const MetricGlsl glsl = EmitMetricGlsl(*metric);
    EXPECT_NE(glsl.Source.find("bool rt_metric_tensor(vec3 p, out mat3 g)"), std::string::npos)
      << name;
    EXPECT_NE(glsl.Source.find("bool rt_metric_acceleration(vec3 p, vec3 v, out vec3 a)"),
      std::string::npos)
      << name;
    std::set<std::string> names;
    for (const GlslUniform& u : glsl.Uniforms)
    {
      EXPECT_TRUE(names.insert(u.Name).second) << name << ": duplicate uniform " << u.Name;
      const size_t expected = u.Type == "float" ? 1 : u.Type == "vec3" ? 3 : 9;
      EXPECT_EQ(u.Values.size(), expected) << name << " " << u.Name;
      EXPECT_NE(glsl.Source.find("uniform " + u.Type + " " + u.Name + ";"), std::string::npos);
    }
  }
}

TEST(Glsl, NumbersAreUniformsAndStructureIsSource)
{
  const auto a = ParseMetricDefinition(R"({"type": "graph", "gaussians": [
      {"amplitude": 1.0, "center": [0,0,0], "sigma": 0.5},
      {"amplitude": 0.5, "center": [1,0,0], "sigma": [0.3,0.4,0.5]}]})");
  const auto b = ParseMetricDefinition(R"({"type": "graph", "gaussians": [
      {"amplitude": -0.7, "center": [0.2,0.1,0], "sigma": 0.9},
      {"amplitude": 0.1, "center": [-1,2,0], "sigma": [0.6,0.4,0.5]}]})");
  const auto c = ParseMetricDefinition(R"({"type": "graph", "gaussians": [
      {"amplitude": 1.0, "center": [0,0,0], "sigma": 0.5}]})");
  const MetricGlsl ga = EmitMetricGlsl(*a);
  const MetricGlsl gb = EmitMetricGlsl(*b);
  EXPECT_EQ(ga.Source, gb.Source) << "same structure must give the same source";
  ASSERT_EQ(ga.Uniforms.size(), gb.Uniforms.size());
  EXPECT_NE(ga.Uniforms[0].Values, gb.Uniforms[0].Values);
  EXPECT_DOUBLE_EQ(ga.Uniforms[0].Values[0], 1.0); // the first Gaussian's amplitude
  EXPECT_NE(EmitMetricGlsl(*c).Source, ga.Source) << "one Gaussian fewer is another structure";

  // A constant-direction bump and an affine-field bump share their source.
  const auto direction = ParseMetricDefinition(R"({"type": "diffeo", "preset": "bump",
      "gaussian": {"amplitude": 0.3, "center": [0,0,0], "sigma": 1}, "direction": [1,0,0]})");
  const auto field = ParseMetricDefinition(R"({"type": "diffeo", "preset": "bump",
      "gaussian": {"amplitude": 0.3, "center": [0,0,0], "sigma": 1},
      "field": {"matrix": [[0,-1,0],[1,0,0],[0,0,0]]}})");
  EXPECT_EQ(EmitMetricGlsl(*direction).Source, EmitMetricGlsl(*field).Source);
  // Twist rates differ only in a uniform.
  EXPECT_EQ(
    EmitMetricGlsl(*ParseMetricDefinition(R"({"type":"diffeo","preset":"twist","rate":1})")).Source,
    EmitMetricGlsl(*ParseMetricDefinition(R"({"type":"diffeo","preset":"twist","rate":-2})"))
      .Source);
}

TEST(Glsl, MatricesAreColumnMajor)
{
  // The bump's field matrix A = [[0,-1,0],[1,0,0],[0,0,0]]: column-major
  // storage puts A(1,0) = 1 at index 1 and A(0,1) = -1 at index 3.
  const auto field = ParseMetricDefinition(R"({"type": "diffeo", "preset": "bump",
      "gaussian": {"amplitude": 0.3, "center": [0,0,0], "sigma": 1},
      "field": {"matrix": [[0,-1,0],[1,0,0],[0,0,0]]}})");
  const MetricGlsl glsl = EmitMetricGlsl(*field);
  const GlslUniform* matrix = nullptr;
  for (const GlslUniform& u : glsl.Uniforms)
  {
    matrix = u.Type == "mat3" ? &u : matrix;
  }
  ASSERT_NE(matrix, nullptr);
  EXPECT_EQ(matrix->Values[1], 1.0);
  EXPECT_EQ(matrix->Values[3], -1.0);
}

TEST(Glsl, UnsupportedMetricIsRefusedByName)
{
  TensorMetric general(std::make_shared<testing::ForwardingTensorField>(
    std::make_shared<GraphMetric>(testing::PaperGaussian())));
  try
  {
    EmitMetricGlsl(general);
    ADD_FAILURE() << "a general tensor field was emitted";
  }
  catch (const GlslUnsupportedError& e)
  {
    EXPECT_NE(std::string(e.what()).find("has no GLSL form"), std::string::npos) << e.what();
  }
}

TEST(ObserverCamera, FrameIsOrthonormalInTheMetric)
{
  for (const auto& [name, metric] : testing::Metrics())
  {
    CameraSettings settings;
    settings.Position = Vec3(0.3, -0.2, 0.4);
    settings.LookAt = Vec3(1.0, 0.5, -0.3);
    settings.ViewUp = Vec3(0.1, 0.2, 1.0);
    settings.ViewAngle = 50.0;
    const ObserverCamera camera(*metric, settings);
    Mat3 g;
    ASSERT_TRUE(metric->Tensor(settings.Position, g));
    Mat3 frame;
    frame << camera.GetForward(), camera.GetUp(), camera.GetRight();
    EXPECT_LT((frame.transpose() * g * frame - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12)
      << name;
    // Forward points at the focal point; right completes a right-handed frame.
    EXPECT_GT(camera.GetForward().dot(settings.LookAt - settings.Position), 0) << name;
    EXPECT_GT(frame.determinant(), 0) << name;
    for (int i = 0; i < 20; ++i)
    {
      const Vec3 d = camera.PixelDirection(i * 7 % 64, i * 5 % 48, 64, 48);
      EXPECT_NEAR(d.dot(g * d), 1.0, 1e-12) << name;
    }
    // Equirectangular: unit speed too, and the image centre looks forward.
    settings.Mode = Projection::Equirectangular;
    const ObserverCamera sphere(*metric, settings);
    EXPECT_LT((sphere.Direction(0, 0, 2.0) - sphere.GetForward()).norm(), 1e-15) << name;
    const Vec3 d = sphere.Direction(0.37, -0.52, 2.0);
    EXPECT_NEAR(d.dot(g * d), 1.0, 1e-12) << name;
  }
}

TEST(ObserverCamera, PerspectiveGeometryInEuclideanSpace)
{
  EuclideanMetric flat;
  CameraSettings settings;
  settings.Position = Vec3(0, 0, 5);
  settings.LookAt = Vec3::Zero();
  settings.ViewUp = Vec3(0, 1, 0);
  settings.ViewAngle = 90.0;
  const ObserverCamera camera(flat, settings);
  EXPECT_LT((camera.GetRight() - Vec3(1, 0, 0)).norm(), 1e-15);
  // The top edge of a 90-degree view is 45 degrees up.
  const Vec3 top = camera.Direction(0.0, 1.0, 1.0);
  EXPECT_LT((top - Vec3(0, 1, -1).normalized()).norm(), 1e-15);
  // Row 0 is the bottom row (OpenGL), column 0 the left column.
  const Vec3 corner = camera.PixelDirection(0, 0, 2, 2);
  EXPECT_LT(corner[0], 0);
  EXPECT_LT(corner[1], 0);
  settings.LookAt = settings.Position;
  EXPECT_THROW(ObserverCamera(flat, settings), std::runtime_error);
  settings.LookAt = Vec3::Zero();
  settings.ViewUp = Vec3(0, 0, 2);
  EXPECT_THROW(ObserverCamera(flat, settings), std::runtime_error);
}
} // namespace
} // namespace riemann
