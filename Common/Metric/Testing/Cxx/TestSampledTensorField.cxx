// SampledTensorField: the cubic B-spline of sampled metric components.
// Exact answers:
// - a field affine in x is reproduced exactly (value, first derivatives,
//   zero second derivatives) wherever the spline's 4^3 samples are inside
//   the grid, on a rotated grid with unequal spacings;
// - the derivatives are those of the interpolant (central differences of g
//   and of dg agree to the differences' own error);
// - g between samples is a convex combination of them: its smallest
//   eigenvalue is at least the samples' smallest;
// - a smooth field is approximated to second order: halving the spacing
//   divides the error of g and of dg by 4 (observed order 2 +- 0.25);
// - outside the grid's box the field is Euclidean; malformed grids are
//   refused with a message that says what is wrong;
// - with "outside": "stop" the field beyond a face is the face's value,
//   constant outward, and every tracer (TraceGeodesic, the packet engine,
//   the Jacobi traces, scalar and packet) stops at its first point beyond the
//   faces with OutOfData, each point before it inside;
// - through TensorMetric, the Christoffel symbols of a sampled affine field
//   are those of the field itself.
// PrepareTensorSamples: inverse and scale exact; the adjugate is det(D) D^-1
// and the sharpened metric keeps det g = det D^-1 while its FA grows with p
// (p = 1 is the inverse); FractionalAnisotropyOfMetric gives D's FA for each; bad samples counted and the
// first named (index, position, eigenvalue); repair clamps to the floor.
#include "GeodesicTrace.h"
#include "GlslSource.h"
#include "MetricGlsl.h"
#include "JacobiField.h"
#include "PacketTrace.h"
#include "SampledTensorField.h"
#include "SampledTensorSamples.h"
#include "TensorMetric.h"
#include "TractStops.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>
#include <vector>

namespace
{
using riemann::Mat3;
using riemann::Mat3Stack;
using riemann::SampledTensorField;
using riemann::SampledTensorGrid;
using riemann::Vec3;

/// A grid of n^3 points over `box` around `centre`, rotated by `direction`,
/// sampling `field`.
SampledTensorGrid Sample(const std::function<Mat3(const Vec3&)>& field, int n, const Vec3& centre,
  const Vec3& size, const Mat3& direction = Mat3::Identity())
{
  SampledTensorGrid grid;
  grid.Dimensions = { n, n, n };
  for (int a = 0; a < 3; ++a)
  {
    grid.Spacing[a] = size[a] / (n - 1);
  }
  grid.Direction = direction;
  grid.Origin = centre - direction * (0.5 * size);
  grid.Components.reserve(6 * static_cast<size_t>(n) * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const Vec3 x = grid.Origin +
          direction * Vec3(i * grid.Spacing[0], j * grid.Spacing[1], k * grid.Spacing[2]);
        const Mat3 g = field(x);
        for (double c : { g(0, 0), g(1, 1), g(2, 2), g(0, 1), g(1, 2), g(0, 2) })
        {
          grid.Components.push_back(c);
        }
      }
    }
  }
  return grid;
}

Mat3 Rotation()
{
  return (Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized())).toRotationMatrix();
}

/// g = A + x_0 B0 + x_1 B1 + x_2 B2, positive definite on |x| < 2.
struct AffineField
{
  Mat3 A, B[3];
  AffineField()
  {
    A << 3.0, 0.4, -0.2, 0.4, 2.5, 0.3, -0.2, 0.3, 2.0;
    B[0] << 0.2, 0.1, 0.0, 0.1, -0.1, 0.05, 0.0, 0.05, 0.15;
    B[1] << -0.1, 0.0, 0.08, 0.0, 0.2, -0.1, 0.08, -0.1, 0.1;
    B[2] << 0.05, -0.07, 0.0, -0.07, 0.1, 0.0, 0.0, 0.0, -0.2;
  }
  Mat3 operator()(const Vec3& x) const { return A + x[0] * B[0] + x[1] * B[1] + x[2] * B[2]; }
};

/// A smooth metric: a conformal bump plus a sheared part, with derivatives.
Mat3 SmoothField(const Vec3& x, Mat3Stack* dg = nullptr)
{
  const double bump = 0.6 * std::exp(-x.squaredNorm() / 0.5);
  Mat3 g = (1.0 + bump) * Mat3::Identity();
  g(0, 1) = g(1, 0) = 0.3 * std::sin(x[1] + 0.5 * x[2]);
  g(2, 2) += 0.2 * std::cos(x[0]);
  if (dg)
  {
    for (int k = 0; k < 3; ++k)
    {
      (*dg)[k] = (-bump * 2.0 * x[k] / 0.5) * Mat3::Identity();
    }
    const double c = 0.3 * std::cos(x[1] + 0.5 * x[2]);
    (*dg)[1](0, 1) = (*dg)[1](1, 0) = c;
    (*dg)[2](0, 1) = (*dg)[2](1, 0) = 0.5 * c;
    (*dg)[0](2, 2) += -0.2 * std::sin(x[0]);
  }
  return g;
}

double MinimumEigenvalue(const Mat3& g)
{
  return Eigen::SelfAdjointEigenSolver<Mat3>(g).eigenvalues()[0];
}
} // namespace

