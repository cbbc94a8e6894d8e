#include "vtkRiemannGeodesicTracer.h"

#include "DirectionLattice.h"
#include "GeodesicTrace.h"
#include "RiemannGeodesicTracerDeclaration.h"
#include "JacobiField.h"
#include "Metric.h"
#include "PacketTrace.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannNewArray.h"
#include "vtkRiemannParallelBatches.h"
#include "RiemannScalarImages.h"
#include "TractStops.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <random>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkRiemannGeodesicTracer);

// The public enums mirror the core's numbering, which is part of the file formats.
static_assert(static_cast<int>(vtkRiemannGeodesicTracer::DEGENERATE_METRIC) ==
      static_cast<int>(riemann::DegenerateMetric) &&
    static_cast<int>(vtkRiemannGeodesicTracer::HIT_SURFACE) ==
      static_cast<int>(riemann::HitSurface) &&
    static_cast<int>(vtkRiemannGeodesicTracer::OUT_OF_LENGTH) ==
      static_cast<int>(riemann::OutOfLength) &&
    static_cast<int>(vtkRiemannGeodesicTracer::OUT_OF_DATA) ==
      static_cast<int>(riemann::OutOfData) &&
    static_cast<int>(vtkRiemannGeodesicTracer::STOPPED_BY_MASK) ==
      static_cast<int>(riemann::StoppedByMask) &&
    static_cast<int>(vtkRiemannGeodesicTracer::LOW_ANISOTROPY) ==
      static_cast<int>(riemann::LowAnisotropy) &&
    static_cast<int>(vtkRiemannGeodesicTracer::SHARP_TURN) ==
      static_cast<int>(riemann::SharpTurn) &&
    static_cast<int>(vtkRiemannGeodesicTracer::OUTRAN_STEP) ==
      static_cast<int>(riemann::OutranStep) &&
    static_cast<int>(vtkRiemannGeodesicTracer::CROSSED_EXCLUDE) ==
      static_cast<int>(riemann::TractCrossedExclude),
  "termination codes must match the core");
static_assert(vtkRiemannIntegrationSettings::DORMAND_PRINCE45 ==
    static_cast<int>(riemann::IntegratorType::DormandPrince45),
  "integrator codes must match the core");

namespace
{
/// The declared defaults (a name of its own: unity batches join this file with the others').
namespace TracerDefault = riemann::declared::vtkRiemannGeodesicTracer::Default;
}

vtkRiemannGeodesicTracer::vtkRiemannGeodesicTracer()
  : StartPosition{ TracerDefault::StartPosition[0], TracerDefault::StartPosition[1],
    TracerDefault::StartPosition[2] }
  , StartDirection{ TracerDefault::StartDirection[0], TracerDefault::StartDirection[1],
    TracerDefault::StartDirection[2] }
  , NumberOfDirections(static_cast<int>(TracerDefault::NumberOfDirections))
  , ConeAngle(TracerDefault::ConeAngle)
  , IntegrationDirection(TracerDefault::IntegrationDirection)
  , ComputeTransverseJacobian(TracerDefault::ComputeTransverseJacobian)
  , SeedsPerVoxel(static_cast<int>(TracerDefault::SeedsPerVoxel))
  , SeedDirection(TracerDefault::SeedDirection)
  , RandomSeed(static_cast<unsigned int>(TracerDefault::RandomSeed))
  , StopFractionalAnisotropy(TracerDefault::StopFractionalAnisotropy)
  , MaximumAngle(TracerDefault::MaximumAngle)
  , MinimumLength(TracerDefault::MinimumLength)
{
  // The seeds, the stop mask, the include and exclude regions (all
  // optional), then the metric.
  this->SetNumberOfDataPorts(4);
  this->SetDirectionArrayName("Direction");
}

vtkRiemannGeodesicTracer::~vtkRiemannGeodesicTracer()
{
  this->SetDirectionArrayName(nullptr);
}

int vtkRiemannGeodesicTracer::FillDataPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkDataSet" : "vtkImageData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

