#include "vtkRiemannGeodesicConnector.h"
#include "RiemannGeodesicConnectorDeclaration.h"
#include "RiemannIntegrationSettingsDeclaration.h"

#include "GeodesicConnector.h"
#include "Metric.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannParallelBatches.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkRiemannGeodesicConnector);

namespace
{
namespace connectorDeclared = riemann::declared::vtkRiemannGeodesicConnector;
// The wrapped header's constants are the declared range (vtkRiemannGeodesicConnector.settings.json).
static_assert(vtkRiemannGeodesicConnector::MinimumTolerance == connectorDeclared::Minimum::Tolerance &&
    vtkRiemannGeodesicConnector::MaximumTolerance == connectorDeclared::Maximum::Tolerance,
  "the tolerance's range is declared in vtkRiemannGeodesicConnector.settings.json");
}

vtkRiemannGeodesicConnector::vtkRiemannGeodesicConnector()
  : NumberOfDirections(static_cast<int>(connectorDeclared::Default::NumberOfDirections))
  , MaximumNumberOfIterations(static_cast<int>(connectorDeclared::Default::MaximumNumberOfIterations))
{
  std::copy(connectorDeclared::Default::StartPosition, connectorDeclared::Default::StartPosition + 3,
    this->StartPosition);
  std::copy(connectorDeclared::Default::EndPosition, connectorDeclared::Default::EndPosition + 3,
    this->EndPosition);
  this->Tolerance = connectorDeclared::Default::Tolerance;
  this->SetNumberOfDataPorts(0);
  ApplyConnectionDefaults(this->GetIntegrationSettings());
}

void vtkRiemannGeodesicConnector::ApplyConnectionDefaults(vtkRiemannIntegrationSettings* settings)
{
  // The declared "Connection" preset (vtkRiemannIntegrationSettings.settings.json):
  // the conjugate locus's integration defaults (vtkRiemannConjugateLocus),
  // as the Morse indices come from the same Maslov-phase search. The step
  // budget is large: no geodesic may stop before MaximumPropagation.
  namespace connection = riemann::declared::vtkRiemannIntegrationSettings::Connection;
  settings->SetIntegratorType(connection::IntegratorType);
  settings->SetMaximumIntegrationStep(connection::MaximumIntegrationStep);
  settings->SetMaximumError(connection::MaximumError);
  settings->SetMaximumNumberOfSteps(static_cast<vtkIdType>(connection::MaximumNumberOfSteps));
}

std::string vtkRiemannGeodesicConnector::CheckTolerance(double tolerance)
{
  if (tolerance >= MinimumTolerance && tolerance <= MaximumTolerance)
  {
    return std::string();
  }
  std::ostringstream why;
  why << "Tolerance is " << tolerance << ": expected a number from " << MinimumTolerance << " to "
      << MaximumTolerance << ".";
  return why.str();
}

vtkRiemannGeodesicConnector::~vtkRiemannGeodesicConnector() = default;

