// Tests of vtkRiemannConjugateLocus (the VTK layer over riemann::FindConjugatePoints).
//
// - Round 3-sphere of radius 1 in stereographic coordinates,
//   n = 2 / (1 + |x|^2): every geodesic from p first meets a conjugate point at
//   arc length pi, the antipode -p / |p|^2, with multiplicity 2.
// - Twist metric (flat, a pull-back of Euclidean space: Hadamard): no
//   conjugate points at all.
// - No metric: an error and empty output.
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannConjugateLocus.h"
#include "vtkRiemannMetric.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

namespace
{
constexpr const char* SphereJson = R"J({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})J";
constexpr const char* TwistJson = R"({"type":"diffeo","preset":"twist"})";
constexpr double Observer[3] = { 0.2, 0.1, -0.3 };

vtkSmartPointer<vtkRiemannMetric> MakeMetric(const char* json)
{
  auto metric = vtkSmartPointer<vtkRiemannMetric>::New();
  EXPECT_TRUE(metric->SetDefinition(json)) << json;
  return metric;
}

struct ErrorCounter
{
  int Errors = 0;
  static void Callback(vtkObject*, unsigned long, void* clientData, void*)
  {
    static_cast<ErrorCounter*>(clientData)->Errors++;
  }
};
}

namespace
{
/// The sphere's first conjugate points from Observer with 200 directions at
/// `step`; returns how many directions miss the exact answer (ArcLength pi to
/// 1e-6, multiplicity 2), after checking what every direction must satisfy.
int CheckSphereAntipode(double step)
{
  auto metric = MakeMetric(SphereJson);
  vtkNew<vtkRiemannConjugateLocus> locus;
  locus->SetMetric(metric);
  locus->SetObserver(Observer[0], Observer[1], Observer[2]);
  locus->SetNumberOfDirections(200);
  locus->GetIntegrationSettings()->SetInitialIntegrationStep(step);
  locus->GetIntegrationSettings()->SetMaximumPropagation(4.0);
  int progressEvents = 0;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&progressEvents);
  progress->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  locus->AddObserver(vtkCommand::ProgressEvent, progress);
  locus->Update();
  EXPECT_GT(progressEvents, 0);

  vtkPolyData* output = locus->GetOutput();
  EXPECT_EQ(output->GetNumberOfPoints(), 200);
  EXPECT_EQ(output->GetNumberOfVerts(), output->GetNumberOfPoints());
  vtkDataArray* arcLength = output->GetPointData()->GetArray("ArcLength");
  vtkDataArray* multiplicity = output->GetPointData()->GetArray("Multiplicity");
  vtkDataArray* index = output->GetPointData()->GetArray("ConjugateIndex");
  vtkDataArray* direction = output->GetPointData()->GetArray("DirectionId");
  if (!arcLength || !multiplicity || !index || !direction)
  {
    ADD_FAILURE() << "missing point-data arrays";
    return 200;
  }
  EXPECT_EQ(multiplicity->GetDataType(), VTK_INT);
  EXPECT_EQ(index->GetDataType(), VTK_INT);
  EXPECT_EQ(direction->GetDataType(), VTK_INT);

  const double r2 =
    Observer[0] * Observer[0] + Observer[1] * Observer[1] + Observer[2] * Observer[2];
  const double antipode[3] = { -Observer[0] / r2, -Observer[1] / r2, -Observer[2] / r2 };
  std::set<int> directions;
  int inexact = 0;
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    directions.insert(static_cast<int>(direction->GetTuple1(i)));
    EXPECT_EQ(static_cast<int>(index->GetTuple1(i)), 1) << "point " << i;
    EXPECT_NEAR(arcLength->GetTuple1(i), M_PI, 1e-5) << "point " << i;
    double p[3];
    output->GetPoint(i, p);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_NEAR(p[k], antipode[k], 1e-5) << "point " << i << " coordinate " << k;
    }
    if (std::abs(arcLength->GetTuple1(i) - M_PI) > 1e-6 ||
      static_cast<int>(multiplicity->GetTuple1(i)) != 2)
    {
      ++inexact;
    }
  }
  EXPECT_EQ(directions.size(), static_cast<size_t>(output->GetNumberOfPoints()));
  return inexact;
}
}

TEST(ConjugateLocus, SphereFirstConjugatePointIsTheAntipode)
{
  // Step 0.01: every direction finds the antipode (1e-5); RK4's error splits
  // the double zero of one of the 200 (DirectionId 175: ArcLength pi + 1.07e-6,
  // found as two simple zeros ~2e-6 apart, so Multiplicity 1). Allow that one.
  EXPECT_LE(CheckSphereAntipode(0.01), 1);
  // Step 0.005: every direction to ArcLength 1e-6 with multiplicity 2.
  EXPECT_EQ(CheckSphereAntipode(0.005), 0);
}

