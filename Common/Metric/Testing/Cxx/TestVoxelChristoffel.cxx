// VoxelChristoffelMetric: the sampled metric's Christoffel symbols sampled at
// the voxels and interpolated trilinearly (tractography's fast path).
// - at the voxels, Gamma and g are the spline's (to float rounding);
// - between them Gamma converges to the spline's at order 2: halving the
//   spacing of a smooth field divides the largest error by about 4
//   (observed order 2 +- 0.35; measured 1.82 from h = 0.2 to 0.1);
// - a geodesic of the fast path stays within O(h^2) of the spline's, and
//   its end converges at order 2 as well (measured 2.5e-3 and 6.1e-4 over
//   length 1.5: order 2.04);
// - beyond the samples' box, and for derivatives, it is the wrapped metric;
// - next to a wall (g 1000 times larger in one voxel, as a repaired
//   background voxel), no step of a geodesic jumps (interpolated symbols
//   once threw one 36 km): every chord is at most the step's length in g = I;
// - its shader reads six RGBA textures with one trilinear read each: OpenGL's
//   trilinear filter (exact weights), applied to them at the shader's
//   coordinate and unpacked by the shader's swizzles, gives the CPU's g and
//   Gamma; beyond the box, g = I without a read, or with "outside": "stop"
//   the spline's continuation and its inside test.
#include "Christoffel.h"
#include "GeodesicTrace.h"
#include "MetricGlsl.h"
#include "SampledTensorSamples.h"
#include "VoxelChristoffelMetric.h"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <regex>

using riemann::Mat3;
using riemann::Mat3Stack;
using riemann::Vec3;

namespace
{
/// A smooth anisotropic metric: a fibre direction turning with x and y.
Mat3 Smooth(const Vec3& x)
{
  const double angle = 0.6 * std::sin(x[0]) + 0.4 * std::cos(1.3 * x[1]);
  const Vec3 t(std::cos(angle), std::sin(angle), 0.2 * std::sin(x[2]));
  const Vec3 u = t.normalized();
  return 0.6 * Mat3::Identity() + 1.2 * (Mat3::Identity() - u * u.transpose()) + 0.1 * std::exp(-x.squaredNorm() / 8.0) * Mat3::Identity();
}

/// The sampled metric of Smooth on [-2, 2]^3 at spacing h, exact and fast.
std::pair<std::shared_ptr<const riemann::Metric>, std::shared_ptr<const riemann::Metric>> Sampled(double h)
{
  riemann::SampledTensorGrid grid;
  const int n = static_cast<int>(std::lround(4.0 / h)) + 1;
  grid.Dimensions = { n, n, n };
  grid.Spacing = Vec3::Constant(h);
  grid.Origin = Vec3::Constant(-2.0);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const Mat3 g = Smooth(grid.Origin + h * Vec3(i, j, k));
        for (double c : { g(0, 0), g(1, 1), g(2, 2), g(0, 1), g(1, 2), g(0, 2) })
        {
          grid.Components.push_back(c);
        }
      }
  riemann::SampledTensorOptions options;
  options.ChristoffelAtVoxels = false;
  auto exact = riemann::MakeSampledTensorMetric(grid, options);
  options.ChristoffelAtVoxels = true;
  return { exact, riemann::MakeSampledTensorMetric(grid, options) };
}

double LargestGammaError(const riemann::Metric& exact, const riemann::Metric& fast)
{
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> inside(-1.0, 1.0);
  double worst = 0.0;
  for (int s = 0; s < 300; ++s)
  {
    const Vec3 p(inside(generator), inside(generator), inside(generator));
    Mat3Stack a, b;
    EXPECT_TRUE(exact.Christoffel(p, a));
    EXPECT_TRUE(fast.Christoffel(p, b));
    for (int m = 0; m < 3; ++m)
    {
      worst = std::max(worst, (a[m] - b[m]).cwiseAbs().maxCoeff());
    }
  }
  return worst;
}