namespace
{
struct Seed
{
  riemann::Vec3 Position;
  riemann::Vec3 Direction;
  vtkIdType Id;
  bool Backward;
};

/// Per path point: the transverse Jacobian's determinant and its two singular values.
using JacobianSamples = std::vector<std::array<double, 3>>;

/// What TraceInParallel returns: the paths in seed order (Traced of them,
/// fewer than the seeds after an abort) and their Jacobians when asked.
struct Traces
{
  std::vector<riemann::GeodesicPath> Paths;
  std::vector<JacobianSamples> Jacobians;
  vtkIdType Traced = 0;
};

/**
 * The packet Jacobi trace's samples as GeodesicPaths plus the transverse
 * Jacobian (determinant, singular values) at every point; packet trace k is
 * seed Index[k].
 */
class PathWithJacobian : public riemann::JacobiVisitor
{
public:
  PathWithJacobian(
    const std::vector<Seed>& seeds, const std::vector<vtkIdType>& index, Traces& traces)
    : Seeds(seeds)
    , Index(index)
    , Out(traces)
  {
  }
  void Start(int, std::size_t trace) override
  {
    this->Out.Paths[this->Index[trace]].Clear();
    this->Out.Jacobians[this->Index[trace]].clear();
  }
  bool Visit(int, std::size_t trace, const riemann::JacobiSample& sample) override
  {
    const vtkIdType i = this->Index[trace];
    riemann::GeodesicPath& path = this->Out.Paths[i];
    path.Points.push_back(sample.Point);
    // Velocity is dx/ds of the forward parametrisation, as TraceGeodesic's.
    path.Velocities.push_back((this->Seeds[i].Backward ? -1.0 : 1.0) * sample.Velocity);
    path.ArcLength.push_back(sample.ArcLength);
    path.SpeedDrift.push_back(sample.SpeedDrift);
    this->Out.Jacobians[i].push_back(
      { sample.Determinant, sample.SingularValues[0], sample.SingularValues[1] });
    return true;
  }
  void End(int, std::size_t trace, int reason) override
  {
    this->Out.Paths[this->Index[trace]].Reason = reason;
  }

private:
  const std::vector<Seed>& Seeds;
  const std::vector<vtkIdType>& Index;
  Traces& Out;
};

/// Seeds [first, last) with their Jacobi fields on the packet engine; a seed
/// whose direction cannot be normalised gets an empty path.
void TraceWithJacobian(const riemann::Metric& metric, const std::vector<Seed>& seeds,
  vtkIdType first, vtkIdType last, const riemann::GeodesicOptions& options, Traces& traces)
{
  std::vector<riemann::JacobiSeed> packetSeeds;
  std::vector<vtkIdType> index;
  for (vtkIdType i = first; i < last; ++i)
  {
    const Seed& seed = seeds[i];
    riemann::Vec3 velocity;
    if (!riemann::UnitSpeedVelocity(metric, seed.Position, seed.Direction, velocity))
    {
      traces.Paths[i].Clear();
      continue;
    }
    packetSeeds.push_back({ seed.Position, seed.Direction, seed.Backward });
    index.push_back(i);
  }
  PathWithJacobian visitor(seeds, index, traces);
  riemann::TraceJacobiFields(
    metric, packetSeeds.data(), packetSeeds.size(), options, {}, false, visitor);
}

/**
 * The starts of a mask (an input image without the direction array): its
 * set voxels' seeds (riemann::MaskSeedPoints), each along E1 (g's
 * eigenvector of the smallest eigenvalue; (1, 0, 0) where g fails, which
 * the tracer then counts as untraced) or a random unit vector.
 */
std::vector<std::pair<riemann::Vec3, riemann::Vec3>> MaskStarts(
  vtkRiemannGeodesicTracer* self, vtkImageData* mask, const riemann::Metric& metric)
{
  std::vector<std::pair<riemann::Vec3, riemann::Vec3>> starts;
  const std::vector<double> points =
    riemann::MaskSeedPoints(mask, self->GetSeedsPerVoxel(), self->GetRandomSeed());
  // Not the points' generator: the directions do not depend on SeedsPerVoxel's draws.
  std::mt19937 generator(self->GetRandomSeed() + 1u);
  std::normal_distribution<double> normal;
  for (std::size_t p = 0; p + 2 < points.size(); p += 3)
  {
    const riemann::Vec3 x(points[p], points[p + 1], points[p + 2]);
    riemann::Vec3 direction(1.0, 0.0, 0.0);
    if (self->GetSeedDirection() == vtkRiemannGeodesicTracer::RANDOM)
    {
      do
      {
        direction = riemann::Vec3(normal(generator), normal(generator), normal(generator));
      } while (!(direction.norm() > 1e-12));
    }
    else
    {
      riemann::Mat3 g;
      if (metric.Tensor(x, g) && g.allFinite())
      {
        direction = Eigen::SelfAdjointEigenSolver<riemann::Mat3>(g).eigenvectors().col(0);
      }
    }
    starts.emplace_back(x, direction);
  }
  return starts;
}

/// Step 1 of RequestData: the seeds, in start order, one per start and
/// direction of integration (two for BOTH). The starts are the input's points
/// with their directions (or StartDirection), a mask's seeds (MaskStarts), or
/// StartPosition without an input. Returns the error that empties the output
/// ("" when all is well); a missing direction array is only a warning.
std::string GatherSeeds(vtkRiemannGeodesicTracer* self, vtkDataSet* input,
  const riemann::Metric& metric, std::vector<Seed>& seeds)
{
  const double* start = self->GetStartDirection();
  const riemann::Vec3 startDirection(start[0], start[1], start[2]);
  const char* arrayName = self->GetDirectionArrayName();
  std::vector<std::pair<riemann::Vec3, riemann::Vec3>> starts;
  auto* mask = vtkImageData::SafeDownCast(input);
  if (mask && !(arrayName && mask->GetPointData()->GetArray(arrayName)))
  {
    if (!mask->GetPointData()->GetScalars())
    {
      return "The input image has neither a direction array nor scalars to seed from as a mask.";
    }
    starts = MaskStarts(self, mask, metric);
  }
  else if (input)
  {
    vtkDataArray* directions = arrayName ? input->GetPointData()->GetArray(arrayName) : nullptr;
    if (directions && directions->GetNumberOfComponents() != 3)
    {
      std::ostringstream message;
      message << "The seeds' array \"" << arrayName << "\" has "
              << directions->GetNumberOfComponents() << " components; it needs 3.";
      return message.str();
    }
    if (!directions && input->GetNumberOfPoints() > 0)
    {
      vtkWarningWithObjectMacro(self, << "The seeds have no point-data array \""
                                      << (arrayName ? arrayName : "")
                                      << "\"; every seed uses StartDirection.");
    }
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      double p[3], d[3];
      input->GetPoint(i, p);
      riemann::Vec3 direction = startDirection;
      if (directions)
      {
        directions->GetTuple(i, d);
        direction = riemann::Vec3(d[0], d[1], d[2]);
      }
      starts.emplace_back(riemann::Vec3(p[0], p[1], p[2]), direction);
    }
  }
  else
  {
    // One seed: along StartDirection, or fanned over the cone around it.
    const double* position = self->GetStartPosition();
    const riemann::Vec3 seed(position[0], position[1], position[2]);
    if (self->GetNumberOfDirections() > 1 && startDirection.squaredNorm() == 0.0)
    {
      return "StartDirection is zero: the cone of directions has no axis.";
    }
    const std::vector<riemann::Vec3> fan = self->GetNumberOfDirections() > 1
      ? riemann::FibonacciDirections(
          self->GetNumberOfDirections(), startDirection, self->GetConeAngle())
      : std::vector<riemann::Vec3>{ startDirection };
    for (const riemann::Vec3& direction : fan)
    {
      starts.emplace_back(seed, direction);
    }
  }
  const int integrationDirection = self->GetIntegrationDirection();
  for (size_t i = 0; i < starts.size(); ++i)
  {
    if (integrationDirection != vtkRiemannGeodesicTracer::BACKWARD)
    {
      seeds.push_back({ starts[i].first, starts[i].second, static_cast<vtkIdType>(i), false });
    }
    if (integrationDirection != vtkRiemannGeodesicTracer::FORWARD)
    {
      seeds.push_back({ starts[i].first, starts[i].second, static_cast<vtkIdType>(i), true });
    }
  }
  return std::string();
}

