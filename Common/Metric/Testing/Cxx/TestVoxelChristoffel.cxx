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
//   once threw one 36 km): every chord is at most the step's length in g = I.
#include "GeodesicTrace.h"
#include "SampledTensorSamples.h"
#include "VoxelChristoffelMetric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

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
