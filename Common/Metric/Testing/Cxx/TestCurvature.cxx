// Curvature from exact second derivatives of g (Curvature.h) against known
// answers: constant-curvature space forms, flat pull-backs, the Gauss
// equation of graphs, Nil; and d2g of every family against finite differences.
#include "Curvature.h"
#include "MetricTestUtilities.h"

#include <Eigen/LU>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace riemann
{
namespace
{
/// R_mijk = g_ml R^l_ijk.
double Lowered(const CurvatureSample& s, int m, int i, int j, int k)
{
  return s.g(m, 0) * s.Riemann[0][i][j][k] + s.g(m, 1) * s.Riemann[1][i][j][k] +
    s.g(m, 2) * s.Riemann[2][i][j][k];
}

/// <R(u, w)w, u> / (|u|^2 |w|^2 - <u, w>^2) with R(u, w)w = R^l_ijk w^i u^j w^k.
double Sectional(const CurvatureSample& s, const Vec3& u, const Vec3& w)
{
  double numerator = 0.0;
  for (int m = 0; m < 3; ++m)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          numerator += Lowered(s, m, i, j, k) * u[m] * w[i] * u[j] * w[k];
  const double uu = u.dot(s.g * u), ww = w.dot(s.g * w), uw = u.dot(s.g * w);
  return numerator / (uu * ww - uw * uw);
}

std::filesystem::path DataDirectory()
{
  if (const char* dir = std::getenv("RIEMANN_DATA_DIR"))
  {
    if (*dir)
    {
      return dir;
    }
  }
  return std::filesystem::path(RIEMANN_TEST_DATA_DIR);
}

/// Every check a space of constant sectional curvature K must pass.
void ExpectConstantCurvature(
  const Metric& metric, const std::vector<Vec3>& points, double K, const char* name)
{
  double worst = 0.0;
  for (const Vec3& p : points)
  {
    CurvatureSample s;
    ASSERT_TRUE(ComputeCurvature(metric, p, s)) << name << " at " << p.transpose();
    const double errors[] = { std::abs(s.Scalar - 6 * K), std::abs(s.SectionalXY - K),
      std::abs(s.SectionalXZ - K), std::abs(s.SectionalYZ - K), std::abs(s.SectionalMin - K),
      std::abs(s.SectionalMax - K), (s.Ricci - 2 * K * s.g).cwiseAbs().maxCoeff(),
      std::abs(s.RiemannNorm - std::sqrt(12.0) * std::abs(K)),
      std::abs(Sectional(s, Vec3(1, 2, -0.5), Vec3(0.3, -1, 2)) - K),
      std::abs(s.VolumeForm - std::sqrt(s.g.determinant())) };
    for (double e : errors)
    {
      EXPECT_LT(e, 1e-9) << name << " at " << p.transpose();
      worst = std::max(worst, e);
    }
    // R^l_ijk = K (delta^l_j g_ik - delta^l_k g_ij).
    for (int l = 0; l < 3; ++l)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          for (int k = 0; k < 3; ++k)
          {
            const double expected = K * ((l == j) * s.g(i, k) - (l == k) * s.g(i, j));
            EXPECT_NEAR(s.Riemann[l][i][j][k], expected, 1e-9 * (1 + s.g.norm())) << name;
          }
  }
  std::cout << name << ": worst error " << worst << " over " << points.size() << " points\n";
}

TEST(Curvature, RoundSphere)
{
  const auto sphere =
    ParseMetricDefinition(R"json({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})json");
  ExpectConstantCurvature(*sphere, testing::RandomPoints(200, 1.5, 4242), 1.0, "round S^3");
}

TEST(Curvature, PoincareBall)
{
  const auto ball =
    ParseMetricDefinition(R"json({"type":"conformal","n":"2/(1-x^2-y^2-z^2)"})json");
  std::vector<Vec3> points;
  for (const Vec3& p : testing::RandomPoints(400, 0.8, 99))
  {
    if (p.norm() < 0.8)
    {
      points.push_back(p);
    }
  }
  ASSERT_GT(points.size(), 100u);
  ExpectConstantCurvature(*ball, points, -1.0, "Poincare ball");
}

TEST(Curvature, DiffeomorphismsAreFlat)
{
  int families = 0;
  for (const auto& [name, metric] : testing::Metrics())
  {
    if (metric->FamilyName() != "diffeo")
    {
      continue;
    }
    ++families;
    double worst = 0.0;
    for (const Vec3& p : testing::RandomPoints(100, 1.5, 31))
    {
      CurvatureSample s;
      ASSERT_TRUE(ComputeCurvature(*metric, p, s)) << name << " at " << p.transpose();
      for (int l = 0; l < 3; ++l)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
            {
              EXPECT_LT(std::abs(s.Riemann[l][i][j][k]), 1e-9) << name << " at " << p.transpose();
              worst = std::max(worst, std::abs(s.Riemann[l][i][j][k]));
            }
      EXPECT_LT(s.RiemannNorm, 1e-9) << name;
      EXPECT_LT(std::abs(s.Scalar), 1e-9) << name;
      EXPECT_LT(std::max(std::abs(s.SectionalMin), std::abs(s.SectionalMax)), 1e-9) << name;
      EXPECT_LT(s.Ricci.cwiseAbs().maxCoeff(), 1e-9) << name;
    }
    std::cout << name << ": max |R^l_ijk| " << worst << "\n";
  }
  EXPECT_GE(families, 7);
}

TEST(Curvature, GraphsObeyGaussEquation)
{
  int families = 0;
  for (const auto& [name, metric] : testing::Metrics())
  {
    const auto* graph = dynamic_cast<const GraphMetric*>(metric.get());
    if (metric->FamilyName() != "graph" || !graph)
    {
      continue;
    }
    ++families;
    double worst = 0.0;
    for (const Vec3& p : testing::RandomPoints(100, 1.5, 57))
    {
      CurvatureSample s;
      ASSERT_TRUE(ComputeCurvature(*metric, p, s)) << name;
      ScalarJet f;
      graph->GetField().Evaluate(p, SecondDerivatives, f);
      const Mat3 h = f.Hessian / std::sqrt(1.0 + f.Gradient.squaredNorm());
      const double scale = 1.0 + h.squaredNorm();
      for (int m = 0; m < 3; ++m)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
            {
              // MATH.md's R_ijkl = h_ik h_jl - h_il h_jk, in our index placement
              // R_mijk = g_ml R^l_ijk = <R(d_j, d_k) d_i, d_m> = h_mj h_ik - h_mk h_ij.
              const double expected = h(m, j) * h(i, k) - h(m, k) * h(i, j);
              const double error = std::abs(Lowered(s, m, i, j, k) - expected);
              EXPECT_LT(error, 1e-9 * scale) << name << " at " << p.transpose();
              worst = std::max(worst, error / scale);
            }
      // Sectional extremes bound every plane's curvature.
      for (const Vec3& w : testing::RandomPoints(5, 1.0, 3))
      {
        const double K = Sectional(s, Vec3(0.2, -0.7, 1.1), w);
        EXPECT_LE(K, s.SectionalMax + 1e-9 * scale) << name;
        EXPECT_GE(K, s.SectionalMin - 1e-9 * scale) << name;
      }
    }
    std::cout << name << ": worst relative Gauss-equation error " << worst << "\n";
  }
  EXPECT_GE(families, 6);
}

TEST(Curvature, ParaboloidAtOrigin)
{
  GraphMetric paraboloid(testing::Paraboloid(1.0));
  CurvatureSample s;
  ASSERT_TRUE(ComputeCurvature(paraboloid, Vec3::Zero(), s));
  EXPECT_NEAR(s.Scalar, 24.0, 1e-12);
  EXPECT_NEAR(s.SectionalXY, 4.0, 1e-12);
  EXPECT_NEAR(s.SectionalXZ, 4.0, 1e-12);
  EXPECT_NEAR(s.SectionalYZ, 4.0, 1e-12);
  EXPECT_NEAR(s.SectionalMin, 4.0, 1e-12);
  EXPECT_NEAR(s.SectionalMax, 4.0, 1e-12);
  EXPECT_LT((s.Ricci - 8.0 * Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(s.VolumeForm, 1.0, 1e-15);
}

TEST(Curvature, NilHasItsConstantCurvatures)
{
  const auto nil = LoadMetricDefinitionFile((DataDirectory() / "metrics" / "nil.json").string());
  ASSERT_EQ(nil->FamilyName(), "tensor");
  double worst = 0.0;
  for (const Vec3& p : testing::RandomPoints(200, 2.0, 8))
  {
    CurvatureSample s;
    ASSERT_TRUE(ComputeCurvature(*nil, p, s)) << p.transpose();
    const double errors[] = { std::abs(s.Scalar + 0.5), std::abs(s.SectionalMin + 0.75),
      std::abs(s.SectionalMax - 0.25), std::abs(s.RiemannNorm - std::sqrt(11.0) / 2),
      std::abs(s.VolumeForm - 1.0) };
    for (double e : errors)
    {
      EXPECT_LT(e, 1e-9) << p.transpose();
      worst = std::max(worst, e);
    }
    // The left-invariant orthonormal frame e1 = d_x, e2 = d_y + x d_z, e3 = d_z:
    // K(e1, e2) = -3/4, K(e1, e3) = K(e2, e3) = 1/4.
    const Vec3 e1(1, 0, 0), e2(0, 1, p.x()), e3(0, 0, 1);
    EXPECT_NEAR(Sectional(s, e1, e2), -0.75, 1e-9);
    EXPECT_NEAR(Sectional(s, e1, e3), 0.25, 1e-9);
    EXPECT_NEAR(Sectional(s, e2, e3), 0.25, 1e-9);
  }
  std::cout << "Nil: worst error " << worst << "\n";
}

TEST(Curvature, SecondDerivativesMatchFiniteDifferences)
{
  constexpr double h = 1e-5;
  for (const auto& [name, metric] : testing::Metrics())
  {
    double worst = 0.0;
    for (const Vec3& p : testing::RandomPoints(30, 1.5, 2024))
    {
      Mat3 g, g1;
      Mat3Stack dg, dg1;
      std::array<Mat3Stack, 3> d2g;
      ASSERT_TRUE(metric->TensorSecondDerivatives(p, g, dg, d2g)) << name;
      ASSERT_TRUE(metric->TensorDerivatives(p, g1, dg1)) << name;
      EXPECT_LT((g - g1).cwiseAbs().maxCoeff(), 1e-13) << name;
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_LT((dg[k] - dg1[k]).cwiseAbs().maxCoeff(), 1e-13) << name;
      }
      for (int l = 0; l < 3; ++l)
      {
        Vec3 step = Vec3::Zero();
        step[l] = h;
        Mat3 gPlus, gMinus;
        Mat3Stack plus, minus;
        ASSERT_TRUE(metric->TensorDerivatives(p + step, gPlus, plus)) << name;
        ASSERT_TRUE(metric->TensorDerivatives(p - step, gMinus, minus)) << name;
        for (int k = 0; k < 3; ++k)
        {
          const Mat3 numeric = (plus[k] - minus[k]) / (2 * h);
          const double error = (d2g[k][l] - numeric).cwiseAbs().maxCoeff();
          EXPECT_LT(error, 1e-6 * (1 + numeric.norm())) << name << " d" << k << " d" << l;
          EXPECT_LT((d2g[k][l] - d2g[l][k]).cwiseAbs().maxCoeff(), 1e-12) << name;
          EXPECT_LT((d2g[k][l] - d2g[k][l].transpose()).cwiseAbs().maxCoeff(), 1e-12) << name;
          worst = std::max(worst, error / (1 + numeric.norm()));
        }
      }
    }
    std::cout << name << ": worst relative d2g error " << worst << "\n";
  }
}

/// A tensor field without second derivatives: curvature must be refused.
class FirstOrderOnlyField : public TensorField
{
public:
  void Evaluate(const Vec3& /*p*/, bool withDerivatives, Mat3& g, Mat3Stack& dg) const override
  {
    g.setIdentity();
    if (withDerivatives)
    {
      for (Mat3& m : dg)
      {
        m.setZero();
      }
    }
  }
  std::string Describe() const override { return "first order only"; }
};

TEST(Curvature, RefusedWithoutSecondDerivatives)
{
  TensorMetric metric(std::make_shared<FirstOrderOnlyField>());
  CurvatureSample s;
  EXPECT_FALSE(ComputeCurvature(metric, Vec3::Zero(), s));
  // Outside the ball the Poincare index is negative: degenerate, refused.
  const auto ball =
    ParseMetricDefinition(R"json({"type":"conformal","n":"2/(1-x^2-y^2-z^2)"})json");
  EXPECT_FALSE(ComputeCurvature(*ball, Vec3(2, 0, 0), s));
}
} // namespace
} // namespace riemann