/// Step 2: every seed's geodesic, in parallel, with progress and abort
/// between batches of 256 seeds; packets of seeds through the packet engine
/// (TraceGeodesics, or the packet TraceJacobiFields with the Jacobi
/// fields). A seed whose
/// direction cannot be normalised gets an empty path.
Traces TraceInParallel(vtkAlgorithm* self, const riemann::Metric& metric,
  const std::vector<Seed>& seeds, const riemann::GeodesicOptions& options, bool jacobian)
{
  Traces traces;
  traces.Paths.resize(seeds.size());
  traces.Jacobians.resize(jacobian ? seeds.size() : 0);
  const vtkIdType count = static_cast<vtkIdType>(seeds.size());
  traces.Traced = vtkRiemannForInBatches(
    self, count, 256,
    [&](vtkIdType first, vtkIdType last)
    {
      if (jacobian)
      {
        TraceWithJacobian(metric, seeds, first, last, options, traces);
        return;
      }
      // The packet engine, PacketWidth geodesics at a time. A seed whose
      // direction cannot be normalised gets a zero velocity: TraceGeodesics
      // then leaves its path empty, as Clear() would.
      std::vector<riemann::GeodesicSeed> packetSeeds(static_cast<size_t>(last - first));
      for (vtkIdType i = first; i < last; ++i)
      {
        riemann::GeodesicSeed& packetSeed = packetSeeds[static_cast<size_t>(i - first)];
        packetSeed.Point = seeds[i].Position;
        packetSeed.Backward = seeds[i].Backward;
        if (!riemann::UnitSpeedVelocity(
              metric, seeds[i].Position, seeds[i].Direction, packetSeed.Velocity))
        {
          packetSeed.Velocity = riemann::Vec3::Zero();
        }
      }
      riemann::TraceGeodesics(
        metric, packetSeeds.data(), packetSeeds.size(), options, traces.Paths.data() + first);
    },
    // Ranges of two packets: 200 seeds make 13 ranges, balanced over the
    // threads (4 packets per range left one thread a range behind).
    2 * riemann::PacketWidth);
  return traces;
}

