// Tests of vtkRiemannDirectionGrid, vtkRiemannExponentialMap and the
// conjugate-locus surface of vtkRiemannConjugateLocus, against exact answers:
// - the direction grid is a closed, outward-oriented triangulation of the
//   unit sphere (Euler characteristic 2) or of a cap (a disc, 1);
// - Euclidean space: the geodesic sphere of radius r is the round sphere of
//   radius r, and the transverse Jacobian is r^2;
// - the unit 3-sphere in stereographic coordinates (n = 2 / (1 + |x|^2)): the
//   geodesic sphere of radius r lies at spherical distance r from the observer
//   (measured on S^3 in R^4, independently of the library), its transverse
//   Jacobian is sin^2 r, and at r = pi it collapses to the antipode, which is
//   also the whole first conjugate locus.
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannConjugateLocus.h"
#include "vtkRiemannDirectionGrid.h"
#include "vtkRiemannExponentialMap.h"
#include "vtkRiemannMetric.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace
{
constexpr const char* SphereJson = R"J({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})J";
constexpr const char* EuclideanJson = R"({"type":"euclidean"})";

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

/// Edge -> number of triangles using it.
std::map<std::pair<vtkIdType, vtkIdType>, int> EdgeUse(vtkPolyData* surface)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> edges;
  vtkNew<vtkIdList> ids;
  vtkCellArray* polys = surface->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(ids);)
  {
    EXPECT_EQ(ids->GetNumberOfIds(), 3);
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType a = ids->GetId(k);
      const vtkIdType b = ids->GetId((k + 1) % 3);
      ++edges[{ std::min(a, b), std::max(a, b) }];
    }
  }
  return edges;
}

/// Inverse stereographic projection to the unit sphere S^3 in R^4.
std::array<double, 4> ToSphere(const double x[3])
{
  const double r2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
  return { 2 * x[0] / (1 + r2), 2 * x[1] / (1 + r2), 2 * x[2] / (1 + r2), (1 - r2) / (1 + r2) };
}

double SphericalDistance(const double a[3], const double b[3])
{
  const auto p = ToSphere(a);
  const auto q = ToSphere(b);
  double dot = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    dot += p[k] * q[k];
  }
  return std::acos(std::max(-1.0, std::min(1.0, dot)));
}
}

TEST(DirectionGrid, WholeSphereIsAClosedOrientedTriangulation)
{
  for (const int n : { 4, 10, 500 })
  {
    SCOPED_TRACE("n = " + std::to_string(n));
    vtkNew<vtkRiemannDirectionGrid> grid;
    grid->SetNumberOfDirections(n);
    grid->Update();
    vtkPolyData* output = grid->GetOutput();
    ASSERT_EQ(output->GetNumberOfPoints(), n);
    // A triangulated sphere: F = 2V - 4, every edge in two triangles.
    EXPECT_EQ(output->GetNumberOfPolys(), 2 * n - 4);
    const auto edges = EdgeUse(output);
    for (const auto& [edge, count] : edges)
    {
      EXPECT_EQ(count, 2) << edge.first << "-" << edge.second;
    }
    EXPECT_EQ(n - static_cast<long>(edges.size()) + output->GetNumberOfPolys(), 2);
    // Unit directions, outward triangles, total area close to 4 pi.
    double area = 0.0;
    vtkNew<vtkIdList> ids;
    for (output->GetPolys()->InitTraversal(); output->GetPolys()->GetNextCell(ids);)
    {
      double a[3], b[3], c[3], ab[3], ac[3], normal[3];
      output->GetPoint(ids->GetId(0), a);
      output->GetPoint(ids->GetId(1), b);
      output->GetPoint(ids->GetId(2), c);
      EXPECT_NEAR(vtkMath::Norm(a), 1.0, 1e-12);
      vtkMath::Subtract(b, a, ab);
      vtkMath::Subtract(c, a, ac);
      vtkMath::Cross(ab, ac, normal);
      EXPECT_GT(vtkMath::Dot(normal, a), 0.0);
      area += 0.5 * vtkMath::Norm(normal);
    }
    if (n == 500)
    {
      EXPECT_NEAR(area / (4 * vtkMath::Pi()), 1.0, 0.01);
    }
    ASSERT_NE(output->GetPointData()->GetArray("DirectionId"), nullptr);
    EXPECT_EQ(output->GetPointData()->GetArray("DirectionId")->GetTuple1(n - 1), n - 1);
  }
}

