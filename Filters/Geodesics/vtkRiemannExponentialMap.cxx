#include "vtkRiemannExponentialMap.h"

#include "JacobiField.h"
#include "Metric.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRiemannDirectionGrid.h"
#include "RiemannExponentialMapDeclaration.h"
#include "vtkRiemannIntegrationSettings.h"
#include "RiemannIntegrationSettingsDeclaration.h"
#include "vtkRiemannNewArray.h"
#include "vtkRiemannParallelBatches.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkRiemannExponentialMap);

vtkRiemannExponentialMap::vtkRiemannExponentialMap()
{
  namespace declared = riemann::declared::vtkRiemannExponentialMap;
  std::copy(declared::Default::Observer, declared::Default::Observer + 3, this->Observer);
  this->NumberOfDirections = static_cast<int>(declared::Default::NumberOfDirections);
  std::copy(declared::Default::ConeAxis, declared::Default::ConeAxis + 3, this->ConeAxis);
  this->ConeAngle = declared::Default::ConeAngle;
  this->SetNumberOfDataPorts(0);
  this->SetNumberOfOutputPorts(2);
  // Defaults of this filter: a bundle of moderate length, fine steps (the
  // declared "ExponentialMap" preset, vtkRiemannIntegrationSettings.settings.json).
  namespace preset = riemann::declared::vtkRiemannIntegrationSettings::ExponentialMap;
  vtkRiemannIntegrationSettings* settings = this->GetIntegrationSettings();
  settings->SetMaximumPropagation(preset::MaximumPropagation);
  settings->SetMaximumIntegrationStep(preset::MaximumIntegrationStep);
  settings->SetMaximumNumberOfSteps(static_cast<vtkIdType>(preset::MaximumNumberOfSteps));
}

vtkRiemannExponentialMap::~vtkRiemannExponentialMap() = default;

void vtkRiemannExponentialMap::AddRadius(double radius)
{
  this->Radii.push_back(radius);
  this->Modified();
}

void vtkRiemannExponentialMap::RemoveAllRadii()
{
  if (!this->Radii.empty())
  {
    this->Radii.clear();
    this->Modified();
  }
}

double vtkRiemannExponentialMap::GetRadius(int i) const
{
  return i >= 0 && i < this->GetNumberOfRadii() ? this->Radii[i] : 0.0;
}

