// CompiledExpressions: values and every derivative to third order against
// hand-written closed forms (the built-in providers' and ours) and against
// finite differences of the next lower order; parameters and t; the output
// layout; common subexpressions computed once; concurrent evaluation; GLSL
// that glslangValidator accepts and that depends only on the structure.
#include "Expression.h"
#include "GaussianField.h"
#include "GlslSource.h"
#include "TwistMap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

namespace riemann
{
namespace
{
std::vector<double> Evaluated(const CompiledExpressions& c, const Vec3& p, double t = 0.0,
  const std::vector<double>& parameters = {})
{
  std::vector<double> out(static_cast<size_t>(c.GetNumberOfOutputs()), std::nan(""));
  c.Evaluate(p.data(), t, parameters.data(), out.data());
  return out;
}

std::vector<Vec3> Points(int count, double radius, unsigned seed = 7)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-radius, radius);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i)
  {
    points.emplace_back(uniform(generator), uniform(generator), uniform(generator));
  }
  return points;
}

/// All (n, i, j, k) of a source's block, in layout order.
struct Derivative
{
  int N, I, J, K;
};
std::vector<Derivative> AllDerivatives(int order)
{
  std::vector<Derivative> all = { { 0, 0, 0, 0 } };
  for (int i = 0; i < 3; ++i)
  {
    if (order >= 1)
    {
      all.push_back({ 1, i, 0, 0 });
    }
    for (int j = i; j < 3 && order >= 2; ++j)
    {
      all.push_back({ 2, i, j, 0 });
      for (int k = j; k < 3 && order >= 3; ++k)
      {
        all.push_back({ 3, i, j, k });
      }
    }
  }
  return all;
}

/**
 * Every derivative of order n >= 1 against the central difference of the
 * order n - 1 output along the last index (so each order is checked against
 * the one below, down to the values).
 */
void ExpectFiniteDifferences(const std::vector<std::string>& sources,
  const std::vector<std::string>& names, const std::vector<double>& values,
  const std::vector<Vec3>& points, double t = 0.3)
{
  const CompiledExpressions c(sources, names, 3);
  constexpr double h = 1e-5;
  for (const Vec3& p : points)
  {
    const std::vector<double> out = Evaluated(c, p, t, values);
    for (int s = 0; s < c.GetNumberOfSources(); ++s)
    {
      for (const Derivative& d : AllDerivatives(3))
      {
        const double value = out[c.OutputIndex(s, d.N, d.I, d.J, d.K)];
        ASSERT_TRUE(std::isfinite(value)) << sources[s] << " at " << p.transpose();
        if (d.N == 0)
        {
          continue;
        }
        const int last = d.N == 1 ? d.I : (d.N == 2 ? d.J : d.K);
        Vec3 step = Vec3::Zero();
        step[last] = h;
        const std::vector<double> plus = Evaluated(c, p + step, t, values);
        const std::vector<double> minus = Evaluated(c, p - step, t, values);
        const int lower = c.OutputIndex(s, d.N - 1, d.I, d.J, d.K);
        const double difference = (plus[lower] - minus[lower]) / (2 * h);
        EXPECT_NEAR(value, difference, 1e-5 * (1.0 + std::fabs(value)))
          << "\"" << sources[s] << "\" d" << d.N << "(" << d.I << d.J << d.K << ") at "
          << p.transpose();
      }
    }
  }
}

