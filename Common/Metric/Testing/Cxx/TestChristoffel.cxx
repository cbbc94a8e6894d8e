// Every family's specialised Christoffel symbols, inverse, acceleration and
// volume form against the general formulas, at random points (MATH.md).
#include "Christoffel.h"
#include "MetricTestUtilities.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <gtest/gtest.h>

namespace riemann
{
namespace
{
TEST(Christoffel, SpecialisedEqualsGeneralFormula)
{
  for (const auto& [name, metric] : testing::Metrics())
  {
    for (const Vec3& p : testing::RandomPoints(100, 1.5))
    {
      Mat3 g;
      Mat3Stack dg, general, specialised;
      ASSERT_TRUE(metric->TensorDerivatives(p, g, dg)) << name;
      ChristoffelFromMetricDerivatives(g.inverse(), dg, general);
      ASSERT_TRUE(metric->Christoffel(p, specialised)) << name;
      for (int m = 0; m < 3; ++m)
      {
        EXPECT_LT((specialised[m] - general[m]).cwiseAbs().maxCoeff(), 1e-9)
          << name << " at " << p.transpose() << " m=" << m;
        EXPECT_LT((specialised[m] - specialised[m].transpose()).cwiseAbs().maxCoeff(), 1e-12)
          << name << ": Gamma^m must be symmetric in i, j";
      }
    }
  }
}

TEST(Christoffel, MetricDerivativesMatchFiniteDifferences)
{
  constexpr double h = 1e-5;
  for (const auto& [name, metric] : testing::Metrics())
  {
    for (const Vec3& p : testing::RandomPoints(30, 1.5, 777))
    {
      Mat3 g;
      Mat3Stack dg;
      ASSERT_TRUE(metric->TensorDerivatives(p, g, dg)) << name;
      Mat3 gOnly;
      ASSERT_TRUE(metric->Tensor(p, gOnly)) << name;
      EXPECT_LT((g - gOnly).cwiseAbs().maxCoeff(), 1e-14) << name;
      for (int k = 0; k < 3; ++k)
      {
        Vec3 step = Vec3::Zero();
        step[k] = h;
        Mat3 plus, minus;
        metric->Tensor(p + step, plus);
        metric->Tensor(p - step, minus);
        const Mat3 numeric = (plus - minus) / (2 * h);
        EXPECT_LT((dg[k] - numeric).cwiseAbs().maxCoeff(), 1e-6 * (1 + numeric.norm()))
          << name << " d" << k << " g";
      }
    }
  }
}

TEST(Christoffel, AccelerationInverseAndVolumeFormAgree)
{
  for (const auto& [name, metric] : testing::Metrics())
  {
    const auto velocities = testing::RandomPoints(100, 1.0, 99);
    const auto points = testing::RandomPoints(100, 1.5, 4242);
    for (size_t n = 0; n < points.size(); ++n)
    {
      const Vec3& p = points[n];
      const Vec3& v = velocities[n];
      Mat3Stack gamma;
      ASSERT_TRUE(metric->Christoffel(p, gamma)) << name;
      Vec3 a;
      ASSERT_TRUE(metric->Acceleration(p, v, a)) << name;
      EXPECT_LT((a - ContractChristoffel(gamma, v)).norm(), 1e-10 * (1 + a.norm())) << name;

      Mat3 g, inverse;
      ASSERT_TRUE(metric->Tensor(p, g)) << name;
      ASSERT_TRUE(metric->InverseTensor(p, inverse)) << name;
      EXPECT_LT((g * inverse - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12) << name;
      EXPECT_NEAR(
        metric->VolumeForm(p), std::sqrt(g.determinant()), 1e-10 * std::sqrt(g.determinant()))
        << name;
      EXPECT_NEAR(metric->InnerProduct(p, v, v), v.dot(g * v), 1e-12 * (1 + v.dot(g * v))) << name;
    }
  }
}

TEST(Christoffel, GraphOfParaboloidAtOrigin)
{
  // f = x^2+y^2+z^2: grad f = 0 at the origin, so g = I and Gamma = 0 there;
  // at (1,0,0): grad f = (2,0,0), H = 2I, Gamma^x_ij = 2*2 delta_ij / 5.
  GraphMetric metric(testing::Paraboloid(1.0));
  Mat3Stack gamma;
  ASSERT_TRUE(metric.Christoffel(Vec3(1, 0, 0), gamma));
  EXPECT_TRUE(gamma[0].isApprox(Mat3::Identity() * 0.8, 1e-15));
  EXPECT_TRUE(gamma[1].isZero(0.0));
  EXPECT_NEAR(metric.VolumeForm(Vec3(1, 0, 0)), std::sqrt(5.0), 1e-15);
}
} // namespace
} // namespace riemann