TEST(ConjugateLocus, SphereSecondConjugatePointInACone)
{
  // Two conjugate points per geodesic within 7: pi (the antipode) and 2 pi (back at p).
  auto metric = MakeMetric(SphereJson);
  vtkNew<vtkRiemannConjugateLocus> locus;
  locus->SetMetric(metric);
  locus->SetObserver(Observer[0], Observer[1], Observer[2]);
  locus->SetNumberOfDirections(10);
  locus->SetConeAxis(1.0, 1.0, 0.0);
  locus->SetConeAngle(30.0);
  locus->GetIntegrationSettings()->SetMaximumPropagation(7.0);
  locus->SetMaximumNumberOfConjugatePoints(2);
  locus->Update();
  vtkPolyData* output = locus->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), 20);
  vtkDataArray* arcLength = output->GetPointData()->GetArray("ArcLength");
  vtkDataArray* index = output->GetPointData()->GetArray("ConjugateIndex");
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    const int k = static_cast<int>(index->GetTuple1(i));
    EXPECT_EQ(k, 1 + static_cast<int>(i % 2));
    EXPECT_NEAR(arcLength->GetTuple1(i), k * M_PI, 1e-5);
  }
}

TEST(ConjugateLocus, HadamardTwistHasNoConjugatePoints)
{
  auto metric = MakeMetric(TwistJson);
  vtkNew<vtkRiemannConjugateLocus> locus;
  locus->SetMetric(metric);
  locus->SetObserver(Observer[0], Observer[1], Observer[2]);
  locus->SetNumberOfDirections(200);
  locus->GetIntegrationSettings()->SetInitialIntegrationStep(0.01);
  locus->GetIntegrationSettings()->SetMaximumPropagation(8.0);
  locus->SetMaximumNumberOfConjugatePoints(0);
  ErrorCounter counter;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(&counter);
  callback->SetCallback(ErrorCounter::Callback);
  locus->AddObserver(vtkCommand::ErrorEvent, callback);
  locus->Update();
  EXPECT_EQ(counter.Errors, 0);
  EXPECT_EQ(locus->GetOutput()->GetNumberOfPoints(), 0);
  ASSERT_NE(locus->GetOutput()->GetPointData()->GetArray("ArcLength"), nullptr);
}

TEST(ConjugateLocus, NoMetricIsAnErrorWithEmptyOutput)
{
  vtkNew<vtkRiemannConjugateLocus> locus;
  locus->SetNumberOfDirections(10);
  ErrorCounter counter;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(&counter);
  callback->SetCallback(ErrorCounter::Callback);
  locus->AddObserver(vtkCommand::ErrorEvent, callback);
  locus->Update();
  EXPECT_EQ(counter.Errors, 1);
  EXPECT_EQ(locus->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(locus->GetOutput()->GetNumberOfCells(), 0);
}

TEST(ConjugateLocus, ErrorsAreKeptInGetLastError)
{
  vtkNew<vtkRiemannConjugateLocus> locus;
  locus->SetMetric(MakeMetric(SphereJson));
  locus->SetNumberOfDirections(10);
  locus->GetIntegrationSettings()->SetMaximumPropagation(4.0);
  ErrorCounter counter;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(&counter);
  callback->SetCallback(ErrorCounter::Callback);
  locus->AddObserver(vtkCommand::ErrorEvent, callback);

  locus->SetObserver(std::numeric_limits<double>::infinity(), 0.0, 0.0);
  locus->Update();
  EXPECT_EQ(counter.Errors, 1);
  EXPECT_STREQ(locus->GetLastError(), "Observer must be finite.");
  EXPECT_EQ(locus->GetOutput(0)->GetNumberOfPoints(), 0);
  EXPECT_EQ(locus->GetOutput(1)->GetNumberOfPoints(), 0);

  locus->SetObserver(Observer[0], Observer[1], Observer[2]);
  locus->SetConeAngle(30.0);
  locus->SetConeAxis(0.0, 0.0, 0.0);
  locus->Update();
  EXPECT_EQ(counter.Errors, 2);
  EXPECT_STREQ(locus->GetLastError(), "ConeAxis: the cone axis must be a finite nonzero vector.");
  EXPECT_EQ(locus->GetOutput(0)->GetNumberOfPoints(), 0);
  EXPECT_EQ(locus->GetOutput(1)->GetNumberOfPoints(), 0);

  // All well again: the antipode in every direction, no error left.
  locus->SetConeAxis(0.0, 0.0, 1.0);
  locus->Update();
  EXPECT_EQ(counter.Errors, 2);
  EXPECT_STREQ(locus->GetLastError(), "");
  EXPECT_EQ(locus->GetOutput(0)->GetNumberOfPoints(), 10);
}