TEST(ExpressionCompiler, LayoutAndIndices)
{
  EXPECT_EQ(CompiledExpressions::OutputsPerSource(0), 1);
  EXPECT_EQ(CompiledExpressions::OutputsPerSource(1), 4);
  EXPECT_EQ(CompiledExpressions::OutputsPerSource(2), 10);
  EXPECT_EQ(CompiledExpressions::OutputsPerSource(3), 20);
  const CompiledExpressions c({ "x", "y", "z" }, {}, 3);
  EXPECT_EQ(c.GetNumberOfSources(), 3);
  EXPECT_EQ(c.GetOrder(), 3);
  EXPECT_EQ(c.GetNumberOfOutputs(), 60);
  // Offsets cover 0..19 once, in the documented order.
  const std::vector<Derivative> all = AllDerivatives(3);
  ASSERT_EQ(all.size(), 20u);
  std::vector<int> seen(20, 0);
  for (const Derivative& d : all)
  {
    ++seen[static_cast<size_t>(CompiledExpressions::DerivativeOffset(d.N, d.I, d.J, d.K))];
  }
  for (int count : seen)
  {
    EXPECT_EQ(count, 1);
  }
  EXPECT_EQ(CompiledExpressions::DerivativeOffset(2, 0, 1), 5);     // xy
  EXPECT_EQ(CompiledExpressions::DerivativeOffset(2, 2, 2), 9);     // zz
  EXPECT_EQ(CompiledExpressions::DerivativeOffset(3, 0, 1, 2), 14); // xyz
  EXPECT_EQ(CompiledExpressions::DerivativeOffset(3, 2, 2, 2), 19);
  // Any index order.
  EXPECT_EQ(c.OutputIndex(1, 2, 1, 0), c.OutputIndex(1, 2, 0, 1));
  EXPECT_EQ(c.OutputIndex(2, 3, 2, 0, 1), c.OutputIndex(2, 3, 0, 1, 2));
  EXPECT_EQ(c.OutputIndex(2, 3, 1, 2, 1), c.OutputIndex(2, 3, 1, 1, 2));
  EXPECT_EQ(c.OutputIndex(1, 0), 20);
  EXPECT_THROW(c.OutputIndex(3, 0), std::out_of_range);
  EXPECT_THROW(CompiledExpressions({ "x" }, {}, 4), std::invalid_argument);

  // Phi = identity: Jacobian = I, the rest 0.
  const std::vector<double> out = Evaluated(c, Vec3(0.3, -0.2, 0.7));
  for (int s = 0; s < 3; ++s)
  {
    EXPECT_EQ(out[c.OutputIndex(s, 0)], Vec3(0.3, -0.2, 0.7)[s]);
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_EQ(out[c.OutputIndex(s, 1, i)], s == i ? 1.0 : 0.0);
    }
    for (int o = 4; o < 20; ++o)
    {
      EXPECT_EQ(out[static_cast<size_t>(s * 20 + o)], 0.0);
    }
  }
}

TEST(ExpressionCompiler, PolynomialClosedForm)
{
  const CompiledExpressions c({ "x^3*y - 2*x*z^2 + y^4/4 + 3" }, {}, 3);
  for (const Vec3& p : Points(5, 2.0))
  {
    const double x = p[0], y = p[1], z = p[2];
    const std::vector<double> o = Evaluated(c, p);
    auto at = [&](int n, int i = 0, int j = 0, int k = 0)
    { return o[c.OutputIndex(0, n, i, j, k)]; };
    const double tolerance = 1e-12 * (1 + p.squaredNorm() * p.squaredNorm());
    EXPECT_NEAR(at(0), x * x * x * y - 2 * x * z * z + y * y * y * y / 4 + 3, tolerance);
    EXPECT_NEAR(at(1, 0), 3 * x * x * y - 2 * z * z, tolerance);
    EXPECT_NEAR(at(1, 1), x * x * x + y * y * y, tolerance);
    EXPECT_NEAR(at(1, 2), -4 * x * z, tolerance);
    EXPECT_NEAR(at(2, 0, 0), 6 * x * y, tolerance);
    EXPECT_NEAR(at(2, 0, 1), 3 * x * x, tolerance);
    EXPECT_NEAR(at(2, 0, 2), -4 * z, tolerance);
    EXPECT_NEAR(at(2, 1, 1), 3 * y * y, tolerance);
    EXPECT_NEAR(at(2, 1, 2), 0.0, tolerance);
    EXPECT_NEAR(at(2, 2, 2), -4 * x, tolerance);
    EXPECT_NEAR(at(3, 0, 0, 0), 6 * y, tolerance);
    EXPECT_NEAR(at(3, 0, 0, 1), 6 * x, tolerance);
    EXPECT_NEAR(at(3, 0, 2, 2), -4.0, tolerance);
    EXPECT_NEAR(at(3, 1, 1, 1), 6 * y, tolerance);
    for (const Derivative& d : std::vector<Derivative>{ { 3, 0, 0, 2 }, { 3, 0, 1, 1 },
           { 3, 0, 1, 2 }, { 3, 1, 1, 2 }, { 3, 1, 2, 2 }, { 3, 2, 2, 2 } })
    {
      EXPECT_EQ(at(d.N, d.I, d.J, d.K), 0.0);
    }
  }
}

