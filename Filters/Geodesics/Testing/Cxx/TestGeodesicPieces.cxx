// The geodesic filters under VTK's piece requests (what an MPI job asks):
// - vtkRiemannGeodesicTracer, N = 2, 3, 5: the pieces appended in order are
//   the one-piece output: the same lines in the same order with the same
//   SeedIds, bitwise the same points and arrays (each seed is traced by the
//   same code wherever it falls), every seed in exactly one piece;
// - vtkRiemannExponentialMap, N = 2, 3: the rays likewise (DirectionIds),
//   and the wavefronts' own points (not ghosts) and triangles are exactly the
//   one-piece output's, bitwise, each in one piece;
// - vtkRiemannConjugateLocus, N = 2, 3, on the astigmatic lens (two sheets
//   with cusp edges): the conjugate points appended in order, and the
//   sheets' own points (with KernelSlope, which reads the neighbours) and
//   triangles (with their Singularity) are the one-piece output's, bitwise.
#include "vtkRiemannConjugateLocus.h"
#include "vtkRiemannExponentialMap.h"
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

#include "vtkDataSetAttributes.h"
#include "vtkIdList.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
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
  const char* IdName = "SeedIds";
  std::vector<std::vector<double>> Values; // per line: points then point arrays
  std::vector<int> SeedIds;
  std::vector<int> Reasons;

  void Append(vtkPolyData* data)
  {
    vtkCellArray* lines = data->GetLines();
    auto* ids = vtkIntArray::SafeDownCast(data->GetCellData()->GetArray(this->IdName));
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

TEST(GeodesicPieces, TracerPiecesAppendedInOrderAreTheWholeOutput)
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

namespace
{
/// A wavefront point: (radius, direction) -> its coordinates and arrays.
using PointKey = std::pair<double, int>;

/// The wavefronts' own points (not ghosts) and triangles (by their corners' keys).
struct Wavefronts
{
  std::map<PointKey, std::vector<double>> Points;
  std::vector<std::array<PointKey, 3>> Triangles;
  int Duplicates = 0;

  void Append(vtkPolyData* data)
  {
    auto* radius = data->GetPointData()->GetArray("Radius");
    auto* direction = data->GetPointData()->GetArray("DirectionId");
    auto* ghost = vtkUnsignedCharArray::SafeDownCast(
      data->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
    ASSERT_NE(radius, nullptr);
    ASSERT_NE(direction, nullptr);
    auto key = [&](vtkIdType id) {
      return PointKey(
        radius->GetComponent(id, 0), static_cast<int>(direction->GetComponent(id, 0)));
    };
    for (vtkIdType id = 0; id < data->GetNumberOfPoints(); ++id)
    {
      if (ghost && ghost->GetValue(id) != 0)
      {
        continue;
      }
      std::vector<double> values(3);
      data->GetPoint(id, values.data());
      for (const char* name : { "TransverseJacobian", "TransverseJacobianSingularValues" })
      {
        vtkDataArray* array = data->GetPointData()->GetArray(name);
        for (int c = 0; c < array->GetNumberOfComponents(); ++c)
        {
          values.push_back(array->GetComponent(id, c));
        }
      }
      this->Duplicates += this->Points.count(key(id)) ? 1 : 0;
      this->Points[key(id)] = values;
    }
    vtkNew<vtkIdList> cell;
    vtkCellArray* polys = data->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(cell);)
    {
      std::array<PointKey, 3> corners = { key(cell->GetId(0)), key(cell->GetId(1)),
        key(cell->GetId(2)) };
      this->Triangles.push_back(corners);
    }
  }
};
} // namespace

TEST(GeodesicPieces, ExponentialMapPiecesAreTheWholeOutput)
{
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(TwoBumps)) << metric->GetLastError();
  vtkNew<vtkRiemannExponentialMap> expmap;
  expmap->SetMetric(metric);
  expmap->SetObserver(-1.8, 0.1, 0.0);
  expmap->SetNumberOfDirections(90);
  expmap->GetIntegrationSettings()->SetMaximumPropagation(2.0);
  expmap->AddRadius(0.7);
  expmap->AddRadius(1.5);
  expmap->Update();
  Lines wholeRays;
  wholeRays.IdName = "DirectionId";
  wholeRays.Append(expmap->GetOutput(0));
  Wavefronts whole;
  whole.Append(expmap->GetOutput(1));
  ASSERT_EQ(wholeRays.Values.size(), 90u);
  ASSERT_GT(whole.Triangles.size(), 100u);
  std::sort(whole.Triangles.begin(), whole.Triangles.end());

  for (int pieces : { 2, 3 })
  {
    SCOPED_TRACE("pieces " + std::to_string(pieces));
    Lines rays;
    rays.IdName = "DirectionId";
    Wavefronts parts;
    for (int piece = 0; piece < pieces; ++piece)
    {
      expmap->UpdatePiece(piece, pieces, 0);
      rays.Append(expmap->GetOutput(0));
      parts.Append(expmap->GetOutput(1));
      EXPECT_NE(
        expmap->GetOutput(1)->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName()),
        nullptr);
    }
    EXPECT_EQ(rays.SeedIds, wholeRays.SeedIds);
    ASSERT_EQ(rays.Values.size(), wholeRays.Values.size());
    for (std::size_t line = 0; line < rays.Values.size(); ++line)
    {
      ASSERT_EQ(rays.Values[line].size(), wholeRays.Values[line].size());
      EXPECT_EQ(std::memcmp(rays.Values[line].data(), wholeRays.Values[line].data(),
                  rays.Values[line].size() * sizeof(double)),
        0)
        << "ray " << line;
    }
    EXPECT_EQ(parts.Duplicates, 0) << "a wavefront point owned by two pieces";
    ASSERT_EQ(parts.Points.size(), whole.Points.size());
    for (const auto& [key, values] : whole.Points)
    {
      const auto found = parts.Points.find(key);
      ASSERT_NE(found, parts.Points.end()) << "radius " << key.first << " direction " << key.second;
      EXPECT_EQ(std::memcmp(found->second.data(), values.data(), values.size() * sizeof(double)), 0)
        << "radius " << key.first << " direction " << key.second;
    }
    std::sort(parts.Triangles.begin(), parts.Triangles.end());
    EXPECT_EQ(parts.Triangles, whole.Triangles);
  }
}