Vec3 GeodesicEnd(const riemann::Metric& metric)
{
  riemann::GeodesicOptions options;
  options.Step = 0.01;
  options.MaximumLength = 1.5;
  riemann::GeodesicPath path;
  riemann::TraceGeodesic(metric, Vec3(-0.7, -0.2, 0.1), Vec3(1.0, 0.4, 0.1), options, path);
  return path.Points.back();
}
} // namespace

TEST(VoxelChristoffel, AtTheVoxelsItIsTheSplines)
{
  const auto [exact, fast] = Sampled(0.25);
  for (const Vec3& p : { Vec3(0.0, 0.0, 0.0), Vec3(-1.0, 0.5, 0.75), Vec3(2.0, -2.0, 1.25) })
  {
    Mat3Stack a, b;
    Mat3 ga, gb;
    ASSERT_TRUE(exact->Christoffel(p, a) && fast->Christoffel(p, b));
    ASSERT_TRUE(exact->Tensor(p, ga) && fast->Tensor(p, gb));
    for (int m = 0; m < 3; ++m)
    {
      EXPECT_LT((a[m] - b[m]).cwiseAbs().maxCoeff(), 1e-6 * (1.0 + a[m].cwiseAbs().maxCoeff()));
    }
    EXPECT_LT((ga - gb).cwiseAbs().maxCoeff(), 1e-6);
  }
  // Beyond the box: the wrapped metric's (g = I, Gamma = 0).
  Mat3Stack outside;
  ASSERT_TRUE(fast->Christoffel(Vec3(3.0, 0.0, 0.0), outside));
  EXPECT_EQ(outside[0].cwiseAbs().maxCoeff(), 0.0);
  EXPECT_NE(fast->Describe().find("sampled at the voxels"), std::string::npos);
}

TEST(VoxelChristoffel, GammaAndGeodesicsConvergeAtOrderTwo)
{
  const auto coarse = Sampled(0.2);
  const auto fine = Sampled(0.1);
  const double coarseError = LargestGammaError(*coarse.first, *coarse.second);
  const double fineError = LargestGammaError(*fine.first, *fine.second);
  const double order = std::log2(coarseError / fineError);
  std::cout << "Gamma errors " << coarseError << " (h 0.2), " << fineError << " (h 0.1): order "
            << order << "\n";
  EXPECT_NEAR(order, 2.0, 0.35);
  const double coarseEnd = (GeodesicEnd(*coarse.first) - GeodesicEnd(*coarse.second)).norm();
  const double fineEnd = (GeodesicEnd(*fine.first) - GeodesicEnd(*fine.second)).norm();
  std::cout << "geodesic end differences " << coarseEnd << ", " << fineEnd << " over length 1.5\n";
  EXPECT_LT(coarseEnd, 0.01);
  EXPECT_NEAR(std::log2(coarseEnd / fineEnd), 2.0, 0.5);
}

TEST(VoxelChristoffel, AWallOfLargeGDoesNotThrowGeodesics)
{
  riemann::SampledTensorGrid grid;
  grid.Dimensions = { 9, 9, 9 };
  grid.Spacing = Vec3::Constant(0.5);
  grid.Origin = Vec3::Constant(-2.0);
  for (int k = 0; k < 9; ++k)
    for (int j = 0; j < 9; ++j)
      for (int i = 0; i < 9; ++i)
      {
        const double scale = (i == 5 && j == 4) ? 1000.0 : 1.0; // one column of wall voxels
        for (double c : { scale, scale, scale, 0.0, 0.0, 0.0 })
        {
          grid.Components.push_back(c);
        }
      }
  riemann::SampledTensorOptions options;
  options.ChristoffelAtVoxels = true;
  options.StopOutside = true;
  const auto fast = riemann::MakeSampledTensorMetric(grid, options);
  riemann::GeodesicOptions trace;
  trace.Step = 0.05;
  trace.MaximumLength = 6.0;
  for (double y : { -0.3, -0.1, 0.0, 0.1, 0.2 })
  {
    riemann::GeodesicPath path;
    riemann::TraceGeodesic(*fast, Vec3(-1.8, y, 0.05), Vec3(1.0, 0.05, 0.0), trace, path);
    ASSERT_GT(path.Points.size(), 10u);
    for (std::size_t k = 1; k < path.Points.size(); ++k)
    {
      // g >= I everywhere, so a step of arc length 0.05 is at most 0.05 long.
      EXPECT_LT((path.Points[k] - path.Points[k - 1]).norm(), 0.05 * 1.01) << "y " << y << " step " << k;
    }
  }
}

