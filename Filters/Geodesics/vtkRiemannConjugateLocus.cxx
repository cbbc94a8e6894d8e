#include "vtkRiemannConjugateLocus.h"

#include "ConjugatePoints.h"
#include "Metric.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRiemannDirectionGrid.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannParallelBatches.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkRiemannConjugateLocus);

vtkRiemannConjugateLocus::vtkRiemannConjugateLocus()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
  // Defaults of this filter. DORMAND_PRINCE45: on the round sphere it finds
  // all of 10,000 double conjugate points to 1e-8 and is faster than RK4 at
  // step 0.01, which gives up on 16 of them: they pass near the chart's point
  // at infinity, where the fixed step drifts g(v, v) past the search's trust
  // limit (Testing/Benchmarks/README.md). The largest step, 0.1, is short
  // enough that no step jumps over two conjugate points; the step budget is
  // large: the search must not stop before MaximumPropagation.
  vtkRiemannIntegrationSettings* settings = this->GetIntegrationSettings();
  settings->SetIntegratorTypeToDormandPrince45();
  settings->SetMaximumIntegrationStep(0.1);
  settings->SetMaximumError(1e-9);
  settings->SetMaximumNumberOfSteps(10000000);
}

vtkRiemannConjugateLocus::~vtkRiemannConjugateLocus() = default;

int vtkRiemannConjugateLocus::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* locus = vtkPolyData::GetData(outputVector, 1);
  output->Initialize();
  locus->Initialize();
  const std::shared_ptr<const riemann::Metric> metric = this->CheckMetricAndSettings();
  if (!metric)
  {
    return 1;
  }
  vtkNew<vtkPolyData> grid;
  if (!this->CheckObserver(this->Observer) ||
    !this->BuildDirectionGrid(this->NumberOfDirections, this->ConeAxis, this->ConeAngle, grid))
  {
    return 1;
  }
  const riemann::Vec3 observer(this->Observer[0], this->Observer[1], this->Observer[2]);
  std::vector<riemann::Vec3> directions(static_cast<size_t>(grid->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    grid->GetPoint(i, directions[i].data());
  }
  const riemann::GeodesicOptions options = this->MakeGeodesicOptions();

  // Search in parallel (progress and abort between batches).
  const vtkIdType count = static_cast<vtkIdType>(directions.size());
  std::vector<std::vector<riemann::ConjugatePoint>> found(directions.size());
  const double tolerance = this->Tolerance;
  const int maximumCount = this->MaximumNumberOfConjugatePoints;
  const vtkIdType done = vtkRiemannForInBatches(this, count, 64,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        found[i] = riemann::FindConjugatePoints(
          *metric, observer, directions[i], options, tolerance, maximumCount);
      }
    });

  vtkIdType pointCount = 0;
  for (vtkIdType i = 0; i < done; ++i)
  {
    pointCount += static_cast<vtkIdType>(found[i].size());
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(pointCount);
  vtkNew<vtkCellArray> vertices;
  vertices->AllocateExact(pointCount, pointCount);
  vtkNew<vtkDoubleArray> arcLength;
  arcLength->SetName("ArcLength");
  arcLength->SetNumberOfTuples(pointCount);
  vtkNew<vtkIntArray> multiplicity, index, directionId;
  multiplicity->SetName("Multiplicity");
  multiplicity->SetNumberOfTuples(pointCount);
  index->SetName("ConjugateIndex");
  index->SetNumberOfTuples(pointCount);
  directionId->SetName("DirectionId");
  directionId->SetNumberOfTuples(pointCount);
  vtkIdType next = 0;
  for (vtkIdType i = 0; i < done; ++i)
  {
    for (const riemann::ConjugatePoint& point : found[i])
    {
      points->SetPoint(next, point.Point.data());
      vertices->InsertNextCell(1, &next);
      arcLength->SetValue(next, point.ArcLength);
      multiplicity->SetValue(next, point.Multiplicity);
      index->SetValue(next, point.Index);
      directionId->SetValue(next, static_cast<int>(i));
      ++next;
    }
  }
  output->SetPoints(points);
  output->SetVerts(vertices);
  output->GetPointData()->AddArray(arcLength);
  output->GetPointData()->AddArray(multiplicity);
  output->GetPointData()->AddArray(index);
  output->GetPointData()->AddArray(directionId);
  if (done == count)
  {
    this->BuildLocusSurfaces(grid, found, locus);
  }
  return 1;
}

void vtkRiemannConjugateLocus::BuildLocusSurfaces(vtkPolyData* grid,
  const std::vector<std::vector<riemann::ConjugatePoint>>& found, vtkPolyData* locus)
{
  size_t deepest = 0;
  for (const auto& points : found)
  {
    deepest = std::max(deepest, points.size());
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkDoubleArray> arcLength;
  arcLength->SetName("ArcLength");
  vtkNew<vtkIntArray> multiplicity, index, directionId, cellIndex;
  multiplicity->SetName("Multiplicity");
  index->SetName("ConjugateIndex");
  directionId->SetName("DirectionId");
  cellIndex->SetName("ConjugateIndex");
  std::vector<vtkIdType> local(found.size());
  for (size_t k = 0; k < deepest; ++k)
  {
    for (size_t i = 0; i < found.size(); ++i)
    {
      local[i] = -1;
      if (found[i].size() > k)
      {
        const riemann::ConjugatePoint& point = found[i][k];
        local[i] = points->InsertNextPoint(point.Point.data());
        arcLength->InsertNextValue(point.ArcLength);
        multiplicity->InsertNextValue(point.Multiplicity);
        index->InsertNextValue(point.Index);
        directionId->InsertNextValue(static_cast<int>(i));
      }
    }
    const vtkIdType appended = vtkRiemannDirectionGrid::AppendTriangles(grid, local, triangles);
    for (vtkIdType t = 0; t < appended; ++t)
    {
      cellIndex->InsertNextValue(static_cast<int>(k) + 1);
    }
  }
  locus->SetPoints(points);
  locus->SetPolys(triangles);
  locus->GetPointData()->AddArray(arcLength);
  locus->GetPointData()->AddArray(multiplicity);
  locus->GetPointData()->AddArray(index);
  locus->GetPointData()->AddArray(directionId);
  locus->GetCellData()->AddArray(cellIndex);
}

void vtkRiemannConjugateLocus::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Observer: " << this->Observer[0] << " " << this->Observer[1] << " "
     << this->Observer[2] << "\n";
  os << indent << "NumberOfDirections: " << this->NumberOfDirections << "\n";
  os << indent << "ConeAxis: " << this->ConeAxis[0] << " " << this->ConeAxis[1] << " "
     << this->ConeAxis[2] << "\n";
  os << indent << "ConeAngle: " << this->ConeAngle << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaximumNumberOfConjugatePoints: " << this->MaximumNumberOfConjugatePoints
     << "\n";
}