TEST(DirectionGrid, ConeIsATriangulatedDisc)
{
  vtkNew<vtkRiemannDirectionGrid> grid;
  grid->SetNumberOfDirections(300);
  grid->SetConeAxis(1.0, 2.0, -1.0);
  grid->SetConeAngle(40.0);
  grid->Update();
  vtkPolyData* output = grid->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), 300);
  double axis[3] = { 1.0, 2.0, -1.0 };
  vtkMath::Normalize(axis);
  for (vtkIdType i = 0; i < 300; ++i)
  {
    double d[3];
    output->GetPoint(i, d);
    EXPECT_GE(vtkMath::Dot(d, axis), std::cos(vtkMath::RadiansFromDegrees(40.0)) - 1e-12);
  }
  const auto edges = EdgeUse(output);
  int boundary = 0;
  for (const auto& [edge, count] : edges)
  {
    EXPECT_LE(count, 2);
    boundary += count == 1 ? 1 : 0;
  }
  EXPECT_GT(boundary, 0);
  EXPECT_EQ(300 - static_cast<long>(edges.size()) + output->GetNumberOfPolys(), 1);
}

TEST(DirectionGrid, ZeroAxisIsAnError)
{
  vtkNew<vtkRiemannDirectionGrid> grid;
  grid->SetConeAxis(0.0, 0.0, 0.0);
  grid->SetConeAngle(30.0);
  ErrorCounter counter;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(&counter);
  callback->SetCallback(ErrorCounter::Callback);
  grid->AddObserver(vtkCommand::ErrorEvent, callback);
  grid->Update();
  EXPECT_EQ(counter.Errors, 1);
  EXPECT_EQ(grid->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(ExponentialMap, EuclideanWavefrontsAreRoundSpheres)
{
  vtkNew<vtkRiemannExponentialMap> expmap;
  expmap->SetMetric(MakeMetric(EuclideanJson));
  const double observer[3] = { 0.5, -1.0, 2.0 };
  expmap->SetObserver(observer[0], observer[1], observer[2]);
  expmap->SetNumberOfDirections(100);
  expmap->AddRadius(0.5);
  expmap->AddRadius(1.25);
  expmap->GetIntegrationSettings()->SetMaximumPropagation(2.0);
  expmap->GetIntegrationSettings()->SetInitialIntegrationStep(0.1);
  expmap->Update();

  vtkPolyData* bundle = expmap->GetOutput(0);
  EXPECT_EQ(bundle->GetNumberOfLines(), 100);
  ASSERT_NE(bundle->GetCellData()->GetArray("DirectionId"), nullptr);
  ASSERT_NE(bundle->GetPointData()->GetArray("TransverseJacobian"), nullptr);

  vtkPolyData* fronts = expmap->GetOutput(1);
  ASSERT_EQ(fronts->GetNumberOfPoints(), 200);
  EXPECT_EQ(fronts->GetNumberOfPolys(), 2 * (2 * 100 - 4));
  vtkDataArray* radius = fronts->GetPointData()->GetArray("Radius");
  vtkDataArray* determinant = fronts->GetPointData()->GetArray("TransverseJacobian");
  ASSERT_NE(radius, nullptr);
  ASSERT_NE(determinant, nullptr);
  ASSERT_NE(fronts->GetCellData()->GetArray("Radius"), nullptr);
  for (vtkIdType i = 0; i < fronts->GetNumberOfPoints(); ++i)
  {
    double x[3];
    fronts->GetPoint(i, x);
    const double r = radius->GetTuple1(i);
    EXPECT_NEAR(std::sqrt(vtkMath::Distance2BetweenPoints(x, observer)), r, 1e-12);
    EXPECT_NEAR(determinant->GetTuple1(i), r * r, 1e-12);
  }
}

TEST(ExponentialMap, UnitSphereWavefrontsAndAntipode)
{
  const double observer[3] = { 0.2, 0.1, -0.3 };
  for (const int integrator :
    { vtkRiemannIntegrationSettings::RUNGE_KUTTA4, vtkRiemannIntegrationSettings::DORMAND_PRINCE45 })
  {
    SCOPED_TRACE("integrator " + std::to_string(integrator));
    vtkNew<vtkRiemannExponentialMap> expmap;
    expmap->SetMetric(MakeMetric(SphereJson));
    expmap->SetObserver(observer[0], observer[1], observer[2]);
    expmap->SetNumberOfDirections(60);
    expmap->GetIntegrationSettings()->SetIntegratorType(integrator);
    expmap->GetIntegrationSettings()->SetMaximumError(1e-10);
    for (const double r : { 1.0, 2.0, vtkMath::Pi() })
    {
      expmap->AddRadius(r);
    }
    expmap->GetIntegrationSettings()->SetMaximumPropagation(3.5);
    expmap->Update();
    vtkPolyData* fronts = expmap->GetOutput(1);
    ASSERT_EQ(fronts->GetNumberOfPoints(), 180);
    vtkDataArray* radius = fronts->GetPointData()->GetArray("Radius");
    vtkDataArray* determinant = fronts->GetPointData()->GetArray("TransverseJacobian");
    const double r2 = observer[0] * observer[0] + observer[1] * observer[1] +
      observer[2] * observer[2];
    const double antipode[3] = { -observer[0] / r2, -observer[1] / r2, -observer[2] / r2 };
    for (vtkIdType i = 0; i < fronts->GetNumberOfPoints(); ++i)
    {
      double x[3];
      fronts->GetPoint(i, x);
      const double r = radius->GetTuple1(i);
      EXPECT_NEAR(SphericalDistance(observer, x), r, 1e-6);
      EXPECT_NEAR(determinant->GetTuple1(i), std::pow(std::sin(r), 2), 1e-7);
      if (r == vtkMath::Pi())
      {
        EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(x, antipode)), 1e-6);
      }
    }
    // Along the bundle the determinant is sin^2 s: negative nowhere, zero at pi.
    vtkPolyData* bundle = expmap->GetOutput(0);
    vtkDataArray* s = bundle->GetPointData()->GetArray("ArcLength");
    vtkDataArray* bundleDeterminant = bundle->GetPointData()->GetArray("TransverseJacobian");
    double worst = 0.0;
    for (vtkIdType i = 0; i < bundle->GetNumberOfPoints(); ++i)
    {
      worst = std::max(worst,
        std::abs(bundleDeterminant->GetTuple1(i) - std::pow(std::sin(s->GetTuple1(i)), 2)));
    }
    // Fixed-step RK4 is less accurate where geodesics run through large
    // coordinates (near the point at infinity of the projection).
    EXPECT_LT(worst, integrator == vtkRiemannIntegrationSettings::RUNGE_KUTTA4 ? 1e-4 : 1e-7);
  }
}