/// Step 3: count the paths that make no line (fewer than two points) by why
/// they stopped, and warn once for each reason.
std::vector<vtkIdType> CountUntracedSeeds(vtkObject* self, const Traces& traces)
{
  std::vector<vtkIdType> untraced(riemann::LastTerminationReason + 1, 0);
  for (vtkIdType i = 0; i < traces.Traced; ++i)
  {
    if (traces.Paths[i].Points.size() < 2)
    {
      const int reason =
        std::clamp(traces.Paths[i].Reason, 0, static_cast<int>(riemann::LastTerminationReason));
      untraced[static_cast<std::size_t>(reason)]++;
    }
  }
  for (std::size_t reason = 0; reason < untraced.size(); ++reason)
  {
    if (untraced[reason] > 0)
    {
      vtkWarningWithObjectMacro(self, << untraced[reason] << " of " << traces.Traced
                                      << " geodesics made no line: "
                                      << riemann::TerminationReasonName(static_cast<int>(reason))
                                      << " at the seed.");
    }
  }
  return untraced;
}

/**
 * Step 4 (tractography): cut every path at its first sharp turn (with a
 * MaximumAngle), then drop the tracts the selection refuses: a tract is a
 * seed's paths (adjacent in `seeds`, both halves with BOTH). Dropped paths
 * are emptied, so BuildOutput skips them. Returns the counts by why.
 */