TEST(SampledTensorField, ReproducesAnAffineFieldExactly)
{
  const AffineField field;
  const Vec3 centre(0.1, -0.2, 0.3);
  const Vec3 size(2.0, 2.6, 1.8); // unequal spacings
  const SampledTensorField sampled(Sample(field, 9, centre, size, Rotation()));
  std::mt19937 random(1);
  std::uniform_real_distribution<double> inner(-0.5 + 1.0 / 8.0, 0.5 - 1.0 / 8.0);
  for (int trial = 0; trial < 500; ++trial)
  {
    // Points whose 4^3 samples all lie inside the grid (one cell from its faces).
    const Vec3 local(inner(random) * size[0], inner(random) * size[1], inner(random) * size[2]);
    const Vec3 x = centre + Rotation() * local;
    Mat3 g;
    Mat3Stack dg;
    std::array<Mat3Stack, 3> d2g;
    ASSERT_TRUE(sampled.EvaluateSecond(x, g, dg, d2g));
    EXPECT_LT((g - field(x)).cwiseAbs().maxCoeff(), 1e-12);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_LT((dg[k] - field.B[k]).cwiseAbs().maxCoeff(), 1e-11) << "d/dx" << k;
      for (int l = 0; l < 3; ++l)
      {
        EXPECT_LT(d2g[k][l].cwiseAbs().maxCoeff(), 1e-10);
      }
    }
  }
}

TEST(SampledTensorField, DerivativesAreTheInterpolantsOwn)
{
  // Random positive definite samples: a rough field, where a wrong
  // derivative of the spline would show at once.
  SampledTensorGrid grid;
  grid.Dimensions = { 7, 6, 8 };
  grid.Spacing = Vec3(0.3, 0.4, 0.25);
  grid.Origin = Vec3(-1.0, -1.0, -1.0);
  grid.Direction = Rotation();
  std::mt19937 random(2);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  for (long long p = 0; p < grid.NumberOfPoints(); ++p)
  {
    Mat3 m;
    m << entry(random), entry(random), entry(random), entry(random), entry(random), entry(random),
      entry(random), entry(random), entry(random);
    const Mat3 g = m * m.transpose() + 0.5 * Mat3::Identity();
    for (double c : { g(0, 0), g(1, 1), g(2, 2), g(0, 1), g(1, 2), g(0, 2) })
    {
      grid.Components.push_back(c);
    }
  }
  const SampledTensorField sampled(grid);
  const double h = 1e-5;
  std::uniform_real_distribution<double> unit(0.05, 0.95);
  for (int trial = 0; trial < 200; ++trial)
  {
    const Vec3 index(unit(random) * 6, unit(random) * 5, unit(random) * 7);
    const Vec3 x = grid.Origin + grid.Direction * index.cwiseProduct(grid.Spacing);
    Mat3 g;
    Mat3Stack dg;
    std::array<Mat3Stack, 3> d2g;
    ASSERT_TRUE(sampled.EvaluateSecond(x, g, dg, d2g));
    Mat3 gOnly;
    Mat3Stack dgFirst;
    sampled.Evaluate(x, true, gOnly, dgFirst);
    EXPECT_LT((gOnly - g).cwiseAbs().maxCoeff(), 1e-14);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_LT((dgFirst[k] - dg[k]).cwiseAbs().maxCoeff(), 1e-13);
      const Vec3 step = h * Vec3::Unit(k);
      Mat3 gp, gm;
      Mat3Stack dgp, dgm;
      sampled.Evaluate(x + step, true, gp, dgp);
      sampled.Evaluate(x - step, true, gm, dgm);
      // Central differences: error h^2 |g'''| / 6 (the spline's third
      // derivative is bounded by the samples over h^3, here ~ 1e3).
      EXPECT_LT(((gp - gm) / (2 * h) - dg[k]).cwiseAbs().maxCoeff(), 1e-6) << "dg" << k;
      for (int l = 0; l < 3; ++l)
      {
        // d2g is piecewise linear: central differences of dg are exact to
        // rounding, except across a knot (then within h |g'''|).
        EXPECT_LT(((dgp[l] - dgm[l]) / (2 * h) - d2g[k][l]).cwiseAbs().maxCoeff(), 2e-3)
          << "d2g " << k << l;
      }
    }
  }
}

TEST(SampledTensorField, StaysPositiveDefiniteBetweenSamples)
{
  // Strongly anisotropic samples (eigenvalues 0.01 to 100, random axes):
  // g between them is a convex combination, never less definite than they.
  SampledTensorGrid grid;
  grid.Dimensions = { 5, 5, 5 };
  grid.Spacing = Vec3(0.5, 0.5, 0.5);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> angle(-3.14, 3.14);
  double smallest = 1e300;
  for (long long p = 0; p < grid.NumberOfPoints(); ++p)
  {
    const Mat3 r = Eigen::AngleAxisd(
      angle(random), Vec3(angle(random), angle(random), angle(random)).normalized())
                     .toRotationMatrix();
    const Mat3 g = r * Vec3(0.01, 1.0, 100.0).asDiagonal() * r.transpose();
    smallest = std::min(smallest, MinimumEigenvalue(g));
    for (double c : { g(0, 0), g(1, 1), g(2, 2), g(0, 1), g(1, 2), g(0, 2) })
    {
      grid.Components.push_back(c);
    }
  }
  const SampledTensorField sampled(grid);
  std::uniform_real_distribution<double> inside(0.0, 2.0);
  for (int trial = 0; trial < 10000; ++trial)
  {
    const Vec3 x(inside(random), inside(random), inside(random));
    Mat3 g;
    Mat3Stack dg;
    sampled.Evaluate(x, false, g, dg);
    ASSERT_GE(MinimumEigenvalue(g), smallest * (1 - 1e-9)) << x.transpose();
  }
}