namespace
{
/// Index of the sample landed on arc length r, or -1 if the geodesic
/// stopped before it.
long SampleAtRadius(const std::vector<riemann::JacobiSample>& samples, double r)
{
  const auto found = std::lower_bound(samples.begin(), samples.end(), r,
    [](const riemann::JacobiSample& s, double value) { return s.ArcLength < value; });
  if (found == samples.end() || std::abs(found->ArcLength - r) > 1e-9 * std::max(1.0, r))
  {
    return -1;
  }
  return static_cast<long>(found - samples.begin());
}

/// Step 2 of RequestData: the directions `todo` of the grid (every one
/// without a piece request) traced with their Jacobi fields from the
/// observer, landing on each radius, in parallel (progress and abort between
/// batches of 64) on the packet engine (PacketWidth directions in lock step).
/// traces[i] is direction i's (empty for a direction not traced). False when
/// aborted.
bool TraceInParallel(vtkAlgorithm* self, const riemann::Metric& metric,
  const riemann::Vec3& observer, vtkPolyData* grid, const std::vector<vtkIdType>& todo,
  const riemann::GeodesicOptions& options, const std::vector<double>& radii,
  std::vector<riemann::JacobiTrace>& traces)
{
  traces.assign(static_cast<size_t>(grid->GetNumberOfPoints()), riemann::JacobiTrace());
  std::vector<riemann::JacobiTrace> traced(todo.size());
  const auto count = static_cast<vtkIdType>(todo.size());
  const vtkIdType done = vtkRiemannForInBatches(
    self, count, 64,
    [&](vtkIdType first, vtkIdType last)
    {
      std::vector<riemann::JacobiSeed> seeds(static_cast<size_t>(last - first));
      for (vtkIdType i = first; i < last; ++i)
      {
        riemann::JacobiSeed& seed = seeds[static_cast<size_t>(i - first)];
        seed.Point = observer;
        grid->GetPoint(todo[static_cast<size_t>(i)], seed.Direction.data());
      }
      riemann::TraceJacobiFields(
        metric, seeds.data(), seeds.size(), options, traced.data() + first, radii);
    },
    4 * riemann::PacketWidth);
  for (size_t i = 0; i < todo.size(); ++i)
  {
    traces[static_cast<size_t>(todo[i])] = std::move(traced[i]);
  }
  return done == count;
}

/**
 * Step 2 under a piece request: the piece owns the directions [first, last)
 * (their rays and wavefront points) and the grid's triangles whose smallest
 * direction is one of them; `owned` gets the grid's points with those
 * triangles only. Returns the directions to trace: the owned ones and the
 * other corners of the owned triangles (the piece's ghost points).
 */
std::vector<vtkIdType> PieceDirections(
  vtkPolyData* grid, vtkIdType first, vtkIdType last, vtkPolyData* owned)
{
  std::vector<bool> needed(static_cast<size_t>(grid->GetNumberOfPoints()), false);
  for (vtkIdType i = first; i < last; ++i)
  {
    needed[static_cast<size_t>(i)] = true;
  }
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkIdList> cell;
  vtkCellArray* all = grid->GetPolys();
  for (all->InitTraversal(); all->GetNextCell(cell);)
  {
    const vtkIdType lowest = std::min({ cell->GetId(0), cell->GetId(1), cell->GetId(2) });
    if (lowest >= first && lowest < last)
    {
      triangles->InsertNextCell(cell);
      for (int k = 0; k < 3; ++k)
      {
        needed[static_cast<size_t>(cell->GetId(k))] = true;
      }
    }
  }
  owned->SetPoints(grid->GetPoints());
  owned->SetPolys(triangles);
  std::vector<vtkIdType> todo;
  for (size_t i = 0; i < needed.size(); ++i)
  {
    if (needed[i])
    {
      todo.push_back(static_cast<vtkIdType>(i));
    }
  }
  return todo;
}

/// Step 3: port 0, the ray bundle: a polyline per direction that made a step,
/// with ArcLength, SpeedDrift and the transverse Jacobian per point and
/// DirectionId and ReasonForTermination per line.
void BuildBundle(const std::vector<riemann::JacobiTrace>& traces, vtkIdType first, vtkIdType last,
  vtkPolyData* bundle)
{
  vtkIdType pointCount = 0;
  vtkIdType lineCount = 0;
  for (vtkIdType i = first; i < last; ++i)
  {
    const riemann::JacobiTrace& trace = traces[static_cast<size_t>(i)];
    if (trace.Samples.size() >= 2)
    {
      pointCount += static_cast<vtkIdType>(trace.Samples.size());
      ++lineCount;
    }
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(pointCount);
  vtkNew<vtkCellArray> lines;
  lines->AllocateExact(lineCount, pointCount);
  auto arcLength = vtkRiemannNewArray<vtkDoubleArray>("ArcLength", 1, pointCount);
  auto speedDrift = vtkRiemannNewArray<vtkDoubleArray>("SpeedDrift", 1, pointCount);
  auto determinant = vtkRiemannNewArray<vtkDoubleArray>("TransverseJacobian", 1, pointCount);
  auto singular =
    vtkRiemannNewArray<vtkDoubleArray>("TransverseJacobianSingularValues", 2, pointCount);
  auto lineDirection = vtkRiemannNewArray<vtkIntArray>("DirectionId", 1, lineCount);
  auto reasons = vtkRiemannNewArray<vtkIntArray>("ReasonForTermination", 1, lineCount);
  vtkIdType next = 0;
  vtkIdType line = 0;
  std::vector<vtkIdType> ids;
  for (auto i = static_cast<size_t>(first); i < static_cast<size_t>(last); ++i)
  {
    const std::vector<riemann::JacobiSample>& samples = traces[i].Samples;
    if (samples.size() < 2)
    {
      continue;
    }
    ids.resize(samples.size());
    for (size_t k = 0; k < samples.size(); ++k, ++next)
    {
      ids[k] = next;
      points->SetPoint(next, samples[k].Point.data());
      arcLength->SetValue(next, samples[k].ArcLength);
      speedDrift->SetValue(next, samples[k].SpeedDrift);
      determinant->SetValue(next, samples[k].Determinant);
      singular->SetTypedTuple(next, samples[k].SingularValues);
    }
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    lineDirection->SetValue(line, static_cast<int>(i));
    reasons->SetValue(line, traces[i].Reason);
    ++line;
  }
  bundle->SetPoints(points);
  bundle->SetLines(lines);
  bundle->GetPointData()->AddArray(arcLength);
  bundle->GetPointData()->AddArray(speedDrift);
  bundle->GetPointData()->AddArray(determinant);
  bundle->GetPointData()->AddArray(singular);
  bundle->GetCellData()->AddArray(lineDirection);
  bundle->GetCellData()->AddArray(reasons);
}

/// Step 4: port 1, one geodesic sphere per radius over the grid's triangles
/// (the samples landed on that radius), with a warning for each radius beyond
/// MaximumPropagation. Under a piece request (`pieced`), the points of
/// directions outside [first, last) are the piece's ghosts (vtkGhostType).
void BuildWavefronts(vtkObject* self, vtkPolyData* grid,
  const std::vector<riemann::JacobiTrace>& traces, const std::vector<double>& radii,
  double maximumPropagation, vtkIdType first, vtkIdType last, bool pieced, vtkPolyData* wavefronts)
{
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  vtkNew<vtkPoints> spherePoints;
  spherePoints->SetDataTypeToDouble();
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkDoubleArray> sphereDeterminant, sphereSingular, pointRadius, cellRadius;
  sphereDeterminant->SetName("TransverseJacobian");
  sphereSingular->SetName("TransverseJacobianSingularValues");
  sphereSingular->SetNumberOfComponents(2);
  pointRadius->SetName("Radius");
  cellRadius->SetName("Radius");
  vtkNew<vtkIntArray> sphereDirection;
  sphereDirection->SetName("DirectionId");
  const vtkIdType count = static_cast<vtkIdType>(traces.size());
  std::vector<vtkIdType> local(traces.size());
  for (double r : radii)
  {
    if (r > maximumPropagation)
    {
      vtkWarningWithObjectMacro(self, << "Radius " << r << " is beyond MaximumPropagation ("
                                      << maximumPropagation << "): no wavefront there.");
      continue;
    }
    for (vtkIdType i = 0; i < count; ++i)
    {
      const long k = SampleAtRadius(traces[i].Samples, r);
      local[i] = -1;
      if (k >= 0)
      {
        const riemann::JacobiSample& sample = traces[i].Samples[k];
        local[i] = spherePoints->InsertNextPoint(sample.Point.data());
        sphereDeterminant->InsertNextValue(sample.Determinant);
        sphereSingular->InsertNextTypedTuple(sample.SingularValues);
        pointRadius->InsertNextValue(r);
        sphereDirection->InsertNextValue(static_cast<int>(i));
        ghosts->InsertNextValue(i >= first && i < last ? 0 : vtkDataSetAttributes::DUPLICATEPOINT);
      }
    }
    const vtkIdType appended = vtkRiemannDirectionGrid::AppendTriangles(grid, local, triangles);
    for (vtkIdType t = 0; t < appended; ++t)
    {
      cellRadius->InsertNextValue(r);
    }
  }
  wavefronts->SetPoints(spherePoints);
  wavefronts->SetPolys(triangles);
  wavefronts->GetPointData()->AddArray(sphereDeterminant);
  wavefronts->GetPointData()->AddArray(sphereSingular);
  wavefronts->GetPointData()->AddArray(sphereDirection);
  wavefronts->GetPointData()->AddArray(pointRadius);
  wavefronts->GetCellData()->AddArray(cellRadius);
  if (pieced)
  {
    wavefronts->GetPointData()->AddArray(ghosts);
  }
}
}

int vtkRiemannExponentialMap::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Any piece can be traced alone: a share of the directions.
  for (int port = 0; port < 2; ++port)
  {
    outputVector->GetInformationObject(port)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  }
  return 1;
}