std::vector<vtkIdType> CutAndSelectTracts(double maximumAngle,
  const riemann::TractSelection& selection, const std::vector<Seed>& seeds, Traces& traces)
{
  std::vector<vtkIdType> rejected(riemann::LastTractRejection + 1, 0);
  if (maximumAngle > 0.0)
  {
    for (vtkIdType i = 0; i < traces.Traced; ++i)
    {
      riemann::CutAtSharpTurn(traces.Paths[i], maximumAngle);
    }
  }
  if (!selection.Any())
  {
    return rejected;
  }
  for (vtkIdType first = 0; first < traces.Traced;)
  {
    vtkIdType last = first + 1;
    while (last < traces.Traced && seeds[last].Id == seeds[first].Id)
    {
      ++last;
    }
    std::vector<const riemann::GeodesicPath*> halves;
    for (vtkIdType i = first; i < last; ++i)
    {
      halves.push_back(&traces.Paths[i]);
    }
    const int why = riemann::SelectTract(halves.data(), static_cast<int>(halves.size()), selection);
    bool anyLine = false;
    for (const riemann::GeodesicPath* half : halves)
    {
      anyLine = anyLine || half->Points.size() >= 2;
    }
    if (why != riemann::TractKept && anyLine)
    {
      rejected[static_cast<std::size_t>(why)]++;
      for (vtkIdType i = first; i < last; ++i)
      {
        traces.Paths[i].Clear();
      }
    }
    first = last;
  }
  return rejected;
}

/// Step 5: the polylines of two or more points, in seed order, with their
/// point arrays (ArcLength, Velocity, SpeedDrift and the Jacobian's when
/// asked) and cell arrays (SeedIds, ReasonForTermination). Each path's
/// points have their place from a prefix sum, so the paths are copied in
/// parallel (serially, copying was a quarter of a 2-thread trace of small
/// paths); the lines are consecutive runs of points, so their connectivity
/// is 0, 1, 2, ... and only their offsets are the sum's.
void BuildOutput(
  const std::vector<Seed>& seeds, const Traces& traces, bool jacobian, vtkPolyData* output)
{
  // Where each kept path's points and line go.
  std::vector<vtkIdType> firstPoint(static_cast<std::size_t>(traces.Traced) + 1, 0);
  std::vector<vtkIdType> lineOf(static_cast<std::size_t>(traces.Traced), -1);
  vtkIdType lineCount = 0;
  for (vtkIdType i = 0; i < traces.Traced; ++i)
  {
    const vtkIdType n = static_cast<vtkIdType>(traces.Paths[i].Points.size());
    const bool kept = n >= 2;
    firstPoint[i + 1] = firstPoint[i] + (kept ? n : 0);
    lineOf[i] = kept ? lineCount++ : -1;
  }
  const vtkIdType pointCount = firstPoint.back();

  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetName("Points"); // vtkPoints' own array's name
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(pointCount);
  auto arcLength = vtkRiemannNewArray<vtkDoubleArray>("ArcLength", 1, pointCount);
  auto velocity = vtkRiemannNewArray<vtkDoubleArray>("Velocity", 3, pointCount);
  auto speedDrift = vtkRiemannNewArray<vtkDoubleArray>("SpeedDrift", 1, pointCount);
  vtkSmartPointer<vtkDoubleArray> determinant, singularValues;
  if (jacobian)
  {
    determinant = vtkRiemannNewArray<vtkDoubleArray>("TransverseJacobian", 1, pointCount);
    singularValues =
      vtkRiemannNewArray<vtkDoubleArray>("TransverseJacobianSingularValues", 2, pointCount);
  }
  vtkNew<vtkIntArray> seedIds, reasons;
  seedIds->SetName("SeedIds");
  seedIds->SetNumberOfTuples(lineCount);
  reasons->SetName("ReasonForTermination");
  reasons->SetNumberOfTuples(lineCount);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(lineCount + 1);
  connectivity->SetNumberOfTuples(pointCount);

  vtkSMPTools::For(0, traces.Traced,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const vtkIdType line = lineOf[i];
        if (line < 0)
        {
          continue;
        }
        const riemann::GeodesicPath& path = traces.Paths[i];
        const vtkIdType first = firstPoint[i];
        offsets->SetValue(line, first);
        seedIds->SetValue(line, static_cast<int>(seeds[i].Id));
        reasons->SetValue(line, path.Reason);
        for (size_t k = 0; k < path.Points.size(); ++k)
        {
          const vtkIdType p = first + static_cast<vtkIdType>(k);
          connectivity->SetValue(p, p);
          coordinates->SetTypedTuple(p, path.Points[k].data());
          arcLength->SetValue(p, path.ArcLength[k]);
          velocity->SetTypedTuple(p, path.Velocities[k].data());
          speedDrift->SetValue(p, path.SpeedDrift[k]);
          if (jacobian)
          {
            determinant->SetValue(p, traces.Jacobians[i][k][0]);
            singularValues->SetTypedTuple(p, traces.Jacobians[i][k].data() + 1);
          }
        }
      }
    });
  offsets->SetValue(lineCount, pointCount);

  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  vtkNew<vtkCellArray> lines;
  lines->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetPointData()->AddArray(arcLength);
  output->GetPointData()->AddArray(velocity);
  output->GetPointData()->SetVectors(velocity);
  output->GetPointData()->AddArray(speedDrift);
  if (jacobian)
  {
    output->GetPointData()->AddArray(determinant);
    output->GetPointData()->AddArray(singularValues);
  }
  output->GetCellData()->AddArray(seedIds);
  output->GetCellData()->AddArray(reasons);
}
} // namespace