/// The typed Gaussian against GaussianField's closed-form derivatives.
void ExpectGaussian(const std::string& source, const GaussianField& field)
{
  const CompiledExpressions c({ source }, {}, 3);
  for (const Vec3& p : Points(20, 1.5))
  {
    ScalarJet jet;
    field.Evaluate(p, ThirdDerivatives, jet);
    const std::vector<double> o = Evaluated(c, p);
    auto at = [&](int n, int i = 0, int j = 0, int k = 0)
    { return o[c.OutputIndex(0, n, i, j, k)]; };
    constexpr double tolerance = 1e-12;
    EXPECT_NEAR(at(0), jet.Value, tolerance) << source;
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_NEAR(at(1, i), jet.Gradient[i], tolerance) << source;
      for (int j = 0; j < 3; ++j)
      {
        EXPECT_NEAR(at(2, i, j), jet.Hessian(i, j), tolerance) << source;
        for (int k = 0; k < 3; ++k)
        {
          EXPECT_NEAR(at(3, i, j, k), jet.Third[i](j, k), 10 * tolerance) << source;
        }
      }
    }
  }
}

TEST(ExpressionCompiler, GaussianMatchesBuiltInProvider)
{
  // The paper's bump.
  ExpectGaussian("exp(-(x^2 + y^2 + z^2) / (2 * 0.5^2))",
    GaussianField(1.0, Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5)));
  ExpectGaussian("-0.7*exp(-(x-0.3)^2/(2*0.6^2) - (y+0.2)^2/(2*0.9^2) - (z-0.4)^2/(2*0.4^2))",
    GaussianField(-0.7, Vec3(0.3, -0.2, 0.4), Vec3(0.6, 0.9, 0.4)));
}

TEST(ExpressionCompiler, TwistMatchesBuiltInMap)
{
  const CompiledExpressions c({ "cos(z)*x - sin(z)*y", "sin(z)*x + cos(z)*y", "z" }, {}, 3);
  const TwistMap twist(1.0);
  for (const Vec3& p : Points(20, 2.0))
  {
    VectorJet jet;
    twist.Evaluate(p, ThirdDerivatives, jet);
    const std::vector<double> o = Evaluated(c, p);
    for (int s = 0; s < 3; ++s)
    {
      EXPECT_NEAR(o[c.OutputIndex(s, 0)], jet.Value[s], 1e-14);
      for (int i = 0; i < 3; ++i)
      {
        EXPECT_NEAR(o[c.OutputIndex(s, 1, i)], jet.Jacobian(s, i), 1e-14);
        for (int j = 0; j < 3; ++j)
        {
          EXPECT_NEAR(o[c.OutputIndex(s, 2, i, j)], jet.Hessian[s](i, j), 1e-14);
          for (int k = 0; k < 3; ++k)
          {
            EXPECT_NEAR(o[c.OutputIndex(s, 3, i, j, k)], jet.Third[s][i](j, k), 1e-14);
          }
        }
      }
    }
  }
}