TEST(SampledTensorField, ConvergesAtSecondOrder)
{
  // Errors of g and dg at 300 fixed points of [-1, 1]^3, sampling [-2, 2]^3
  // with spacings 1/4, 1/8, 1/16: each halving divides them by about 4.
  std::mt19937 random(4);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < 300; ++i)
  {
    points.emplace_back(coordinate(random), coordinate(random), coordinate(random));
  }
  std::vector<double> valueErrors, derivativeErrors;
  for (int n : { 17, 33, 65 })
  {
    const SampledTensorField sampled(
      Sample([](const Vec3& x) { return SmoothField(x); }, n, Vec3::Zero(), Vec3(4, 4, 4)));
    double value = 0.0, derivative = 0.0;
    for (const Vec3& x : points)
    {
      Mat3 g;
      Mat3Stack dg, exact;
      sampled.Evaluate(x, true, g, dg);
      value = std::max(value, (g - SmoothField(x, &exact)).cwiseAbs().maxCoeff());
      for (int k = 0; k < 3; ++k)
      {
        derivative = std::max(derivative, (dg[k] - exact[k]).cwiseAbs().maxCoeff());
      }
    }
    valueErrors.push_back(value);
    derivativeErrors.push_back(derivative);
    std::cout << "spacing " << 4.0 / (n - 1) << ": max error of g " << value << ", of dg "
              << derivative << "\n";
  }
  for (size_t i = 1; i < valueErrors.size(); ++i)
  {
    const double valueOrder = std::log2(valueErrors[i - 1] / valueErrors[i]);
    const double derivativeOrder = std::log2(derivativeErrors[i - 1] / derivativeErrors[i]);
    std::cout << "observed order: g " << valueOrder << ", dg " << derivativeOrder << "\n";
    EXPECT_NEAR(valueOrder, 2.0, 0.25);
    EXPECT_NEAR(derivativeOrder, 2.0, 0.25);
  }
}

TEST(SampledTensorField, OutsideTheGridIsEuclidean)
{
  // Samples 0.5 apart from -1 to 1: the box reaches the outer voxels'
  // faces, half a spacing beyond, at +-1.25.
  const SampledTensorField sampled(Sample(AffineField(), 5, Vec3::Zero(), Vec3(2, 2, 2)));
  EXPECT_TRUE(sampled.Inside(Vec3(1.24, -1.24, 0.0)));
  EXPECT_TRUE(sampled.Inside(Vec3(1.25, 1.25, -1.25)));
  EXPECT_FALSE(sampled.Inside(Vec3(1.26, 0.0, 0.0)));
  EXPECT_FALSE(sampled.Inside(Vec3(0.0, -1.26, 0.0)));
  Mat3 g;
  Mat3Stack dg;
  std::array<Mat3Stack, 3> d2g;
  ASSERT_TRUE(sampled.EvaluateSecond(Vec3(0.0, 0.0, -1.5), g, dg, d2g));
  EXPECT_EQ(g, Mat3::Identity());
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_EQ(dg[k], Mat3::Zero());
    EXPECT_EQ(d2g[k][1], Mat3::Zero());
  }
}

TEST(SampledTensorField, StopOutsideContinuesTheFacesAndEndsEveryTracer)
{
  // The smooth field on [-1, 1]^3, rays stopping outside it.
  const auto field = [](const Vec3& x) { return SmoothField(x); };
  riemann::SampledTensorOptions options;
  options.StopOutside = true;
  const auto metric =
    riemann::MakeSampledTensorMetric(Sample(field, 9, Vec3::Zero(), Vec3(2, 2, 2)), options);
  const SampledTensorField sampled(Sample(field, 9, Vec3::Zero(), Vec3(2, 2, 2)), true);
  // Samples 0.25 apart: the outer voxels' faces at +-1.125. Beyond the face
  // x = 1.125: the face's value, constant along x.
  const double face = 1.125;
  Mat3 onFace;
  Mat3 beyond;
  Mat3Stack faceDg;
  Mat3Stack beyondDg;
  sampled.Evaluate(Vec3(face, 0.3, -0.2), true, onFace, faceDg);
  sampled.Evaluate(Vec3(1.7, 0.3, -0.2), true, beyond, beyondDg);
  EXPECT_EQ(onFace, beyond);
  EXPECT_EQ(beyondDg[0], Mat3::Zero());
  EXPECT_EQ(faceDg[1], beyondDg[1]);
  EXPECT_TRUE(sampled.InsideData(Vec3(face, 0.3, -0.2)));
  EXPECT_FALSE(sampled.InsideData(Vec3(face + 1e-4, 0.3, -0.2)));
  EXPECT_TRUE(metric->InsideData(Vec3(0.2, 0.3, -0.2)));
  EXPECT_FALSE(metric->InsideData(Vec3(0.2, 0.3, -1.2)));

  riemann::GeodesicOptions options2;
  options2.Step = 0.01;
  options2.MaximumLength = 20.0;
  const Vec3 start(0.1, -0.2, 0.3);
  const Vec3 directions[3] = { Vec3(1, 0.2, 0), Vec3(-0.3, 1, 0.5), Vec3(0.1, -0.4, -1) };
  // TraceGeodesic and the packet engine.
  std::vector<riemann::GeodesicSeed> seeds;
  for (const Vec3& d : directions)
  {
    riemann::GeodesicSeed seed;
    seed.Point = start;
    ASSERT_TRUE(riemann::UnitSpeedVelocity(*metric, start, d, seed.Velocity));
    seeds.push_back(seed);
  }
  std::vector<riemann::GeodesicPath> packet(seeds.size());
  riemann::TraceGeodesics(*metric, seeds.data(), seeds.size(), options2, packet.data());
  for (std::size_t i = 0; i < seeds.size(); ++i)
  {
    SCOPED_TRACE(i);
    riemann::GeodesicPath path;
    riemann::TraceGeodesic(*metric, start, seeds[i].Velocity, options2, path);
    for (const riemann::GeodesicPath* p : { &path, &packet[i] })
    {
      EXPECT_EQ(p->Reason, riemann::OutOfData);
      ASSERT_GE(p->Points.size(), 3u);
      for (std::size_t k = 0; k < p->Points.size(); ++k)
      {
        ASSERT_TRUE(sampled.Inside(p->Points[k])) << k;
      }
      // The geodesic ends on the face its last step crossed (the chord's
      // crossing, up to the face's tolerance of 1e-6 voxel), closer than a
      // step to the point before.
      const Vec3 last = p->Points.back();
      EXPECT_GE(last.cwiseAbs().maxCoeff(), face - 1e-12);
      EXPECT_LE(last.cwiseAbs().maxCoeff(), face + SampledTensorField::FaceTolerance * 0.25);
      const double before = p->ArcLength[p->ArcLength.size() - 2];
      EXPECT_GT(p->ArcLength.back(), before);
      EXPECT_LE(p->ArcLength.back(), before + options2.Step * (1 + 1e-12));
      EXPECT_LT(p->ArcLength.back(), options2.MaximumLength);
    }
    EXPECT_EQ(path.Points.size(), packet[i].Points.size());
    EXPECT_LT((path.Points.back() - packet[i].Points.back()).norm(), 1e-12);
  }
  // The Jacobi traces, scalar and packet.
  std::vector<riemann::JacobiSeed> jacobiSeeds;
  for (const Vec3& d : directions)
  {
    riemann::JacobiSeed seed;
    seed.Point = start;
    seed.Direction = d;
    jacobiSeeds.push_back(seed);
  }
  std::vector<riemann::JacobiTrace> traces(jacobiSeeds.size());
  riemann::TraceJacobiFields(
    *metric, jacobiSeeds.data(), jacobiSeeds.size(), options2, traces.data());
  for (std::size_t i = 0; i < jacobiSeeds.size(); ++i)
  {
    SCOPED_TRACE(i);
    riemann::JacobiTrace scalar;
    riemann::TraceJacobiFields(*metric, start, directions[i], options2, scalar);
    // The Jacobi traces keep the first sample beyond the face.
    for (const riemann::JacobiTrace* t : { &scalar, &traces[i] })
    {
      EXPECT_EQ(t->Reason, riemann::OutOfData);
      ASSERT_GE(t->Samples.size(), 2u);
      EXPECT_FALSE(sampled.Inside(t->Samples.back().Point));
      EXPECT_TRUE(sampled.Inside(t->Samples[t->Samples.size() - 2].Point));
    }
  }
  EXPECT_STREQ(riemann::TerminationReasonName(riemann::OutOfData), "left the sampled data");
}

