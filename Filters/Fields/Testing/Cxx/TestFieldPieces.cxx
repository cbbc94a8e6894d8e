// The field filters under VTK's piece requests (what an MPI job or a
// streaming pipeline asks): for N = 1, 2, 3 and 7 pieces, every piece is a
// sub-extent of the whole grid whose values are bitwise the whole grid's at
// the same points, and the pieces cover the grid; with one ghost level a
// piece grows, and exactly the points it adds are marked as duplicated.
#include "vtkRiemannCurvatureField.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannMetricTensorField.h"
#include "vtkRiemannVolumeForm.h"

#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace
{
// Two Gaussian bumps: curvature of both signs everywhere in the grid.
constexpr const char* TwoBumps = R"({"type": "graph", "gaussians": [
  {"amplitude": 1.0, "center": [-0.6, 0, 0], "sigma": 0.5},
  {"amplitude": -0.7, "center": [0.7, 0.3, 0.2], "sigma": 0.4}]})";

/// The grid's point (i, j, k) in `image`'s point ids.
vtkIdType PointId(vtkImageData* image, int i, int j, int k)
{
  const int* e = image->GetExtent();
  const vtkIdType nx = e[1] - e[0] + 1;
  const vtkIdType ny = e[3] - e[2] + 1;
  return (i - e[0]) + nx * ((j - e[2]) + ny * (k - e[4]));
}

template <typename Filter>
void CheckPieces(const char* name)
{
  SCOPED_TRACE(name);
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(TwoBumps)) << metric->GetLastError();
  auto filter = vtkSmartPointer<Filter>::New();
  filter->SetMetric(metric);
  filter->SetBounds(-1.5, 1.5, -1.2, 1.2, -1.0, 1.0);
  filter->SetDimensions(17, 13, 11);
  filter->Update();
  vtkNew<vtkImageData> whole;
  whole->DeepCopy(filter->GetOutput());
  ASSERT_EQ(whole->GetNumberOfPoints(), 17 * 13 * 11);
  const int arrays = whole->GetPointData()->GetNumberOfArrays();
  ASSERT_GT(arrays, 0);

  // Every point of `part` equals the whole grid's, bitwise (NaN included).
  auto checkValues = [&](vtkImageData* part)
  {
    const int* e = part->GetExtent();
    for (int k = e[4]; k <= e[5]; ++k)
    {
      for (int j = e[2]; j <= e[3]; ++j)
      {
        for (int i = e[0]; i <= e[1]; ++i)
        {
          for (int a = 0; a < arrays; ++a)
          {
            vtkDataArray* expected = whole->GetPointData()->GetArray(a);
            vtkDataArray* got = part->GetPointData()->GetArray(expected->GetName());
            ASSERT_NE(got, nullptr) << expected->GetName();
            for (int c = 0; c < expected->GetNumberOfComponents(); ++c)
            {
              const double x = expected->GetComponent(PointId(whole, i, j, k), c);
              const double y = got->GetComponent(PointId(part, i, j, k), c);
              ASSERT_EQ(std::memcmp(&x, &y, sizeof x), 0)
                << expected->GetName() << " at " << i << " " << j << " " << k << ": " << x << " vs "
                << y;
            }
          }
        }
      }
    }
  };
  for (int pieces : { 1, 2, 3, 7 })
  {
    SCOPED_TRACE("pieces " + std::to_string(pieces));
    std::vector<int> covered(static_cast<std::size_t>(whole->GetNumberOfPoints()), 0);
    for (int piece = 0; piece < pieces; ++piece)
    {
      // Without ghost levels: a sub-extent (neighbours share their boundary
      // plane of points, VTK's convention for structured pieces).
      filter->UpdatePiece(piece, pieces, 0);
      auto* part = vtkImageData::SafeDownCast(filter->GetOutput());
      ASSERT_NE(part, nullptr);
      ASSERT_GT(part->GetNumberOfPoints(), 0);
      int own[6];
      part->GetExtent(own);
      EXPECT_EQ(part->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName()), nullptr);
      checkValues(part);
      for (int k = own[4]; k <= own[5]; ++k)
        for (int j = own[2]; j <= own[3]; ++j)
          for (int i = own[0]; i <= own[1]; ++i)
            ++covered[static_cast<std::size_t>(PointId(whole, i, j, k))];

      // One ghost level: a larger extent, the added points marked as duplicated.
      filter->UpdatePiece(piece, pieces, 1);
      part = vtkImageData::SafeDownCast(filter->GetOutput());
      checkValues(part);
      const int* e = part->GetExtent();
      auto* ghost = vtkUnsignedCharArray::SafeDownCast(
        part->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
      if (pieces == 1)
      {
        EXPECT_EQ(ghost, nullptr);
        continue;
      }
      ASSERT_NE(ghost, nullptr);
      int marked = 0;
      for (int k = e[4]; k <= e[5]; ++k)
        for (int j = e[2]; j <= e[3]; ++j)
          for (int i = e[0]; i <= e[1]; ++i)
          {
            const bool inside = i >= own[0] && i <= own[1] && j >= own[2] && j <= own[3] &&
              k >= own[4] && k <= own[5];
            const int value = ghost->GetValue(PointId(part, i, j, k));
            ASSERT_EQ(value, inside ? 0 : vtkDataSetAttributes::DUPLICATEPOINT);
            marked += inside ? 0 : 1;
          }
      EXPECT_GT(marked, 0) << "a piece of several has a ghost layer";
    }
    for (std::size_t p = 0; p < covered.size(); ++p)
    {
      ASSERT_GE(covered[p], 1) << "point " << p << " is in no piece";
    }
  }
}
} // namespace

TEST(FieldPieces, CurvatureFieldPiecesAreTheWholeGrid)
{
  CheckPieces<vtkRiemannCurvatureField>("vtkRiemannCurvatureField");
}

TEST(FieldPieces, MetricTensorFieldPiecesAreTheWholeGrid)
{
  CheckPieces<vtkRiemannMetricTensorField>("vtkRiemannMetricTensorField");
}

TEST(FieldPieces, VolumeFormPiecesAreTheWholeGrid)
{
  CheckPieces<vtkRiemannVolumeForm>("vtkRiemannVolumeForm");
}
