// Shared fixtures of the metric-core tests: the providers and families under
// test, random points, and finite differences used as the independent check.
#ifndef RiemannMetricTestUtilities_h
#define RiemannMetricTestUtilities_h

#include "BumpTranslationMap.h"
#include "ConformalMetric.h"
#include "DiffeoMetric.h"
#include "EuclideanMetric.h"
#include "GaussianField.h"
#include "GraphMetric.h"
#include "MapComposition.h"
#include "MetricDefinition.h"
#include "QuadraticField.h"
#include "ScalarFieldSum.h"
#include "TensorMetric.h"
#include "TwistMap.h"

#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace riemann
{
namespace testing
{
inline std::vector<Vec3> RandomPoints(int count, double radius, unsigned seed = 12345)
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

inline std::shared_ptr<const ScalarField> PaperGaussian()
{
  return std::make_shared<GaussianField>(1.0, Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5));
}

inline std::shared_ptr<const ScalarField> AnisotropicGaussian()
{
  return std::make_shared<GaussianField>(-0.7, Vec3(0.3, -0.2, 0.4), Vec3(0.6, 0.9, 0.4));
}

/// Two Gaussians and a quadratic, summed: exercises ScalarFieldSum.
inline std::shared_ptr<const ScalarField> MixedSum()
{
  Mat3 a;
  a << 0.3, 0.1, 0.0, 0.1, -0.2, 0.05, 0.0, 0.05, 0.1;
  return std::make_shared<ScalarFieldSum>(0.5,
    std::vector<std::shared_ptr<const ScalarField>>{ PaperGaussian(), AnisotropicGaussian(),
      std::make_shared<QuadraticField>(a, Vec3(0.2, -0.1, 0.3), 1.0) });
}

inline std::shared_ptr<const ScalarField> Paraboloid(double zSign)
{
  return std::make_shared<QuadraticField>(
    Vec3(1.0, 1.0, zSign).asDiagonal().toDenseMatrix(), Vec3::Zero(), 0.0);
}

/// The composition of two bump translations of the convergence study.
inline std::shared_ptr<const SpaceMap> TwoBumpComposition()
{
  auto first = std::make_shared<BumpTranslationMap>(
    std::make_shared<GaussianField>(0.5, Vec3(0.5, 0.0, 0.0), Vec3(0.7, 0.7, 0.7)), Vec3(0, 1, 0));
  auto second = std::make_shared<BumpTranslationMap>(
    std::make_shared<GaussianField>(0.4, Vec3(-0.3, 0.2, 0.1), Vec3(0.6, 0.8, 0.5)),
    Vec3(1, 0, 0.5));
  return std::make_shared<MapComposition>(
    std::vector<std::shared_ptr<const SpaceMap>>{ first, second });
}

/// A bump moved along an affine field: a local twist about the z axis.
inline std::shared_ptr<const SpaceMap> LocalTwistBump()
{
  Mat3 rotation;
  rotation << 0, -1, 0, 1, 0, 0, 0, 0, 0.2;
  return std::make_shared<BumpTranslationMap>(
    std::make_shared<GaussianField>(0.4, Vec3(0.1, 0.0, -0.1), Vec3(0.8, 0.8, 0.6)), rotation,
    Vec3(0.1, 0.0, -0.1), Vec3(0.1, 0.0, 0.0));
}

/// Every scalar provider under test, with a name for failure messages.
inline std::vector<std::pair<std::string, std::shared_ptr<const ScalarField>>> ScalarProviders()
{
  return { { "paper gaussian", PaperGaussian() }, { "anisotropic gaussian", AnisotropicGaussian() },
    { "paraboloid x2+y2+z2", Paraboloid(1.0) }, { "saddle x2+y2-z2", Paraboloid(-1.0) },
    { "sum", MixedSum() } };
}

/// Every map provider under test.
inline std::vector<std::pair<std::string, std::shared_ptr<const SpaceMap>>> MapProviders()
{
  return { { "twist", std::make_shared<TwistMap>(1.0) },
    { "twist rate 0.7", std::make_shared<TwistMap>(0.7) },
    { "bump direction",
      std::make_shared<BumpTranslationMap>(AnisotropicGaussian(), Vec3(0.2, 0.3, -0.1)) },
    { "bump field", LocalTwistBump() }, { "two-bump composition", TwoBumpComposition() },
    { "twist o bump",
      std::make_shared<MapComposition>(std::vector<std::shared_ptr<const SpaceMap>>{
        std::make_shared<TwistMap>(0.8), LocalTwistBump() }) } };
}

/// A tensor field that forwards to another metric's g and dg: lets the general
/// (tensor-family) path be compared with each specialised family.
class ForwardingTensorField : public TensorField
{
public:
  explicit ForwardingTensorField(std::shared_ptr<const Metric> metric)
    : Source(std::move(metric))
  {
  }
  void Evaluate(const Vec3& p, bool withDerivatives, Mat3& g, Mat3Stack& dg) const override
  {
    if (withDerivatives)
    {
      this->Source->TensorDerivatives(p, g, dg);
    }
    else
    {
      this->Source->Tensor(p, g);
    }
  }
  bool EvaluateSecond(
    const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const override
  {
    return this->Source->TensorSecondDerivatives(p, g, dg, d2g);
  }
  std::string Describe() const override { return "forwarded " + this->Source->Describe(); }

private:
  std::shared_ptr<const Metric> Source;
};

/// Every metric family with every provider.
inline std::vector<std::pair<std::string, std::shared_ptr<const Metric>>> Metrics()
{
  std::vector<std::pair<std::string, std::shared_ptr<const Metric>>> metrics;
  for (const auto& [name, field] : ScalarProviders())
  {
    metrics.emplace_back("graph of " + name, std::make_shared<GraphMetric>(field));
  }
  for (const auto& [name, map] : MapProviders())
  {
    metrics.emplace_back("diffeo " + name, std::make_shared<DiffeoMetric>(map));
  }
  // Conformal indices that stay positive on the test region.
  metrics.emplace_back("conformal 1 + gaussian",
    std::make_shared<ConformalMetric>(std::make_shared<ScalarFieldSum>(
      1.0, std::vector<std::shared_ptr<const ScalarField>>{ PaperGaussian() })));
  metrics.emplace_back("conformal 1 + sum",
    std::make_shared<ConformalMetric>(std::make_shared<ScalarFieldSum>(2.0,
      std::vector<std::shared_ptr<const ScalarField>>{ AnisotropicGaussian(), PaperGaussian() })));
  metrics.emplace_back("euclidean", std::make_shared<EuclideanMetric>());
  Mat3 constant;
  constant << 2.0, 0.3, 0.1, 0.3, 1.5, -0.2, 0.1, -0.2, 1.0;
  metrics.emplace_back("tensor constant",
    std::make_shared<TensorMetric>(std::make_shared<ConstantTensorField>(constant)));
  // Typed expressions, one per family.
  metrics.emplace_back(
    "graph of typed f", ParseMetricDefinition(R"json({"type": "graph", "parameters": {"a": 0.7},
      "f": "a*exp(-(x^2 + 2*y^2 + z^2)/2) + 0.2*sin(x)*cos(y + z) + 0.1*x^3"})json"));
  metrics.emplace_back("conformal typed n (round sphere)",
    ParseMetricDefinition(R"json({"type": "conformal", "n": "2/(1 + x^2 + y^2 + z^2)"})json"));
  metrics.emplace_back("diffeo typed phi",
    ParseMetricDefinition(R"json({"type": "diffeo", "phi": ["x + 0.3*exp(-(x^2+y^2+z^2))",
      "y + 0.2*sin(z)", "z + 0.1*tanh(x)"]})json"));
  metrics.emplace_back("tensor typed g (Nil)",
    ParseMetricDefinition(R"json({"type": "tensor", "g": [["1", "0", "0"], ["0", "1 + x^2", "-x"],
      ["0", "-x", "1"]]})json"));
  metrics.emplace_back("tensor forwarding graph",
    std::make_shared<TensorMetric>(
      std::make_shared<ForwardingTensorField>(std::make_shared<GraphMetric>(MixedSum()))));
  return metrics;
}
} // namespace testing
} // namespace riemann

#endif