TEST(SampledTensorField, MalformedGridsAreRefusedWithWhatIsWrong)
{
  SampledTensorGrid good = Sample(AffineField(), 3, Vec3::Zero(), Vec3(1, 1, 1));
  EXPECT_EQ(good.Check(), "");
  auto refused = [](SampledTensorGrid grid, const std::string& expected)
  {
    try
    {
      SampledTensorField field(grid);
      ADD_FAILURE() << "accepted; expected: " << expected;
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  SampledTensorGrid grid = good;
  grid.Dimensions[1] = 1;
  refused(grid, "at least 2 points on each axis, axis 1 has 1");
  grid = good;
  grid.Spacing[2] = std::nan("");
  refused(grid, "spacing must be finite and positive, axis 2");
  grid = good;
  grid.Spacing[0] = -0.5;
  refused(grid, "spacing must be finite and positive, axis 0");
  grid = good;
  grid.Direction(0, 1) = 0.5;
  refused(grid, "direction matrix is not orthonormal");
  grid = good;
  grid.Components.pop_back();
  refused(grid, "expected 6 components per point (162), got 161");
}

TEST(SampledTensorField, ChristoffelSymbolsOfTheSampledFieldAreTheFields)
{
  const AffineField field;
  const riemann::TensorMetric metric(std::make_shared<SampledTensorField>(
    Sample(field, 7, Vec3::Zero(), Vec3(3, 3, 3), Rotation())));
  const Vec3 x(0.2, -0.3, 0.1);
  Mat3Stack gamma;
  ASSERT_TRUE(metric.Christoffel(x, gamma));
  // Gamma^m_ij = 1/2 g^ml (d_i g_lj + d_j g_li - d_l g_ij), with the exact dg = B.
  const Mat3 inverse = field(x).inverse();
  for (int m = 0; m < 3; ++m)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        double exact = 0.0;
        for (int l = 0; l < 3; ++l)
        {
          exact += 0.5 * inverse(m, l) * (field.B[i](l, j) + field.B[j](l, i) - field.B[l](i, j));
        }
        EXPECT_NEAR(gamma[m](i, j), exact, 1e-12) << m << i << j;
      }
    }
  }
}

//------------------------------------------------------------------------------
// PrepareTensorSamples: the data's tensors to metric samples.

