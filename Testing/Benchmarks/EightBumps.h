/**
 * @file EightBumps.h
 * @brief The benchmarks' 8 Gaussian bumps (BenchGeodesicSteps.cxx's
 * workload, also used by BenchJacobiSteps.cxx and BenchFieldPoints.cxx) and
 * the graph metric of their sum, built from the library's providers.
 *
 * Amplitudes 0.3-1, centers in [-1.5, 1.5]^3, sigmas 0.4-0.8; half of them
 * anisotropic, so the Hessians have off-diagonal structure along geodesics.
 */
#ifndef RiemannBenchmarksEightBumps_h
#define RiemannBenchmarksEightBumps_h

#include "GaussianField.h"
#include "GraphMetric.h"
#include "ScalarFieldSum.h"

#include <memory>
#include <vector>

namespace riemann
{
namespace bench
{
constexpr int BumpCount = 8;

struct Bump
{
  double Amplitude;
  double Center[3];
  double Sigma[3];
};

constexpr Bump Bumps[BumpCount] = {
  { 1.00, { -1.0, -1.0, -0.5 }, { 0.60, 0.60, 0.60 } },
  { 0.70, { 1.2, -0.8, 0.4 }, { 0.50, 0.80, 0.50 } },
  { 0.45, { -0.3, 1.1, 1.0 }, { 0.40, 0.40, 0.70 } },
  { 0.90, { 0.6, 0.5, -1.2 }, { 0.70, 0.50, 0.60 } },
  { 0.30, { -1.4, 0.3, 0.8 }, { 0.80, 0.80, 0.80 } },
  { 0.60, { 1.5, 1.4, 1.3 }, { 0.45, 0.60, 0.75 } },
  { 0.80, { 0.0, -1.5, 1.5 }, { 0.50, 0.50, 0.50 } },
  { 0.55, { 0.2, 0.1, 0.0 }, { 0.80, 0.40, 0.60 } },
};

/// The graph metric of the sum of the bumps (built-in providers).
inline std::shared_ptr<const GraphMetric> GraphOfEightBumps()
{
  std::vector<std::shared_ptr<const ScalarField>> terms;
  for (const Bump& bump : Bumps)
  {
    terms.push_back(std::make_shared<GaussianField>(bump.Amplitude,
      Vec3(bump.Center[0], bump.Center[1], bump.Center[2]),
      Vec3(bump.Sigma[0], bump.Sigma[1], bump.Sigma[2])));
  }
  return std::make_shared<GraphMetric>(std::make_shared<ScalarFieldSum>(0.0, std::move(terms)));
}
} // namespace bench
} // namespace riemann

#endif
