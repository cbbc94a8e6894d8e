// Tests of vtkRiemannGeodesicTracer (the VTK layer over riemann::TraceGeodesic).
//
// Reference answers are independent of the library wherever possible:
// - twist metric (flat): every geodesic is Phi^-1(Phi(p) + s J(p) v) with
//   v = d / |d|_g (MATH.md, Family 2); Phi, Phi^-1 and J are written out here;
// - Euclidean: straight lines p + s d/|d|;
// - conformal n = 1 + a exp(-|x|^2 / (2 s^2)): a radial ray stays on its line
//   with arc length s(x) = int n dx (closed form with erf), and every ray keeps
//   the angular momentum n^2 (x × v) (the rotations are Killing fields);
// - the parallel filter against a serial loop over the core's TraceGeodesic.
#include "vtkRiemannDirectionGrid.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannGeodesicTracer.h"
#include "vtkRiemannMetric.h"

#include "GeodesicTrace.h"
#include "MetricDefinition.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace
{
using V3 = std::array<double, 3>;

constexpr const char* TwistJson = R"({"type": "diffeo", "preset": "twist", "rate": 1})";
constexpr const char* EuclideanJson = R"({"type": "euclidean"})";
// A copy of Data/metrics/eight-gaussians.json (the benchmark metric), inline
// so that these tests do not depend on the data folder.
constexpr const char* EightGaussiansJson = R"({"type": "graph", "gaussians": [
  {"amplitude": 0.9, "center": [-1.2, -0.8, 0.3], "sigma": [0.5, 0.5, 0.5]},
  {"amplitude": 0.6, "center": [0.7, 1.1, -0.4], "sigma": [0.4, 0.6, 0.5]},
  {"amplitude": -0.5, "center": [1.3, -0.9, 0.8], "sigma": 0.6},
  {"amplitude": 0.8, "center": [-0.3, 0.2, -1.2], "sigma": [0.7, 0.4, 0.6]},
  {"amplitude": 0.4, "center": [0.1, -1.4, -0.2], "sigma": 0.5},
  {"amplitude": -0.7, "center": [-1.1, 1.0, 1.1], "sigma": [0.6, 0.8, 0.4]},
  {"amplitude": 1.0, "center": [1.4, 0.4, 0.1], "sigma": 0.45},
  {"amplitude": 0.3, "center": [0.0, 0.0, 1.4], "sigma": [0.8, 0.8, 0.5]}]})";
// Refractive index n = 1 + A exp(-|x|^2 / (2 S^2)) (a converging lens).
constexpr double LensAmplitude = 0.5;
constexpr double LensSigma = 0.6;
constexpr const char* LensJson = R"({"type": "conformal", "constant": 1,
  "gaussians": [{"amplitude": 0.5, "center": [0, 0, 0], "sigma": 0.6}]})";

// ---- small vector helpers ---------------------------------------------------
V3 Add(const V3& a, const V3& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
V3 Sub(const V3& a, const V3& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
V3 Scale(double s, const V3& a)
{
  return { s * a[0], s * a[1], s * a[2] };
}
double Dot(const V3& a, const V3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double Norm(const V3& a)
{
  return std::sqrt(Dot(a, a));
}
V3 Cross(const V3& a, const V3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double Distance(const V3& a, const V3& b)
{
  return Norm(Sub(a, b));
}
V3 MatVec(const double m[9], const V3& v)
{
  return { m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
    m[6] * v[0] + m[7] * v[1] + m[8] * v[2] };
}

// ---- the twist, written out independently of the library --------------------
V3 TwistPhi(const V3& p)
{
  const double c = std::cos(p[2]), s = std::sin(p[2]);
  return { c * p[0] - s * p[1], s * p[0] + c * p[1], p[2] };
}

V3 TwistPhiInverse(const V3& q)
{
  const double c = std::cos(q[2]), s = std::sin(q[2]);
  return { c * q[0] + s * q[1], -s * q[0] + c * q[1], q[2] };
}

/// J = dPhi/dx at p, row-major.
std::array<double, 9> TwistJacobian(const V3& p)
{
  const double c = std::cos(p[2]), s = std::sin(p[2]);
  return { c, -s, -s * p[0] - c * p[1], s, c, c * p[0] - s * p[1], 0.0, 0.0, 1.0 };
}

/// v = d / sqrt(d^T J^T J d): the unit-speed velocity of the twist metric.
V3 TwistUnitVelocity(const V3& p, const V3& d)
{
  const auto j = TwistJacobian(p);
  return Scale(1.0 / Norm(MatVec(j.data(), d)), d);
}

/// The exact geodesic of the twist metric from p, direction d, at arc length s.
V3 TwistExact(const V3& p, const V3& d, double s)
{
  const auto j = TwistJacobian(p);
  return TwistPhiInverse(Add(TwistPhi(p), Scale(s, MatVec(j.data(), TwistUnitVelocity(p, d)))));
}

// ---- pipeline helpers ------------------------------------------------------------
vtkSmartPointer<vtkRiemannMetric> MakeMetric(const char* json)
{
  auto metric = vtkSmartPointer<vtkRiemannMetric>::New();
  EXPECT_TRUE(metric->SetDefinition(json)) << metric->GetLastError();
  return metric;
}

/// Seeds as the tracer takes them: points with a point-data "Direction".
vtkSmartPointer<vtkPolyData> MakeSeeds(
  const std::vector<V3>& points, const std::vector<V3>& directions)
{
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> dirs;
  dirs->SetName("Direction");
  dirs->SetNumberOfComponents(3);
  for (size_t i = 0; i < points.size(); ++i)
  {
    pts->InsertNextPoint(points[i].data());
    dirs->InsertNextTuple(directions[i].data());
  }
  auto seeds = vtkSmartPointer<vtkPolyData>::New();
  seeds->SetPoints(pts);
  seeds->GetPointData()->AddArray(dirs);
  return seeds;
}

/// Random seeds in [-r, r]^3 with random nonzero directions.
void RandomSeeds(int count, double r, unsigned seed, std::vector<V3>& points, std::vector<V3>& dirs)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> position(-r, r), direction(-1.0, 1.0);
  points.clear();
  dirs.clear();
  for (int i = 0; i < count; ++i)
  {
    points.push_back({ position(generator), position(generator), position(generator) });
    V3 d;
    do
    {
      d = { direction(generator), direction(generator), direction(generator) };
    } while (Norm(d) < 0.1);
    dirs.push_back(d);
  }
}

/// Records the error and warning messages of an object (observing them also
/// keeps them off the output window, so expected messages do not clutter the log).
struct MessageLog
{
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
  vtkNew<vtkCallbackCommand> Callback;

  explicit MessageLog(vtkObject* object)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback(
      [](vtkObject*, unsigned long event, void* clientData, void* callData)
      {
        auto* self = static_cast<MessageLog*>(clientData);
        const std::string text = callData ? static_cast<const char*>(callData) : "";
        (event == vtkCommand::ErrorEvent ? self->Errors : self->Warnings).push_back(text);
      });
    object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
    object->AddObserver(vtkCommand::WarningEvent, this->Callback);
  }
};

/// One output polyline as plain vectors.
struct Line
{
  std::vector<V3> Points;
  std::vector<V3> Velocities;
  std::vector<double> ArcLength;
  std::vector<double> SpeedDrift;
  int SeedId = -1;
  int Reason = -1;
};

/// The output's lines, checking on the way that every array is there with the
/// right name, size and number of components.
std::vector<Line> Lines(vtkPolyData* output)
{
  std::vector<Line> lines;
  vtkDataArray* arc = output->GetPointData()->GetArray("ArcLength");
  vtkDataArray* velocity = output->GetPointData()->GetArray("Velocity");
  vtkDataArray* drift = output->GetPointData()->GetArray("SpeedDrift");
  vtkDataArray* seedIds = output->GetCellData()->GetArray("SeedIds");
  vtkDataArray* reasons = output->GetCellData()->GetArray("ReasonForTermination");
  const bool complete = arc && velocity && drift && seedIds && reasons;
  EXPECT_TRUE(complete) << "missing output arrays";
  if (!complete)
  {
    return lines;
  }
  const vtkIdType np = output->GetNumberOfPoints();
  const vtkIdType nl = output->GetNumberOfLines();
  EXPECT_EQ(arc->GetNumberOfTuples(), np);
  EXPECT_EQ(arc->GetNumberOfComponents(), 1);
  EXPECT_EQ(velocity->GetNumberOfTuples(), np);
  EXPECT_EQ(velocity->GetNumberOfComponents(), 3);
  EXPECT_EQ(drift->GetNumberOfTuples(), np);
  EXPECT_EQ(seedIds->GetNumberOfTuples(), nl);
  EXPECT_EQ(reasons->GetNumberOfTuples(), nl);
  EXPECT_EQ(output->GetNumberOfCells(), nl) << "only polylines expected";
  vtkCellArray* cells = output->GetLines();
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < nl; ++c)
  {
    cells->GetCellAtId(c, ids);
    Line line;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      const vtkIdType id = ids->GetId(k);
      V3 p, v;
      output->GetPoint(id, p.data());
      velocity->GetTuple(id, v.data());
      line.Points.push_back(p);
      line.Velocities.push_back(v);
      line.ArcLength.push_back(arc->GetComponent(id, 0));
      line.SpeedDrift.push_back(drift->GetComponent(id, 0));
    }
    line.SeedId = static_cast<int>(seedIds->GetComponent(c, 0));
    line.Reason = static_cast<int>(reasons->GetComponent(c, 0));
    lines.push_back(std::move(line));
  }
  return lines;
}