int vtkRiemannGeodesicTracer::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Any piece can be traced alone: a share of the seeds.
  outputVector->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

int vtkRiemannGeodesicTracer::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Every piece needs all the seeds (they are few) to take its share of
  // them, and the whole of each mask (a tract goes anywhere).
  for (int port = 0; port <= ExcludeRegionPort; ++port)
  {
    if (this->GetNumberOfInputConnections(port) == 0)
    {
      continue;
    }
    vtkInformation* inInfo = inputVector[port]->GetInformationObject(0);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
  return 1;
}

// RequestData as named steps: GatherSeeds -> PieceShare -> TraceInParallel
// -> CountUntracedSeeds -> CutAndSelectTracts -> BuildOutput (each in an
// anonymous namespace above).
int vtkRiemannGeodesicTracer::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  this->UntracedSeeds.clear();
  this->RejectedTracts.clear();
  const std::shared_ptr<const riemann::Metric> metric = this->CheckMetricAndSettings();
  if (!metric)
  {
    return 1;
  }
  vtkDataSet* input =
    this->GetNumberOfInputConnections(0) > 0 ? vtkDataSet::GetData(inputVector[0], 0) : nullptr;
  std::vector<Seed> seeds;
  const std::string error = GatherSeeds(this, input, *metric, seeds);
  if (!error.empty())
  {
    this->ReportError(error);
    return 1;
  }
  // This piece's share of the seeds (all of them without a piece request).
  vtkIdType first = 0;
  vtkIdType last = 0;
  PieceShare(request, outputVector, static_cast<vtkIdType>(seeds.size()), first, last);
  seeds.erase(seeds.begin() + last, seeds.end());
  seeds.erase(seeds.begin(), seeds.begin() + first);
  riemann::GeodesicOptions options = this->MakeGeodesicOptions();
  options.UseBounds = this->UseDomainBounds;
  std::copy(this->DomainBounds, this->DomainBounds + 6, options.Bounds);
  // A mask's connection wins over its setter's image.
  const auto mask = [this, inputVector](int port, vtkImageData* own)
  {
    return this->GetNumberOfInputConnections(port) > 0 ? vtkImageData::GetData(inputVector[port], 0)
                                                       : own;
  };
  vtkImageData* stopMask = mask(StopMaskPort, this->StopMask);
  vtkImageData* includeRegion = mask(IncludeRegionPort, this->IncludeRegion);
  vtkImageData* excludeRegion = mask(ExcludeRegionPort, this->ExcludeRegion);
  riemann::TractStopRules stops(*metric);
  stops.StopMask = riemann::VoxelMaskFromImage(stopMask);
  stops.MinimumAnisotropy = this->StopFractionalAnisotropy;
  options.Stop = stops.Any() ? &stops : nullptr;
  riemann::TractSelection selection;
  selection.Include = riemann::VoxelMaskFromImage(includeRegion);
  selection.Exclude = riemann::VoxelMaskFromImage(excludeRegion);
  selection.MinimumLength = this->MinimumLength;
  if ((stopMask && stops.StopMask.Empty()) || (includeRegion && selection.Include.Empty()) ||
    (excludeRegion && selection.Exclude.Empty()))
  {
    this->ReportError("A stop mask, include or exclude region has no scalars to read.");
    return 1;
  }
  Traces traces =
    TraceInParallel(this, *metric, seeds, options, this->ComputeTransverseJacobian);
  this->UntracedSeeds = CountUntracedSeeds(this, traces);
  this->RejectedTracts = CutAndSelectTracts(this->MaximumAngle, selection, seeds, traces);
  BuildOutput(seeds, traces, this->ComputeTransverseJacobian, output);
  return 1;
}

