// Tests of vtkRiemannGeodesicConnector (the VTK layer over riemann::ConnectPoints):
// - on the round 3-sphere (stereographic coordinates) the two arcs of the
//   great circle through p and q, as polylines from p to q sorted by
//   length, with their lengths d and 2 pi - d, Morse indices 0 and 2, the
//   shortest marked, and point data along them as the tracer's;
// - in the twist metric (flat) one geodesic, of length |Phi(q) - Phi(p)|;
// - bad properties and p = q: an error, GetLastError, and empty output;
// - an abort during the shooting: empty output, no error.
#include "ErrorObserver.h"
#include "vtkRiemannGeodesicConnector.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <string>

namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr const char* SphereJson = R"J({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})J";
constexpr const char* TwistJson = R"({"type":"diffeo","preset":"twist"})";

vtkSmartPointer<vtkRiemannMetric> MakeMetric(const char* json)
{
  auto metric = vtkSmartPointer<vtkRiemannMetric>::New();
  EXPECT_TRUE(metric->SetDefinition(json)) << json;
  return metric;
}

Eigen::Vector4d OnSphere(const double x[3])
{
  const double r2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
  Eigen::Vector4d X;
  X << 2 * x[0] / (1 + r2), 2 * x[1] / (1 + r2), 2 * x[2] / (1 + r2), (1 - r2) / (1 + r2);
  return X;
}

/// The twist of the paper: rotation by z about the z axis.
Eigen::Vector3d Twist(const double x[3])
{
  return { std::cos(x[2]) * x[0] - std::sin(x[2]) * x[1],
    std::sin(x[2]) * x[0] + std::cos(x[2]) * x[1], x[2] };
}

TEST(GeodesicConnector, TheRoundSphereGivesBothArcsAsPolylines)
{
  const double p[3] = { 0.4, 0.1, -0.2 };
  const double q[3] = { -0.3, 0.5, 0.6 };
  const double d = std::acos(OnSphere(p).dot(OnSphere(q)));
  vtkNew<vtkRiemannGeodesicConnector> connector;
  connector->SetMetric(MakeMetric(SphereJson));
  connector->SetStartPosition(p);
  connector->SetEndPosition(q);
  connector->SetNumberOfDirections(500);
  connector->GetIntegrationSettings()->SetMaximumPropagation(7.0);
  connector->Update();
  EXPECT_STREQ(connector->GetLastError(), "");
  vtkPolyData* out = connector->GetOutput();
  ASSERT_EQ(out->GetNumberOfLines(), 2);
  EXPECT_EQ(connector->GetNumberOfGeodesics(), 2);
  vtkCellData* cd = out->GetCellData();
  EXPECT_NEAR(cd->GetArray("Length")->GetTuple1(0), d, 1e-8);
  EXPECT_NEAR(cd->GetArray("Length")->GetTuple1(1), 2 * Pi - d, 1e-8);
  EXPECT_EQ(cd->GetArray("MorseIndex")->GetTuple1(0), 0);
  EXPECT_EQ(cd->GetArray("MorseIndex")->GetTuple1(1), 2);
  EXPECT_EQ(cd->GetArray("Shortest")->GetTuple1(0), 1);
  EXPECT_EQ(cd->GetArray("Shortest")->GetTuple1(1), 0);
  EXPECT_EQ(cd->GetArray("SeedIds")->GetTuple1(1), 1);
  for (const char* name : { "ConjugateMultiplicity", "Miss", "Iterations", "InitialDirection" })
  {
    ASSERT_NE(cd->GetArray(name), nullptr) << name;
  }
  // Each polyline runs from p to q, its ArcLength from 0 to its Length.
  vtkNew<vtkIdList> ids;
  for (vtkIdType line = 0; line < 2; ++line)
  {
    out->GetCellPoints(line, ids);
    const vtkIdType first = ids->GetId(0);
    const vtkIdType last = ids->GetId(ids->GetNumberOfIds() - 1);
    double a[3], b[3];
    out->GetPoint(first, a);
    out->GetPoint(last, b);
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_EQ(a[i], p[i]);
      EXPECT_NEAR(b[i], q[i], 1e-8);
    }
    vtkDataArray* arcLength = out->GetPointData()->GetArray("ArcLength");
    EXPECT_EQ(arcLength->GetTuple1(first), 0.0);
    EXPECT_DOUBLE_EQ(arcLength->GetTuple1(last), cd->GetArray("Length")->GetTuple1(line));
    ASSERT_NE(out->GetPointData()->GetArray("Velocity"), nullptr);
  }
}