double MaxAbsDrift(const Line& line)
{
  double m = 0.0;
  for (double d : line.SpeedDrift)
  {
    m = std::max(m, std::abs(d));
  }
  return m;
}

double SpeedSquared(vtkRiemannMetric* metric, const V3& p, const V3& v)
{
  double g[9];
  EXPECT_TRUE(metric->EvaluateMetricTensor(p.data(), g));
  return Dot(v, MatVec(g, v));
}

std::vector<V3> TwistSeedPoints()
{
  return { { 1.0, 0.0, -1.0 }, { 0.3, -0.7, 0.2 }, { -1.2, 0.5, 0.9 }, { 0.0, 0.0, 0.0 },
    { 0.8, 1.1, -0.4 }, { -0.5, -0.5, 1.5 } };
}

std::vector<V3> TwistSeedDirections()
{
  // Deliberately not unit vectors (neither in R^3 nor in g).
  return { { 0.3, 1.0, 0.5 }, { 1.0, 0.0, 0.0 }, { 0.0, 0.0, 2.0 }, { -0.4, 0.7, -0.2 },
    { 0.5, -0.5, 0.9 }, { 3.0, 1.0, -1.0 } };
}

// ---- tests -----------------------------------------------------------------------

TEST(GeodesicTracer, TwistMatchesExactGeodesics)
{
  const auto points = TwistSeedPoints();
  const auto dirs = TwistSeedDirections();
  auto metric = MakeMetric(TwistJson);
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  MessageLog log(tracer);
  tracer->SetMetric(metric);
  tracer->SetInputData(MakeSeeds(points, dirs));
  tracer->GetIntegrationSettings()->SetIntegratorTypeToRungeKutta4();
  tracer->GetIntegrationSettings()->SetInitialIntegrationStep(0.01);
  tracer->GetIntegrationSettings()->SetMaximumPropagation(3.0);
  tracer->Update();
  EXPECT_TRUE(log.Errors.empty() && log.Warnings.empty());

  const auto lines = Lines(tracer->GetOutput());
  ASSERT_EQ(lines.size(), points.size());
  for (size_t c = 0; c < lines.size(); ++c)
  {
    SCOPED_TRACE("seed " + std::to_string(c));
    const Line& line = lines[c];
    EXPECT_EQ(line.SeedId, static_cast<int>(c));
    EXPECT_EQ(line.Reason, vtkRiemannGeodesicTracer::OUT_OF_LENGTH);
    // 300 RK4 steps of 0.01 (plus at most a rounding sliver).
    EXPECT_GE(line.Points.size(), 301u);
    EXPECT_LE(line.Points.size(), 302u);
    EXPECT_EQ(line.Points.front(), points[c]);
    EXPECT_EQ(line.ArcLength.front(), 0.0);
    EXPECT_NEAR(line.ArcLength.back(), 3.0, 1e-12);
    for (size_t k = 1; k < line.ArcLength.size(); ++k)
    {
      ASSERT_GT(line.ArcLength[k], line.ArcLength[k - 1]);
    }
    // Every sample lies on the exact geodesic at its own arc length.
    double worst = 0.0;
    for (size_t k = 0; k < line.Points.size(); ++k)
    {
      worst = std::max(
        worst, Distance(line.Points[k], TwistExact(points[c], dirs[c], line.ArcLength[k])));
    }
    EXPECT_LT(Distance(line.Points.back(), TwistExact(points[c], dirs[c], 3.0)), 1e-8);
    EXPECT_LT(worst, 1e-8);
    // Velocity at the seed: the direction scaled to unit speed in g.
    EXPECT_NEAR(SpeedSquared(metric, points[c], line.Velocities.front()), 1.0, 1e-12);
    EXPECT_LT(Distance(line.Velocities.front(), TwistUnitVelocity(points[c], dirs[c])), 1e-12);
    // ... and unit speed all along (the velocity is dx/ds).
    EXPECT_NEAR(SpeedSquared(metric, line.Points.back(), line.Velocities.back()), 1.0, 1e-9);
    EXPECT_EQ(line.SpeedDrift.front(), 0.0);
    EXPECT_LT(MaxAbsDrift(line), 1e-9);
  }
}