TEST(ExpressionCompiler, Atan2AbsAndPowClosedForms)
{
  const CompiledExpressions c(
    { "atan2(y, x)", "abs(x - 2*y) * z", "pow(1 + x^2 + y^2 + z^2, 2.5)", "pow(2 + x, y)" }, {}, 2);
  for (const Vec3& p : Points(20, 0.9))
  {
    const double x = p[0], y = p[1], z = p[2];
    const std::vector<double> o = Evaluated(c, p);
    auto at = [&](int s, int n, int i = 0, int j = 0) { return o[c.OutputIndex(s, n, i, j)]; };
    // atan2: d = (-y, x) / r^2, Hessian (2xy, y^2 - x^2, -2xy) / r^4.
    const double r2 = x * x + y * y;
    EXPECT_NEAR(at(0, 0), std::atan2(y, x), 1e-14);
    EXPECT_NEAR(at(0, 1, 0), -y / r2, 1e-12);
    EXPECT_NEAR(at(0, 1, 1), x / r2, 1e-12);
    EXPECT_EQ(at(0, 1, 2), 0.0);
    EXPECT_NEAR(at(0, 2, 0, 0), 2 * x * y / (r2 * r2), 1e-10);
    EXPECT_NEAR(at(0, 2, 0, 1), (y * y - x * x) / (r2 * r2), 1e-10);
    EXPECT_NEAR(at(0, 2, 1, 1), -2 * x * y / (r2 * r2), 1e-10);
    // |x - 2y| z: d = sign(x - 2y) (z, -2z, .) and |x - 2y| along z.
    const double u = x - 2 * y;
    const double s = u > 0 ? 1.0 : -1.0;
    EXPECT_NEAR(at(1, 0), std::fabs(u) * z, 1e-15);
    EXPECT_NEAR(at(1, 1, 0), s * z, 1e-15);
    EXPECT_NEAR(at(1, 1, 1), -2 * s * z, 1e-15);
    EXPECT_NEAR(at(1, 1, 2), std::fabs(u), 1e-15);
    EXPECT_EQ(at(1, 2, 0, 0), 0.0);
    EXPECT_NEAR(at(1, 2, 0, 2), s, 1e-15);
    EXPECT_NEAR(at(1, 2, 1, 2), -2 * s, 1e-15);
    // w^2.5 with w = 1 + |p|^2: d_i = 5 p_i w^1.5, d_ij = 5 delta_ij w^1.5 + 15 p_i p_j w^0.5.
    const double w = 1 + p.squaredNorm();
    EXPECT_NEAR(at(2, 0), std::pow(w, 2.5), 1e-12);
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_NEAR(at(2, 1, i), 5 * p[i] * std::pow(w, 1.5), 1e-12);
      for (int j = 0; j < 3; ++j)
      {
        EXPECT_NEAR(at(2, 2, i, j),
          (i == j ? 5 * std::pow(w, 1.5) : 0.0) + 15 * p[i] * p[j] * std::sqrt(w), 1e-11);
      }
    }
    // (2 + x)^y: d/dx = y (2+x)^(y-1), d/dy = (2+x)^y log(2+x).
    const double b = 2 + x;
    EXPECT_NEAR(at(3, 0), std::pow(b, y), 1e-14);
    EXPECT_NEAR(at(3, 1, 0), y * std::pow(b, y - 1), 1e-13);
    EXPECT_NEAR(at(3, 1, 1), std::pow(b, y) * std::log(b), 1e-13);
    EXPECT_NEAR(at(3, 2, 0, 1), std::pow(b, y - 1) * (1 + y * std::log(b)), 1e-12);
    EXPECT_NEAR(at(3, 2, 1, 1), std::pow(b, y) * std::log(b) * std::log(b), 1e-12);
  }
}

TEST(ExpressionCompiler, AbsHasTheSignAsDerivative)
{
  // d|u| = sign(u) du: 0 at u = 0 (GiNaC's own u/|u| would give NaN).
  const CompiledExpressions c({ "abs(x)", "abs(y)^3" }, {}, 3);
  std::vector<double> o = Evaluated(c, Vec3(0, 0, 0));
  EXPECT_EQ(o[c.OutputIndex(0, 1, 0)], 0.0);
  EXPECT_EQ(o[c.OutputIndex(0, 2, 0, 0)], 0.0);
  o = Evaluated(c, Vec3(-2, 0.5, 0));
  EXPECT_EQ(o[c.OutputIndex(0, 0)], 2.0);
  EXPECT_EQ(o[c.OutputIndex(0, 1, 0)], -1.0);
  EXPECT_NEAR(o[c.OutputIndex(1, 1, 1)], 3 * 0.25, 1e-15);
  EXPECT_NEAR(o[c.OutputIndex(1, 2, 1, 1)], 6 * 0.5, 1e-15);
  EXPECT_NEAR(o[c.OutputIndex(1, 3, 1, 1, 1)], 6.0, 1e-15);
}

