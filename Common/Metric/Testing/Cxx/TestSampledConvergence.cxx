// Sampled versions of analytic metrics against the analytic ones (issue 17):
// the twist (flat, a diffeomorphism), the Gaussian lens (conformal) and Nil
// (a tensor of expressions), each sampled on 16^3, 32^3 and 64^3 points over
// [-1.6, 1.6]^3 and interpolated by the cubic B-spline (SampledTensorField).
// At 200 random points of [-1, 1]^3 (two cells and more from the faces) the
// errors of g, of the Christoffel symbols and of the scalar curvature, and
// the endpoint errors of 12 geodesics of length 0.6 from points of
// [-0.4, 0.4]^3, fall with the spacing h at the spline's order, 2: each
// halving of h divides them by about 4. Stated tolerance: the observed order
// from 32^3 to 64^3 is at least 1.7 for every quantity and metric, except
// where the sampled value is exact: the twist's g is polynomial (g_zz =
// 1 + x^2 + y^2, the rest affine), so its spline is g + (2 h^2 / 3) dz^2,
// and adding c dz^2 to this flat metric, whose dz is parallel, changes
// neither its Christoffel symbols nor its curvature: those errors stay below
// 1e-10 at every size (measured about 1e-14). The table of errors and orders
// is printed (the figures of issue 17's note).
#include "Christoffel.h"
#include "Curvature.h"
#include "GeodesicTrace.h"
#include "MetricDefinition.h"
#include "SampledTensorSamples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace
{
using riemann::Mat3;
using riemann::Mat3Stack;
using riemann::Metric;
using riemann::Vec3;

constexpr double Half = 1.6;

/// g of `metric` sampled on n^3 points over [-Half, Half]^3.
std::shared_ptr<const Metric> Sampled(const Metric& metric, int n)
{
  riemann::SampledTensorGrid grid;
  grid.Dimensions = { n, n, n };
  const double h = 2.0 * Half / (n - 1);
  grid.Spacing = Vec3(h, h, h);
  grid.Origin = Vec3(-Half, -Half, -Half);
  grid.Components.reserve(6 * static_cast<std::size_t>(n) * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        Mat3 g;
        EXPECT_TRUE(metric.Tensor(grid.Origin + h * Vec3(i, j, k), g));
        for (double c : { g(0, 0), g(1, 1), g(2, 2), g(0, 1), g(1, 2), g(0, 2) })
        {
          grid.Components.push_back(c);
        }
      }
    }
  }
  // The spline's own symbols ("christoffel": "spline"): the reading whose
  // order and exactness this test states.
  riemann::SampledTensorOptions options;
  options.ChristoffelAtVoxels = false;
  return riemann::MakeSampledTensorMetric(std::move(grid), options);
}

struct Errors
{
  double G = 0.0;
  double Gamma = 0.0;
  double Scalar = 0.0;
  double Endpoint = 0.0;
};

double MaxAbs(const Mat3& m)
{
  return m.cwiseAbs().maxCoeff();
}

Errors Compare(const Metric& exact, const Metric& sampled)
{
  Errors e;
  std::mt19937 random(17);
  std::uniform_real_distribution<double> inner(-1.0, 1.0);
  for (int n = 0; n < 200; ++n)
  {
    const Vec3 p(inner(random), inner(random), inner(random));
    Mat3 g;
    Mat3 gs;
    EXPECT_TRUE(exact.Tensor(p, g) && sampled.Tensor(p, gs));
    e.G = std::max(e.G, MaxAbs(gs - g));
    Mat3Stack gamma;
    Mat3Stack gammaSampled;
    EXPECT_TRUE(exact.Christoffel(p, gamma) && sampled.Christoffel(p, gammaSampled));
    for (int m = 0; m < 3; ++m)
    {
      e.Gamma = std::max(e.Gamma, MaxAbs(gammaSampled[m] - gamma[m]));
    }
    riemann::CurvatureSample c;
    riemann::CurvatureSample cs;
    EXPECT_TRUE(
      riemann::ComputeCurvature(exact, p, c) && riemann::ComputeCurvature(sampled, p, cs));
    e.Scalar = std::max(e.Scalar, std::abs(cs.Scalar - c.Scalar));
  }
  riemann::GeodesicOptions options;
  options.Step = 0.005;
  options.MaximumLength = 0.6;
  options.RecordSpeedDrift = false;
  std::uniform_real_distribution<double> seed(-0.4, 0.4);
  std::normal_distribution<double> direction;
  for (int n = 0; n < 12; ++n)
  {
    const Vec3 p(seed(random), seed(random), seed(random));
    const Vec3 d(direction(random), direction(random), direction(random));
    Vec3 v;
    Vec3 vs;
    EXPECT_TRUE(riemann::UnitSpeedVelocity(exact, p, d, v));
    EXPECT_TRUE(riemann::UnitSpeedVelocity(sampled, p, d, vs));
    riemann::GeodesicPath path;
    riemann::GeodesicPath pathSampled;
    riemann::TraceGeodesic(exact, p, v, options, path);
    riemann::TraceGeodesic(sampled, p, vs, options, pathSampled);
    EXPECT_EQ(path.Reason, riemann::OutOfLength);
    EXPECT_EQ(pathSampled.Reason, riemann::OutOfLength);
    e.Endpoint = std::max(e.Endpoint, (pathSampled.Points.back() - path.Points.back()).norm());
  }
  return e;
}
} // namespace

