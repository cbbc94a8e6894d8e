// riemann trace: geodesics of a metric from one seed, a CSV of seeds, a mask
// or a streamline file, written as .vtp (VTK XML polylines), .csv
// (seed_id,step,t,x,y,z,vx,vy,vz) or, for tractography, .tck / .trk
// (TractOptions.h, with the stop and selection options).
#include "CliUtilities.h"
#include "Commands.h"
#include "CsvColumns.h"
#include "CsvWriter.h"
#include "DeclaredOptions.h"
#include "Distributed.h"
#include "GeodesicCsv.h"
#include "GeodesicTrace.h"
#include "InputFiles.h"
#include "IntegrationOptions.h"
#include "RiemannScalarImages.h"
#include "TractOptions.h"
#include "vtkRiemannGeodesicTracerSettingAccess.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRiemannGeodesicTracer.h"
#include "vtkRiemannMetric.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace riemann
{
namespace cli
{
namespace
{
/// The largest TerminationReason code (GeodesicTrace.h), for the summary's counts.
constexpr int MaximumReason = LastTerminationReason;

struct TraceArguments
{
  std::string Metric;
  std::string SeedsFile;
  std::string SeedMask;
  /// The tracer's settings (vtkRiemannGeodesicTracer.settings.json): the seed
  /// and its fan, the mask's seeds, the way, the stops, the Jacobi fields.
  std::unique_ptr<DeclaredOptions> Settings;
  /// The integration options, with the tracer's defaults (IntegrationOptions.h).
  std::unique_ptr<DeclaredOptions> Integration;
  TractArguments Tracts;
  std::string Compress = "lz4";
  bool Gather = false;
  std::string Output;
};

/// "3 seed(s) made no geodesic: 2 left the sampled data, 1 degenerate
/// metric" from the counts by reason (0..MaximumReason) of seed-direction
/// pairs, `ways` per seed (2 for --propagation both: every reason to make no
/// line is the seed's, so both halves fail alike); "" when none.
std::string DescribeUntraced(const long long* byReason, int ways)
{
  long long all = 0;
  std::string reasons;
  for (int reason = 0; reason <= MaximumReason; ++reason)
  {
    if (byReason[reason] > 0)
    {
      all += byReason[reason] / ways;
      reasons += (reasons.empty() ? "" : ", ") + std::to_string(byReason[reason] / ways) + " " +
        TerminationReasonName(reason);
    }
  }
  return all == 0 ? std::string()
                  : std::to_string(all) + " seed(s) made no geodesic: " + reasons + " at the seed";
}

/**
 * The mask of --seed-mask (placed by its own affine), which the tracer seeds
 * from (vtkRiemannGeodesicTracer: SeedsPerVoxel seeds in every voxel that is
 * not 0, along SeedDirection); `count` receives how many seeds that makes.
 */
vtkSmartPointer<vtkImageData> ReadSeedMask(const TraceArguments& args, vtkIdType& count)
{
  vtkSmartPointer<vtkImageData> mask;
  try
  {
    mask = ReadScalarImageFile(args.SeedMask, "the seed mask");
  }
  catch (const std::runtime_error& e)
  {
    throw Failure(std::string("--seed-mask: ") + e.what());
  }
  vtkDataArray* values = mask->GetPointData()->GetScalars();
  const long long seedsPerVoxel = args.Settings->Integer("SeedsPerVoxel");
  count = 0;
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    count += values->GetTuple1(i) != 0.0 ? seedsPerVoxel : 0;
  }
  if (count == 0)
  {
    throw Failure("--seed-mask " + args.SeedMask + ": no voxel of the mask is set (not 0)");
  }
  return mask;
}

/// Reads seeds from a CSV with a header naming x,y,z,dx,dy,dz (any order,
/// extra columns ignored), or from a streamline file (SeedsFromTracts).
vtkSmartPointer<vtkPolyData> ReadSeeds(const std::string& path)
{
  if (IsTractFile(path) || Extension(path) == "vtp")
  {
    return SeedsFromTracts(path);
  }
  std::vector<long long> lines;
  const std::vector<std::vector<double>> rows =
    ReadCsvColumns(path, { "x", "y", "z", "dx", "dy", "dz" }, "seeds", 10000000, &lines);
  std::vector<Vec3> starts, directions;
  for (std::size_t r = 0; r < rows.size(); ++r)
  {
    const double* d = rows[r].data();
    std::ostringstream direction;
    direction << d[3] << ',' << d[4] << ',' << d[5];
    const std::string degenerate = CheckDirection(d + 3, direction.str());
    if (!degenerate.empty())
    {
      throw Failure(path + ": line " + std::to_string(lines[r]) + ": dx,dy,dz " + degenerate);
    }
    starts.emplace_back(d[0], d[1], d[2]);
    directions.emplace_back(d[3], d[4], d[5]);
  }
  return SeedsWithDirections(starts, directions);
}

/// The most points a trace writes (about 10 GB as .vtp with its arrays, more as CSV).
constexpr double MaximumOutputPoints = 2e8;

/**
 * Refuse (usage, status 2) a run whose geodesics could hold more than
 * MaximumOutputPoints: per geodesic min(--max-steps, --length / --step) + 1
 * points (dp45 may shrink its step below --step, still within --max-steps).
 * `--max-steps 1e9 --step 1e-9 --length 1e9` once wrote 80 MB/s until the
 * disk was full.
 */
void CheckOutputSize(const TraceArguments& args, vtkIdType numberOfSeeds, const std::string& propagation)
{
  const DeclaredOptions& integration = *args.Integration;
  const double stepsPerGeodesic =
    std::min(static_cast<double>(integration.Integer("MaximumNumberOfSteps")),
      std::ceil(integration.Number("MaximumPropagation") / integration.Number("InitialIntegrationStep")));
  const double ways = propagation == "both" ? 2.0 : 1.0;
  const double points = static_cast<double>(numberOfSeeds) * ways * (stepsPerGeodesic + 1.0);
  if (points > MaximumOutputPoints)
  {
    std::ostringstream message;
    message << numberOfSeeds << " seed(s) x " << (ways > 1 ? "2 ways x " : "") << stepsPerGeodesic
            << " steps (min of --max-steps and --length / --step): up to " << points
            << " points, more than the " << MaximumOutputPoints
            << " a trace writes; lower --max-steps or --length, or raise --step";
    throw Failure(message.str(), 2);
  }
}

/// Refuse missing inputs and an output of no known kind before any work;
/// the output's extension.
std::string CheckTracePaths(const TraceArguments& args)
{
  std::vector<NamedPath> inputs = { { "-m", args.Metric },
    { "--seeds", args.SeedsFile }, { "--seed-mask", args.SeedMask } };
  for (const auto& input : TractInputFiles(args.Tracts))
  {
    inputs.push_back(input);
  }
  CheckFilePaths(inputs, { { "-o", args.Output } });
  const std::string extension = Extension(args.Output);
  if (extension != "vtp" && extension != "csv" && extension != "pvtp" && !IsTractFile(args.Output))
  {
    throw Failure(
      "-o " + args.Output + ": the output must end in .vtp, .pvtp, .csv, .tck or .trk", 2);
  }
  return extension;
}

/// Give the tracer the declared, integration and tract options; returns the
/// propagation ("forward", "backward" or "both").
std::string ConfigureTracer(const TraceArguments& args, vtkRiemannGeodesicTracer* tracer)
{
  // Seeds from a mask go both ways along e1 unless --propagation says otherwise.
  nlohmann::json settings = args.Settings->Given();
  if (!args.SeedMask.empty() && args.Settings->Text("SeedDirection") == "e1" &&
    !settings.contains("IntegrationDirection"))
  {
    settings["IntegrationDirection"] = "both";
  }
  riemann::settings::ApplySettings(tracer, settings);
  ApplyIntegrationOptions(*args.Integration, tracer->GetIntegrationSettings());
  ApplyTractOptions(args.Tracts, tracer);
  return settings.value("IntegrationDirection", args.Settings->Text("IntegrationDirection"));
}

/// The tracer's input: the seeds file, else the seed mask, else none (one
/// seed fanned over NumberOfDirections). Sets how many seeds that is; returns
/// the mask (null without one).
vtkSmartPointer<vtkImageData> SetTracerSeeds(
  const TraceArguments& args, vtkRiemannGeodesicTracer* tracer, vtkIdType& numberOfSeeds)
{
  numberOfSeeds = args.Settings->Integer("NumberOfDirections");
  if (!args.SeedsFile.empty())
  {
    vtkSmartPointer<vtkPolyData> seeds = ReadSeeds(args.SeedsFile);
    numberOfSeeds = seeds->GetNumberOfPoints();
    tracer->SetInputData(seeds);
    return nullptr;
  }
  if (args.SeedMask.empty())
  {
    return nullptr;
  }
  vtkSmartPointer<vtkImageData> seedMask = ReadSeedMask(args, numberOfSeeds);
  tracer->SetInputData(seedMask);
  return seedMask;
}

/// The job's figures over every rank: geodesics, points, the lines by why
/// they stopped, the seeds that made no geodesic by why, and the tracts the
/// selection dropped by why (TraceFigures' layout).
struct TraceFigures
{
  std::vector<long long> Counts;
  long long Lines() const { return this->Counts[0]; }
  long long Points() const { return this->Counts[1]; }
  long long LinesStoppedBy(int reason) const { return this->Counts[2 + reason]; }
  const long long* Untraced() const { return this->Counts.data() + 2 + MaximumReason + 1; }
  const long long* Rejected() const { return this->Counts.data() + 2 + 2 * (MaximumReason + 1); }
};

TraceFigures CountTraceFigures(vtkRiemannGeodesicTracer* tracer)
{
  vtkPolyData* lines = tracer->GetOutput();
  std::vector<long long> counts(2 + MaximumReason + 1, 0);
  counts[0] = lines->GetNumberOfLines();
  counts[1] = lines->GetNumberOfPoints();
  if (vtkDataArray* reasonArray = lines->GetCellData()->GetArray("ReasonForTermination"))
  {
    for (vtkIdType i = 0; i < reasonArray->GetNumberOfTuples(); ++i)
    {
      const int reason = static_cast<int>(reasonArray->GetTuple1(i));
      counts[2 + std::min(std::max(reason, 0), MaximumReason)]++;
    }
  }
  for (int reason = 0; reason <= MaximumReason; ++reason)
  {
    counts.push_back(static_cast<long long>(tracer->GetNumberOfUntracedSeeds(reason)));
  }
  for (int why = 0; why <= LastTractRejection; ++why)
  {
    counts.push_back(static_cast<long long>(tracer->GetNumberOfRejectedTracts(why)));
  }
  return TraceFigures{ SumOverRanks(counts) };
}

/// The one-line summary on stderr: how many lines, and why they stopped.
void PrintTraceSummary(const TraceArguments& args, const TraceFigures& figures,
  const std::string& untraced, const std::string& rejected)
{
  std::cerr << "riemann trace: " << figures.Lines() << " geodesic(s), " << figures.Points()
            << " points -> " << args.Output << " (";
  bool first = true;
  for (int reason = 0; reason <= MaximumReason; ++reason)
  {
    if (figures.LinesStoppedBy(reason) > 0)
    {
      std::cerr << (first ? "" : ", ") << figures.LinesStoppedBy(reason) << " "
                << TerminationReasonName(reason);
      first = false;
    }
  }
  if (!untraced.empty())
  {
    std::cerr << "; " << untraced;
  }
  if (!rejected.empty())
  {
    std::cerr << "; " << rejected;
  }
  if (IsDistributed())
  {
    std::cerr << "; " << NumberOfRanks() << " ranks";
  }
  std::cerr << ")\n";
}

void RunTrace(const TraceArguments& args)
{
  const std::string extension = CheckTracePaths(args);
  const OutputLayout layout = ChooseOutputLayout("-o", args.Output, args.Gather, "pvtp");

  vtkSmartPointer<vtkRiemannMetric> metric = LoadMetric(args.Metric);
  vtkNew<vtkRiemannGeodesicTracer> tracer;
  vtkNew<ErrorCollector> errors;
  errors->Observe(tracer);
  tracer->SetMetric(metric);
  const std::string propagation = ConfigureTracer(args, tracer);
  vtkIdType numberOfSeeds = 0;
  vtkSmartPointer<vtkImageData> seedMask = SetTracerSeeds(args, tracer, numberOfSeeds);
  CheckOutputSize(args, numberOfSeeds, propagation);
  // A .trk's reference, before the work: a run without one is refused at once.
  TractReference reference;
  if (extension == "trk")
  {
    TractArguments tracts = args.Tracts;
    tracts.SeedMask = args.SeedMask;
    reference = ChooseTrkReference(tracts, metric, seedMask);
  }
  // This rank's share of the seeds (all of them in a single process).
  UpdateThisRanksPiece(tracer);
  errors->ThrowIfAny("tracing failed:");
  AgreeToGoOn();

  const TraceFigures figures = CountTraceFigures(tracer);
  const std::string untraced = DescribeUntraced(figures.Untraced(), propagation == "both" ? 2 : 1);
  const std::string rejected = DescribeRejectedTracts(figures.Rejected());
  if (figures.Lines() == 0)
  {
    std::string why = untraced;
    why += (why.empty() || rejected.empty() ? "" : "; ") + rejected;
    throw Failure("no geodesic could be traced from the given seeds" +
      (why.empty() ? std::string() : ": " + why));
  }

  WriteOutput(tracer, 0, args.Output, layout, args.Compress, {},
    [&](vtkPolyData* all, const std::string& temporary)
    {
      if (IsTractFile(args.Output))
      {
        return WriteTractFile(all, temporary, args.Output, reference);
      }
      return extension == "csv" ? WriteGeodesicCsv(all, temporary)
                                : WritePolyDataFile(all, temporary, args.Compress);
    });
  if (Rank() == 0)
  {
    PrintTraceSummary(args, figures, untraced, rejected);
  }
}
} // namespace

void RegisterTraceCommand(CLI::App& app)
{
  auto args = std::make_shared<TraceArguments>();
  CLI::App* command = app.add_subcommand("trace", "Trace geodesics of a metric from seeds.");
  command->add_option("--metric,-m", args->Metric, "Metric definition (JSON file)")
    ->required()
    ->check(CLI::ExistingFile);
  // The seed, its fan, the mask's seeds, the way, the stops, the Jacobi fields.
  args->Settings = std::make_unique<DeclaredOptions>(command, riemann::declared::vtkRiemannGeodesicTracer::Settings);
  CLI::Option* seed = args->Settings->OptionOf("StartPosition");
  CLI::Option* direction = args->Settings->OptionOf("StartDirection");
  command
    ->add_option("--seeds", args->SeedsFile,
      "CSV of seeds with header x,y,z,dx,dy,dz, or a streamline file (.tck, .trk, .vtp: each "
      "streamline's first point along its tangent there) (replaces --seed/--direction)")
    ->check(CLI::ExistingFile)
    ->excludes(seed)
    ->excludes(direction);
  command
    ->add_option("--seed-mask", args->SeedMask,
      "Seeds from a mask or label image (.nii, .nii.gz, .nrrd, .nhdr, .vti, .vtk, placed by its "
      "own affine): every voxel that is not 0, along --seed-direction (e1: traced both ways "
      "unless --propagation says otherwise) (replaces --seed/--seeds)")
    ->check(CLI::ExistingFile)
    ->excludes(seed)
    ->excludes(direction)
    ->excludes(command->get_option("--seeds"));
  args->Integration =
    AddIntegrationOptions(command, vtkNew<vtkRiemannGeodesicTracer>()->GetIntegrationSettings());
  AddTractOptions(command, args->Tracts);
  AddCompressOption(command, args->Compress);
  AddGatherOption(command, args->Gather);
  command
    ->add_option("--output,-o", args->Output,
      std::string("Output file: .vtp, .csv (with --compute-transverse-jacobian its last columns "
                  "are TransverseJacobian,SingularValue0,SingularValue1), .tck or .trk "
                  "(streamlines in RAS+ mm, one per seed: both halves joined), or .pvtp ") +
        PiecesHelp)
    ->required();
  command->callback([args]() { RunTrace(*args); });
}
} // namespace cli
} // namespace riemann
