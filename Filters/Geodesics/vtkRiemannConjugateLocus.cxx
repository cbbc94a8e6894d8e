#include "vtkRiemannConjugateLocus.h"

#include "CausticSheets.h"
#include "ConjugatePoints.h"
#include "Metric.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
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
#include <array>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkRiemannConjugateLocus);

vtkRiemannConjugateLocus::vtkRiemannConjugateLocus()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
  // Defaults of this filter. DORMAND_PRINCE45: on the round sphere it finds
  // all of 10,000 double conjugate points to 1e-8, where RK4 at step 0.01
  // gives up on some: they pass near the chart's point at infinity, where the
  // fixed step drifts g(v, v) past the search's trust limit
  // (Testing/Benchmarks/README.md). MaximumError is only a cap: the
  // integration tolerance follows Tolerance (FindConjugatePoints). The step
  // budget is large: the search must not stop before MaximumPropagation.
  vtkRiemannIntegrationSettings* settings = this->GetIntegrationSettings();
  settings->SetIntegratorTypeToDormandPrince45();
  settings->SetMaximumIntegrationStep(0.1);
  settings->SetMaximumError(1e-6);
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

  // Search in parallel (progress and abort between batches), PacketWidth
  // directions in lock step on the packet engine.
  const vtkIdType count = static_cast<vtkIdType>(directions.size());
  std::vector<std::vector<riemann::ConjugatePoint>> found(directions.size());
  const double tolerance = this->Tolerance;
  const int maximumCount = this->MaximumNumberOfConjugatePoints;
  const vtkIdType done = vtkRiemannForInBatches(
    this, count, 64,
    [&](vtkIdType first, vtkIdType last)
    {
      riemann::FindConjugatePoints(*metric, observer, directions.data() + first,
        static_cast<size_t>(last - first), options, tolerance, maximumCount, found.data() + first);
    },
    4 * riemann::PacketWidth);

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
  vtkNew<vtkIntArray> sheet;
  sheet->SetName("Sheet");
  sheet->SetNumberOfTuples(pointCount);
  vtkNew<vtkDoubleArray> kernel;
  kernel->SetName("KernelDirection");
  kernel->SetNumberOfComponents(3);
  kernel->SetNumberOfTuples(pointCount);
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
      sheet->SetValue(next, point.Sheet);
      kernel->SetTypedTuple(next, point.KernelDirection.data());
      ++next;
    }
  }
  output->SetPoints(points);
  output->SetVerts(vertices);
  output->GetPointData()->AddArray(arcLength);
  output->GetPointData()->AddArray(multiplicity);
  output->GetPointData()->AddArray(index);
  output->GetPointData()->AddArray(directionId);
  output->GetPointData()->AddArray(sheet);
  output->GetPointData()->AddArray(kernel);
  if (done == count)
  {
    riemann::Mat3 g;
    if (metric->Tensor(observer, g))
    {
      this->BuildLocusSurfaces(grid, directions, found, g, locus);
    }
  }
  return 1;
}

void vtkRiemannConjugateLocus::BuildLocusSurfaces(vtkPolyData* grid,
  const std::vector<riemann::Vec3>& directions,
  const std::vector<std::vector<riemann::ConjugatePoint>>& found, const riemann::Mat3& g,
  vtkPolyData* locus)
{
  std::vector<std::array<int, 3>> gridTriangles;
  gridTriangles.reserve(static_cast<size_t>(grid->GetNumberOfPolys()));
  vtkCellArray* polys = grid->GetPolys();
  vtkNew<vtkIdList> cell;
  for (polys->InitTraversal(); polys->GetNextCell(cell);)
  {
    gridTriangles.push_back({ static_cast<int>(cell->GetId(0)), static_cast<int>(cell->GetId(1)),
      static_cast<int>(cell->GetId(2)) });
  }
  const riemann::CausticSheets sheets =
    riemann::BuildCausticSheets(directions, gridTriangles, found, g);

  const vtkIdType pointCount = static_cast<vtkIdType>(sheets.Points.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(pointCount);
  vtkNew<vtkDoubleArray> arcLength, kernelSlope;
  arcLength->SetName("ArcLength");
  arcLength->SetNumberOfTuples(pointCount);
  kernelSlope->SetName("KernelSlope");
  kernelSlope->SetNumberOfTuples(pointCount);
  vtkNew<vtkIntArray> multiplicity, index, sheet, directionId;
  multiplicity->SetName("Multiplicity");
  multiplicity->SetNumberOfTuples(pointCount);
  index->SetName("ConjugateIndex");
  index->SetNumberOfTuples(pointCount);
  sheet->SetName("Sheet");
  sheet->SetNumberOfTuples(pointCount);
  directionId->SetName("DirectionId");
  directionId->SetNumberOfTuples(pointCount);
  for (vtkIdType v = 0; v < pointCount; ++v)
  {
    points->SetPoint(v, sheets.Points[v].data());
    arcLength->SetValue(v, sheets.ArcLength[v]);
    kernelSlope->SetValue(v, sheets.KernelSlope[v]);
    multiplicity->SetValue(v, sheets.Multiplicity[v]);
    index->SetValue(v, sheets.Index[v]);
    sheet->SetValue(v, sheets.Sheet[v]);
    directionId->SetValue(v, sheets.Direction[v]);
  }

  const vtkIdType triangleCount = static_cast<vtkIdType>(sheets.Triangles.size());
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(triangleCount, 3 * triangleCount);
  vtkNew<vtkIntArray> cellSheet, singularity;
  cellSheet->SetName("Sheet");
  cellSheet->SetNumberOfTuples(triangleCount);
  singularity->SetName("Singularity");
  singularity->SetNumberOfTuples(triangleCount);
  for (vtkIdType t = 0; t < triangleCount; ++t)
  {
    const vtkIdType ids[3] = { sheets.Triangles[t][0], sheets.Triangles[t][1],
      sheets.Triangles[t][2] };
    triangles->InsertNextCell(3, ids);
    cellSheet->SetValue(t, sheets.TriangleSheet[t]);
    singularity->SetValue(t, sheets.TriangleSingularity[t]);
  }
  locus->SetPoints(points);
  locus->SetPolys(triangles);
  locus->GetPointData()->AddArray(arcLength);
  locus->GetPointData()->AddArray(multiplicity);
  locus->GetPointData()->AddArray(index);
  locus->GetPointData()->AddArray(sheet);
  locus->GetPointData()->AddArray(directionId);
  locus->GetPointData()->AddArray(kernelSlope);
  locus->GetCellData()->AddArray(cellSheet);
  locus->GetCellData()->AddArray(singularity);
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