TEST(ExpressionCompiler, EveryFunctionAgainstFiniteDifferences)
{
  const std::vector<std::string> sources = {
    "x^3*y - 2*x*z^2 + y^4/4 + 3",
    "exp(-((x-0.3)^2 + (y+0.2)^2 + z^2) / (2*0.7^2))",
    "cos(z)*x - sin(z)*y",
    "sin(z)*x + cos(z)*y",
    "atan2(y, x + 3)",
    "atan2(y, 2) + atan2(3, x - 4)", // GiNaC rewrites the first as atan(y/2)
    "abs(x - 2*y + 5) * z",
    "pow(1 + x^2 + y^2 + z^2, 2.5)",
    "pow(2 + x, y) + 2^z",
    "log(2 + x^2 + y*z*z + y^2) + sqrt(3 + x - y*z)",
    "tan(0.3*x*y) + sinh(x - z) * cosh(y/2) + tanh(x*y*z)",
    "1/(2 + x^2) - z/(y^2 + 1)^2 + x^(-3/2)*0 + (4 + x)^(-1/2) + (4 + y)^(5/2)",
    "x^7 - y^5*z^2 + (x*y)^4",
    "x^2.5*0 + (5 + x + y)^0.3",
  };
  ExpectFiniteDifferences(sources, {}, {}, Points(6, 0.9));
}

TEST(ExpressionCompiler, ParametersAndTime)
{
  const std::vector<std::string> names = { "amplitude", "width", "unused" };
  const std::vector<std::string> sources = {
    "amplitude * exp(-(x^2 + y^2) / width^2) + 0.5 * t * z", "sin(t * x) + width", "x + y"
  };
  const CompiledExpressions c(sources, names, 3);
  EXPECT_TRUE(c.DependsOnTime());
  EXPECT_TRUE(c.DependsOnParameter(0));
  EXPECT_TRUE(c.DependsOnParameter(1));
  EXPECT_FALSE(c.DependsOnParameter(2));
  EXPECT_FALSE(c.DependsOnParameter(3));
  EXPECT_EQ(c.GetParameterNames(), names);
  EXPECT_FALSE(CompiledExpressions({ "x + t - t" }, {}, 1).DependsOnTime())
    << "t - t simplifies away";

  const Vec3 p(0.3, -0.4, 0.8);
  const double t = 0.25;
  const std::vector<double> values = { 1.7, 0.9, 123.0 };
  const std::vector<double> o = Evaluated(c, p, t, values);
  const double r2 = p[0] * p[0] + p[1] * p[1];
  const double e = 1.7 * std::exp(-r2 / 0.81);
  EXPECT_NEAR(o[c.OutputIndex(0, 0)], e + 0.5 * t * p[2], 1e-15);
  EXPECT_NEAR(o[c.OutputIndex(0, 1, 0)], -2 * p[0] / 0.81 * e, 1e-14);
  EXPECT_NEAR(o[c.OutputIndex(0, 1, 2)], 0.5 * t, 1e-15);
  EXPECT_NEAR(o[c.OutputIndex(1, 0)], std::sin(t * p[0]) + 0.9, 1e-15);
  EXPECT_NEAR(o[c.OutputIndex(1, 1, 0)], t * std::cos(t * p[0]), 1e-15);
  EXPECT_NEAR(o[c.OutputIndex(1, 3, 0, 0, 0)], -t * t * t * std::cos(t * p[0]), 1e-15);

  // New values, same object.
  const std::vector<double> o2 = Evaluated(c, p, 0.0, { -1.0, 2.0, 0.0 });
  EXPECT_NEAR(o2[c.OutputIndex(0, 0)], -std::exp(-r2 / 4.0), 1e-15);
  EXPECT_NEAR(o2[c.OutputIndex(1, 0)], 2.0, 1e-15);

  ExpectFiniteDifferences(sources, names, values, Points(4, 1.0));
}