// RequestData as named steps: CheckRequest -> the direction grid ->
// PieceShare and PieceDirections -> TraceInParallel -> BuildBundle (port 0) ->
// BuildWavefronts (port 1).
int vtkRiemannExponentialMap::RequestData(
  vtkInformation* request, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* bundle = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* wavefronts = vtkPolyData::GetData(outputVector, 1);
  bundle->Initialize();
  wavefronts->Initialize();
  const std::shared_ptr<const riemann::Metric> metric = this->CheckMetricAndSettings();
  if (!metric || !this->CheckRequest())
  {
    return 1;
  }
  vtkNew<vtkPolyData> grid;
  if (!this->BuildDirectionGrid(this->NumberOfDirections, this->ConeAxis, this->ConeAngle, grid))
  {
    return 1;
  }
  vtkIdType first = 0;
  vtkIdType last = 0;
  const bool pieced = PieceShare(request, outputVector, grid->GetNumberOfPoints(), first, last);
  vtkNew<vtkPolyData> ownedGrid;
  std::vector<vtkIdType> todo;
  if (pieced)
  {
    todo = PieceDirections(grid, first, last, ownedGrid);
  }
  else
  {
    ownedGrid->ShallowCopy(grid);
    for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    {
      todo.push_back(i);
    }
  }
  const riemann::Vec3 observer(this->Observer[0], this->Observer[1], this->Observer[2]);
  std::vector<riemann::JacobiTrace> traces;
  if (!TraceInParallel(
        this, *metric, observer, grid, todo, this->MakeGeodesicOptions(), this->Radii, traces))
  {
    return 1; // aborted: empty outputs
  }
  BuildBundle(traces, first, last, bundle);
  BuildWavefronts(this, ownedGrid, traces, this->Radii,
    this->IntegrationSettings->GetMaximumPropagation(), first, last, pieced, wavefronts);
  return 1;
}

