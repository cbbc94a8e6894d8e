#include "vtkRiemannConjugateLocus.h"
#include "RiemannConjugateLocusDeclaration.h"

#include "CausticSheets.h"
#include "ConjugatePoints.h"
#include "Metric.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
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
#include "RiemannIntegrationSettingsDeclaration.h"
#include "vtkRiemannParallelBatches.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkRiemannConjugateLocus);

vtkRiemannConjugateLocus::vtkRiemannConjugateLocus()
{
  namespace declared = riemann::declared::vtkRiemannConjugateLocus;
  std::copy(declared::Default::Observer, declared::Default::Observer + 3, this->Observer);
  this->NumberOfDirections = static_cast<int>(declared::Default::NumberOfDirections);
  std::copy(declared::Default::ConeAxis, declared::Default::ConeAxis + 3, this->ConeAxis);
  this->ConeAngle = declared::Default::ConeAngle;
  this->Tolerance = declared::Default::Tolerance;
  this->MaximumNumberOfConjugatePoints =
    static_cast<int>(declared::Default::MaximumNumberOfConjugatePoints);
  this->SetNumberOfDataPorts(0);
  this->SetNumberOfOutputPorts(2);
  // Defaults of this filter. DORMAND_PRINCE45: on the round sphere it finds
  // all of 10,000 double conjugate points to 1e-8, where RK4 at step 0.01
  // gives up on some: they pass near the chart's point at infinity, where the
  // fixed step drifts g(v, v) past the search's trust limit
  // (Testing/Benchmarks/README.md). MaximumError is only a cap: the
  // integration tolerance follows Tolerance (FindConjugatePoints). The step
  // budget is large: the search must not stop before MaximumPropagation.
  // The declared "ConjugateLocus" preset (vtkRiemannIntegrationSettings.settings.json).
  namespace preset = riemann::declared::vtkRiemannIntegrationSettings::ConjugateLocus;
  vtkRiemannIntegrationSettings* settings = this->GetIntegrationSettings();
  settings->SetIntegratorType(preset::IntegratorType);
  settings->SetMaximumIntegrationStep(preset::MaximumIntegrationStep);
  settings->SetMaximumError(preset::MaximumError);
  settings->SetMaximumNumberOfSteps(static_cast<vtkIdType>(preset::MaximumNumberOfSteps));
}

vtkRiemannConjugateLocus::~vtkRiemannConjugateLocus() = default;

int vtkRiemannConjugateLocus::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Any piece can be searched alone: a share of the directions.
  for (int port = 0; port < 2; ++port)
  {
    outputVector->GetInformationObject(port)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  }
  return 1;
}

namespace
{
using Triangle = std::array<int, 3>;

/// The grid's triangles, in order.
std::vector<Triangle> GridTriangles(vtkPolyData* grid)
{
  std::vector<Triangle> triangles;
  triangles.reserve(static_cast<size_t>(grid->GetNumberOfPolys()));
  vtkCellArray* polys = grid->GetPolys();
  vtkNew<vtkIdList> cell;
  for (polys->InitTraversal(); polys->GetNextCell(cell);)
  {
    triangles.push_back({ static_cast<int>(cell->GetId(0)), static_cast<int>(cell->GetId(1)),
      static_cast<int>(cell->GetId(2)) });
  }
  return triangles;
}

/// What a piece owning the directions [First, Last) computes.
struct LocusPiece
{
  int First = 0;
  int Last = 0;
  bool Pieced = false;
  /// Directions whose sheet points it outputs: its own and the other corners
  /// of its triangles (ghosts).
  std::vector<char> Kept;
  /// Directions it searches: the kept ones and their neighbours, so that
  /// every kept point's KernelSlope sees all its neighbours.
  std::vector<int> Searched;
  /// The grid triangles the sheets are built over: those touching a kept
  /// direction, in the grid's order (so each kept point's neighbour list, and
  /// its least squares, are the whole grid's, bitwise).
  std::vector<Triangle> Triangles;