TEST(GeodesicConnector, TheTwistHasOneGeodesicOfTheMappedLength)
{
  const double p[3] = { 0.2, -0.4, 0.3 };
  const double q[3] = { 1.0, 0.7, 1.6 };
  vtkNew<vtkRiemannGeodesicConnector> connector;
  connector->SetMetric(MakeMetric(TwistJson));
  connector->SetStartPosition(p);
  connector->SetEndPosition(q);
  connector->SetNumberOfDirections(300);
  connector->Update();
  vtkPolyData* out = connector->GetOutput();
  ASSERT_EQ(out->GetNumberOfLines(), 1);
  EXPECT_NEAR(out->GetCellData()->GetArray("Length")->GetTuple1(0), (Twist(q) - Twist(p)).norm(), 1e-8);
  EXPECT_LE(out->GetCellData()->GetArray("Miss")->GetTuple1(0), 1e-9);
}

TEST(GeodesicConnector, BadPropertiesGiveAnErrorAndEmptyOutput)
{
  struct Case
  {
    const char* Why;
    void (*Set)(vtkRiemannGeodesicConnector*);
    const char* Message;
  };
  const Case cases[] = {
    { "same point", [](vtkRiemannGeodesicConnector* c) { c->SetEndPosition(0, 0, 0); },
      "StartPosition and EndPosition are the same point" },
    { "NaN", [](vtkRiemannGeodesicConnector* c) { c->SetStartPosition(NAN, 0, 0); },
      "must be finite" },
    { "tolerance", [](vtkRiemannGeodesicConnector* c) { c->SetTolerance(0.5); },
      "Tolerance is" },
    { "directions", [](vtkRiemannGeodesicConnector* c) { c->SetNumberOfDirections(0); },
      "NumberOfDirections is 0" },
    { "iterations", [](vtkRiemannGeodesicConnector* c) { c->SetMaximumNumberOfIterations(2147483647); },
      "MaximumNumberOfIterations is 2147483647" },
    { "length", [](vtkRiemannGeodesicConnector* c) { c->GetIntegrationSettings()->SetMaximumPropagation(-1); },
      "MaximumPropagation" },
  };
  for (const Case& c : cases)
  {
    vtkNew<vtkRiemannGeodesicConnector> connector;
    connector->SetMetric(MakeMetric(TwistJson));
    c.Set(connector);
    riemann::testing::ErrorObserver errors(connector);
    connector->Update();
    EXPECT_EQ(errors.Messages.size(), 1u) << c.Why;
    EXPECT_NE(std::string(connector->GetLastError()).find(c.Message), std::string::npos)
      << c.Why << ": " << connector->GetLastError();
    EXPECT_EQ(connector->GetOutput()->GetNumberOfPoints(), 0) << c.Why;
  }
  vtkNew<vtkRiemannGeodesicConnector> withoutMetric;
  riemann::testing::ErrorObserver errors(withoutMetric);
  withoutMetric->Update();
  EXPECT_EQ(errors.Messages.size(), 1u);
  EXPECT_EQ(withoutMetric->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(GeodesicConnector, AnAbortLeavesEmptyOutput)
{
  vtkNew<vtkRiemannGeodesicConnector> connector;
  connector->SetMetric(MakeMetric(SphereJson));
  connector->SetEndPosition(-0.3, 0.5, 0.6);
  connector->SetNumberOfDirections(5000);
  vtkNew<vtkCallbackCommand> abort;
  abort->SetCallback([](vtkObject* caller, unsigned long, void*, void* progress)
    {
      if (*static_cast<double*>(progress) > 0.1)
      {
        static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
      }
    });
  connector->AddObserver(vtkCommand::ProgressEvent, abort);
  riemann::testing::ErrorObserver errors(connector);
  connector->Update();
  EXPECT_TRUE(errors.Messages.empty());
  EXPECT_EQ(connector->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(connector->GetNumberOfGeodesics(), 0);
}
} // namespace