namespace
{
/// Why a property is unusable ("" when none is).
std::string CheckProperties(const double start[3], const double end[3], double tolerance,
  int directions, int iterations)
{
  for (int i = 0; i < 3; ++i)
  {
    if (!std::isfinite(start[i]) || !std::isfinite(end[i]))
    {
      return "StartPosition and EndPosition must be finite.";
    }
  }
  const std::string tolerable = vtkRiemannGeodesicConnector::CheckTolerance(tolerance);
  if (!tolerable.empty())
  {
    return tolerable;
  }
  const int mostDirections = static_cast<int>(connectorDeclared::Maximum::NumberOfDirections);
  if (directions < 1 || directions > mostDirections)
  {
    return "NumberOfDirections is " + std::to_string(directions) +
      ": expected a whole number from 1 to " + std::to_string(mostDirections) + ".";
  }
  const int mostIterations = static_cast<int>(connectorDeclared::Maximum::MaximumNumberOfIterations);
  if (iterations < 1 || iterations > mostIterations)
  {
    return "MaximumNumberOfIterations is " + std::to_string(iterations) +
      ": expected a whole number from 1 to " + std::to_string(mostIterations) + ".";
  }
  return std::string();
}

/// Step 1: the candidates of every direction, in parallel (PacketWidth
/// directions in lock step). False when aborted.
bool ShootInParallel(vtkAlgorithm* self, const riemann::Metric& metric, const riemann::Vec3& p,
  const riemann::Vec3& q, const std::vector<riemann::Vec3>& directions,
  const riemann::ConnectOptions& options, std::vector<riemann::ConnectionCandidate>& candidates)
{
  std::mutex guard;
  const auto count = static_cast<vtkIdType>(directions.size());
  const vtkIdType done = vtkRiemannForInBatches(
    self, count, 64,
    [&](vtkIdType first, vtkIdType last)
    {
      const std::vector<riemann::ConnectionCandidate> found =
        riemann::FindConnectionCandidates(metric, p, q, directions.data() + first,
          static_cast<std::size_t>(last - first), static_cast<int>(directions.size()), options);
      const std::lock_guard<std::mutex> lock(guard);
      candidates.insert(candidates.end(), found.begin(), found.end());
    },
    4 * riemann::PacketWidth);
  return done == count;
}

/// Step 2: Newton from every candidate, in parallel; the distinct
/// geodesics. False when aborted.
bool RefineInParallel(vtkAlgorithm* self, const riemann::Metric& metric, const riemann::Vec3& p,
  const riemann::Vec3& q, const std::vector<riemann::ConnectionCandidate>& candidates,
  const riemann::ConnectOptions& options, std::vector<riemann::ConnectingGeodesic>& geodesics)
{
  std::vector<riemann::ConnectingGeodesic> refined(candidates.size());
  std::vector<unsigned char> converged(candidates.size(), 0);
  const auto count = static_cast<vtkIdType>(candidates.size());
  const vtkIdType done = vtkRiemannForInBatches(self, count, 4,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        converged[i] = riemann::RefineConnection(metric, p, q, candidates[i], options, refined[i]);
      }
    });
  std::vector<riemann::ConnectingGeodesic> found;
  for (std::size_t i = 0; i < refined.size(); ++i)
  {
    if (converged[i])
    {
      found.push_back(refined[i]);
    }
  }
  geodesics = riemann::MergeConnections(std::move(found), options);
  return done == count;
}

/// Step 3: the Morse index of every geodesic, in parallel. False when aborted.
bool ClassifyInParallel(vtkAlgorithm* self, const riemann::Metric& metric,
  const riemann::Vec3& p, const riemann::ConnectOptions& options,
  std::vector<riemann::ConnectingGeodesic>& geodesics)
{
  const auto count = static_cast<vtkIdType>(geodesics.size());
  return vtkRiemannForInBatches(self, count, 1,
           [&](vtkIdType first, vtkIdType last)
           {
             for (vtkIdType i = first; i < last; ++i)
             {
               riemann::ClassifyConnection(metric, p, options, geodesics[i]);
             }
           }) == count;
}

/// Step 4: the geodesics as polylines with their arrays.
void BuildGeodesics(const riemann::Metric& metric, const riemann::Vec3& p,
  const riemann::ConnectOptions& options, const std::vector<riemann::ConnectingGeodesic>& geodesics,
  vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkDoubleArray> arcLength, velocity;
  arcLength->SetName("ArcLength");
  velocity->SetName("Velocity");
  velocity->SetNumberOfComponents(3);
  vtkNew<vtkIntArray> seedIds, morseIndex, conjugate, iterations;
  seedIds->SetName("SeedIds");
  morseIndex->SetName("MorseIndex");
  conjugate->SetName("ConjugateMultiplicity");
  iterations->SetName("Iterations");
  vtkNew<vtkUnsignedCharArray> shortest;
  shortest->SetName("Shortest");
  vtkNew<vtkDoubleArray> length, miss, direction;
  length->SetName("Length");
  miss->SetName("Miss");
  direction->SetName("InitialDirection");
  direction->SetNumberOfComponents(3);
  riemann::GeodesicPath path;
  for (std::size_t i = 0; i < geodesics.size(); ++i)
  {
    const riemann::ConnectingGeodesic& g = geodesics[i];
    riemann::TraceConnection(metric, p, g, options, path);
    lines->InsertNextCell(static_cast<vtkIdType>(path.Points.size()));
    for (std::size_t k = 0; k < path.Points.size(); ++k)
    {
      lines->InsertCellPoint(points->InsertNextPoint(path.Points[k].data()));
      arcLength->InsertNextValue(path.ArcLength[k]);
      velocity->InsertNextTuple(path.Velocities[k].data());
    }
    seedIds->InsertNextValue(static_cast<int>(i));
    length->InsertNextValue(g.Length);
    morseIndex->InsertNextValue(g.MorseIndex);
    conjugate->InsertNextValue(g.ConjugateMultiplicity);
    shortest->InsertNextValue(g.Shortest ? 1 : 0);
    miss->InsertNextValue(g.Miss);
    iterations->InsertNextValue(g.Iterations);
    direction->InsertNextTuple(g.Direction.data());
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetPointData()->AddArray(arcLength);
  output->GetPointData()->AddArray(velocity);
  for (vtkDataArray* array : std::vector<vtkDataArray*>{ seedIds, length, morseIndex, conjugate,
         shortest, miss, iterations, direction })
  {
    output->GetCellData()->AddArray(array);
  }
}
} // namespace