TEST(GeodesicTracer, StartPositionWithoutInput)
{
  const V3 p{ 0.4, -0.3, 0.6 };
  const V3 d{ 0.2, 0.9, -0.4 };
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(MakeMetric(TwistJson));
  tracer->SetStartPosition(p.data());
  tracer->SetStartDirection(d.data());
  tracer->GetIntegrationSettings()->SetMaximumPropagation(2.0);
  tracer->Update();
  const auto lines = Lines(tracer->GetOutput());
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].SeedId, 0);
  EXPECT_EQ(lines[0].Points.front(), p);
  EXPECT_NEAR(lines[0].ArcLength.back(), 2.0, 1e-12);
  EXPECT_LT(Distance(lines[0].Points.back(), TwistExact(p, d, 2.0)), 1e-8);
}

// Without an input, NumberOfDirections > 1 fans the seed over the cone that
// vtkRiemannDirectionGrid spreads around StartDirection: each geodesic is the
// twist's exact one along its direction of the grid, in the grid's order.
TEST(GeodesicTracer, FanOverTheConeWithoutInput)
{
  const V3 p{ 0.3, -0.2, 0.1 };
  const V3 axis{ 0.3, 1.0, -0.2 };
  constexpr int Count = 9;
  constexpr double Angle = 30.0;
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(MakeMetric(TwistJson));
  tracer->SetStartPosition(p.data());
  tracer->SetStartDirection(axis.data());
  tracer->SetNumberOfDirections(Count);
  tracer->SetConeAngle(Angle);
  tracer->GetIntegrationSettings()->SetMaximumPropagation(1.5);
  tracer->Update();
  vtkNew<vtkRiemannDirectionGrid> grid;
  grid->SetNumberOfDirections(Count);
  grid->SetConeAxis(axis.data());
  grid->SetConeAngle(Angle);
  grid->Update();
  ASSERT_EQ(grid->GetOutput()->GetNumberOfPoints(), Count);
  const auto lines = Lines(tracer->GetOutput());
  ASSERT_EQ(lines.size(), static_cast<std::size_t>(Count));
  const V3 unitAxis = Scale(1.0 / Norm(axis), axis);
  for (int i = 0; i < Count; ++i)
  {
    V3 d;
    grid->GetOutput()->GetPoint(i, d.data());
    // The grid's directions are in the cone, so the fan's are.
    EXPECT_GE(Dot(d, unitAxis) / Norm(d), std::cos(Angle * M_PI / 180.0) - 1e-6);
    EXPECT_EQ(lines[i].SeedId, i);
    EXPECT_EQ(lines[i].Points.front(), p);
    EXPECT_NEAR(lines[i].ArcLength.back(), 1.5, 1e-12);
    // vtkPoints are float: the grid's directions to about 1e-7.
    EXPECT_LT(Distance(lines[i].Points.back(), TwistExact(p, d, 1.5)), 1e-5) << "direction " << i;
  }

  // One direction is StartDirection itself; an input's seeds ignore the fan.
  tracer->SetNumberOfDirections(1);
  tracer->Update();
  const auto one = Lines(tracer->GetOutput());
  ASSERT_EQ(one.size(), 1u);
  EXPECT_LT(Distance(one[0].Points.back(), TwistExact(p, axis, 1.5)), 1e-8);
  tracer->SetNumberOfDirections(Count);
  const auto seeds = MakeSeeds(TwistSeedPoints(), TwistSeedDirections());
  tracer->SetInputData(seeds);
  tracer->Update();
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfLines(), seeds->GetNumberOfPoints());

  // A fan needs an axis: a zero StartDirection is an error and empty output.
  tracer->SetInputData(nullptr);
  tracer->SetStartDirection(0.0, 0.0, 0.0);
  MessageLog log(tracer);
  tracer->Update();
  ASSERT_EQ(log.Errors.size(), 1u);
  EXPECT_NE(log.Errors[0].find("no axis"), std::string::npos) << log.Errors[0];
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(GeodesicTracer, BothDirections)
{
  const auto points = TwistSeedPoints();
  const auto dirs = TwistSeedDirections();
  const double length = 3.0;
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(MakeMetric(TwistJson));
  tracer->SetInputData(MakeSeeds(points, dirs));
  tracer->GetIntegrationSettings()->SetMaximumPropagation(length);
  tracer->SetIntegrationDirectionToBoth();
  tracer->Update();

  const auto lines = Lines(tracer->GetOutput());
  ASSERT_EQ(lines.size(), 2 * points.size());
  std::vector<int> forward(points.size(), 0), backward(points.size(), 0);
  for (const Line& line : lines)
  {
    ASSERT_GE(line.SeedId, 0);
    ASSERT_LT(line.SeedId, static_cast<int>(points.size()));
    SCOPED_TRACE("seed " + std::to_string(line.SeedId));
    const V3& p = points[line.SeedId];
    const V3& d = dirs[line.SeedId];
    EXPECT_EQ(line.Reason, vtkRiemannGeodesicTracer::OUT_OF_LENGTH);
    EXPECT_EQ(line.Points.front(), p);
    const bool isBackward = line.ArcLength.back() < 0;
    ++(isBackward ? backward : forward)[line.SeedId];
    const double sign = isBackward ? -1.0 : 1.0;
    EXPECT_NEAR(line.ArcLength.back(), sign * length, 1e-12);
    for (size_t k = 1; k < line.ArcLength.size(); ++k)
    {
      ASSERT_GT(sign * (line.ArcLength[k] - line.ArcLength[k - 1]), 0.0);
    }
    EXPECT_LT(Distance(line.Points.back(), TwistExact(p, d, sign * length)), 1e-8);
    EXPECT_LT(Distance(line.Points[line.Points.size() / 2],
                TwistExact(p, d, line.ArcLength[line.Points.size() / 2])),
      1e-8);
    EXPECT_LT(MaxAbsDrift(line), 1e-9);
    // Velocity is dx/ds for the signed arc length s, on either side:
    // the same unit vector at the seed, and the slope of the samples.
    EXPECT_LT(Distance(line.Velocities.front(), TwistUnitVelocity(p, d)), 1e-12);
    double worstSlope = 0.0;
    for (size_t k = 1; k + 1 < line.Points.size(); ++k)
    {
      const V3 slope = Scale(1.0 / (line.ArcLength[k + 1] - line.ArcLength[k - 1]),
        Sub(line.Points[k + 1], line.Points[k - 1]));
      worstSlope = std::max(worstSlope, Distance(slope, line.Velocities[k]));
    }
    EXPECT_LT(worstSlope, 1e-3);
  }
  for (size_t i = 0; i < points.size(); ++i)
  {
    EXPECT_EQ(forward[i], 1) << "seed " << i;
    EXPECT_EQ(backward[i], 1) << "seed " << i;
  }

  // BACKWARD alone: one line per seed, the same as BOTH's backward lines.
  tracer->SetIntegrationDirectionToBackward();
  tracer->Update();
  const auto back = Lines(tracer->GetOutput());
  ASSERT_EQ(back.size(), points.size());
  for (size_t i = 0; i < back.size(); ++i)
  {
    EXPECT_EQ(back[i].SeedId, static_cast<int>(i));
    EXPECT_NEAR(back[i].ArcLength.back(), -length, 1e-12);
    EXPECT_LT(Distance(back[i].Points.back(), TwistExact(points[i], dirs[i], -length)), 1e-8);
  }
}

