// vtkRiemannGeodesicTracer under VTK's piece requests (what an MPI job asks):
// for N = 2, 3 and 5 pieces, the pieces appended in order are the one-piece
// output: the same lines in the same order with the same SeedIds, bitwise the
// same points and arrays (each seed is traced by the same code wherever it
// falls), and every seed appears in exactly one piece.
#include "vtkRiemannGeodesicTracer.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace
{
constexpr const char* TwoBumps = R"({"type": "graph", "gaussians": [
  {"amplitude": 1.0, "center": [-0.6, 0, 0], "sigma": 0.5},
  {"amplitude": -0.7, "center": [0.7, 0.3, 0.2], "sigma": 0.4}]})";

/// 11 seeds on a line through the bumps, directions fanned out.
vtkSmartPointer<vtkPolyData> Seeds()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> directions;
  directions->SetName("Direction");
  directions->SetNumberOfComponents(3);
  for (int i = 0; i < 11; ++i)
  {
    const double a = -1.0 + 0.2 * i;
    points->InsertNextPoint(-2.0, 0.3 * a, 0.1 * a);
    directions->InsertNextTuple3(1.0, 0.2 * std::sin(3.0 * a), 0.1 * a);
  }
  auto seeds = vtkSmartPointer<vtkPolyData>::New();
  seeds->SetPoints(points);
  seeds->GetPointData()->AddArray(directions);
  return seeds;
}

/// Copies of the lines of `data`: their points and every array's values.
struct Lines
{
  std::vector<std::vector<double>> Values; // per line: points then point arrays
  std::vector<int> SeedIds;
  std::vector<int> Reasons;

  void Append(vtkPolyData* data)
  {
    vtkCellArray* lines = data->GetLines();
    auto* ids = vtkIntArray::SafeDownCast(data->GetCellData()->GetArray("SeedIds"));
    auto* reasons =
      vtkIntArray::SafeDownCast(data->GetCellData()->GetArray("ReasonForTermination"));
    ASSERT_NE(ids, nullptr);
    ASSERT_NE(reasons, nullptr);
    vtkIdType line = 0;
    vtkIdType count = 0;
    const vtkIdType* pointIds = nullptr;
    for (lines->InitTraversal(); lines->GetNextCell(count, pointIds); ++line)
    {
      std::vector<double> values;
      for (vtkIdType k = 0; k < count; ++k)
      {
        double p[3];
        data->GetPoint(pointIds[k], p);
        values.insert(values.end(), p, p + 3);
        for (int a = 0; a < data->GetPointData()->GetNumberOfArrays(); ++a)
        {
          vtkDataArray* array = data->GetPointData()->GetArray(a);
          for (int c = 0; c < array->GetNumberOfComponents(); ++c)
          {
            values.push_back(array->GetComponent(pointIds[k], c));
          }
        }
      }
      this->Values.push_back(values);
      this->SeedIds.push_back(ids->GetValue(line));
      this->Reasons.push_back(reasons->GetValue(line));
    }
  }
};
} // namespace

TEST(TracerPieces, PiecesAppendedInOrderAreTheWholeOutput)
{
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(TwoBumps)) << metric->GetLastError();
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  tracer->SetMetric(metric);
  tracer->SetInputData(Seeds());
  tracer->SetIntegrationDirectionToBoth();
  tracer->GetIntegrationSettings()->SetMaximumPropagation(4.0);
  tracer->ComputeTransverseJacobianOn();
  tracer->Update();
  Lines whole;
  whole.Append(tracer->GetOutput());
  ASSERT_EQ(whole.Values.size(), 22u) << "11 seeds, both directions";

  for (int pieces : { 2, 3, 5 })
  {
    SCOPED_TRACE("pieces " + std::to_string(pieces));
    Lines appended;
    for (int piece = 0; piece < pieces; ++piece)
    {
      tracer->UpdatePiece(piece, pieces, 0);
      EXPECT_GT(tracer->GetOutput()->GetNumberOfLines(), 0);
      appended.Append(tracer->GetOutput());
    }
    ASSERT_EQ(appended.Values.size(), whole.Values.size());
    EXPECT_EQ(appended.SeedIds, whole.SeedIds);
    EXPECT_EQ(appended.Reasons, whole.Reasons);
    for (std::size_t line = 0; line < whole.Values.size(); ++line)
    {
      ASSERT_EQ(appended.Values[line].size(), whole.Values[line].size()) << "line " << line;
      EXPECT_EQ(std::memcmp(appended.Values[line].data(), whole.Values[line].data(),
                  whole.Values[line].size() * sizeof(double)),
        0)
        << "line " << line << " differs";
    }
  }
  // Asked for the whole again: everything.
  tracer->UpdatePiece(0, 1, 0);
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfLines(), 22);
}