namespace
{
/// A 3 x 3 x 3 grid of the same sample `g`, spacing 0.5 from (1, 2, 3).
SampledTensorGrid Uniform(const Mat3& g)
{
  SampledTensorGrid grid;
  grid.Dimensions = { 3, 3, 3 };
  grid.Spacing = Vec3(0.5, 0.5, 0.5);
  grid.Origin = Vec3(1, 2, 3);
  for (int p = 0; p < 27; ++p)
  {
    for (double c : { g(0, 0), g(1, 1), g(2, 2), g(0, 1), g(1, 2), g(0, 2) })
    {
      grid.Components.push_back(c);
    }
  }
  return grid;
}

Mat3 SampleOf(const SampledTensorGrid& grid, int point)
{
  const double* c = grid.Components.data() + 6 * point;
  Mat3 g;
  g << c[0], c[3], c[5], c[3], c[1], c[4], c[5], c[4], c[2];
  return g;
}

void SetSample(SampledTensorGrid& grid, int point, const Mat3& g)
{
  double* c = grid.Components.data() + 6 * point;
  const double values[6] = { g(0, 0), g(1, 1), g(2, 2), g(0, 1), g(1, 2), g(0, 2) };
  std::copy(values, values + 6, c);
}

Mat3 Diffusion()
{
  Mat3 d; // a fibre along (1, 1, 0): fast diffusion there
  d << 1.6, 1.4, 0.0, 1.4, 1.6, 0.0, 0.0, 0.0, 0.3;
  return d;
}
} // namespace