namespace
{
/// OpenGL's GL_LINEAR read of an RGBA 3D texture (clamped to its edges) at
/// normalised coordinate c, with exact weights (llvmpipe's are float).
std::array<double, 4> LinearRead(const std::vector<float>& texels, const std::array<int, 3>& n, const Vec3& c)
{
  int low[3];
  double t[3];
  for (int a = 0; a < 3; ++a)
  {
    const double u = c[a] * n[a] - 0.5;
    low[a] = static_cast<int>(std::floor(u));
    t[a] = u - low[a];
  }
  std::array<double, 4> sum = { 0, 0, 0, 0 };
  for (int corner = 0; corner < 8; ++corner)
  {
    double weight = 1.0;
    long long index = 0, stride = 1;
    for (int a = 0; a < 3; ++a)
    {
      const int bit = (corner >> a) & 1;
      weight *= bit ? t[a] : 1.0 - t[a];
      index += stride * std::clamp(low[a] + bit, 0, n[a] - 1);
      stride *= n[a];
    }
    for (int m = 0; m < 4; ++m)
    {
      sum[m] += weight * texels[4 * index + m];
    }
  }
  return sum;
}
} // namespace

TEST(VoxelChristoffel, TheShadersFilteredReadsAreTheCpusReading)
{
  const auto [exact, fast] = Sampled(0.25);
  const riemann::MetricGlsl glsl = riemann::EmitMetricGlsl(*fast);
  ASSERT_EQ(glsl.Textures.size(), 6u) << "g and dg in six RGBA textures, no spline texels";
  for (const riemann::GlslTexture3D& texture : glsl.Textures)
  {
    EXPECT_EQ(texture.Components, 4);
    EXPECT_EQ(texture.Dimensions, (std::array<int, 3>{ 17, 17, 17 }));
  }
  // One filtered read per texture, nothing read texel by texel.
  const std::regex reads(R"(texture\(rt_voxel_jet(\d+), c\))");
  EXPECT_EQ(std::distance(std::sregex_iterator(glsl.Source.begin(), glsl.Source.end(), reads),
              std::sregex_iterator()),
    6);
  EXPECT_EQ(glsl.Source.find("texelFetch("), std::string::npos);

  // The shader's coordinate, c = (clamp(u, 0, n - 1) + 1/2) / n, and its
  // unpacking: value v of the 24 is component v % 4 of texture v / 4.
  std::mt19937 generator(11);
  std::uniform_real_distribution<double> box(-2.1, 2.1); // to the faces, 0.125 beyond the samples
  const std::array<int, 3> n = { 17, 17, 17 };
  for (int s = 0; s < 200; ++s)
  {
    const Vec3 p(box(generator), box(generator), box(generator));
    const Vec3 u = (p - Vec3::Constant(-2.0)) / 0.25;
    Vec3 c;
    for (int a = 0; a < 3; ++a)
    {
      c[a] = (std::clamp(u[a], 0.0, 16.0) + 0.5) / 17.0;
    }
    double value[24];
    for (int t = 0; t < 6; ++t)
    {
      const std::array<double, 4> r = LinearRead(*glsl.Textures[t].Values, n, c);
      std::copy(r.begin(), r.end(), value + 4 * t);
    }
    const auto symmetric = [&](int first)
    {
      const double* v = value + first;
      Mat3 m;
      m << v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2];
      return m;
    };
    const Mat3 g = symmetric(0);
    const Mat3Stack dg = { symmetric(6), symmetric(12), symmetric(18) };
    Mat3 cpuG;
    Mat3Stack cpuGamma, shaderGamma;
    ASSERT_TRUE(fast->Tensor(p, cpuG) && fast->Christoffel(p, cpuGamma));
    riemann::ChristoffelFromMetricDerivatives(g.inverse(), dg, shaderGamma);
    EXPECT_LT((g - cpuG).cwiseAbs().maxCoeff(), 1e-5) << "at " << p.transpose();
    for (int m = 0; m < 3; ++m)
    {
      EXPECT_LT((shaderGamma[m] - cpuGamma[m]).cwiseAbs().maxCoeff(), 1e-4) << "at " << p.transpose();
    }
  }

  // Beyond the box: g = I ("euclidean"), or the spline's own continuation
  // with its textures and the inside test ("outside": "stop").
  EXPECT_NE(glsl.Source.find("g = mat3(1.0);"), std::string::npos);
  EXPECT_EQ(glsl.Source.find("bool rt_sampled_inside"), std::string::npos);
  riemann::SampledTensorGrid grid;
  grid.Dimensions = { 3, 3, 3 };
  grid.Components.assign(6 * 27, 0.0);
  for (int v = 0; v < 27; ++v)
  {
    std::fill_n(grid.Components.begin() + 6 * v, 3, 2.0);
  }
  riemann::SampledTensorOptions options;
  options.StopOutside = true;
  const riemann::MetricGlsl stopping =
    riemann::EmitMetricGlsl(*riemann::MakeSampledTensorMetric(grid, options));
  EXPECT_EQ(stopping.Textures.size(), 8u) << "the spline's two textures, then the voxels' six";
  EXPECT_NE(stopping.Source.find("bool rt_sampled_inside"), std::string::npos);
  EXPECT_NE(stopping.Source.find("rt_sampled_tensor"), std::string::npos);
}