TEST(GeodesicTracer, NoMetricGivesErrorAndEmptyOutput)
{
  const auto seeds = MakeSeeds(TwistSeedPoints(), TwistSeedDirections());
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  MessageLog log(tracer);
  tracer->SetInputData(seeds);
  tracer->Update();
  EXPECT_EQ(log.Errors.size(), 1u);
  ASSERT_NE(tracer->GetOutput(), nullptr);
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfCells(), 0);

  // A metric without a definition (and one whose only definition was refused).
  vtkNew<vtkRiemannMetric> metric;
  EXPECT_FALSE(metric->HasDefinition());
  EXPECT_FALSE(metric->SetDefinition(R"({"type": "twist"})"));
  EXPECT_FALSE(metric->HasDefinition());
  tracer->SetMetric(metric);
  tracer->Update();
  EXPECT_EQ(log.Errors.size(), 2u);
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfCells(), 0);

  // Defining the metric afterwards re-executes the filter (the metric's
  // modification time is part of the filter's).
  ASSERT_TRUE(metric->SetDefinition(TwistJson)) << metric->GetLastError();
  tracer->GetIntegrationSettings()->SetMaximumPropagation(1.0);
  tracer->Update();
  EXPECT_EQ(log.Errors.size(), 2u);
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfLines(), seeds->GetNumberOfPoints());
}

TEST(GeodesicTracer, MetricChangeReexecutes)
{
  const V3 p{ 0.5, 0.5, 0.0 };
  const V3 d{ 1.0, 0.0, 1.0 };
  auto metric = MakeMetric(EuclideanJson);
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(metric);
  tracer->SetInputData(MakeSeeds({ p }, { d }));
  tracer->GetIntegrationSettings()->SetMaximumPropagation(2.0);
  tracer->Update();
  auto lines = Lines(tracer->GetOutput());
  ASSERT_EQ(lines.size(), 1u);
  const V3 straight = Add(p, Scale(2.0 / Norm(d), d));
  EXPECT_LT(Distance(lines[0].Points.back(), straight), 1e-12);

  ASSERT_TRUE(metric->SetDefinition(TwistJson));
  tracer->Update(); // no change to the filter itself
  lines = Lines(tracer->GetOutput());
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_LT(Distance(lines[0].Points.back(), TwistExact(p, d, 2.0)), 1e-8);
  EXPECT_GT(Distance(lines[0].Points.back(), straight), 0.1);
}

TEST(GeodesicTracer, ZeroDirectionSeedIsSkipped)
{
  const double nan = std::nan("");
  const std::vector<V3> points{ { 0.0, 0.0, 0.0 }, { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.5 },
    { 0.5, 0.5, 0.5 } };
  const std::vector<V3> dirs{ { 1.0, 0.0, 0.0 }, { 0.0, 0.0, 0.0 }, { 0.0, -1.0, 1.0 },
    { nan, 1.0, 0.0 } };
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  MessageLog log(tracer);
  tracer->SetMetric(MakeMetric(TwistJson));
  tracer->SetInputData(MakeSeeds(points, dirs));
  tracer->GetIntegrationSettings()->SetMaximumPropagation(1.0);
  tracer->Update();
  EXPECT_TRUE(log.Errors.empty());
  ASSERT_EQ(log.Warnings.size(), 1u);
  EXPECT_NE(log.Warnings[0].find("2 of 4"), std::string::npos) << log.Warnings[0];

  const auto lines = Lines(tracer->GetOutput());
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].SeedId, 0);
  EXPECT_EQ(lines[1].SeedId, 2);
  for (const Line& line : lines)
  {
    EXPECT_EQ(line.Reason, vtkRiemannGeodesicTracer::OUT_OF_LENGTH);
    EXPECT_LT(
      Distance(line.Points.back(), TwistExact(points[line.SeedId], dirs[line.SeedId], 1.0)), 1e-8);
  }
}

