// Tests of the packet curvature and tensor kernels (PacketCurvature.h):
// - every family's packet curvature against the scalar ComputeCurvature,
//   lane by lane, with masked-out and degenerate lanes;
// - exact answers: constant curvature +1 (round sphere) and -1 (Poincare
//   ball): S = 6K, every sectional curvature K, |Rm| = sqrt(12) |K|;
// - the Jacobi eigenvalue sweeps and the Cholesky inverse against Eigen,
//   including repeated eigenvalues and matrices that are not positive
//   definite.
#include "MetricTestUtilities.h"

#include "Curvature.h"
#include "PacketCurvature.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace riemann
{
namespace
{
using testing::Metrics;
using testing::RandomPoints;

PacketVec3 PacketOf(const std::vector<Vec3>& points, size_t start)
{
  PacketVec3 p;
  for (int l = 0; l < PacketWidth; ++l)
  {
    p.SetLane(l, points[std::min(points.size() - 1, start + l)]);
  }
  return p;
}

TEST(PacketCurvature, EveryFamilyEqualsTheScalarCurvature)
{
  auto metrics = Metrics();
  metrics.emplace_back("graph of 2 bumps",
    std::make_shared<GraphMetric>(std::make_shared<ScalarFieldSum>(0.2,
      std::vector<std::shared_ptr<const ScalarField>>{
        std::make_shared<GaussianField>(0.9, Vec3(0.2, -0.1, 0.3), Vec3(0.6, 0.5, 0.7)),
        std::make_shared<GaussianField>(-0.6, Vec3(-0.5, 0.4, -0.2), Vec3(0.4, 0.7, 0.5)) })));
  metrics.emplace_back("Poincare ball (degenerate outside the unit ball)",
    ParseMetricDefinition(R"json({"type": "conformal", "n": "2 / (1 - x^2 - y^2 - z^2)"})json"));
  const auto points = RandomPoints(3 * PacketWidth, 1.1, 61);
  // Lane 3 is never asked for.
  const LaneMask lanes = AllLanes & ~(LaneMask{ 1 } << 3);
  for (const auto& [name, metric] : metrics)
  {
    SCOPED_TRACE(name);
    int compared = 0;
    for (size_t start = 0; start < points.size(); start += PacketWidth)
    {
      PacketCurvature packet;
      const LaneMask defined = ComputeCurvature(*metric, PacketOf(points, start), lanes, packet);
      for (int l = 0; l < PacketWidth; ++l)
      {
        if (!HasLane(lanes, l))
        {
          EXPECT_FALSE(HasLane(defined, l));
          continue;
        }
        CurvatureSample scalar;
        const bool expected = ComputeCurvature(*metric, points[start + l], scalar);
        ASSERT_EQ(HasLane(defined, l), expected) << "point " << points[start + l].transpose();
        if (!expected)
        {
          continue;
        }
        ++compared;
        // Relative to the size of the curvature at the point.
        const double scale = 1e-9 * std::max(1.0, scalar.RiemannNorm);
        EXPECT_NEAR(packet.Scalar[l], scalar.Scalar, scale);
        EXPECT_LT((packet.Ricci.Lane(l) - scalar.Ricci).cwiseAbs().maxCoeff(), scale);
        EXPECT_NEAR(packet.SectionalXY[l], scalar.SectionalXY, scale);
        EXPECT_NEAR(packet.SectionalXZ[l], scalar.SectionalXZ, scale);
        EXPECT_NEAR(packet.SectionalYZ[l], scalar.SectionalYZ, scale);
        EXPECT_NEAR(packet.SectionalMin[l], scalar.SectionalMin, scale);
        EXPECT_NEAR(packet.SectionalMax[l], scalar.SectionalMax, scale);
        EXPECT_NEAR(packet.RiemannNorm[l], scalar.RiemannNorm, scale);
        EXPECT_NEAR(packet.VolumeForm[l], scalar.VolumeForm, 1e-12 * scalar.VolumeForm);
      }
    }
    EXPECT_GT(compared, 0);
  }
}

TEST(PacketCurvature, ConstantCurvatureSpacesAreExact)
{
  const auto sphere =
    ParseMetricDefinition(R"json({"type": "conformal", "n": "2/(1 + x^2 + y^2 + z^2)"})json");
  const auto ball =
    ParseMetricDefinition(R"json({"type": "conformal", "n": "2 / (1 - x^2 - y^2 - z^2)"})json");
  for (const auto& [metric, k, radius] :
    { std::make_tuple(sphere, 1.0, 2.0), std::make_tuple(ball, -1.0, 0.55) })
  {
    const auto points = RandomPoints(2 * PacketWidth, radius, 62);
    for (size_t start = 0; start < points.size(); start += PacketWidth)
    {
      PacketCurvature c;
      ASSERT_EQ(ComputeCurvature(*metric, PacketOf(points, start), AllLanes, c), AllLanes);
      for (int l = 0; l < PacketWidth; ++l)
      {
        EXPECT_NEAR(c.Scalar[l], 6.0 * k, 1e-9);
        EXPECT_NEAR(c.SectionalXY[l], k, 1e-9);
        EXPECT_NEAR(c.SectionalXZ[l], k, 1e-9);
        EXPECT_NEAR(c.SectionalYZ[l], k, 1e-9);
        EXPECT_NEAR(c.SectionalMin[l], k, 1e-9);
        EXPECT_NEAR(c.SectionalMax[l], k, 1e-9);
        EXPECT_NEAR(c.RiemannNorm[l], std::sqrt(12.0), 1e-9);
        // Ric = 2 K g, g = n^2 I.
        const double n2 = std::pow(c.VolumeForm[l], 2.0 / 3.0);
        EXPECT_NEAR(c.Ricci.C[XX][l], 2.0 * k * n2, 1e-9 * n2);
        EXPECT_NEAR(c.Ricci.C[XY][l], 0.0, 1e-9 * n2);
      }
    }
  }
}

TEST(PacketCurvature, EigenvaluesAndInverseEqualEigen)
{
  std::mt19937 generator(63);
  std::uniform_real_distribution<double> uniform(-2.0, 2.0);
  std::vector<Mat3> matrices;
  // Repeated eigenvalues, diagonal, and a large spread.
  matrices.push_back(Mat3::Identity());
  matrices.push_back(Vec3(1.0, 1.0, 2.0).asDiagonal());
  Mat3 rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  matrices.push_back(rotation * Vec3(3.0, 3.0, -1.0).asDiagonal() * rotation.transpose());
  matrices.push_back(rotation * Vec3(1e3, 1.0, 1e-3).asDiagonal() * rotation.transpose());
  while (matrices.size() < 4 * PacketWidth)
  {
    Mat3 a;
    for (int i = 0; i < 9; ++i)
    {
      a.data()[i] = uniform(generator);
    }
    matrices.push_back(a + a.transpose());
  }
  for (size_t start = 0; start < matrices.size(); start += PacketWidth)
  {
    PacketSym3 packet;
    for (int l = 0; l < PacketWidth; ++l)
    {
      packet.SetLane(l, matrices[start + l]);
    }
    double eigenvalues[3][PacketWidth];
    SymmetricEigenvalues(packet, eigenvalues);
    PacketSym3 inverse;
    const LaneMask invertible = InverseTensor(packet, inverse);
    for (int l = 0; l < PacketWidth; ++l)
    {
      const Mat3& a = matrices[start + l];
      const Eigen::SelfAdjointEigenSolver<Mat3> eigen(a, Eigen::EigenvaluesOnly);
      const double scale = a.cwiseAbs().maxCoeff();
      for (int i = 0; i < 3; ++i)
      {
        EXPECT_NEAR(eigenvalues[i][l], eigen.eigenvalues()[i], 1e-14 * scale) << a;
      }
      const bool positive = eigen.eigenvalues()[0] > 0.0;
      ASSERT_EQ(HasLane(invertible, l), positive) << a;
      if (positive)
      {
        // As the scalar path computes it (Eigen::LLT), to rounding times
        // the condition number (1e6 at most here).
        const Mat3 expected = Eigen::LLT<Mat3>(a).solve(Mat3::Identity());
        EXPECT_LT(
          (inverse.Lane(l) - expected).cwiseAbs().maxCoeff(), 1e-9 * expected.cwiseAbs().maxCoeff())
          << a;
      }
      else
      {
        EXPECT_TRUE(std::isnan(inverse.C[XX][l]));
      }
    }
  }
}
} // namespace
} // namespace riemann