bool vtkRiemannExponentialMap::CheckRequest()
{
  if (!this->CheckObserver(this->Observer))
  {
    return false;
  }
  for (double r : this->Radii)
  {
    if (!(r > 0.0) || !std::isfinite(r))
    {
      std::ostringstream error;
      error << "Every radius must be a positive number; got " << r << ".";
      this->ReportError(error.str());
      return false;
    }
  }
  const double stepsPerGeodesic = this->IntegrationSettings->GetMaximumPropagation() /
    this->IntegrationSettings->GetInitialIntegrationStep();
  const double samples = static_cast<double>(this->NumberOfDirections) * (stepsPerGeodesic + 1.0);
  if (samples > MaximumNumberOfSamples)
  {
    std::ostringstream error;
    error << "Too many samples: " << this->NumberOfDirections << " directions x "
          << stepsPerGeodesic << " steps is more than " << MaximumNumberOfSamples
          << " (about 8 GiB); use fewer directions or a longer InitialIntegrationStep.";
    this->ReportError(error.str());
    return false;
  }
  return true;
}

void vtkRiemannExponentialMap::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Observer: " << this->Observer[0] << " " << this->Observer[1] << " "
     << this->Observer[2] << "\n";
  os << indent << "NumberOfDirections: " << this->NumberOfDirections << "\n";
  os << indent << "ConeAxis: " << this->ConeAxis[0] << " " << this->ConeAxis[1] << " "
     << this->ConeAxis[2] << "\n";
  os << indent << "ConeAngle: " << this->ConeAngle << "\n";
  os << indent << "Radii:";
  for (double r : this->Radii)
  {
    os << " " << r;
  }
  os << "\n";
}
