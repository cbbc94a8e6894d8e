#include "vtkRiemannMinimalGeodesics.h"

#include "RiemannMinimalGeodesicsDeclaration.h"

#include "DistanceDescent.h"
#include "GeodesicConnector.h"
#include "Metric.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRiemannGeodesicConnector.h"
#include "vtkRiemannDistanceImage.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannParallelBatches.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkRiemannMinimalGeodesics);

vtkRiemannMinimalGeodesics::vtkRiemannMinimalGeodesics()
  : Tolerance(riemann::declared::vtkRiemannMinimalGeodesics::Default::Tolerance)
{
  // The distance field, then the targets (optional).
  this->SetNumberOfDataPorts(2);
  // Newton's is the connector's: its integration defaults.
  vtkRiemannGeodesicConnector::ApplyConnectionDefaults(this->GetIntegrationSettings());
}

vtkRiemannMinimalGeodesics::~vtkRiemannMinimalGeodesics() = default;

void vtkRiemannMinimalGeodesics::AddTarget(double x, double y, double z)
{
  this->Targets.insert(this->Targets.end(), { x, y, z });
  this->Modified();
}

void vtkRiemannMinimalGeodesics::RemoveAllTargets()
{
  if (!this->Targets.empty())
  {
    this->Targets.clear();
    this->Modified();
  }
}

int vtkRiemannMinimalGeodesics::FillDataPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

namespace
{
/// One target's answer: its line from the seed, and what it is.
struct MinimalGeodesic
{
  riemann::GeodesicPath Path;
  int Seed = -1;
  double Length = 0.0;
  double Distance = 0.0;
  bool Refined = false;
  /// Found by shooting (ConnectPoints), Newton from the descent having
  /// found a longer geodesic or none.
  bool Shot = false;
};

/// The descent from `target`, then Newton from its start at the seed.
MinimalGeodesic FindOne(const riemann::Metric& metric, const riemann::DistanceGrid& grid,
  const riemann::DistanceFieldResult& field, const std::vector<riemann::Vec3>& seeds,
  const riemann::Vec3& target, const riemann::ConnectOptions& connect)
{
  MinimalGeodesic found;
  const riemann::DistanceDescent descent = riemann::DescendToSeed(grid, field, seeds, target);
  if (descent.Seed < 0 || descent.Points.size() < 2)
  {
    return found;
  }
  found.Seed = descent.Seed;
  found.Distance = descent.Distance;
  const riemann::Vec3& seed = seeds[static_cast<std::size_t>(descent.Seed)];
  // Newton starts from the descent's direction at the seed, averaged over its
  // first few spacings (its first step is the local distance's), and the
  // field's distance.
  const double reach = 3.0 * grid.Spacing.maxCoeff();
  riemann::Vec3 leaving = descent.Points.front() - seed;
  for (auto p = descent.Points.rbegin(); p != descent.Points.rend(); ++p)
  {
    if ((*p - seed).norm() >= reach)
    {
      leaving = *p - seed;
      break;
    }
  }
  riemann::ConnectionCandidate candidate;
  candidate.Direction = leaving;
  candidate.ArcLength = descent.Distance;
  riemann::ConnectingGeodesic geodesic;
  riemann::ConnectOptions options = connect;
  options.MaximumLength = 1.5 * descent.Distance + 1.0;
  bool refined = riemann::RefineConnection(metric, seed, target, candidate, options, geodesic);
  // Newton may find a geodesic that is not minimal: from a point on the cut
  // locus the descent can run along it (over a bump's top, between the two
  // minimal ways round). Longer than the field's distance by more than half
  // a spacing, it is checked against every geodesic shooting finds.
  const double slack = 0.5 * grid.Spacing.maxCoeff();
  if (!refined || geodesic.Length > descent.Distance + slack)
  {
    options.MaximumLength = 1.2 * descent.Distance + 2.0 * grid.Spacing.maxCoeff();
    try
    {
      const std::vector<riemann::ConnectingGeodesic> all =
        riemann::ConnectPoints(metric, seed, target, options);
      if (!all.empty() && (!refined || all.front().Length < geodesic.Length))
      {
        geodesic = all.front();
        refined = true;
        found.Shot = true;
      }
    }
    catch (const std::invalid_argument&)
    {
      // The target is the seed itself: the descent is its answer.
    }
  }
  if (refined)
  {
    riemann::TraceConnection(metric, seed, geodesic, options, found.Path);
    found.Length = geodesic.Length;
    found.Refined = true;
    return found;
  }
  // Newton failed: the descent itself, from the seed (its velocities the
  // chords' directions, g-normalised; its arc length the chords' g-lengths).
  double length = 0.0;
  const std::vector<riemann::Vec3> points(descent.Points.rbegin(), descent.Points.rend());
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    const riemann::Vec3 chord =
      k + 1 < points.size() ? points[k + 1] - points[k] : points[k] - points[k - 1];
    riemann::Vec3 velocity = riemann::Vec3::Zero();
    riemann::UnitSpeedVelocity(metric, points[k], chord, velocity);
    if (k > 0)
    {
      const riemann::Vec3 step = points[k] - points[k - 1];
      riemann::Mat3 g;
      length += metric.Tensor(0.5 * (points[k] + points[k - 1]), g)
        ? std::sqrt(std::max(0.0, step.dot(g * step)))
        : step.norm();
    }
    found.Path.Points.push_back(points[k]);
    found.Path.Velocities.push_back(velocity);
    found.Path.ArcLength.push_back(length);
  }
  found.Length = descent.Distance;
  return found;
}