TEST(ExpressionCompiler, ConstantsFold)
{
  const CompiledExpressions c(
    { "2*pi*x + sqrt(2) + exp(1)*y^2 + atan2(1, 1) + abs(-3) + 1e-3" }, {}, 1);
  const std::vector<double> o = Evaluated(c, Vec3(1, 2, 0));
  EXPECT_NEAR(o[0], 2 * M_PI + std::sqrt(2.0) + std::exp(1.0) * 4 + M_PI / 4 + 3 + 1e-3, 1e-13);
  EXPECT_NEAR(o[1], 2 * M_PI, 1e-14);
  EXPECT_NEAR(o[2], std::exp(1.0) * 4, 1e-14);
  EXPECT_EQ(o[3], 0.0);
  // Decimal numbers are exact rationals in GiNaC: 0.1*3 - 0.3 is exactly 0.
  const CompiledExpressions zero({ "(0.1*3 - 0.3) * x + x*0.5*2 - x" }, {}, 1);
  EXPECT_FALSE(zero.DependsOnTime());
  EXPECT_EQ(zero.GetStatistics().Operations, 0);
  EXPECT_EQ(Evaluated(zero, Vec3(5, 1, 1))[0], 0.0);
}

TEST(ExpressionCompiler, LowerOrdersRunAPrefix)
{
  const CompiledExpressions c({ "exp(x*y) * sin(z)", "x^2*y" }, {}, 3);
  const Vec3 p(0.2, 0.7, -0.4);
  const std::vector<double> all = Evaluated(c, p);
  for (int order = 0; order <= 3; ++order)
  {
    std::vector<double> out(all.size(), -999.0);
    c.Evaluate(p.data(), 0.0, nullptr, out.data(), order);
    for (int s = 0; s < 2; ++s)
    {
      for (const Derivative& d : AllDerivatives(3))
      {
        const size_t o = static_cast<size_t>(c.OutputIndex(s, d.N, d.I, d.J, d.K));
        if (d.N <= order)
        {
          EXPECT_EQ(out[o], all[o]);
        }
        else
        {
          EXPECT_EQ(out[o], -999.0) << "order " << order << " wrote a higher derivative";
        }
      }
    }
  }
}

/// The 8-Gaussian graph metric of the benchmarks, typed as one expression.
std::string EightGaussians()
{
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::ostringstream s;
  s.precision(6);
  for (int i = 0; i < 8; ++i)
  {
    const double a = uniform(generator), cx = uniform(generator), cy = uniform(generator),
                 cz = uniform(generator), sigma = 0.4 + 0.3 * std::fabs(uniform(generator));
    s << (i ? " + " : "") << a << "*exp(-((x - (" << cx << "))^2 + (y - (" << cy << "))^2 + (z - ("
      << cz << "))^2) / (2*" << sigma << "^2))";
  }
  return s.str();
}