namespace
{
/// Every value of point `id`: its coordinates, then each point array's components.
std::vector<double> PointValues(vtkPolyData* data, vtkIdType id)
{
  std::vector<double> values(3);
  data->GetPoint(id, values.data());
  for (int a = 0; a < data->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = data->GetPointData()->GetArray(a);
    if (std::string(array->GetName()) == vtkDataSetAttributes::GhostArrayName())
    {
      continue;
    }
    for (int c = 0; c < array->GetNumberOfComponents(); ++c)
    {
      values.push_back(array->GetComponent(id, c));
    }
  }
  return values;
}

/// The caustic sheets' own points by (Sheet, DirectionId), and triangles by
/// (sheet, corner directions, singularity).
struct Sheets
{
  std::map<std::pair<int, int>, std::vector<double>> Points;
  std::vector<std::array<int, 5>> Triangles;
  int Duplicates = 0;

  void Append(vtkPolyData* data)
  {
    vtkDataArray* sheet = data->GetPointData()->GetArray("Sheet");
    vtkDataArray* direction = data->GetPointData()->GetArray("DirectionId");
    auto* ghost = vtkUnsignedCharArray::SafeDownCast(
      data->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
    ASSERT_NE(sheet, nullptr);
    for (vtkIdType id = 0; id < data->GetNumberOfPoints(); ++id)
    {
      if (ghost && ghost->GetValue(id) != 0)
      {
        continue;
      }
      const std::pair<int, int> key(
        static_cast<int>(sheet->GetTuple1(id)), static_cast<int>(direction->GetTuple1(id)));
      this->Duplicates += this->Points.count(key) ? 1 : 0;
      this->Points[key] = PointValues(data, id);
    }
    vtkDataArray* cellSheet = data->GetCellData()->GetArray("Sheet");
    vtkDataArray* singularity = data->GetCellData()->GetArray("Singularity");
    vtkNew<vtkIdList> cell;
    vtkIdType t = 0;
    vtkCellArray* polys = data->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(cell); ++t)
    {
      this->Triangles.push_back({ static_cast<int>(cellSheet->GetTuple1(t)),
        static_cast<int>(direction->GetTuple1(cell->GetId(0))),
        static_cast<int>(direction->GetTuple1(cell->GetId(1))),
        static_cast<int>(direction->GetTuple1(cell->GetId(2))),
        static_cast<int>(singularity->GetTuple1(t)) });
    }
  }
};
} // namespace

