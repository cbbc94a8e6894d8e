// TractStops: tractography's stops and selection, with exact answers.
// - VoxelMask reads the voxel that holds a point (nearest centre) on a
//   rotated, anisotropic grid, and nothing beyond its outer faces;
// - a straight geodesic of flat space stops at its first point outside a
//   stop mask (StoppedByMask), every point before it inside, on both the
//   one-geodesic and the packet tracers;
// - the anisotropy threshold reads the FA of g^-1 (0.6 for diag(1, 4, 4)^-1
//   ... computed in closed form) and stops, or not, on either side of it;
// - CutAtSharpTurn keeps a circle of radius R (curvature 180/(pi R) degrees
//   per mm) under a larger limit and cuts it at its first step under a
//   smaller one; a straight part followed by a circle is cut where it bends;
// - SelectTract: exclude before include before length; lengths Euclidean.
#include "EuclideanMetric.h"
#include "GeodesicTrace.h"
#include "PacketTrace.h"
#include "TensorMetric.h"
#include "TractStops.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using riemann::Mat3;
using riemann::Vec3;

namespace
{
/// A 4 x 3 x 2 mask with spacing (1, 2, 0.5), rotated a quarter turn about z.
riemann::VoxelMask RotatedMask()
{
  riemann::VoxelMask mask;
  mask.Dimensions = { 4, 3, 2 };
  mask.Spacing = Vec3(1.0, 2.0, 0.5);
  mask.Origin = Vec3(10.0, 0.0, 0.0);
  mask.Direction << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  mask.Set.assign(24, 0);
  mask.Set[1 + 4 * (2 + 3 * 1)] = 1; // voxel (1, 2, 1)
  return mask;
}

/// Points (cos, sin) of a circle of radius r in mm, with unit tangents, every h mm.
riemann::GeodesicPath Circle(double r, double h, int n, const Vec3& start = Vec3::Zero())
{
  riemann::GeodesicPath path;
  for (int k = 0; k < n; ++k)
  {
    const double a = k * h / r;
    path.Points.push_back(start + Vec3(r * std::sin(a), r * (1.0 - std::cos(a)), 0.0));
    path.Velocities.push_back(Vec3(std::cos(a), std::sin(a), 0.0));
    path.ArcLength.push_back(k * h);
    path.SpeedDrift.push_back(0.0);
  }
  path.Reason = riemann::OutOfLength;
  return path;
}
} // namespace

TEST(TractStops, VoxelMaskReadsTheVoxelHoldingThePoint)
{
  const riemann::VoxelMask mask = RotatedMask();
  // Voxel (1, 2, 1): index axis i is world +y, j is world -x.
  const Vec3 centre = Vec3(10.0, 0.0, 0.0) + Vec3(-2.0 * 2.0, 1.0 * 1.0, 0.5 * 1.0);
  EXPECT_TRUE(mask.Contains(centre));
  EXPECT_TRUE(mask.Contains(centre + Vec3(0.99, 0.49, 0.24)));  // inside its box
  EXPECT_FALSE(mask.Contains(centre + Vec3(0.0, 0.51, 0.0)));  // voxel (2, 2, 1)
  EXPECT_FALSE(mask.Contains(centre + Vec3(-1.01, 0.0, 0.0))); // voxel (1, 3, 1): off the grid
  EXPECT_FALSE(mask.Contains(Vec3(NAN, 0.0, 0.0)));
  EXPECT_FALSE(riemann::VoxelMask().Contains(centre));
}

TEST(TractStops, AStraightGeodesicStopsAtTheMasksEdge)
{
  riemann::EuclideanMetric flat;
  riemann::TractStopRules rules(flat);
  // Voxels of 0.5 over x in [-1.25, 1.25), y and z in [-0.25, 0.25).
  rules.StopMask.Dimensions = { 5, 1, 1 };
  rules.StopMask.Spacing = Vec3(0.5, 0.5, 0.5);
  rules.StopMask.Origin = Vec3(-1.0, 0.0, 0.0);
  rules.StopMask.Set.assign(5, 1);
  riemann::GeodesicOptions options;
  options.Step = 0.01;
  options.MaximumLength = 5.0;
  options.Stop = &rules;
  riemann::GeodesicPath one;
  riemann::TraceGeodesic(flat, Vec3::Zero(), Vec3(1, 0, 0), options, one);
  std::vector<riemann::GeodesicPath> packet(2);
  const riemann::GeodesicSeed seeds[2] = { { Vec3::Zero(), Vec3(1, 0, 0), false },
    { Vec3::Zero(), Vec3(1, 0, 0), true } };
  riemann::TraceGeodesics(flat, seeds, 2, options, packet.data());
  for (const riemann::GeodesicPath* path : { &one, &packet[0], &packet[1] })
  {
    ASSERT_EQ(path->Reason, riemann::StoppedByMask);
    const std::size_t n = path->Points.size();
    EXPECT_NEAR(std::abs(path->Points[n - 1][0]), 1.25, 0.0101); // the first point beyond
    EXPECT_GE(std::abs(path->Points[n - 1][0]), 1.25);
    for (std::size_t k = 0; k + 1 < n; ++k)
    {
      EXPECT_TRUE(rules.StopMask.Contains(path->Points[k]));
    }
  }
  // A seed outside the mask makes no line.
  riemann::GeodesicPath outside;
  riemann::TraceGeodesic(flat, Vec3(2, 0, 0), Vec3(1, 0, 0), options, outside);
  EXPECT_EQ(outside.Reason, riemann::StoppedByMask);
  EXPECT_EQ(outside.Points.size(), 1u);
}

