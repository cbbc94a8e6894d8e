/**
 * @file BenchFieldPoints.cxx
 * @brief What the field filters compute per point, points per second on
 * one core: the scalar path (ComputeCurvature, or Tensor + Eigen's
 * eigenvalues and LLT inverse, one point at a time, as the filters did)
 * against the packet path they use now (PacketCurvature.h: the curvature,
 * eigenvalues and inverse of PacketWidth points at once), in one run.
 *
 * Named BM_FieldPoints/<metric>_<field>_<scalar|packet>, <field> =
 * curvature or tensor; 32^3 points of [-2, 2]^3. Metrics: graph8 (the 8
 * Gaussian bumps of BenchGeodesicSteps.cxx, built-in providers), typed (the
 * paper's Gaussian bump as a typed expression, Data/metrics/
 * gaussian-bump-typed.json's formula) and diffeo (a typed map: no SIMD
 * provider, the lane-by-lane derivatives with the SIMD curvature algebra).
 * Counter items_per_second = points per second. Writing the file is not
 * included (riemann fields' wall time is in Testing/Benchmarks/README.md).
 */
#include "Curvature.h"
#include "EightBumps.h"
#include "MetricDefinition.h"
#include "PacketCurvature.h"

#include <benchmark/benchmark.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <memory>
#include <string>
#include <vector>

namespace
{
using riemann::Vec3;

constexpr int GridSide = 32;

std::shared_ptr<const riemann::Metric> FieldMetric(const std::string& name)
{
  if (name == "graph8")
  {
    return riemann::bench::GraphOfEightBumps();
  }
  if (name == "typed")
  {
    return riemann::ParseMetricDefinition(
      R"json({"type": "graph", "f": "exp(-(x^2 + y^2 + z^2) / 2)"})json");
  }
  return riemann::ParseMetricDefinition(R"json({"type": "diffeo", "phi": [
    "x + 0.3*exp(-(x^2+y^2+z^2))", "y + 0.2*sin(z)", "z + 0.1*tanh(x)"]})json");
}

std::vector<Vec3> GridPoints()
{
  std::vector<Vec3> points;
  for (int k = 0; k < GridSide; ++k)
  {
    for (int j = 0; j < GridSide; ++j)
    {
      for (int i = 0; i < GridSide; ++i)
      {
        const double step = 4.0 / (GridSide - 1);
        points.emplace_back(-2.0 + step * i, -2.0 + step * j, -2.0 + step * k);
      }
    }
  }
  return points;
}

/// The points in packets, as vtkRiemannForEachPointPacket hands them out.
template <class Work>
void ForEachPacket(const std::vector<Vec3>& points, const Work& work)
{
  riemann::PacketVec3 x;
  for (size_t start = 0; start < points.size(); start += riemann::PacketWidth)
  {
    for (int l = 0; l < riemann::PacketWidth; ++l)
    {
      x.SetLane(l, points[std::min(points.size() - 1, start + l)]);
    }
    work(x);
  }
}

void BM_FieldPoints(
  benchmark::State& state, const std::string& metricName, bool curvature, bool packet)
{
  const auto metric = FieldMetric(metricName);
  const std::vector<Vec3> points = GridPoints();
  double sum = 0.0;
  for (auto _ : state)
  {
    if (curvature && packet)
    {
      ForEachPacket(points,
        [&](const riemann::PacketVec3& x)
        {
          riemann::PacketCurvature c;
          riemann::ComputeCurvature(*metric, x, riemann::AllLanes, c);
          sum += c.Scalar[0] + c.SectionalMin[0];
        });
    }
    else if (curvature)
    {
      riemann::CurvatureSample sample;
      for (const Vec3& p : points)
      {
        riemann::ComputeCurvature(*metric, p, sample);
        sum += sample.Scalar + sample.SectionalMin;
      }
    }
    else if (packet)
    {
      ForEachPacket(points,
        [&](const riemann::PacketVec3& x)
        {
          riemann::PacketSym3 g, inverse;
          metric->TensorPacket(x, g, riemann::AllLanes);
          double lambda[3][riemann::PacketWidth];
          riemann::SymmetricEigenvalues(g, lambda);
          riemann::InverseTensor(g, inverse);
          sum += lambda[0][0] + inverse.C[riemann::XX][0];
        });
    }
    else
    {
      riemann::Mat3 g;
      for (const Vec3& p : points)
      {
        metric->Tensor(p, g);
        const Eigen::SelfAdjointEigenSolver<riemann::Mat3> eigen(g, Eigen::EigenvaluesOnly);
        const riemann::Mat3 inverse = Eigen::LLT<riemann::Mat3>(g).solve(riemann::Mat3::Identity());
        sum += eigen.eigenvalues()[0] + inverse(0, 0);
      }
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(points.size()));
}

#define RIEMANN_FIELD_BENCHMARK(name, metric, curvature, packet)                                   \
  BENCHMARK_CAPTURE(BM_FieldPoints, name, std::string(metric), curvature, packet)                  \
    ->Unit(benchmark::kMillisecond)

RIEMANN_FIELD_BENCHMARK(graph8_curvature_scalar, "graph8", true, false);
RIEMANN_FIELD_BENCHMARK(graph8_curvature_packet, "graph8", true, true);
RIEMANN_FIELD_BENCHMARK(typed_curvature_scalar, "typed", true, false);
RIEMANN_FIELD_BENCHMARK(typed_curvature_packet, "typed", true, true);
RIEMANN_FIELD_BENCHMARK(diffeo_curvature_scalar, "diffeo", true, false);
RIEMANN_FIELD_BENCHMARK(diffeo_curvature_packet, "diffeo", true, true);
RIEMANN_FIELD_BENCHMARK(graph8_tensor_scalar, "graph8", false, false);
RIEMANN_FIELD_BENCHMARK(graph8_tensor_packet, "graph8", false, true);
} // namespace
