// The caustic as sheets (vtkRiemannConjugateLocus port 1, CausticSheets.h):
// - the round 3-sphere: every one of 10,000 first conjugate points is the
//   antipode at pi, of multiplicity 2 (sheets 1 and 2 meet everywhere);
// - the astigmatic lens of Data/metrics: two separate sheets (the two focal
//   surfaces), each with its cusp edge in its symmetry plane (the kernel
//   direction is the one the sheet focuses, and by symmetry the conjugate
//   distance does not change along it there).
#include "vtkRiemannConjugateLocus.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace
{
// Data/metrics/astigmatic-lens.json.
constexpr const char* LensJson = R"J({"type":"conformal","constant":1.0,
  "gaussians":[{"amplitude":0.6,"center":[0,0,0],"sigma":[1.0,0.6,0.85]}]})J";

vtkSmartPointer<vtkRiemannMetric> MakeMetric(const char* json)
{
  auto metric = vtkSmartPointer<vtkRiemannMetric>::New();
  EXPECT_TRUE(metric->SetDefinition(json)) << json;
  return metric;
}

TEST(CausticSheets, RoundSphereIsDoubleInEveryOfTenThousandDirections)
{
  vtkNew<vtkRiemannConjugateLocus> locus;
  locus->SetMetric(MakeMetric(R"J({"type":"conformal","n":"2/(1+x^2+y^2+z^2)"})J"));
  locus->SetObserver(0.2, 0.1, -0.3);
  locus->SetNumberOfDirections(10000);
  locus->Update(); // the filter's defaults: dp45, tolerance 1e-8, length 10
  vtkPolyData* points = locus->GetOutput(0);
  ASSERT_EQ(points->GetNumberOfPoints(), 10000);
  vtkDataArray* arcLength = points->GetPointData()->GetArray("ArcLength");
  vtkDataArray* multiplicity = points->GetPointData()->GetArray("Multiplicity");
  vtkDataArray* sheet = points->GetPointData()->GetArray("Sheet");
  double largestError = 0.0;
  int doubles = 0;
  for (vtkIdType i = 0; i < 10000; ++i)
  {
    largestError = std::max(largestError, std::abs(arcLength->GetTuple1(i) - M_PI));
    doubles += multiplicity->GetTuple1(i) == 2 ? 1 : 0;
    EXPECT_EQ(sheet->GetTuple1(i), 1);
  }
  std::cout << "round sphere: " << doubles << " of 10000 double, largest |ArcLength - pi| "
            << largestError << "\n";
  EXPECT_EQ(doubles, 10000);
  EXPECT_LT(largestError, 1e-8);
}

TEST(CausticSheets, AstigmaticLensHasTwoSheetsWithCuspEdgesInTheirPlanes)
{
  // Observer on the lens axis, 3 in front; a cone of 14 degrees through it.
  vtkNew<vtkRiemannConjugateLocus> locus;
  locus->SetMetric(MakeMetric(LensJson));
  locus->SetObserver(-3.0, 0.0, 0.0);
  locus->SetConeAxis(1.0, 0.0, 0.0);
  locus->SetConeAngle(14.0);
  locus->SetNumberOfDirections(1500);
  locus->SetMaximumNumberOfConjugatePoints(3);
  locus->GetIntegrationSettings()->SetMaximumPropagation(9.0);
  locus->Update();
  vtkPolyData* points = locus->GetOutput(0);
  vtkPolyData* sheets = locus->GetOutput(1);
  // Two simple points per direction: the first focuses across y (the lens
  // is stronger across y: sigma 0.6 against 0.85), the second across z.
  ASSERT_EQ(points->GetNumberOfPoints(), 3000);
  vtkDataArray* kernel = points->GetPointData()->GetArray("KernelDirection");
  vtkDataArray* pointSheet = points->GetPointData()->GetArray("Sheet");
  ASSERT_NE(kernel, nullptr);
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    ASSERT_EQ(points->GetPointData()->GetArray("Multiplicity")->GetTuple1(i), 1);
    const double* u = kernel->GetTuple3(i);
    const int k = static_cast<int>(pointSheet->GetTuple1(i));
    ASSERT_EQ(k, 1 + static_cast<int>(i % 2));
    EXPECT_GT(std::abs(u[k]), std::abs(u[3 - k])) << "point " << i;
  }

  // Each sheet has every direction's point and the grid's triangles, apart
  // from each other: the y-focus (sheet 1) before the z-focus (sheet 2).
  vtkDataArray* cellSheet = sheets->GetCellData()->GetArray("Sheet");
  vtkDataArray* singularity = sheets->GetCellData()->GetArray("Singularity");
  vtkDataArray* sheetOfPoint = sheets->GetPointData()->GetArray("Sheet");
  ASSERT_NE(cellSheet, nullptr);
  ASSERT_NE(singularity, nullptr);
  ASSERT_EQ(sheets->GetNumberOfPoints(), 3000);
  double xRange[2][2] = { { HUGE_VAL, -HUGE_VAL }, { HUGE_VAL, -HUGE_VAL } };
  for (vtkIdType i = 0; i < sheets->GetNumberOfPoints(); ++i)
  {
    const int k = static_cast<int>(sheetOfPoint->GetTuple1(i)) - 1;
    const double x = sheets->GetPoint(i)[0];
    xRange[k][0] = std::min(xRange[k][0], x);
    xRange[k][1] = std::max(xRange[k][1], x);
  }
  std::cout << "sheet 1: x in [" << xRange[0][0] << ", " << xRange[0][1] << "], sheet 2: x in ["
            << xRange[1][0] << ", " << xRange[1][1] << "]\n";
  EXPECT_LT(xRange[0][1], xRange[1][0]);

  // Cusp edges: sheet 1's in the plane y = 0, sheet 2's in z = 0, and no
  // cusp triangle elsewhere; every triangle of a sheet joins points of that
  // sheet.
  int cusps[2] = { 0, 0 };
  int triangles[2] = { 0, 0 };
  vtkNew<vtkIdList> cell;
  vtkCellArray* polys = sheets->GetPolys();
  vtkIdType t = 0;
  for (polys->InitTraversal(); polys->GetNextCell(cell); ++t)
  {
    const int k = static_cast<int>(cellSheet->GetTuple1(t)) - 1;
    ++triangles[k];
    double centroid[3] = { 0.0, 0.0, 0.0 };
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_EQ(sheetOfPoint->GetTuple1(cell->GetId(c)), k + 1);
      const double* x = sheets->GetPoint(cell->GetId(c));
      for (int j = 0; j < 3; ++j)
      {
        centroid[j] += x[j] / 3.0;
      }
    }
    EXPECT_NE(singularity->GetTuple1(t), 2); // no double points here
    if (singularity->GetTuple1(t) == 1)
    {
      ++cusps[k];
      EXPECT_LT(std::abs(centroid[1 + k]), 1e-3) << "cusp triangle " << t << " of sheet " << k + 1;
    }
  }
  std::cout << "sheet 1: " << triangles[0] << " triangles, " << cusps[0]
            << " on its cusp edge; sheet 2: " << triangles[1] << ", " << cusps[1] << "\n";
  EXPECT_GT(triangles[0], 2900);
  EXPECT_EQ(triangles[0], triangles[1]);
  EXPECT_GT(cusps[0], 20);
  EXPECT_GT(cusps[1], 20);
}
} // namespace