TEST(GeodesicPieces, ConjugateLocusPiecesAreTheWholeOutput)
{
  // Data/metrics/astigmatic-lens.json, seen from its axis through a cone.
  vtkNew<vtkRiemannMetric> metric;
  ASSERT_TRUE(metric->SetDefinition(R"({"type": "conformal", "constant": 1.0,
    "gaussians": [{"amplitude": 0.6, "center": [0, 0, 0], "sigma": [1.0, 0.6, 0.85]}]})"));
  vtkNew<vtkRiemannConjugateLocus> locus;
  locus->SetMetric(metric);
  locus->SetObserver(-3.0, 0.0, 0.0);
  locus->SetConeAxis(1.0, 0.0, 0.0);
  locus->SetConeAngle(14.0);
  locus->SetNumberOfDirections(300);
  locus->SetMaximumNumberOfConjugatePoints(3);
  locus->GetIntegrationSettings()->SetMaximumPropagation(9.0);
  locus->Update();
  vtkPolyData* wholePoints = locus->GetOutput(0);
  std::vector<std::vector<double>> points;
  for (vtkIdType id = 0; id < wholePoints->GetNumberOfPoints(); ++id)
  {
    points.push_back(PointValues(wholePoints, id));
  }
  ASSERT_EQ(points.size(), 600u) << "two conjugate points per direction";
  Sheets whole;
  whole.Append(locus->GetOutput(1));
  std::sort(whole.Triangles.begin(), whole.Triangles.end());
  int cusps = 0;
  for (const auto& t : whole.Triangles)
  {
    cusps += t[4] == 1 ? 1 : 0;
  }
  ASSERT_GT(cusps, 0) << "the sheets have cusp edges";

  for (int pieces : { 2, 3 })
  {
    SCOPED_TRACE("pieces " + std::to_string(pieces));
    std::vector<std::vector<double>> appended;
    Sheets parts;
    for (int piece = 0; piece < pieces; ++piece)
    {
      locus->UpdatePiece(piece, pieces, 0);
      vtkPolyData* part = locus->GetOutput(0);
      for (vtkIdType id = 0; id < part->GetNumberOfPoints(); ++id)
      {
        appended.push_back(PointValues(part, id));
      }
      parts.Append(locus->GetOutput(1));
    }
    ASSERT_EQ(appended.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      ASSERT_EQ(appended[i].size(), points[i].size());
      EXPECT_EQ(
        std::memcmp(appended[i].data(), points[i].data(), points[i].size() * sizeof(double)), 0)
        << "conjugate point " << i;
    }
    EXPECT_EQ(parts.Duplicates, 0);
    ASSERT_EQ(parts.Points.size(), whole.Points.size());
    for (const auto& [key, values] : whole.Points)
    {
      const auto found = parts.Points.find(key);
      ASSERT_NE(found, parts.Points.end()) << "sheet " << key.first << " direction " << key.second;
      ASSERT_EQ(found->second.size(), values.size());
      EXPECT_EQ(std::memcmp(found->second.data(), values.data(), values.size() * sizeof(double)), 0)
        << "sheet " << key.first << " direction " << key.second;
    }
    std::sort(parts.Triangles.begin(), parts.Triangles.end());
    EXPECT_EQ(parts.Triangles, whole.Triangles);
  }
}