TEST(GeodesicTracer, DirectionArrayWithWrongComponentsIsAnError)
{
  auto seeds = MakeSeeds(TwistSeedPoints(), TwistSeedDirections());
  vtkNew<vtkDoubleArray> flat;
  flat->SetName("Direction");
  flat->SetNumberOfComponents(2);
  flat->SetNumberOfTuples(seeds->GetNumberOfPoints());
  flat->Fill(1.0);
  seeds->GetPointData()->RemoveArray("Direction");
  seeds->GetPointData()->AddArray(flat);
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  MessageLog log(tracer);
  tracer->SetMetric(MakeMetric(TwistJson));
  tracer->SetInputData(seeds);
  tracer->Update();
  ASSERT_EQ(log.Errors.size(), 1u);
  EXPECT_NE(log.Errors[0].find("Direction"), std::string::npos) << log.Errors[0];
  EXPECT_STREQ(
    tracer->GetLastError(), "The seeds' array \"Direction\" has 2 components; it needs 3.");
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfCells(), 0);
}

TEST(GeodesicTracer, EmptySeedsGiveEmptyOutput)
{
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  MessageLog log(tracer);
  tracer->SetMetric(MakeMetric(TwistJson));
  tracer->SetInputData(MakeSeeds({}, {}));
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&progress);
  observer->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData)
    { static_cast<std::vector<double>*>(clientData)->push_back(*static_cast<double*>(callData)); });
  tracer->AddObserver(vtkCommand::ProgressEvent, observer);
  tracer->Update();
  EXPECT_TRUE(log.Errors.empty() && log.Warnings.empty());
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfLines(), 0);
  ASSERT_FALSE(progress.empty());
  EXPECT_EQ(progress.back(), 1.0);
  for (double x : progress)
  {
    EXPECT_TRUE(std::isfinite(x));
  }
}

TEST(GeodesicTracer, SeedsWithoutDirectionArrayUseStartDirection)
{
  const std::vector<V3> points{ { 0.0, 0.0, 0.0 }, { 0.0, 1.0, -1.0 } };
  auto seeds = MakeSeeds(points, { { 1, 0, 0 }, { 1, 0, 0 } });
  seeds->GetPointData()->RemoveArray("Direction");
  const V3 d{ 0.0, 1.0, 1.0 };
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  MessageLog log(tracer);
  tracer->SetMetric(MakeMetric(EuclideanJson));
  tracer->SetInputData(seeds);
  tracer->SetStartDirection(d.data());
  tracer->GetIntegrationSettings()->SetMaximumPropagation(1.5);
  tracer->Update();
  EXPECT_EQ(log.Warnings.size(), 1u);
  const auto lines = Lines(tracer->GetOutput());
  ASSERT_EQ(lines.size(), 2u);
  for (const Line& line : lines)
  {
    EXPECT_LT(
      Distance(line.Points.back(), Add(points[line.SeedId], Scale(1.5 / Norm(d), d))), 1e-12);
  }
}

TEST(GeodesicTracer, ProgressReachesOne)
{
  std::vector<V3> points, dirs;
  RandomSeeds(1000, 1.0, 7, points, dirs);
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(MakeMetric(TwistJson));
  tracer->SetInputData(MakeSeeds(points, dirs));
  tracer->GetIntegrationSettings()->SetMaximumPropagation(0.5);
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&progress);
  observer->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData)
    { static_cast<std::vector<double>*>(clientData)->push_back(*static_cast<double*>(callData)); });
  tracer->AddObserver(vtkCommand::ProgressEvent, observer);
  tracer->Update();
  ASSERT_FALSE(progress.empty());
  EXPECT_EQ(progress.back(), 1.0);
  for (size_t i = 1; i < progress.size(); ++i)
  {
    EXPECT_GE(progress[i], progress[i - 1]) << "progress went backwards";
  }
  // 1000 seeds are several batches: there are reports strictly between 0 and 1.
  EXPECT_TRUE(
    std::any_of(progress.begin(), progress.end(), [](double x) { return x > 0 && x < 1; }));
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfLines(), 1000);
}

TEST(GeodesicTracer, AbortFromProgressObserverStopsEarly)
{
  const int count = 5000;
  std::vector<V3> points, dirs;
  RandomSeeds(count, 2.0, 11, points, dirs);
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(MakeMetric(EightGaussiansJson));
  tracer->SetInputData(MakeSeeds(points, dirs));
  tracer->GetIntegrationSettings()->SetMaximumPropagation(5.0);
  // Abort at the first report between 0 and 1 (after the first batch of
  // seeds), then count the reports that still come: none should, as the
  // filter stops tracing instead of finishing the other batches.
  struct AbortState
  {
    bool Aborted = false;
    int ReportsAfterAbort = 0;
  } state;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&state);
  observer->SetCallback(
    [](vtkObject* caller, unsigned long, void* clientData, void* callData)
    {
      auto* s = static_cast<AbortState*>(clientData);
      const double progress = *static_cast<double*>(callData);
      if (s->Aborted)
      {
        ++s->ReportsAfterAbort;
      }
      else if (progress > 0.0 && progress < 1.0)
      {
        static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
        s->Aborted = true;
      }
    });
  tracer->AddObserver(vtkCommand::ProgressEvent, observer);
  tracer->Update();
  ASSERT_TRUE(state.Aborted);
  EXPECT_EQ(state.ReportsAfterAbort, 0);

  const auto lines = Lines(tracer->GetOutput());
  EXPECT_GT(lines.size(), 0u);
  EXPECT_LT(lines.size(), static_cast<size_t>(count) / 2);
  // The lines that were traced are complete and in seed order.
  for (size_t i = 0; i < lines.size(); ++i)
  {
    ASSERT_EQ(lines[i].SeedId, static_cast<int>(i));
    EXPECT_EQ(lines[i].Points.front(), points[i]);
    EXPECT_EQ(lines[i].Reason, vtkRiemannGeodesicTracer::OUT_OF_LENGTH);
    EXPECT_NEAR(lines[i].ArcLength.back(), 5.0, 1e-12);
  }

  // The abort flag does not stick: a later run traces every seed.
  tracer->RemoveObserver(observer);
  tracer->GetIntegrationSettings()->SetMaximumPropagation(0.2);
  tracer->Update();
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfLines(), count);
}