TEST(ExpressionCompiler, CommonSubexpressionsAreComputedOnce)
{
  for (int order = 0; order <= 3; ++order)
  {
    const CompiledExpressions c({ EightGaussians() }, {}, order);
    const CompiledExpressions::Statistics s = c.GetStatistics();
    std::printf("8 Gaussians, order %d: %d instructions (%d operations, %d operands, %d "
                "registers); the outputs' expression trees have %.0f nodes\n",
      order, s.Instructions, s.Operations, s.Operands, s.Registers, s.TreeNodes);
    if (order >= 1) // derivatives repeat the value's parts: sharing pays
    {
      EXPECT_LT(s.Operations * 10, s.TreeNodes) << "order " << order;
    }
  }
  const CompiledExpressions c({ EightGaussians() }, {}, 2);
  // 8 exponentials, 3 differences and 3 squares each, then sums: about 9 per Gaussian.
  EXPECT_LE(c.GetStatistics().Operations, 8 * 9 + 10);

  // The same expression twice costs nothing more (only the stores).
  const CompiledExpressions twice({ EightGaussians(), EightGaussians() }, {}, 2);
  EXPECT_EQ(twice.GetStatistics().Operations, c.GetStatistics().Operations);

  // sin(x) appears in every derivative but is computed once.
  const CompiledExpressions shared({ "sin(x)*cos(y) + sin(x)^2 + exp(sin(x))" }, {}, 2);
  GlslBuilder builder;
  shared.EmitGlsl(builder, {}, "", 2);
  const std::string source = builder.Source();
  size_t count = 0;
  for (size_t at = source.find("sin(p.x)"); at != std::string::npos;
       at = source.find("sin(p.x)", at + 1))
  {
    ++count;
  }
  EXPECT_EQ(count, 1u) << source;
}

TEST(ExpressionCompiler, LargeRegisterFilesUseTheHeap)
{
  // 700 exponentials all alive until their sum: more registers than the
  // evaluator's stack buffer.
  std::string source;
  const double x = 0.37;
  double expected = 0.0;
  for (int i = 1; i <= 700; ++i)
  {
    source += (i > 1 ? "+exp(x/" : "exp(x/") + std::to_string(i) + ")";
    expected += std::exp(x / i);
  }
  const CompiledExpressions c({ source }, {}, 0);
  EXPECT_GT(c.GetStatistics().Registers, 512);
  EXPECT_NEAR(Evaluated(c, Vec3(x, 0, 0))[0], expected, 1e-12 * expected);
}

