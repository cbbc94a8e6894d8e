// Exact derivatives of every field provider against central finite
// differences of the next lower order, at random points.
//
// Central differences with step h have error O(h^2 f''') plus rounding
// O(eps/h); with h = 1e-5 both are ~1e-10 for these O(1) fields, so a
// tolerance of 1e-6 (relative to the derivative's scale) cannot pass by
// accident and cannot fail by noise.
#include "MetricTestUtilities.h"

#include <gtest/gtest.h>

namespace riemann
{
namespace
{
constexpr double FiniteStep = 1e-5;
constexpr double Tolerance = 1e-6;

double Scale(double magnitude)
{
  return 1.0 + std::abs(magnitude);
}

TEST(FieldProviders, ScalarDerivativesMatchFiniteDifferences)
{
  for (const auto& [name, field] : testing::ScalarProviders())
  {
    for (const Vec3& p : testing::RandomPoints(40, 1.5))
    {
      ScalarJet jet;
      field->Evaluate(p, ThirdDerivatives, jet);
      for (int i = 0; i < 3; ++i)
      {
        Vec3 h = Vec3::Zero();
        h[i] = FiniteStep;
        ScalarJet plus, minus;
        field->Evaluate(p + h, ThirdDerivatives, plus);
        field->Evaluate(p - h, ThirdDerivatives, minus);
        const double dValue = (plus.Value - minus.Value) / (2 * FiniteStep);
        EXPECT_NEAR(jet.Gradient[i], dValue, Tolerance * Scale(dValue)) << name << " d" << i;
        for (int j = 0; j < 3; ++j)
        {
          const double dGradient = (plus.Gradient[j] - minus.Gradient[j]) / (2 * FiniteStep);
          EXPECT_NEAR(jet.Hessian(i, j), dGradient, Tolerance * Scale(dGradient)) << name;
          for (int k = 0; k < 3; ++k)
          {
            const double dHessian = (plus.Hessian(j, k) - minus.Hessian(j, k)) / (2 * FiniteStep);
            EXPECT_NEAR(jet.Third[i](j, k), dHessian, Tolerance * Scale(dHessian))
              << name << " third " << i << j << k;
          }
        }
      }
    }
  }
}

TEST(FieldProviders, MapDerivativesMatchFiniteDifferences)
{
  for (const auto& [name, map] : testing::MapProviders())
  {
    for (const Vec3& p : testing::RandomPoints(40, 1.5))
    {
      VectorJet jet;
      map->Evaluate(p, ThirdDerivatives, jet);
      for (int i = 0; i < 3; ++i)
      {
        Vec3 h = Vec3::Zero();
        h[i] = FiniteStep;
        VectorJet plus, minus;
        map->Evaluate(p + h, ThirdDerivatives, plus);
        map->Evaluate(p - h, ThirdDerivatives, minus);
        for (int s = 0; s < 3; ++s)
        {
          const double dValue = (plus.Value[s] - minus.Value[s]) / (2 * FiniteStep);
          EXPECT_NEAR(jet.Jacobian(s, i), dValue, Tolerance * Scale(dValue)) << name;
          for (int j = 0; j < 3; ++j)
          {
            const double dJacobian =
              (plus.Jacobian(s, j) - minus.Jacobian(s, j)) / (2 * FiniteStep);
            EXPECT_NEAR(jet.Hessian[s](i, j), dJacobian, Tolerance * Scale(dJacobian))
              << name << " Hessian s=" << s << " " << i << j;
            for (int k = 0; k < 3; ++k)
            {
              const double dHessian =
                (plus.Hessian[s](j, k) - minus.Hessian[s](j, k)) / (2 * FiniteStep);
              EXPECT_NEAR(jet.Third[s][i](j, k), dHessian, Tolerance * Scale(dHessian))
                << name << " third s=" << s << " " << i << j << k;
            }
          }
        }
      }
    }
  }
}

TEST(FieldProviders, LowerOrdersDoNotDependOnRequestedOrder)
{
  const Vec3 p(0.3, -0.4, 0.2);
  for (const auto& [name, map] : testing::MapProviders())
  {
    VectorJet full, first;
    map->Evaluate(p, ThirdDerivatives, full);
    map->Evaluate(p, FirstDerivatives, first);
    EXPECT_TRUE(full.Value.isApprox(first.Value, 1e-15)) << name;
    EXPECT_TRUE(full.Jacobian.isApprox(first.Jacobian, 1e-15)) << name;
  }
}

TEST(FieldProviders, InversesRecoverThePoint)
{
  for (const auto& [name, map] : testing::MapProviders())
  {
    for (const Vec3& p : testing::RandomPoints(50, 2.0))
    {
      VectorJet jet;
      map->Evaluate(p, ValueOnly, jet);
      Vec3 back;
      ASSERT_TRUE(map->Inverse(jet.Value, back)) << name;
      EXPECT_LT((back - p).norm(), 1e-11) << name;
    }
  }
}

TEST(FieldProviders, GaussianMatchesThePaperFormula)
{
  GaussianField f(2.0, Vec3(1, 2, 3), Vec3(0.5, 1.0, 2.0));
  ScalarJet jet;
  const Vec3 p(1.5, 1.0, 5.0);
  f.Evaluate(p, ValueOnly, jet);
  const double expected = 2.0 * std::exp(-0.25 / (2 * 0.25) - 1.0 / (2 * 1.0) - 4.0 / (2 * 4.0));
  EXPECT_NEAR(jet.Value, expected, 1e-15);
}

TEST(FieldProviders, TwistMatchesThePaperFormula)
{
  TwistMap twist(1.0);
  const Vec3 p(0.7, -0.3, 1.1);
  VectorJet jet;
  twist.Evaluate(p, ValueOnly, jet);
  EXPECT_NEAR(jet.Value[0], std::cos(1.1) * 0.7 - std::sin(1.1) * -0.3, 1e-15);
  EXPECT_NEAR(jet.Value[1], std::sin(1.1) * 0.7 + std::cos(1.1) * -0.3, 1e-15);
  EXPECT_NEAR(jet.Value[2], 1.1, 1e-15);
}
} // namespace
} // namespace riemann