TEST(ExponentialMap, ErrorsGiveEmptyOutputs)
{
  ErrorCounter counter;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(&counter);
  callback->SetCallback(ErrorCounter::Callback);
  vtkNew<vtkRiemannExponentialMap> expmap;
  expmap->AddObserver(vtkCommand::ErrorEvent, callback);
  expmap->Update(); // no metric
  EXPECT_EQ(counter.Errors, 1);
  expmap->SetMetric(MakeMetric(EuclideanJson));
  expmap->AddRadius(-1.0);
  expmap->Update(); // negative radius
  EXPECT_EQ(counter.Errors, 2);
  EXPECT_STREQ(expmap->GetLastError(), "Every radius must be a positive number; got -1.");
  EXPECT_EQ(expmap->GetOutput(0)->GetNumberOfPoints(), 0);
  EXPECT_EQ(expmap->GetOutput(1)->GetNumberOfPoints(), 0);
  expmap->RemoveAllRadii();
  expmap->SetNumberOfDirections(1000000);
  expmap->GetIntegrationSettings()->SetMaximumPropagation(100.0);
  expmap->Update(); // 1e10 samples: refused before tracing
  EXPECT_EQ(counter.Errors, 3);
  EXPECT_STREQ(expmap->GetLastError(),
    "Too many samples: 1000000 directions x 10000 steps is more than 3e+07 (about 8 GiB); use "
    "fewer directions or a longer InitialIntegrationStep.");
  EXPECT_EQ(expmap->GetOutput(0)->GetNumberOfPoints(), 0);
  expmap->SetNumberOfDirections(100);
  expmap->GetIntegrationSettings()->SetMaximumPropagation(5.0);
  expmap->SetConeAngle(20.0);
  expmap->SetConeAxis(0.0, 0.0, 0.0);
  expmap->Update(); // zero axis
  EXPECT_EQ(counter.Errors, 4);
  EXPECT_STREQ(expmap->GetLastError(), "ConeAxis: the cone axis must be a finite nonzero vector.");
  EXPECT_EQ(expmap->GetOutput(0)->GetNumberOfPoints(), 0);
  expmap->SetConeAxis(0.0, 0.0, 1.0);
  expmap->SetObserver(0.0, std::numeric_limits<double>::quiet_NaN(), 0.0);
  expmap->Update(); // non-finite observer
  EXPECT_EQ(counter.Errors, 5);
  EXPECT_STREQ(expmap->GetLastError(), "Observer must be finite.");
  EXPECT_EQ(expmap->GetOutput(0)->GetNumberOfPoints(), 0);
  EXPECT_EQ(expmap->GetOutput(1)->GetNumberOfPoints(), 0);
  expmap->SetObserver(0.0, 0.0, 0.0);
  expmap->Update(); // all well again: the error is cleared
  EXPECT_EQ(counter.Errors, 5);
  EXPECT_STREQ(expmap->GetLastError(), "");
  EXPECT_GT(expmap->GetOutput(0)->GetNumberOfPoints(), 0);
}