  bool Owns(int direction) const { return direction >= this->First && direction < this->Last; }
  bool OwnsTriangle(const Triangle& t) const { return this->Owns(std::min({ t[0], t[1], t[2] })); }
};

/// Step 2 of RequestData: the piece's directions and triangles.
LocusPiece MakePiece(
  const std::vector<Triangle>& all, int count, vtkIdType first, vtkIdType last, bool pieced)
{
  LocusPiece piece;
  piece.First = static_cast<int>(first);
  piece.Last = static_cast<int>(last);
  piece.Pieced = pieced;
  piece.Kept.assign(static_cast<size_t>(count), pieced ? 0 : 1);
  if (!pieced)
  {
    piece.Triangles = all;
    for (int i = 0; i < count; ++i)
    {
      piece.Searched.push_back(i);
    }
    return piece;
  }
  for (int i = piece.First; i < piece.Last; ++i)
  {
    piece.Kept[static_cast<size_t>(i)] = 1;
  }
  for (const Triangle& t : all)
  {
    if (piece.OwnsTriangle(t))
    {
      for (int c : t)
      {
        piece.Kept[static_cast<size_t>(c)] = 1;
      }
    }
  }
  std::vector<char> searched(piece.Kept);
  for (const Triangle& t : all)
  {
    if (piece.Kept[t[0]] || piece.Kept[t[1]] || piece.Kept[t[2]])
    {
      piece.Triangles.push_back(t);
      for (int c : t)
      {
        searched[static_cast<size_t>(c)] = 1;
      }
    }
  }
  for (int i = 0; i < count; ++i)
  {
    if (searched[static_cast<size_t>(i)])
    {
      piece.Searched.push_back(i);
    }
  }
  return piece;
}

/// Step 3: the conjugate points of the piece's searched directions, in
/// parallel (progress and abort between batches), PacketWidth directions in
/// lock step on the packet engine; found[i] stays empty for the others.
/// False when aborted.
bool SearchInParallel(vtkAlgorithm* self, const riemann::Metric& metric,
  const riemann::Vec3& observer, const std::vector<riemann::Vec3>& directions,
  const LocusPiece& piece, const riemann::GeodesicOptions& options, double tolerance,
  int maximumCount, std::vector<std::vector<riemann::ConjugatePoint>>& found)
{
  found.assign(directions.size(), {});
  const auto count = static_cast<vtkIdType>(piece.Searched.size());
  std::vector<riemann::Vec3> searched(piece.Searched.size());
  for (size_t i = 0; i < searched.size(); ++i)
  {
    searched[i] = directions[static_cast<size_t>(piece.Searched[i])];
  }
  std::vector<std::vector<riemann::ConjugatePoint>> results(searched.size());
  const vtkIdType done = vtkRiemannForInBatches(
    self, count, 64,
    [&](vtkIdType first, vtkIdType last)
    {
      riemann::FindConjugatePoints(metric, observer, searched.data() + first,
        static_cast<size_t>(last - first), options, tolerance, maximumCount,
        results.data() + first);
    },
    4 * riemann::PacketWidth);
  for (size_t i = 0; i < results.size(); ++i)
  {
    found[static_cast<size_t>(piece.Searched[i])] = std::move(results[i]);
  }
  return done == count;
}

/// Step 4: port 0, a vertex per conjugate point of the owned directions.
void BuildConjugatePoints(const std::vector<std::vector<riemann::ConjugatePoint>>& found,
  const LocusPiece& piece, vtkPolyData* output)
{
  const auto first = static_cast<size_t>(piece.Pieced ? piece.First : 0);
  const auto last = piece.Pieced ? static_cast<size_t>(piece.Last) : found.size();
  vtkIdType pointCount = 0;
  for (size_t i = first; i < last; ++i)
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
  for (size_t i = first; i < last; ++i)
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
}

/// The sheets' points of kept directions and the owned triangles (a piece's
/// part of the whole sheets), with the ghost flag of each point.
riemann::CausticSheets KeepPiece(
  const riemann::CausticSheets& all, const LocusPiece& piece, std::vector<unsigned char>& ghosts)
{
  riemann::CausticSheets kept;
  std::vector<int> local(all.Points.size(), -1);
  for (size_t v = 0; v < all.Points.size(); ++v)
  {
    const int direction = all.Direction[v];
    if (!piece.Kept[static_cast<size_t>(direction)])
    {
      continue;
    }
    local[v] = static_cast<int>(kept.Points.size());
    kept.Points.push_back(all.Points[v]);
    kept.Direction.push_back(direction);
    kept.Sheet.push_back(all.Sheet[v]);
    kept.ArcLength.push_back(all.ArcLength[v]);
    kept.Multiplicity.push_back(all.Multiplicity[v]);
    kept.Index.push_back(all.Index[v]);
    kept.KernelSlope.push_back(all.KernelSlope[v]);
    ghosts.push_back(piece.Owns(direction) ? 0 : vtkDataSetAttributes::DUPLICATEPOINT);
  }
  for (size_t t = 0; t < all.Triangles.size(); ++t)
  {
    const Triangle& corners = all.Triangles[t];
    const Triangle directions = { all.Direction[corners[0]], all.Direction[corners[1]],
      all.Direction[corners[2]] };
    if (!piece.OwnsTriangle(directions))
    {
      continue;
    }
    kept.Triangles.push_back({ local[corners[0]], local[corners[1]], local[corners[2]] });
    kept.TriangleSheet.push_back(all.TriangleSheet[t]);
    kept.TriangleSingularity.push_back(all.TriangleSingularity[t]);
  }
  return kept;
}

/// Step 5: port 1, the sheets as polydata (vtkGhostType when `ghosts` is not empty).
void BuildLocusSurfaces(const riemann::CausticSheets& sheets,
  const std::vector<unsigned char>& ghosts, vtkPolyData* locus)
{
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
  if (!ghosts.empty())
  {
    vtkNew<vtkUnsignedCharArray> ghost;
    ghost->SetName(vtkDataSetAttributes::GhostArrayName());
    ghost->SetNumberOfTuples(pointCount);
    std::copy(ghosts.begin(), ghosts.end(), ghost->GetPointer(0));
    locus->GetPointData()->AddArray(ghost);
  }
}
} // namespace

