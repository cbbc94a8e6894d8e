// CameraPath: the frames of a flight through curved space, with exact answers.
// - flat space: a geodesic flight is a straight line at unit speed with a
//   constant frame; a spline through collinear keys is the same line;
// - a pulled-back flat metric (the twist, g = J^T J): the flight follows
//   Phi^-1 of a straight line and each transported vector is the pull-back
//   of a constant one, X(s) = J(x(s))^-1 J(x(0)) X(0), to 1e-8;
// - every frame of every flight (geodesic and spline, in the twist and in
//   the curved bump) is g-orthonormal to 1e-9 without re-orthonormalising,
//   which checks that the transport preserves g-inner products;
// - a spline flight looks along its tangent, and in the plane z = 0 of flat
//   space its up stays e_z: the horizon does not spin;
// - bad settings are refused, saying why.
#include "CameraPath.h"
#include "DiffeoMetric.h"
#include "EuclideanMetric.h"
#include "GaussianField.h"
#include "GraphMetric.h"
#include "TwistMap.h"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

using riemann::CameraFrame;
using riemann::CameraPathKind;
using riemann::CameraPathSettings;
using riemann::Mat3;
using riemann::Vec3;

namespace
{
/// The largest |g(e_i, e_j) - delta_ij| of a frame.
double OrthonormalityError(const riemann::Metric& metric, const CameraFrame& frame)
{
  Mat3 g;
  EXPECT_TRUE(metric.Tensor(frame.Position, g));
  Mat3 e;
  e << frame.Forward, frame.Up, frame.Right;
  return (e.transpose() * g * e - Mat3::Identity()).cwiseAbs().maxCoeff();
}

double LargestOrthonormalityError(
  const riemann::Metric& metric, const std::vector<CameraFrame>& frames)
{
  double largest = 0.0;
  for (const CameraFrame& frame : frames)
  {
    largest = std::max(largest, OrthonormalityError(metric, frame));
  }
  return largest;
}

CameraPathSettings GeodesicFlight(const Vec3& from, const Vec3& towards, double length)
{
  CameraPathSettings settings;
  settings.Start.Position = from;
  settings.Start.LookAt = towards;
  settings.Start.ViewUp = Vec3(0.0, 0.0, 1.0);
  settings.Length = length;
  settings.Frames = 25;
  return settings;
}

std::shared_ptr<riemann::GraphMetric> Bump()
{
  return std::make_shared<riemann::GraphMetric>(
    std::make_shared<riemann::GaussianField>(1.0, Vec3::Zero(), Vec3(0.5, 0.5, 0.5)));
}

std::string ErrorOf(const riemann::Metric& metric, const CameraPathSettings& settings)
{
  try
  {
    riemann::ComputeCameraPath(metric, settings);
  }
  catch (const riemann::CameraPathError& e)
  {
    return e.what();
  }
  return {};
}
} // namespace

TEST(CameraPath, AFlatGeodesicFlightIsAStraightLineWithAConstantFrame)
{
  riemann::EuclideanMetric flat;
  const auto frames =
    riemann::ComputeCameraPath(flat, GeodesicFlight(Vec3(0, 0, 0), Vec3(3, 4, 0), 10.0));
  ASSERT_EQ(frames.size(), 25u);
  for (size_t k = 0; k < frames.size(); ++k)
  {
    const double s = 10.0 * k / 24.0;
    EXPECT_NEAR(frames[k].ArcLength, s, 1e-12);
    EXPECT_LT((frames[k].Position - s * Vec3(0.6, 0.8, 0.0)).norm(), 1e-12);
    EXPECT_LT((frames[k].Forward - Vec3(0.6, 0.8, 0.0)).norm(), 1e-12);
    EXPECT_LT((frames[k].Up - Vec3(0.0, 0.0, 1.0)).norm(), 1e-12);
    EXPECT_LT((frames[k].Right - Vec3(0.8, -0.6, 0.0)).norm(), 1e-12);
  }
}

TEST(CameraPath, InAPulledBackFlatMetricTheFrameIsThePullBackOfAConstantFrame)
{
  const auto twist = std::make_shared<riemann::TwistMap>(1.0);
  riemann::DiffeoMetric metric(twist);
  CameraPathSettings settings = GeodesicFlight(Vec3(1.0, 0.0, -1.0), Vec3(1.3, 1.0, -0.5), 4.0);
  settings.Start.ViewUp = Vec3(0.2, -0.1, 1.0);
  const auto frames = riemann::ComputeCameraPath(metric, settings);
  ASSERT_EQ(frames.size(), 25u);

  const auto jacobian = [&twist](const Vec3& p) {
    riemann::VectorJet jet;
    twist->Evaluate(p, riemann::FirstDerivatives, jet);
    return Mat3(jet.Jacobian);
  };
  const Mat3 j0 = jacobian(frames[0].Position);
  double largest = 0.0;
  for (const CameraFrame& frame : frames)
  {
    // The position: Phi^-1 of the straight line Phi(x0) + s J(x0) v0.
    Vec3 exact;
    ASSERT_TRUE(metric.ExactGeodesic(frames[0].Position, frames[0].Forward, frame.ArcLength, exact));
    largest = std::max(largest, (frame.Position - exact).norm());
    // Each vector: J(x)^-1 J(x0) X0.
    const Mat3 pull = jacobian(frame.Position).inverse() * j0;
    largest = std::max(largest, (frame.Forward - pull * frames[0].Forward).norm());
    largest = std::max(largest, (frame.Up - pull * frames[0].Up).norm());
    largest = std::max(largest, (frame.Right - pull * frames[0].Right).norm());
  }
  EXPECT_LT(largest, 1e-8);
  EXPECT_LT(LargestOrthonormalityError(metric, frames), 1e-9);
}