TEST(ConjugateLocus, SphereLocusSurfaceCollapsesToTheAntipode)
{
  const double observer[3] = { 0.2, 0.1, -0.3 };
  vtkNew<vtkRiemannConjugateLocus> locus;
  locus->SetMetric(MakeMetric(SphereJson));
  locus->SetObserver(observer[0], observer[1], observer[2]);
  locus->SetNumberOfDirections(50);
  locus->GetIntegrationSettings()->SetMaximumPropagation(4.0);
  locus->GetIntegrationSettings()->SetIntegratorTypeToDormandPrince45();
  locus->GetIntegrationSettings()->SetInitialIntegrationStep(0.01);
  locus->Update();
  // Every first conjugate point is double: it lies on sheets 1 and 2, which
  // meet everywhere (each sheet its own copy of the grid's triangles).
  vtkPolyData* surface = locus->GetOutput(1);
  ASSERT_EQ(surface->GetNumberOfPoints(), 100);
  EXPECT_EQ(surface->GetNumberOfPolys(), 2 * (2 * 50 - 4));
  const double r2 =
    observer[0] * observer[0] + observer[1] * observer[1] + observer[2] * observer[2];
  const double antipode[3] = { -observer[0] / r2, -observer[1] / r2, -observer[2] / r2 };
  vtkDataArray* arcLength = surface->GetPointData()->GetArray("ArcLength");
  vtkDataArray* multiplicity = surface->GetPointData()->GetArray("Multiplicity");
  vtkDataArray* pointSheet = surface->GetPointData()->GetArray("Sheet");
  vtkDataArray* cellSheet = surface->GetCellData()->GetArray("Sheet");
  vtkDataArray* singularity = surface->GetCellData()->GetArray("Singularity");
  ASSERT_NE(pointSheet, nullptr);
  ASSERT_NE(cellSheet, nullptr);
  ASSERT_NE(singularity, nullptr);
  for (vtkIdType t = 0; t < surface->GetNumberOfPolys(); ++t)
  {
    EXPECT_EQ(cellSheet->GetTuple1(t), t < 2 * 50 - 4 ? 1 : 2);
    EXPECT_EQ(singularity->GetTuple1(t), 2); // where two sheets meet
  }
  for (vtkIdType i = 0; i < 100; ++i)
  {
    double x[3];
    surface->GetPoint(i, x);
    EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(x, antipode)), 1e-6);
    EXPECT_NEAR(arcLength->GetTuple1(i), vtkMath::Pi(), 1e-6);
    EXPECT_EQ(pointSheet->GetTuple1(i), i < 50 ? 1 : 2);
    EXPECT_EQ(multiplicity->GetTuple1(i), 2);
  }
}