TEST(TractStops, AnisotropyThresholdReadsTheDiffusionTensorsFA)
{
  // g = diag(1, 4, 4) stands for D = g^-1 = diag(1, 1/4, 1/4): FA in closed form.
  Mat3 g = Mat3::Zero();
  g.diagonal() = Vec3(1.0, 4.0, 4.0);
  riemann::TensorMetric metric(std::make_shared<riemann::ConstantTensorField>(g));
  const Vec3 l(1.0, 0.25, 0.25);
  const double expected = std::sqrt(0.5) * std::sqrt(2.0 * 0.75 * 0.75) / l.norm();
  double fa = 0.0;
  ASSERT_TRUE(riemann::FractionalAnisotropyOfMetric(metric, Vec3::Zero(), fa));
  EXPECT_NEAR(fa, expected, 1e-12);
  EXPECT_NEAR(riemann::FractionalAnisotropy(Vec3(1.0, 0.0, 0.0)), 1.0, 1e-15);
  EXPECT_NEAR(riemann::FractionalAnisotropy(Vec3(2.0, 2.0, 2.0)), 0.0, 1e-15);
  riemann::TractStopRules rules(metric);
  rules.MinimumAnisotropy = expected - 1e-6;
  EXPECT_EQ(rules.ReasonToStop(Vec3::Zero()), 0);
  rules.MinimumAnisotropy = expected + 1e-6;
  EXPECT_EQ(rules.ReasonToStop(Vec3::Zero()), riemann::LowAnisotropy);
}

TEST(TractStops, SharpTurnsAreCutWhereTheCurvatureExceedsTheLimit)
{
  const double r = 2.0; // curvature 180 / (2 pi) = 28.6 degrees per mm
  const double curvature = 180.0 / (std::acos(-1.0) * r);
  riemann::GeodesicPath kept = Circle(r, 0.1, 50);
  EXPECT_FALSE(riemann::CutAtSharpTurn(kept, curvature * 1.01));
  EXPECT_EQ(kept.Points.size(), 50u);
  riemann::GeodesicPath cut = Circle(r, 0.1, 50);
  EXPECT_TRUE(riemann::CutAtSharpTurn(cut, curvature * 0.99));
  EXPECT_EQ(cut.Points.size(), 1u);
  EXPECT_EQ(cut.Reason, riemann::SharpTurn);
  // 21 straight points up to the origin, then the circle: cut at the origin.
  riemann::GeodesicPath bend;
  for (int k = 0; k <= 20; ++k)
  {
    bend.Points.push_back(Vec3(k * 0.1 - 2.0, 0.0, 0.0));
    bend.Velocities.push_back(Vec3(1, 0, 0));
  }
  const riemann::GeodesicPath arc = Circle(r, 0.1, 30, Vec3(0.0, 0.0, 0.0));
  bend.Points.insert(bend.Points.end(), arc.Points.begin() + 1, arc.Points.end());
  bend.Velocities.insert(bend.Velocities.end(), arc.Velocities.begin() + 1, arc.Velocities.end());
  EXPECT_TRUE(riemann::CutAtSharpTurn(bend, curvature * 0.9));
  EXPECT_EQ(bend.Points.size(), 21u);
  EXPECT_NEAR(bend.Points.back()[0], 0.0, 1e-12);
}

TEST(TractStops, SelectionExcludesThenIncludesThenMeasures)
{
  riemann::GeodesicPath a = Circle(1e6, 0.5, 11); // straight along x, 5 mm
  riemann::GeodesicPath b = Circle(1e6, 0.5, 5);  // 2 mm
  const riemann::GeodesicPath* both[2] = { &a, &b };
  riemann::TractSelection selection;
  EXPECT_EQ(riemann::SelectTract(both, 2, selection), riemann::TractKept);
  selection.MinimumLength = 7.01;
  EXPECT_EQ(riemann::SelectTract(both, 2, selection), riemann::TractTooShort);
  selection.MinimumLength = 6.99;
  EXPECT_EQ(riemann::SelectTract(both, 2, selection), riemann::TractKept);
  // One voxel around x = 3: a passes through it, b does not.
  riemann::VoxelMask region;
  region.Dimensions = { 1, 1, 1 };
  region.Origin = Vec3(3.0, 0.0, 0.0);
  region.Set = { 1 };
  selection.Include = region;
  EXPECT_EQ(riemann::SelectTract(both, 2, selection), riemann::TractKept);
  EXPECT_EQ(riemann::SelectTract(both + 1, 1, selection), riemann::TractMissedInclude);
  selection.Exclude = region;
  EXPECT_EQ(riemann::SelectTract(both, 2, selection), riemann::TractCrossedExclude);
  EXPECT_STREQ(riemann::TractRejectionName(riemann::TractCrossedExclude),
    "entered the exclude region");
}