TEST(GeodesicTracer, ParallelEqualsSerialCore)
{
  const int count = 500;
  std::vector<V3> points, dirs;
  RandomSeeds(count, 2.0, 3, points, dirs);

  // The reference: one seed after the other, with the core directly (forward
  // then backward, as the filter orders its lines for BOTH).
  const auto metric = riemann::ParseMetricDefinition(EightGaussiansJson);
  riemann::GeodesicOptions options;
  options.Integrator = riemann::IntegratorType::RungeKutta4;
  options.Step = 0.02;
  options.MaximumLength = 2.0;
  options.MaximumSteps = 100000; // the filter's default: the core's (GeodesicOptions)
  std::vector<riemann::GeodesicPath> reference(2 * count);
  for (int i = 0; i < count; ++i)
  {
    const riemann::Vec3 p(points[i][0], points[i][1], points[i][2]);
    riemann::Vec3 v;
    ASSERT_TRUE(
      riemann::UnitSpeedVelocity(*metric, p, riemann::Vec3(dirs[i][0], dirs[i][1], dirs[i][2]), v));
    riemann::TraceGeodesic(*metric, p, v, options, reference[2 * i], false);
    riemann::TraceGeodesic(*metric, p, v, options, reference[2 * i + 1], true);
  }

  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(MakeMetric(EightGaussiansJson));
  tracer->SetInputData(MakeSeeds(points, dirs));
  tracer->GetIntegrationSettings()->SetMaximumPropagation(2.0);
  tracer->GetIntegrationSettings()->SetInitialIntegrationStep(0.02);
  tracer->SetIntegrationDirectionToBoth();
  ASSERT_EQ(tracer->GetIntegrationSettings()->GetMaximumNumberOfSteps(), options.MaximumSteps);

  // Every SMP backend this VTK has (TBB is Debian's default, with as many
  // threads as cores), then back to the default.
  const std::string defaultBackend = vtkSMPTools::GetBackend();
  int backendsRun = 0;
  for (const char* backend : { "TBB", "STDThread", "Sequential" })
  {
    if (!vtkSMPTools::SetBackend(backend))
    {
      continue;
    }
    ++backendsRun;
    SCOPED_TRACE(std::string("SMP backend ") + vtkSMPTools::GetBackend() + ", " +
      std::to_string(vtkSMPTools::GetEstimatedNumberOfThreads()) + " threads");
    tracer->Modified();
    tracer->Update();
    const auto lines = Lines(tracer->GetOutput());
    ASSERT_EQ(lines.size(), reference.size());
    double worstPoint = 0.0, worstVelocity = 0.0, worstArc = 0.0;
    for (size_t c = 0; c < lines.size(); ++c)
    {
      const Line& line = lines[c];
      const riemann::GeodesicPath& path = reference[c];
      ASSERT_EQ(line.SeedId, static_cast<int>(c / 2));
      ASSERT_EQ(line.Points.size(), path.Points.size()) << "line " << c;
      EXPECT_EQ(line.Reason, path.Reason);
      for (size_t k = 0; k < path.Points.size(); ++k)
      {
        for (int a = 0; a < 3; ++a)
        {
          worstPoint = std::max(worstPoint, std::abs(line.Points[k][a] - path.Points[k][a]));
          worstVelocity =
            std::max(worstVelocity, std::abs(line.Velocities[k][a] - path.Velocities[k][a]));
        }
        worstArc = std::max(worstArc, std::abs(line.ArcLength[k] - path.ArcLength[k]));
      }
    }
    EXPECT_LE(worstPoint, 1e-12);
    EXPECT_LE(worstVelocity, 1e-12);
    EXPECT_LE(worstArc, 1e-12);
  }
  vtkSMPTools::SetBackend(defaultBackend.c_str());
  EXPECT_GE(backendsRun, 2);
}

TEST(GeodesicTracer, DomainBoundsStopLines)
{
  // Euclidean lines from near the origin leave [-1,1]^3 after arc length < 2.
  std::vector<V3> points, dirs;
  RandomSeeds(50, 0.5, 5, points, dirs);
  const double h = 0.01;
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(MakeMetric(EuclideanJson));
  tracer->SetInputData(MakeSeeds(points, dirs));
  tracer->GetIntegrationSettings()->SetInitialIntegrationStep(h);
  tracer->GetIntegrationSettings()->SetMaximumPropagation(10.0);
  tracer->UseDomainBoundsOn();
  const double bounds[6] = { -1, 1, -1, 1, -1, 1 };
  tracer->SetDomainBounds(bounds);
  tracer->Update();
  const auto lines = Lines(tracer->GetOutput());
  ASSERT_EQ(lines.size(), points.size());
  auto maxNorm = [](const V3& p) {
    return std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) });
  };
  for (const Line& line : lines)
  {
    SCOPED_TRACE("seed " + std::to_string(line.SeedId));
    EXPECT_EQ(line.Reason, vtkRiemannGeodesicTracer::OUT_OF_DOMAIN);
    EXPECT_LT(line.ArcLength.back(), 10.0);
    // The last point is the first one outside, one step past the boundary at most.
    EXPECT_GT(maxNorm(line.Points.back()), 1.0);
    EXPECT_LE(maxNorm(line.Points.back()), 1.0 + h + 1e-12);
    for (size_t k = 0; k + 1 < line.Points.size(); ++k)
    {
      ASSERT_LE(maxNorm(line.Points[k]), 1.0);
    }
  }

  // The same seeds without bounds run to the full length.
  tracer->UseDomainBoundsOff();
  tracer->GetIntegrationSettings()->SetMaximumPropagation(3.0);
  tracer->Update();
  for (const Line& line : Lines(tracer->GetOutput()))
  {
    EXPECT_EQ(line.Reason, vtkRiemannGeodesicTracer::OUT_OF_LENGTH);
  }
}

TEST(GeodesicTracer, MaximumNumberOfSteps)
{
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(MakeMetric(TwistJson));
  tracer->SetStartPosition(0.2, 0.1, 0.0);
  tracer->SetStartDirection(1.0, 1.0, 1.0);
  tracer->GetIntegrationSettings()->SetInitialIntegrationStep(0.01);
  tracer->GetIntegrationSettings()->SetMaximumPropagation(10.0);
  tracer->GetIntegrationSettings()->SetMaximumNumberOfSteps(37);
  tracer->Update();
  const auto lines = Lines(tracer->GetOutput());
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].Reason, vtkRiemannGeodesicTracer::OUT_OF_STEPS);
  EXPECT_EQ(lines[0].Points.size(), 38u);
  EXPECT_NEAR(lines[0].ArcLength.back(), 0.37, 1e-12);
}