TEST(ExpressionCompiler, ConcurrentEvaluationAndConstruction)
{
  const CompiledExpressions c(
    { EightGaussians(), "cos(z)*x - sin(z)*y + a*t", "atan2(y, x) * abs(z) + b" }, { "a", "b" }, 3);
  const std::vector<Vec3> points = Points(2000, 1.5, 11);
  const std::vector<double> parameters = { 0.4, -1.2 };
  std::vector<std::vector<double>> expected;
  for (const Vec3& p : points)
  {
    expected.push_back(Evaluated(c, p, 0.5, parameters));
  }
  std::vector<int> mismatches(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
  {
    threads.emplace_back(
      [&, t]
      {
        // Construction is serialised (GiNaC is not thread-safe) but allowed from any thread.
        const CompiledExpressions own({ "x*y*z + exp(x)" }, {}, 2);
        for (int repeat = 0; repeat < 5; ++repeat)
        {
          for (size_t i = 0; i < points.size(); ++i)
          {
            if (Evaluated(c, points[i], 0.5, parameters) != expected[i])
            {
              ++mismatches[static_cast<size_t>(t)];
            }
          }
        }
        if (Evaluated(own, Vec3(1, 2, 3))[0] != 6 + std::exp(1.0))
        {
          ++mismatches[static_cast<size_t>(t)];
        }
      });
  }
  for (std::thread& thread : threads)
  {
    thread.join();
  }
  for (int m : mismatches)
  {
    EXPECT_EQ(m, 0);
  }
}

/// glslangValidator's verdict on `functions` inside a minimal fragment shader
/// of the renderer's version ("" when it compiles, else its output).
std::string CompileGlsl(
  const std::string& functions, const std::string& call, const std::string& name)
{
  const std::string path =
    (std::filesystem::temp_directory_path() / ("TestExpressionCompiler_" + name + ".frag"))
      .string();
  {
    std::ofstream file(path);
    file << "#version 150\n" << functions << "\nout vec4 color;\nvoid main()\n{\n" << call << "}\n";
  }
  const std::string log = path + ".log";
  const int status = std::system(("glslangValidator " + path + " > " + log + " 2>&1").c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return status == 0 ? std::string() : text.str();
}

TEST(ExpressionCompiler, GlslCompilesAndDependsOnlyOnStructure)
{
  if (std::system("glslangValidator --version > /dev/null 2>&1") != 0)
  {
    GTEST_SKIP() << "glslangValidator (glslang-tools) not installed";
  }
  const std::vector<std::string> sources = { "a*exp(-((x-1)^2 + y^2 + z^2)/(2*s^2)) + t*z",
    "atan2(y, x) + abs(x - z)^1.5 + pow(2 + x*x, y) + log(3 + x) - sqrt(4 + y*y)",
    "tan(x)/cosh(y) + sinh(z)*tanh(x) + x^-3*y^7 + sin(z)*cos(x)" };
  const CompiledExpressions c(sources, { "a", "s" }, 3);
  for (int maxOrder = 0; maxOrder <= 2; ++maxOrder)
  {
    GlslBuilder builder;
    const std::string a = builder.AddUniform("parameter_a", "float", { 0.3 });
    const std::string s = builder.AddUniform("parameter_s", "float", { 0.5 });
    const std::string t = builder.AddUniform("time", "float", { 0.0 });
    const std::string name = c.EmitGlsl(builder, { a, s }, t, maxOrder);
    const int m = 3 * CompiledExpressions::OutputsPerSource(maxOrder);
    EXPECT_NE(
      builder.Source().find("void " + name + "(vec3 p, out float o[" + std::to_string(m) + "])"),
      std::string::npos);
    const std::string call = "  float o[" + std::to_string(m) + "];\n  " + name +
      "(gl_FragCoord.xyz, o);\n  color = vec4(o[0], o[" + std::to_string(m - 1) + "], 0.0, 1.0);\n";
    EXPECT_EQ(CompileGlsl(builder.Source(), call, "order" + std::to_string(maxOrder)), "")
      << builder.Source();
    if (maxOrder == 2)
    {
      std::printf("GLSL of 3 expressions to order 2: %zu characters\n", builder.Source().size());
    }
  }

  // Same structure, other parameter values: byte-identical source (the values
  // are uniforms). Typed numbers are literals, so another number is another source.
  auto emit = [](const std::vector<std::string>& sourceTexts, double a)
  {
    const CompiledExpressions e(sourceTexts, { "a" }, 2);
    GlslBuilder builder;
    const std::string uniform = builder.AddUniform("parameter_a", "float", { a });
    e.EmitGlsl(builder, { uniform }, "", 2);
    return builder.Source();
  };
  // Sums and products are compiled in an order of their own, not in GiNaC's
  // (which follows the serial numbers of symbols, new for every compilation).
  const std::string sum = emit({ "a*exp(-x^2-y^2-z^2)" }, 1.0);
  for (int repeat = 0; repeat < 8; ++repeat)
  {
    const CompiledExpressions other({ "b*z + y*c - x" }, { "c", "b" }, 1);
    EXPECT_EQ(sum, emit({ "a*exp(-x^2-y^2-z^2)" }, 2.5)) << "repeat " << repeat;
  }
  const std::string first = emit({ "a*exp(-x^2) + y" }, 0.3);
  EXPECT_EQ(first, emit({ "a*exp(-x^2) + y" }, -7.0));
  EXPECT_EQ(first, emit({ "a * exp(-(x ^ 2)) + (y)" }, 0.3)) << "spacing and parentheses";
  EXPECT_NE(first, emit({ "a*exp(-2*x^2) + y" }, 0.3));

  EXPECT_THROW(
    c.EmitGlsl(*std::make_unique<GlslBuilder>(), { "u" }, "time", 2), std::invalid_argument);
  EXPECT_THROW(
    c.EmitGlsl(*std::make_unique<GlslBuilder>(), { "u", "v" }, "", 2), std::invalid_argument)
    << "depends on t";
  EXPECT_THROW(
    c.EmitGlsl(*std::make_unique<GlslBuilder>(), { "u", "v" }, "time", 4), std::invalid_argument);
}
} // namespace
} // namespace riemann
