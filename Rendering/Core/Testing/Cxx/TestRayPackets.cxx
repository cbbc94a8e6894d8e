// TraceRays (rays in the packet engine, AdvanceRayPacket) against TraceRay
// one ray at a time, on the paper's scenes: the same hits, termination
// reasons and step counts, and the same points to rounding; the packet's
// lanes end at different steps (rays that hit early, rays that escape).
#include "RiemannRay.h"
#include "RiemannScene.h"
#include "RiemannSceneParser.h"

#include "GeodesicTrace.h"
#include "MetricDefinition.h"

#include "TestDataDirectory.h"

#include <Eigen/Geometry> // cross
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace riemann
{
namespace
{
namespace fs = std::filesystem;

using riemann::testing::DataDirectory;

/// 11 x 9 unit-speed directions across the camera's view (99 rays: 12 full
/// packets and a partial one).
std::vector<Vec3> ViewDirections(const Scene& scene, const Metric& metric)
{
  const Vec3 eye = scene.Camera.Position;
  const Vec3 forward = (scene.Camera.LookAt - eye).normalized();
  const Vec3 right = forward.cross(scene.Camera.ViewUp).normalized();
  const Vec3 up = right.cross(forward);
  const double spread = std::tan(0.5 * scene.Camera.ViewAngle * std::acos(-1.0) / 180);
  std::vector<Vec3> directions;
  for (int i = -5; i <= 5; ++i)
  {
    for (int j = -4; j <= 4; ++j)
    {
      Vec3 v;
      EXPECT_TRUE(UnitSpeedVelocity(
        metric, eye, forward + spread * (0.2 * i * right + 0.25 * j * up), v));
      directions.push_back(v);
    }
  }
  return directions;
}

TEST(RayPackets, TraceRaysEqualsTraceRayOnThePaperScenes)
{
  for (const char* name : { "paper-grid", "paper-one-bump", "paper-two-bumps", "paper-twist",
         "paper-saddle-along-x" })
  {
    const Scene scene =
      LoadSceneFile((DataDirectory() / "scenes" / (std::string(name) + ".json")).string());
    const auto metric = ParseMetricDefinition(scene.MetricDefinition);
    const std::vector<Vec3> directions = ViewDirections(scene, *metric);
    for (IntegratorType type :
      { IntegratorType::RungeKutta4, IntegratorType::Euler, IntegratorType::DormandPrince45 })
    {
      SCOPED_TRACE(std::string(name) + ", " + IntegratorName(type));
      RaySettings settings = scene.Rays;
      settings.Integrator = type;
      std::vector<RayPath> packet(directions.size());
      TraceRays(*metric, scene, scene.Camera.Position, directions.data(),
        static_cast<int>(directions.size()), settings, packet.data());
      int hits = 0;
      for (size_t i = 0; i < directions.size(); ++i)
      {
        RayPath single;
        TraceRay(*metric, scene, scene.Camera.Position, directions[i], settings, single);
        SCOPED_TRACE("ray " + std::to_string(i));
        ASSERT_EQ(packet[i].Hit, single.Hit);
        ASSERT_EQ(packet[i].Reason, single.Reason);
        ASSERT_EQ(packet[i].Steps, single.Steps);
        ASSERT_EQ(packet[i].Points.size(), single.Points.size());
        for (size_t k = 0; k < single.Points.size(); ++k)
        {
          ASSERT_LT((packet[i].Points[k] - single.Points[k]).norm(), 1e-9) << "point " << k;
        }
        EXPECT_NEAR(packet[i].Length, single.Length, 1e-9);
        hits += single.Hit ? 1 : 0;
      }
      // Some rays hit the grid and some do not: lanes end apart.
      EXPECT_GT(hits, 0);
    }
  }
}
} // namespace
} // namespace riemann