vtkIdType vtkRiemannGeodesicTracer::GetNumberOfUntracedSeeds() const
{
  vtkIdType all = 0;
  for (vtkIdType n : this->UntracedSeeds)
  {
    all += n;
  }
  return all;
}

vtkIdType vtkRiemannGeodesicTracer::GetNumberOfUntracedSeeds(int reason) const
{
  return reason >= 0 && reason < static_cast<int>(this->UntracedSeeds.size())
    ? this->UntracedSeeds[static_cast<std::size_t>(reason)]
    : 0;
}

vtkIdType vtkRiemannGeodesicTracer::GetNumberOfRejectedTracts() const
{
  vtkIdType all = 0;
  for (vtkIdType n : this->RejectedTracts)
  {
    all += n;
  }
  return all;
}

vtkIdType vtkRiemannGeodesicTracer::GetNumberOfRejectedTracts(int why) const
{
  return why >= 0 && why < static_cast<int>(this->RejectedTracts.size())
    ? this->RejectedTracts[static_cast<std::size_t>(why)]
    : 0;
}

vtkMTimeType vtkRiemannGeodesicTracer::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  for (vtkImageData* image : { this->StopMask.Get(), this->IncludeRegion.Get(), this->ExcludeRegion.Get() })
  {
    if (image)
    {
      time = std::max(time, image->GetMTime());
    }
  }
  return time;
}

void vtkRiemannGeodesicTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "StartPosition: " << this->StartPosition[0] << " " << this->StartPosition[1]
     << " " << this->StartPosition[2] << "\n";
  os << indent << "StartDirection: " << this->StartDirection[0] << " " << this->StartDirection[1]
     << " " << this->StartDirection[2] << "\n";
  os << indent << "NumberOfDirections: " << this->NumberOfDirections << "\n";
  os << indent << "ConeAngle: " << this->ConeAngle << "\n";
  os << indent
     << "DirectionArrayName: " << (this->DirectionArrayName ? this->DirectionArrayName : "(none)")
     << "\n";
  os << indent << "IntegrationDirection: " << this->IntegrationDirection << "\n";
  os << indent << "SeedsPerVoxel: " << this->SeedsPerVoxel << "\n";
  os << indent << "SeedDirection: " << (this->SeedDirection == RANDOM ? "RANDOM" : "E1") << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "UseDomainBounds: " << this->UseDomainBounds << "\n";
  os << indent << "DomainBounds: " << this->DomainBounds[0] << " " << this->DomainBounds[1] << " "
     << this->DomainBounds[2] << " " << this->DomainBounds[3] << " " << this->DomainBounds[4] << " "
     << this->DomainBounds[5] << "\n";
  os << indent << "ComputeTransverseJacobian: " << this->ComputeTransverseJacobian << "\n";
  os << indent << "StopMask: " << this->StopMask.Get() << "\n";
  os << indent << "StopFractionalAnisotropy: " << this->StopFractionalAnisotropy << "\n";
  os << indent << "MaximumAngle: " << this->MaximumAngle << "\n";
  os << indent << "IncludeRegion: " << this->IncludeRegion.Get() << "\n";
  os << indent << "ExcludeRegion: " << this->ExcludeRegion.Get() << "\n";
  os << indent << "MinimumLength: " << this->MinimumLength << "\n";
}