TEST(GeodesicTracer, EuclideanLinesAreStraight)
{
  const std::vector<V3> points{ { 0, 0, 0 }, { 1, -2, 3 }, { -0.5, 0.25, 0.125 } };
  const std::vector<V3> dirs{ { 1, 0, 0 }, { 0.3, -4, 2 }, { -1e-3, 2e-3, 5e-4 } };
  const double length = 4.0;
  for (int integrator : { vtkRiemannIntegrationSettings::EULER, vtkRiemannIntegrationSettings::RUNGE_KUTTA4,
         vtkRiemannIntegrationSettings::DORMAND_PRINCE45 })
  {
    SCOPED_TRACE("integrator " + std::to_string(integrator));
    vtkNew<vtkRiemannGeodesicTracer> tracer;
    MessageLog log(tracer);
    tracer->SetMetric(MakeMetric(EuclideanJson));
    tracer->SetInputData(MakeSeeds(points, dirs));
    tracer->GetIntegrationSettings()->SetIntegratorType(integrator);
    tracer->GetIntegrationSettings()->SetInitialIntegrationStep(0.05);
    tracer->GetIntegrationSettings()->SetMaximumPropagation(length);
    tracer->Update();
    EXPECT_TRUE(log.Errors.empty() && log.Warnings.empty());
    const auto lines = Lines(tracer->GetOutput());
    ASSERT_EQ(lines.size(), points.size());
    for (const Line& line : lines)
    {
      const V3& p = points[line.SeedId];
      const V3 u = Scale(1.0 / Norm(dirs[line.SeedId]), dirs[line.SeedId]);
      EXPECT_EQ(line.Reason, vtkRiemannGeodesicTracer::OUT_OF_LENGTH);
      EXPECT_NEAR(line.ArcLength.back(), length, 1e-12);
      for (size_t k = 0; k < line.Points.size(); ++k)
      {
        ASSERT_LT(Distance(line.Points[k], Add(p, Scale(line.ArcLength[k], u))), 1e-12) << k;
        ASSERT_LT(Distance(line.Velocities[k], u), 1e-12) << k;
        ASSERT_LT(std::abs(line.SpeedDrift[k]), 1e-14) << k;
      }
    }
  }
}

/// n(x) of LensJson, and s(x) = int_{x0}^{x} n(t, 0, 0) dt on the x axis.
double LensIndex(const V3& p)
{
  return 1.0 + LensAmplitude * std::exp(-Dot(p, p) / (2 * LensSigma * LensSigma));
}
double LensAxisArcLength(double x0, double x)
{
  const double k = LensSigma * std::sqrt(2.0);
  return (x - x0) +
    LensAmplitude * LensSigma * std::sqrt(M_PI / 2.0) * (std::erf(x / k) - std::erf(x0 / k));
}

TEST(GeodesicTracer, ConformalLens)
{
  // Seed 0 runs along the axis through the lens centre; the others pass at
  // impact parameters 0.2 and 0.5 (in different planes).
  const std::vector<V3> points{ { -2, 0, 0 }, { -2, 0.2, 0 }, { -2, 0, -0.5 }, { 0.3, 0.3, 0.3 } };
  const std::vector<V3> dirs{ { 1, 0, 0 }, { 1, 0, 0 }, { 1, 0.1, 0 }, { -0.2, 1.0, 0.4 } };
  auto metric = MakeMetric(LensJson);
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(metric);
  tracer->SetInputData(MakeSeeds(points, dirs));
  tracer->GetIntegrationSettings()->SetMaximumPropagation(4.5);
  tracer->Update();
  const auto lines = Lines(tracer->GetOutput());
  ASSERT_EQ(lines.size(), points.size());

  for (const Line& line : lines)
  {
    SCOPED_TRACE("seed " + std::to_string(line.SeedId));
    const V3& p = points[line.SeedId];
    EXPECT_EQ(line.Reason, vtkRiemannGeodesicTracer::OUT_OF_LENGTH);
    EXPECT_NEAR(line.ArcLength.back(), 4.5, 1e-12);
    // Unit speed in g = n^2 I at the seed, along the direction given.
    const V3& v0 = line.Velocities.front();
    EXPECT_NEAR(LensIndex(p) * LensIndex(p) * Dot(v0, v0), 1.0, 1e-12);
    EXPECT_NEAR(SpeedSquared(metric, p, v0), 1.0, 1e-12);
    EXPECT_LT(Norm(Cross(v0, dirs[line.SeedId])), 1e-12);
    EXPECT_GT(Dot(v0, dirs[line.SeedId]), 0.0);
    EXPECT_LT(MaxAbsDrift(line), 1e-9);
    // Angular momentum about the centre, g(e_a × x, v) = n^2 (x × v), is conserved.
    const V3 l0 = Scale(LensIndex(p) * LensIndex(p), Cross(p, v0));
    double worst = 0.0;
    for (size_t k = 0; k < line.Points.size(); ++k)
    {
      const double n = LensIndex(line.Points[k]);
      worst =
        std::max(worst, Distance(Scale(n * n, Cross(line.Points[k], line.Velocities[k])), l0));
    }
    EXPECT_LT(worst, 1e-8);
  }

  // On the axis: the ray stays on it, and its arc length is int n dx.
  const Line& axis = lines[0];
  double worstArc = 0.0;
  for (size_t k = 0; k < axis.Points.size(); ++k)
  {
    ASSERT_EQ(axis.Points[k][1], 0.0);
    ASSERT_EQ(axis.Points[k][2], 0.0);
    worstArc =
      std::max(worstArc, std::abs(axis.ArcLength[k] - LensAxisArcLength(-2.0, axis.Points[k][0])));
  }
  EXPECT_LT(worstArc, 1e-9);
  // The lens slows the ray: less coordinate distance than arc length.
  EXPECT_LT(axis.Points.back()[0] + 2.0, 4.5 - 0.5);

  // A converging lens bends the off-axis ray towards the axis.
  const Line& offAxis = lines[1];
  EXPECT_LT(offAxis.Velocities.back()[1], -1e-3);
  EXPECT_NEAR(offAxis.Points.back()[2], 0.0, 1e-12);
}