TEST(SampledConvergence, AnalyticMetricsAreApproachedAtSecondOrder)
{
  const struct
  {
    const char* Name;
    const char* Json;
  } metrics[] = {
    { "twist", R"({"type": "diffeo", "preset": "twist", "rate": 1})" },
    { "Gaussian lens",
      R"({"type": "conformal", "constant": 1.0, "gaussians": [{"amplitude": 0.5, "center": [0, 0, 0], "sigma": 1.0}]})" },
    { "Nil",
      R"({"type": "tensor", "g": [["1", "0", "0"], ["0", "1 + x^2", "-x"], ["0", "-x", "1"]]})" },
  };
  const int sizes[] = { 16, 32, 64 };
  std::printf("%-14s %5s %8s %10s %10s %10s %10s\n", "metric", "n", "h", "g", "Gamma", "scalar R",
    "endpoint");
  for (const auto& m : metrics)
  {
    SCOPED_TRACE(m.Name);
    const auto exact = riemann::ParseMetricDefinition(m.Json);
    Errors errors[3];
    for (int s = 0; s < 3; ++s)
    {
      errors[s] = Compare(*exact, *Sampled(*exact, sizes[s]));
      std::printf("%-14s %5d %8.4f %10.3e %10.3e %10.3e %10.3e\n", m.Name, sizes[s],
        2.0 * Half / (sizes[s] - 1), errors[s].G, errors[s].Gamma, errors[s].Scalar,
        errors[s].Endpoint);
    }
    // Orders over each halving of h (h = 3.2 / (n - 1): the ratio is not
    // exactly 2, so the order is log(e1 / e2) / log(h1 / h2)).
    for (int s = 0; s < 2; ++s)
    {
      const double ratio = std::log((sizes[s + 1] - 1.0) / (sizes[s] - 1.0));
      const double orders[4] = { std::log(errors[s].G / errors[s + 1].G) / ratio,
        std::log(errors[s].Gamma / errors[s + 1].Gamma) / ratio,
        std::log(errors[s].Scalar / errors[s + 1].Scalar) / ratio,
        std::log(errors[s].Endpoint / errors[s + 1].Endpoint) / ratio };
      std::printf("%-14s %5s %8s %10.2f %10.2f %10.2f %10.2f\n", m.Name,
        (std::to_string(sizes[s]) + "-" + std::to_string(sizes[s + 1])).c_str(), "order", orders[0],
        orders[1], orders[2], orders[3]);
      if (s == 1)
      {
        const double finest[4] = { errors[2].G, errors[2].Gamma, errors[2].Scalar,
          errors[2].Endpoint };
        for (int q = 0; q < 4; ++q)
        {
          if (std::string(m.Name) == "twist" && (q == 1 || q == 2))
          {
            EXPECT_LT(std::max({ errors[0].Gamma, errors[0].Scalar, finest[q] }), 1e-10);
            continue;
          }
          EXPECT_GT(orders[q], 1.7) << "quantity " << q;
        }
      }
    }
  }
}