TEST(SampledTensorSamples, InverseAndScaleMakeTheDiffusionTensorsMetric)
{
  SampledTensorGrid grid = Uniform(Diffusion());
  riemann::SampledTensorOptions options;
  options.Kind = riemann::TensorMetricKind::Inverse;
  options.Scale = 2.0;
  riemann::SampledTensorReport report;
  ASSERT_EQ(riemann::PrepareTensorSamples(grid, options, &report), "");
  EXPECT_EQ(report.NotPositiveDefinite, 0);
  for (int p = 0; p < 27; ++p)
  {
    EXPECT_LT(
      (SampleOf(grid, p) * Diffusion() - 2.0 * Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12);
  }
  // Along the fibre the metric is small: length^2 of (1, 1, 0) is 2 * 2 / 3.
  const Vec3 fibre(1, 1, 0);
  EXPECT_NEAR(fibre.dot(SampleOf(grid, 0) * fibre), 4.0 / 3.0, 1e-12);
}

TEST(SampledTensorSamples, MeanDiffusivityScaleMakesIsotropicTissueEuclidean)
{
  // Diffusion tensors in mm^2/s (about 1e-3): 26 isotropic samples of mean
  // diffusivity 0.9e-3 and one fibre of 1.2e-3. The median mean diffusivity
  // is 0.9e-3, so the isotropic samples become I: arc length is length in mm.
  const double md = 0.9e-3;
  SampledTensorGrid grid = Uniform(md * Mat3::Identity());
  SetSample(grid, 13, 1e-3 * Diffusion() * (1.2 / (Diffusion().trace() / 3.0)));
  riemann::SampledTensorOptions options;
  options.Kind = riemann::TensorMetricKind::Inverse;
  options.ScaleToMeanDiffusivity = true;
  riemann::SampledTensorReport report;
  ASSERT_EQ(riemann::PrepareTensorSamples(grid, options, &report), "");
  EXPECT_NEAR(report.MedianMeanDiffusivity, md, 1e-18);
  EXPECT_NEAR(report.AppliedScale, md, 1e-18);
  EXPECT_LT((SampleOf(grid, 0) - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12);
  // Without the inverse, the tensors are divided by it.
  SampledTensorGrid direct = Uniform(md * Mat3::Identity());
  options.Kind = riemann::TensorMetricKind::Tensor;
  ASSERT_EQ(riemann::PrepareTensorSamples(direct, options, &report), "");
  EXPECT_NEAR(report.AppliedScale, 1.0 / md, 1e-9);
  EXPECT_LT((SampleOf(direct, 26) - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(SampledTensorSamples, AdjugateAndSharpenedMetricsOfADiffusionTensor)
{
  const Mat3 d = Diffusion();
  const Mat3 inverse = d.inverse();
  riemann::SampledTensorOptions options;
  // Adjugate: det(D) D^-1, exactly.
  SampledTensorGrid adjugate = Uniform(d);
  options.Kind = riemann::TensorMetricKind::Adjugate;
  ASSERT_EQ(riemann::PrepareTensorSamples(adjugate, options), "");
  EXPECT_LT((SampleOf(adjugate, 4) - d.determinant() * inverse).cwiseAbs().maxCoeff(), 1e-12);
  // Sharpened with p = 1 is the inverse; with p = 2, det g = det D^-1, same
  // eigenvectors, and FA of g^(-1/2) is D's FA (what the stops read).
  options.Kind = riemann::TensorMetricKind::Sharpened;
  options.Sharpening = 1.0;
  SampledTensorGrid one = Uniform(d);
  ASSERT_EQ(riemann::PrepareTensorSamples(one, options), "");
  EXPECT_LT((SampleOf(one, 0) - inverse).cwiseAbs().maxCoeff(), 1e-12);
  options.Sharpening = 2.0;
  SampledTensorGrid two = Uniform(d);
  ASSERT_EQ(riemann::PrepareTensorSamples(two, options), "");
  const Mat3 g = SampleOf(two, 0);
  EXPECT_NEAR(g.determinant(), inverse.determinant(), 1e-12 * inverse.determinant());
  EXPECT_LT((g * d - d * g).cwiseAbs().maxCoeff(), 1e-12); // same eigenvectors
  const auto fa = [](const Mat3& m)
  { return riemann::FractionalAnisotropy(Eigen::SelfAdjointEigenSolver<Mat3>(m).eigenvalues()); };
  EXPECT_GT(fa(g), fa(inverse) + 0.05); // sharper
  EXPECT_GT(fa(d), 0.5);
  for (auto kind : { riemann::TensorMetricKind::Tensor, riemann::TensorMetricKind::Inverse,
         riemann::TensorMetricKind::Adjugate, riemann::TensorMetricKind::Sharpened })
  {
    options.Kind = kind;
    for (bool voxels : { false, true }) // the spline's symbols, and the fast path's
    {
      options.ChristoffelAtVoxels = voxels;
      riemann::SampledTensorGrid grid = Uniform(d);
      const auto metric = riemann::MakeSampledTensorMetric(grid, options);
      double anisotropy = 0.0;
      ASSERT_TRUE(riemann::FractionalAnisotropyOfMetric(*metric, Vec3(1.5, 2.5, 3.5), anisotropy));
      // float storage on the fast path
      EXPECT_NEAR(anisotropy, fa(d), voxels ? 1e-6 : 1e-9) << riemann::TensorMetricName(kind);
    }
    options.ChristoffelAtVoxels = false;
  }
  // Scaled to the mean diffusivity m, m I becomes I for every kind.
  const double md = 0.8e-3;
  options.ScaleToMeanDiffusivity = true;
  for (auto kind : { riemann::TensorMetricKind::Adjugate, riemann::TensorMetricKind::Sharpened })
  {
    options.Kind = kind;
    SampledTensorGrid isotropic = Uniform(md * Mat3::Identity());
    ASSERT_EQ(riemann::PrepareTensorSamples(isotropic, options), "");
    EXPECT_LT((SampleOf(isotropic, 0) - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-9)
      << riemann::TensorMetricName(kind);
  }
  // The sharpening's range is checked.
  options.Sharpening = 0.5;
  SampledTensorGrid refused = Uniform(d);
  EXPECT_NE(riemann::PrepareTensorSamples(refused, options).find("sharpening"), std::string::npos);
}

TEST(SampledTensorSamples, StepsThatWouldJumpAreRefusedAndNoPointLeavesTheVolume)
{
  // Tensors as a noisy fit leaves them after "repair": "clamp": each voxel's
  // eigenvalues log-uniform over [1e-3, 1] (the clamp's floor is 1e-3 of the
  // largest), its axes at random. Their sharpened and adjugate metrics are
  // nearly degenerate in places, next to voxels that are not: the
  // Christoffel symbols are huge there, and an RK4 step could land far from
  // where it started (issue 41: on DIPY's small_64D, a point 28 m from a
  // 20 mm scan).
  std::mt19937 random(41);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> exponent(-3.0, 0.0);
  SampledTensorGrid grid = Sample([](const Vec3&) { return Mat3(Mat3::Identity()); }, 9,
    Vec3::Zero(), Vec3(2, 2, 2));
  for (int p = 0; p < 729; ++p)
  {
    const Mat3 axes =
      Eigen::Quaterniond(normal(random), normal(random), normal(random), normal(random))
        .normalized()
        .toRotationMatrix();
    const Vec3 eigenvalues(std::pow(10.0, exponent(random)), std::pow(10.0, exponent(random)),
      std::pow(10.0, exponent(random)));
    SetSample(grid, p, axes * eigenvalues.asDiagonal() * axes.transpose());
  }
  const SampledTensorField box(grid);
  std::vector<riemann::GeodesicSeed> seeds;
  for (int i = 0; i < 256; ++i)
  {
    riemann::GeodesicSeed seed;
    seed.Point = Vec3(0.6 * normal(random), 0.6 * normal(random), 0.3 * normal(random))
                   .cwiseMax(Vec3::Constant(-1.0))
                   .cwiseMin(Vec3::Constant(1.0));
    seed.Velocity = Vec3(normal(random), normal(random), normal(random));
    seed.Backward = i % 2 == 1;
    seeds.push_back(seed);
  }
  riemann::GeodesicOptions trace;
  trace.Step = 0.05;
  trace.MaximumLength = 6.0;
  for (auto kind : { riemann::TensorMetricKind::Sharpened, riemann::TensorMetricKind::Adjugate,
         riemann::TensorMetricKind::Inverse })
  {
    for (bool voxels : { false, true })
    {
      SCOPED_TRACE(std::string(riemann::TensorMetricName(kind)) + (voxels ? " voxels" : " spline"));
      riemann::SampledTensorOptions options;
      options.Kind = kind;
      options.StopOutside = true;
      options.ChristoffelAtVoxels = voxels;
      const auto metric = riemann::MakeSampledTensorMetric(grid, options);
      std::vector<riemann::GeodesicSeed> unit = seeds;
      for (riemann::GeodesicSeed& seed : unit)
      {
        ASSERT_TRUE(riemann::UnitSpeedVelocity(*metric, seed.Point, seed.Velocity, seed.Velocity));
      }
      std::vector<riemann::GeodesicPath> packet(unit.size());
      riemann::TraceGeodesics(*metric, unit.data(), unit.size(), trace, packet.data());
      int refused = 0;
      double worst = 0.0; // the largest chord over nominal length of a step
      for (std::size_t i = 0; i < unit.size(); ++i)
      {
        riemann::GeodesicPath scalar;
        riemann::TraceGeodesic(*metric, unit[i].Point, unit[i].Velocity, trace, scalar, unit[i].Backward);
        ASSERT_EQ(scalar.Reason, packet[i].Reason) << i;
        ASSERT_EQ(scalar.Points.size(), packet[i].Points.size()) << i;
        refused += scalar.Reason == riemann::OutranStep;
        for (std::size_t k = 0; k < scalar.Points.size(); ++k)
        {
          // Every point in the volume (its faces up to their tolerance)...
          ASSERT_TRUE(box.Inside(scalar.Points[k])) << i << " " << k;
          if (k == 0)
          {
            continue;
          }
          // ... and every step's chord within twice its nominal length.
          const double chord = (scalar.Points[k] - scalar.Points[k - 1]).norm();
          const double nominal = scalar.Velocities[k - 1].norm() *
            std::abs(scalar.ArcLength[k] - scalar.ArcLength[k - 1]);
          worst = std::max(worst, chord / nominal);
        }
      }
      EXPECT_LE(worst, riemann::MaximumChordToStepRatio * (1 + 1e-12));
      // The adjugate's g spans six orders of magnitude between neighbouring
      // voxels here: unchecked, one of its steps went 2.8e8 times its length
      // (spline; 1.8e8 on the voxels' symbols), so some must be refused.
      // (Sharpened and D^-1 stayed under 1.02 times their steps.)
      if (kind == riemann::TensorMetricKind::Adjugate)
      {
        EXPECT_GT(refused, 0);
      }
      std::cout << riemann::TensorMetricName(kind) << (voxels ? " voxels" : " spline") << ": "
                << refused << " of " << unit.size()
                << " geodesics refused a step; the longest chord kept: " << worst
                << " times its step\n";
    }
  }
  EXPECT_STREQ(riemann::TerminationReasonName(riemann::OutranStep),
    "outran its step (the metric changes faster than the step resolves)");
}

TEST(SampledTensorSamples, PositiveSamplesWithoutOptionsAreKeptBitwise)
{
  SampledTensorGrid grid = Uniform(Diffusion());
  const std::vector<double> before = grid.Components;
  ASSERT_EQ(riemann::PrepareTensorSamples(grid, riemann::SampledTensorOptions()), "");
  EXPECT_EQ(grid.Components, before);
}

TEST(SampledTensorSamples, BadSamplesAreCountedAndTheFirstIsNamed)
{
  SampledTensorGrid grid = Uniform(Diffusion());
  // Point (2, 1, 0) (index 5) is at (2, 2.5, 3); (0, 0, 2) (index 18) at (1, 2, 4).
  Mat3 indefinite = Diffusion();
  indefinite(2, 2) = -0.1;
  SetSample(grid, 5, indefinite);
  SetSample(grid, 18, Mat3::Zero());
  riemann::SampledTensorReport report;
  std::string message =
    riemann::PrepareTensorSamples(grid, riemann::SampledTensorOptions(), &report);
  EXPECT_NE(message.find("2 of 27 samples are not positive definite; the first is sample "
                         "(2, 1, 0) at (2, 2.5, 3), smallest eigenvalue -0.1"),
    std::string::npos)
    << message;
  EXPECT_NE(message.find("\"repair\": \"clamp\""), std::string::npos) << message;
  EXPECT_EQ(report.NotPositiveDefinite, 2);
  EXPECT_EQ(report.FirstBad, (std::array<int, 3>{ 2, 1, 0 }));

  SampledTensorGrid withNaN = Uniform(Diffusion());
  Mat3 nan = Diffusion();
  nan(0, 1) = nan(1, 0) = std::nan("");
  SetSample(withNaN, 18, nan);
  message = riemann::PrepareTensorSamples(withNaN, riemann::SampledTensorOptions(), &report);
  EXPECT_NE(message.find("1 of 27 samples are not finite (NaN or infinite components); the "
                         "first is sample (0, 0, 2) at (1, 2, 4)"),
    std::string::npos)
    << message;

  riemann::SampledTensorOptions options;
  options.Repair = true; // NaN cannot be repaired
  EXPECT_NE(riemann::PrepareTensorSamples(withNaN, options).find("not finite"), std::string::npos);

  SampledTensorGrid zeros = Uniform(Mat3::Zero());
  EXPECT_EQ(
    riemann::PrepareTensorSamples(zeros, options), "no sample is positive definite (27 samples)");
}

TEST(SampledTensorSamples, RepairClampsEigenvaluesToTheFloor)
{
  SampledTensorGrid grid = Uniform(Diffusion());
  Mat3 indefinite = Diffusion();
  indefinite(2, 2) = -0.1;
  SetSample(grid, 5, indefinite);
  SetSample(grid, 18, Mat3::Zero()); // background
  riemann::SampledTensorOptions options;
  options.Repair = true;
  options.RelativeFloor = 0.01;
  options.Kind = riemann::TensorMetricKind::Inverse;
  riemann::SampledTensorReport report;
  ASSERT_EQ(riemann::PrepareTensorSamples(grid, options, &report), "");
  EXPECT_EQ(report.NotPositiveDefinite, 2);
  EXPECT_EQ(report.Repaired, 2);
  // The largest eigenvalue of the data is 3.0 (Diffusion's along the fibre):
  // the floor 0.03, so the background's metric is I / 0.03.
  EXPECT_LT((SampleOf(grid, 18) - Mat3::Identity() / 0.03).cwiseAbs().maxCoeff(), 1e-9);
  for (int p = 0; p < 27; ++p)
  {
    EXPECT_GT(MinimumEigenvalue(SampleOf(grid, p)), 0.0);
  }
  // Untouched samples are only inverted.
  EXPECT_LT((SampleOf(grid, 0) * Diffusion() - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(SampledTensorSamples, BadOptionsAreRefused)
{
  SampledTensorGrid grid = Uniform(Diffusion());
  riemann::SampledTensorOptions options;
  options.Scale = 0.0;
  EXPECT_EQ(riemann::PrepareTensorSamples(grid, options),
    "the scale must be a finite positive number, got 0");
  options.Scale = 1.0;
  options.RelativeFloor = 1.5;
  EXPECT_NE(
    riemann::PrepareTensorSamples(grid, options).find("repair floor must be between 0 and 1"),
    std::string::npos);
  grid.Components.resize(10);
  EXPECT_NE(riemann::PrepareTensorSamples(grid, riemann::SampledTensorOptions())
              .find("expected 6 components per point"),
    std::string::npos);
}

namespace
{
/// Linear interpolation of sample component `m` along the grid at texel
/// position x (texel centres at integers, indices clamped to the grid, as a
/// GPU's trilinear read of a texture clamped to its edges).
double TrilinearRead(const SampledTensorGrid& grid, int m, const Vec3& x)
{
  double sum = 0.0;
  const Vec3 floorX(std::floor(x[0]), std::floor(x[1]), std::floor(x[2]));
  const Vec3 alpha = x - floorX;
  for (int corner = 0; corner < 8; ++corner)
  {
    long long index[3];
    double weight = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      const int bit = (corner >> a) & 1;
      index[a] = std::clamp(static_cast<long long>(floorX[a]) + bit, 0LL,
        static_cast<long long>(grid.Dimensions[a] - 1));
      weight *= bit ? alpha[a] : 1.0 - alpha[a];
    }
    const long long point =
      index[0] + grid.Dimensions[0] * (index[1] + grid.Dimensions[1] * index[2]);
    sum += weight * grid.Components[static_cast<std::size_t>(6 * point + m)];
  }
  return sum;
}

/// One axis of the filtered spline (SampledTensorFieldGlsl.cxx,
/// bspline_axis): pair weights and read positions (texel units) of the
/// value, or of the derivative.
void PairReads(double u, double cell, bool derivative, double g[2], double position[2])
{
  const double t = u - cell, s = 1.0 - t, t2 = t * t, t3 = t2 * t;
  double w[4] = { s * s * s / 6.0, (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0,
    (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0, t3 / 6.0 };
  if (derivative)
  {
    const double d[4] = { -0.5 * s * s, 1.5 * t2 - 2.0 * t, -1.5 * t2 + t + 0.5, 0.5 * t2 };
    std::copy(d, d + 4, w);
  }
  g[0] = w[0] + w[1];
  g[1] = w[2] + w[3];
  position[0] = cell - 1.0 + w[1] / g[0];
  position[1] = cell + 1.0 + w[3] / g[1];
}
} // namespace

TEST(SampledTensorField, EightTrilinearReadsAreTheSixtyFourTexelSum)
{
  // The GPU's FilteredTextureReads: each of g, dg/du0, dg/du1, dg/du2 as 8
  // trilinear reads. With exact weights they are the B-spline's 4 x 4 x 4
  // sums, everywhere in the box, edges included (grid coordinates = world
  // coordinates here: origin 0, spacing 1).
  SampledTensorGrid grid =
    Sample([](const Vec3& x) { return SmoothField(0.4 * x - Vec3(1, 1, 1)); }, 6,
      Vec3(2.5, 2.5, 2.5), Vec3(5, 5, 5));
  const SampledTensorField sampled(grid);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(0.0, 5.0);
  std::vector<Vec3> points = { Vec3(0, 0, 0), Vec3(5, 5, 5), Vec3(0.02, 4.98, 2.5), Vec3(4, 1, 3) };
  for (int i = 0; i < 200; ++i)
  {
    points.emplace_back(coordinate(random), coordinate(random), coordinate(random));
  }
  for (const Vec3& u : points)
  {
    Mat3 g;
    Mat3Stack dg;
    sampled.Evaluate(u, true, g, dg);
    double pairs[3][2][2], positions[3][2][2]; // [axis][value, derivative][pair]
    for (int a = 0; a < 3; ++a)
    {
      const double cell = std::min(std::floor(u[a]), 4.0);
      PairReads(u[a], cell, false, pairs[a][0], positions[a][0]);
      PairReads(u[a], cell, true, pairs[a][1], positions[a][1]);
    }
    // which = -1: the value; 0, 1, 2: the derivative along that axis.
    for (int which = -1; which < 3; ++which)
    {
      const Mat3& expected = which < 0 ? g : dg[which];
      for (int m = 0; m < 6; ++m)
      {
        double sum = 0.0;
        for (int corner = 0; corner < 8; ++corner)
        {
          Vec3 position;
          double weight = 1.0;
          for (int a = 0; a < 3; ++a)
          {
            const int kind = a == which ? 1 : 0;
            const int bit = (corner >> a) & 1;
            weight *= pairs[a][kind][bit];
            position[a] = positions[a][kind][bit];
          }
          sum += weight * TrilinearRead(grid, m, position);
        }
        const int rows[6] = { 0, 1, 2, 0, 1, 0 }, columns[6] = { 0, 1, 2, 1, 2, 2 };
        EXPECT_NEAR(sum, expected(rows[m], columns[m]), 1e-12)
          << "at " << u.transpose() << ", component " << m << ", derivative " << which;
      }
    }
  }

  // The shader reads that way only when the renderer asks; both ways share
  // the same textures, and differ in source (separate programs).
  const riemann::TensorMetric metric(std::make_shared<SampledTensorField>(grid));
  const riemann::MetricGlsl texels = riemann::EmitMetricGlsl(metric);
  riemann::GlslEmitOptions options;
  options.FilteredTextureReads = true;
  const riemann::MetricGlsl filtered = riemann::EmitMetricGlsl(metric, options);
  EXPECT_NE(texels.Source.find("texelFetch("), std::string::npos);
  EXPECT_EQ(texels.Source.find("texture("), std::string::npos);
  EXPECT_NE(filtered.Source.find("texture("), std::string::npos);
  EXPECT_EQ(filtered.Source.find("texelFetch("), std::string::npos);
  ASSERT_EQ(filtered.Textures.size(), 2u);
  ASSERT_EQ(texels.Textures.size(), 2u);
  for (int t = 0; t < 2; ++t)
  {
    EXPECT_EQ(filtered.Textures[t].Values, texels.Textures[t].Values);
  }
}