// RequestData as named steps: CheckProperties -> ShootingDirections ->
// ShootInParallel -> RefineInParallel (with MergeConnections) ->
// ClassifyInParallel -> BuildGeodesics.
int vtkRiemannGeodesicConnector::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  this->NumberOfGeodesics = 0;
  const std::shared_ptr<const riemann::Metric> metric = this->CheckMetricAndSettings();
  if (!metric)
  {
    return 1;
  }
  const std::string problem = CheckProperties(this->StartPosition, this->EndPosition,
    this->Tolerance, this->NumberOfDirections, this->MaximumNumberOfIterations);
  if (!problem.empty())
  {
    this->ReportError(problem);
    return 1;
  }
  const riemann::Vec3 p(this->StartPosition[0], this->StartPosition[1], this->StartPosition[2]);
  const riemann::Vec3 q(this->EndPosition[0], this->EndPosition[1], this->EndPosition[2]);
  riemann::ConnectOptions options;
  options.Integration = this->MakeGeodesicOptions();
  options.MaximumLength = options.Integration.MaximumLength;
  options.Tolerance = this->Tolerance;
  options.NumberOfDirections = this->NumberOfDirections;
  options.MaximumIterations = this->MaximumNumberOfIterations;
  // Finiteness was CheckProperties'.
  const riemann::ConnectionProblem refused = riemann::CheckConnection(*metric, p, q, options);
  if (refused == riemann::ConnectionProblem::StartOutsideData ||
    refused == riemann::ConnectionProblem::EndOutsideData)
  {
    this->ReportError(std::string(refused == riemann::ConnectionProblem::EndOutsideData
                          ? "EndPosition"
                          : "StartPosition") +
      " is outside the metric's data: geodesics stop there (a sampled volume with \"outside\": "
      "\"stop\").");
    return 1;
  }
  if (refused == riemann::ConnectionProblem::SamePoint)
  {
    this->ReportError("StartPosition and EndPosition are the same point (within the Tolerance).");
    return 1;
  }
  const std::vector<riemann::Vec3> directions =
    riemann::ShootingDirections(*metric, p, q, options.NumberOfDirections);
  if (directions.empty())
  {
    this->ReportError("The metric is not positive definite at StartPosition.");
    return 1;
  }

  std::vector<riemann::ConnectionCandidate> candidates;
  std::vector<riemann::ConnectingGeodesic> geodesics;
  this->SetProgressShiftScale(0.0, 0.6);
  bool complete = ShootInParallel(this, *metric, p, q, directions, options, candidates);
  this->SetProgressShiftScale(0.6, 0.3);
  complete = complete && RefineInParallel(this, *metric, p, q, candidates, options, geodesics);
  this->SetProgressShiftScale(0.9, 0.1);
  complete = complete && ClassifyInParallel(this, *metric, p, options, geodesics);
  this->SetProgressShiftScale(0.0, 1.0);
  if (!complete)
  {
    return 1; // aborted: empty output
  }
  BuildGeodesics(*metric, p, options, geodesics, output);
  this->NumberOfGeodesics = static_cast<int>(geodesics.size());
  return 1;
}

void vtkRiemannGeodesicConnector::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "StartPosition: " << this->StartPosition[0] << " " << this->StartPosition[1]
     << " " << this->StartPosition[2] << "\n";
  os << indent << "EndPosition: " << this->EndPosition[0] << " " << this->EndPosition[1] << " "
     << this->EndPosition[2] << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "NumberOfDirections: " << this->NumberOfDirections << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "NumberOfGeodesics: " << this->NumberOfGeodesics << "\n";
}