// RequestData as named steps: the direction grid -> MakePiece ->
// SearchInParallel -> BuildConjugatePoints (port 0) -> the caustic sheets,
// KeepPiece, BuildLocusSurfaces (port 1).
int vtkRiemannConjugateLocus::RequestData(
  vtkInformation* request, vtkInformationVector**, vtkInformationVector* outputVector)
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
  vtkIdType first = 0;
  vtkIdType last = 0;
  const bool pieced =
    PieceShare(request, outputVector, static_cast<vtkIdType>(directions.size()), first, last);
  const std::vector<Triangle> gridTriangles = GridTriangles(grid);
  const LocusPiece piece =
    MakePiece(gridTriangles, static_cast<int>(directions.size()), first, last, pieced);

  std::vector<std::vector<riemann::ConjugatePoint>> found;
  const bool complete = SearchInParallel(this, *metric, observer, directions, piece,
    this->MakeGeodesicOptions(), this->Tolerance, this->MaximumNumberOfConjugatePoints, found);
  if (!complete)
  {
    return 1; // aborted: empty outputs
  }
  BuildConjugatePoints(found, piece, output);
  riemann::Mat3 g;
  if (metric->Tensor(observer, g))
  {
    const riemann::CausticSheets sheets =
      riemann::BuildCausticSheets(directions, piece.Triangles, found, g);
    std::vector<unsigned char> ghosts;
    BuildLocusSurfaces(pieced ? KeepPiece(sheets, piece, ghosts) : sheets, ghosts, locus);
  }
  return 1;
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