TEST(GeodesicTracer, DormandPrince45OnTwist)
{
  const auto points = TwistSeedPoints();
  const auto dirs = TwistSeedDirections();
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(MakeMetric(TwistJson));
  tracer->SetInputData(MakeSeeds(points, dirs));
  tracer->GetIntegrationSettings()->SetIntegratorTypeToDormandPrince45();
  tracer->GetIntegrationSettings()->SetMaximumError(1e-9);
  tracer->GetIntegrationSettings()->SetMaximumPropagation(3.0);
  tracer->Update();
  const auto lines = Lines(tracer->GetOutput());
  ASSERT_EQ(lines.size(), points.size());
  for (const Line& line : lines)
  {
    SCOPED_TRACE("seed " + std::to_string(line.SeedId));
    EXPECT_EQ(line.Reason, vtkRiemannGeodesicTracer::OUT_OF_LENGTH);
    EXPECT_NEAR(line.ArcLength.back(), 3.0, 1e-12);
    EXPECT_LT(
      Distance(line.Points.back(), TwistExact(points[line.SeedId], dirs[line.SeedId], 3.0)), 1e-6);
    // Adaptive: far fewer steps than RK4's 300 at h = 0.01.
    EXPECT_LT(line.Points.size(), 200u);
  }
}

TEST(GeodesicTracer, TransverseJacobianOnTheUnitSphere)
{
  // Stereographic unit sphere (K = 1): det = sin^2 s and both singular
  // values |sin s| along every geodesic, forward and backward, with every
  // integrator; the lines are the ones traced without the Jacobian.
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(MakeMetric(R"json({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})json"));
  const std::vector<V3> points = { { 0.5, 0.0, 0.0 }, { 0.1, -0.2, 0.3 } };
  const std::vector<V3> dirs = { { 0.2, 1.0, 0.5 }, { 1.0, 1.0, 0.0 } };
  tracer->SetInputData(MakeSeeds(points, dirs));
  tracer->GetIntegrationSettings()->SetMaximumPropagation(3.0);
  tracer->SetIntegrationDirectionToBoth();
  for (const int integrator : { vtkRiemannIntegrationSettings::EULER,
         vtkRiemannIntegrationSettings::RUNGE_KUTTA4, vtkRiemannIntegrationSettings::DORMAND_PRINCE45 })
  {
    SCOPED_TRACE("integrator " + std::to_string(integrator));
    tracer->GetIntegrationSettings()->SetIntegratorType(integrator);
    tracer->GetIntegrationSettings()->SetInitialIntegrationStep(integrator == vtkRiemannIntegrationSettings::EULER ? 0.001 : 0.01);
    tracer->ComputeTransverseJacobianOff();
    tracer->Update();
    vtkNew<vtkPolyData> plain;
    plain->DeepCopy(tracer->GetOutput());
    EXPECT_EQ(plain->GetPointData()->GetArray("TransverseJacobian"), nullptr);

    tracer->ComputeTransverseJacobianOn();
    tracer->Update();
    vtkPolyData* output = tracer->GetOutput();
    vtkDataArray* determinant = output->GetPointData()->GetArray("TransverseJacobian");
    vtkDataArray* singular = output->GetPointData()->GetArray("TransverseJacobianSingularValues");
    vtkDataArray* arcLength = output->GetPointData()->GetArray("ArcLength");
    ASSERT_NE(determinant, nullptr);
    ASSERT_NE(singular, nullptr);
    ASSERT_EQ(singular->GetNumberOfComponents(), 2);
    ASSERT_EQ(output->GetNumberOfLines(), 4);
    const double tolerance = integrator == vtkRiemannIntegrationSettings::EULER ? 5e-3 : 1e-6;
    double worst = 0.0;
    for (vtkIdType k = 0; k < output->GetNumberOfPoints(); ++k)
    {
      const double s = arcLength->GetTuple1(k);
      worst = std::max(worst, std::abs(determinant->GetTuple1(k) - std::pow(std::sin(s), 2)));
      worst = std::max(worst, std::abs(singular->GetComponent(k, 0) - std::abs(std::sin(s))));
      worst = std::max(worst, std::abs(singular->GetComponent(k, 1) - std::abs(std::sin(s))));
    }
    EXPECT_LT(worst, tolerance);
    if (integrator != vtkRiemannIntegrationSettings::DORMAND_PRINCE45)
    {
      // Fixed steps: the geodesic part of the Jacobi system is the geodesic
      // flow itself, so the points are the same.
      ASSERT_EQ(plain->GetNumberOfPoints(), output->GetNumberOfPoints());
      double apart = 0.0;
      for (vtkIdType k = 0; k < output->GetNumberOfPoints(); ++k)
      {
        double a[3], b[3];
        plain->GetPoint(k, a);
        output->GetPoint(k, b);
        apart = std::max(apart, Distance({ a[0], a[1], a[2] }, { b[0], b[1], b[2] }));
      }
      EXPECT_LT(apart, 1e-12);
    }
  }
}

TEST(GeodesicTracer, TransverseJacobianOfAFlatMetricIsSSquared)
{
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(MakeMetric(TwistJson));
  tracer->SetInputData(MakeSeeds(TwistSeedPoints(), TwistSeedDirections()));
  tracer->GetIntegrationSettings()->SetMaximumPropagation(3.0);
  tracer->ComputeTransverseJacobianOn();
  tracer->Update();
  vtkPolyData* output = tracer->GetOutput();
  vtkDataArray* determinant = output->GetPointData()->GetArray("TransverseJacobian");
  vtkDataArray* singular = output->GetPointData()->GetArray("TransverseJacobianSingularValues");
  vtkDataArray* arcLength = output->GetPointData()->GetArray("ArcLength");
  ASSERT_NE(determinant, nullptr);
  double worst = 0.0;
  for (vtkIdType k = 0; k < output->GetNumberOfPoints(); ++k)
  {
    const double s = arcLength->GetTuple1(k);
    worst = std::max(worst, std::abs(determinant->GetTuple1(k) - s * s));
    worst = std::max(worst, std::abs(singular->GetComponent(k, 1) - s));
  }
  EXPECT_LT(worst, 1e-8);
}
} // namespace