/// The answers as polylines with their arrays.
void BuildLines(const std::vector<MinimalGeodesic>& found, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkDoubleArray> arcLength, velocity, length, distance;
  arcLength->SetName("ArcLength");
  velocity->SetName("Velocity");
  velocity->SetNumberOfComponents(3);
  length->SetName("Length");
  distance->SetName("Distance");
  vtkNew<vtkIntArray> targetIds, seedIds;
  targetIds->SetName("TargetIds");
  seedIds->SetName("SeedId");
  vtkNew<vtkUnsignedCharArray> refined;
  refined->SetName("Refined");
  for (std::size_t t = 0; t < found.size(); ++t)
  {
    const MinimalGeodesic& g = found[t];
    if (g.Seed < 0)
    {
      continue;
    }
    lines->InsertNextCell(static_cast<vtkIdType>(g.Path.Points.size()));
    for (std::size_t k = 0; k < g.Path.Points.size(); ++k)
    {
      lines->InsertCellPoint(points->InsertNextPoint(g.Path.Points[k].data()));
      arcLength->InsertNextValue(g.Path.ArcLength[k]);
      velocity->InsertNextTuple(g.Path.Velocities[k].data());
    }
    targetIds->InsertNextValue(static_cast<int>(t));
    seedIds->InsertNextValue(g.Seed);
    length->InsertNextValue(g.Length);
    distance->InsertNextValue(g.Distance);
    refined->InsertNextValue(g.Shot ? 2 : g.Refined ? 1 : 0);
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetPointData()->AddArray(arcLength);
  output->GetPointData()->AddArray(velocity);
  for (vtkDataArray* array :
    std::vector<vtkDataArray*>{ targetIds, seedIds, length, distance, refined })
  {
    output->GetCellData()->AddArray(array);
  }
}
} // namespace

// RequestData as named steps: the checks -> vtkRiemannReadDistanceImage ->
// FindOne for every target, in parallel -> BuildLines.
int vtkRiemannMinimalGeodesics::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  this->NumberOfUnrefined = 0;
  const std::shared_ptr<const riemann::Metric> metric = this->CheckMetricAndSettings();
  if (!metric)
  {
    return 1;
  }
  const std::string tolerable = vtkRiemannGeodesicConnector::CheckTolerance(this->Tolerance);
  if (!tolerable.empty())
  {
    this->ReportError(tolerable);
    return 1;
  }
  vtkImageData* image = vtkImageData::GetData(inputVector[0], 0);
  riemann::DistanceGrid grid;
  riemann::DistanceFieldResult field;
  std::vector<riemann::Vec3> seeds;
  if (!image || !vtkRiemannReadDistanceImage(image, grid, field, &seeds) || seeds.empty())
  {
    this->ReportError("The input must be a distance field: point arrays Distance, "
                      "ArrivalDirection and SeedId and field data Seeds, as "
                      "vtkRiemannDistanceField makes them.");
    return 1;
  }
  // AddTarget's, then port 1's points (TargetIds' order).
  std::vector<double> targets = this->Targets;
  if (vtkDataSet* more = this->GetNumberOfInputConnections(1) > 0
        ? vtkDataSet::GetData(inputVector[1], 0)
        : nullptr)
  {
    for (vtkIdType n = 0; n < more->GetNumberOfPoints(); ++n)
    {
      double p[3];
      more->GetPoint(n, p);
      targets.insert(targets.end(), p, p + 3);
    }
  }
  riemann::ConnectOptions connect;
  connect.Integration = this->MakeGeodesicOptions();
  connect.Tolerance = this->Tolerance;
  std::vector<MinimalGeodesic> found(targets.size() / 3);
  const auto count = static_cast<vtkIdType>(found.size());
  const vtkIdType done = vtkRiemannForInBatches(this, count, 1,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType t = first; t < last; ++t)
      {
        const riemann::Vec3 target(targets[3 * t], targets[3 * t + 1], targets[3 * t + 2]);
        found[static_cast<std::size_t>(t)] = FindOne(*metric, grid, field, seeds, target, connect);
      }
    });
  if (done != count)
  {
    return 1; // aborted: empty output
  }
  this->NumberOfUnrefined = static_cast<int>(std::count_if(found.begin(), found.end(),
    [](const MinimalGeodesic& g) { return g.Seed >= 0 && !g.Refined; }));
  BuildLines(found, output);
  return 1;
}

void vtkRiemannMinimalGeodesics::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfTargets: " << this->GetNumberOfTargets() << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "NumberOfUnrefined: " << this->NumberOfUnrefined << "\n";
}