TEST(VoxelChristoffel, PacketAccelerationsAreTheLanesAccelerations)
{
  // All lanes at once (the adjugate, a structure of arrays) against each
  // lane's Acceleration() (the 27 symbols from g^-1): the same quantity in
  // another order of operations, to 1e-12 relative. Lanes beyond the box
  // (g = I there: zero acceleration) and lanes not asked for are mixed in.
  const auto [exact, fast] = Sampled(0.25);
  std::mt19937 generator(5);
  std::uniform_real_distribution<double> box(-2.6, 2.6); // some beyond the faces at +-2.125
  std::uniform_real_distribution<double> speed(-1.5, 1.5);
  int beyond = 0;
  for (int packet = 0; packet < 200; ++packet)
  {
    riemann::PacketVec3 x, v, a;
    for (int l = 0; l < riemann::PacketWidth; ++l)
    {
      x.SetLane(l, Vec3(box(generator), box(generator), box(generator)));
      v.SetLane(l, Vec3(speed(generator), speed(generator), speed(generator)));
    }
    const riemann::LaneMask asked = packet % 3 == 0 ? 0x5Bu : riemann::AllLanes;
    const riemann::LaneMask defined = fast->AccelerationPacket(x, v, a, asked);
    EXPECT_EQ(defined, asked) << "every lane asked for is defined (g > 0 everywhere)";
    for (int l = 0; l < riemann::PacketWidth; ++l)
    {
      if (!riemann::HasLane(asked, l))
      {
        continue;
      }
      Vec3 expected;
      ASSERT_TRUE(fast->Acceleration(x.Lane(l), v.Lane(l), expected));
      EXPECT_LT((a.Lane(l) - expected).norm(), 1e-12 * (1.0 + expected.norm()))
        << "lane " << l << " at " << x.Lane(l).transpose();
      beyond += (x.Lane(l).cwiseAbs().maxCoeff() > 2.125) ? 1 : 0;
    }
  }
  EXPECT_GT(beyond, 100) << "lanes beyond the box were tried";
}