TEST(CameraPath, FramesStayOrthonormalInGAlongEveryFlight)
{
  const auto bump = Bump();
  riemann::DiffeoMetric twist(std::make_shared<riemann::TwistMap>(1.0));
  CameraPathSettings spline;
  spline.Kind = CameraPathKind::Spline;
  spline.Keys = { Vec3(-2.0, -1.0, 0.3), Vec3(-0.5, 0.4, 0.1), Vec3(0.6, -0.3, -0.2),
    Vec3(2.0, 0.5, 0.4) };
  spline.Start.ViewUp = Vec3(0.0, 0.0, 1.0);
  spline.Frames = 40;
  for (const riemann::Metric* metric : { static_cast<const riemann::Metric*>(bump.get()),
         static_cast<const riemann::Metric*>(&twist) })
  {
    SCOPED_TRACE(metric->Describe());
    const auto geodesic =
      riemann::ComputeCameraPath(*metric, GeodesicFlight(Vec3(-2, -0.3, 0.1), Vec3(0, 0, 0), 4.0));
    EXPECT_LT(LargestOrthonormalityError(*metric, geodesic), 1e-9);
    const auto flight = riemann::ComputeCameraPath(*metric, spline);
    EXPECT_LT(LargestOrthonormalityError(*metric, flight), 1e-9);
    // It passes through the keys, first and last at the ends.
    EXPECT_LT((flight.front().Position - spline.Keys.front()).norm(), 1e-12);
    EXPECT_LT((flight.back().Position - spline.Keys.back()).norm(), 1e-6);
  }
}

TEST(CameraPath, ASplineFlightLooksAlongItsTangentAndItsHorizonDoesNotSpin)
{
  riemann::EuclideanMetric flat;
  CameraPathSettings settings;
  settings.Kind = CameraPathKind::Spline;
  settings.Keys = { Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(2, 0, 0), Vec3(3, -1, 0), Vec3(4, 0.5, 0) };
  settings.Start.ViewUp = Vec3(0.0, 0.0, 1.0);
  settings.Frames = 50;
  const auto frames = riemann::ComputeCameraPath(flat, settings);
  ASSERT_EQ(frames.size(), 50u);
  for (size_t k = 1; k < frames.size(); ++k)
  {
    // Forward is the unit tangent: the chord to the next frame leans on it.
    const Vec3 chord = (frames[k].Position - frames[k - 1].Position).normalized();
    EXPECT_GT(chord.dot(frames[k - 1].Forward), 0.95);
    EXPECT_NEAR(frames[k].Forward.z(), 0.0, 1e-12);
    // In the plane, up stays the plane's normal: no roll.
    EXPECT_LT((frames[k].Up - Vec3(0.0, 0.0, 1.0)).norm(), 1e-9);
  }
  // Collinear keys: a straight line, a geodesic, and a constant frame.
  settings.Keys = { Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5), Vec3(2, 2, 2) };
  settings.Start.ViewUp = Vec3(0, 0, 1);
  const auto line = riemann::ComputeCameraPath(flat, settings);
  EXPECT_NEAR(line.back().ArcLength, 2.0 * std::sqrt(3.0), 1e-9);
  for (const CameraFrame& frame : line)
  {
    EXPECT_LT((frame.Forward - line.front().Forward).norm(), 1e-9);
    EXPECT_LT((frame.Up - line.front().Up).norm(), 1e-9);
  }
}

TEST(CameraPath, BadSettingsAreRefusedSayingWhy)
{
  riemann::EuclideanMetric flat;
  CameraPathSettings spline;
  spline.Kind = CameraPathKind::Spline;
  spline.Keys = { Vec3(0, 0, 0) };
  EXPECT_NE(ErrorOf(flat, spline).find("at least 2 key positions"), std::string::npos);
  spline.Keys = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0) };
  EXPECT_NE(ErrorOf(flat, spline).find("key positions 2 and 3 coincide"), std::string::npos);
  CameraPathSettings geodesic = GeodesicFlight(Vec3(0, 0, 0), Vec3(1, 0, 0), 0.0);
  EXPECT_NE(ErrorOf(flat, geodesic).find("length must be positive"), std::string::npos);
  geodesic = GeodesicFlight(Vec3(0, 0, 0), Vec3(0, 0, 0), 1.0);
  EXPECT_NE(ErrorOf(flat, geodesic).find("first frame"), std::string::npos);
  geodesic = GeodesicFlight(Vec3(0, 0, 0), Vec3(1, 0, 0), 1.0);
  int calls = 0;
  try
  {
    riemann::ComputeCameraPath(flat, geodesic, [&calls](double) { return ++calls < 3; });
    ADD_FAILURE() << "a cancelled flight returned";
  }
  catch (const riemann::CameraPathError& e)
  {
    EXPECT_STREQ(e.what(), "cancelled");
    EXPECT_EQ(calls, 3);
  }
}
