// riemann conjugate: conjugate points of an observer along a fan of geodesics
// (vtkRiemannConjugateLocus), written as .vtp (vertices with point data) or
// .csv (direction_id,x,y,z,ArcLength,Multiplicity,ConjugateIndex,Sheet); with
// --surface, the caustic as sheets over the direction grid (.vtp).
#include "CliUtilities.h"
#include "DeclaredOptions.h"
#include "IntegrationOptions.h"
#include "Commands.h"
#include "CsvWriter.h"
#include "Distributed.h"
#include "ProgressBar.h"
#include "vtkRiemannConjugateLocusSettingAccess.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRiemannConjugateLocus.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include <CLI/CLI.hpp>

#include <algorithm>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <string>

namespace riemann
{
namespace cli
{
namespace
{
struct ConjugateArguments
{
  std::string Metric;
  /// The filter's settings (vtkRiemannConjugateLocus.settings.json): its
  /// Tolerance is --tolerance (the integration error follows it).
  std::unique_ptr<DeclaredOptions> Settings;
  /// The integration options but MaximumError, with the filter's own
  /// defaults (dp45: the search for conjugate points needs its error control).
  std::unique_ptr<DeclaredOptions> Integration;
  std::string Compress = "lz4";
  bool Gather = false;
  std::string Output;
  std::string Surface;
};

/// Sheets the summary tells apart (sheet indices are not bounded by --count:
/// a point of multiplicity 2 starts two).
constexpr long long MaximumCountedSheets = 1024;

bool WriteCsv(vtkPolyData* locus, const std::string& path)
{
  std::ofstream out(path);
  if (!out)
  {
    return false;
  }
  out << "direction_id,x,y,z,ArcLength,Multiplicity,ConjugateIndex,Sheet\n";
  CsvWriter csv(out);
  vtkPointData* pd = locus->GetPointData();
  vtkDataArray* arcLength = pd->GetArray("ArcLength");
  vtkDataArray* multiplicity = pd->GetArray("Multiplicity");
  vtkDataArray* index = pd->GetArray("ConjugateIndex");
  vtkDataArray* direction = pd->GetArray("DirectionId");
  vtkDataArray* sheet = pd->GetArray("Sheet");
  for (vtkIdType i = 0; i < locus->GetNumberOfPoints(); ++i)
  {
    double p[3];
    locus->GetPoint(i, p);
    csv.Add(static_cast<long long>(direction->GetTuple1(i))).Add(p[0]).Add(p[1]).Add(p[2]);
    csv.Add(arcLength->GetTuple1(i))
      .Add(static_cast<long long>(multiplicity->GetTuple1(i)))
      .Add(static_cast<long long>(index->GetTuple1(i)))
      .Add(static_cast<long long>(sheet->GetTuple1(i)));
    csv.EndRow();
  }
  return csv.Finish();
}

/// The caustic's figures for the summary, summed over ranks: triangles,
/// those crossed by a cusp edge, those where two sheets meet, then the
/// triangles of each sheet (the first `sheets` of them).
std::vector<long long> CountSheets(vtkPolyData* surface, long long sheets)
{
  std::vector<long long> counts(3 + static_cast<size_t>(sheets), 0);
  vtkDataArray* sheet = surface->GetCellData()->GetArray("Sheet");
  vtkDataArray* singularity = surface->GetCellData()->GetArray("Singularity");
  for (vtkIdType t = 0; sheet && singularity && t < surface->GetNumberOfPolys(); ++t)
  {
    counts[0]++;
    counts[1] += singularity->GetTuple1(t) == 1 ? 1 : 0;
    counts[2] += singularity->GetTuple1(t) == 2 ? 1 : 0;
    const long long index = static_cast<long long>(sheet->GetTuple1(t));
    if (index >= 0 && index < sheets)
    {
      counts[3 + static_cast<size_t>(index)]++;
    }
  }
  return SumOverRanks(counts);
}

/// "N sheet(s), T triangles (C crossed by a cusp edge, M where sheets meet)".
std::string DescribeSheets(const std::vector<long long>& counts)
{
  const auto sheets =
    std::count_if(counts.begin() + 3, counts.end(), [](long long n) { return n > 0; });
  return std::to_string(sheets) + " sheet(s), " + std::to_string(counts[0]) + " triangles (" +
    std::to_string(counts[1]) + " crossed by a cusp edge, " + std::to_string(counts[2]) +
    " where two sheets meet)";
}

void RunConjugate(const ConjugateArguments& args)
{
  CheckFilePaths({ { "-m", args.Metric } }, { { "-o", args.Output }, { "--surface", args.Surface } });
  const std::string extension = Extension(args.Output);
  if (extension != "vtp" && extension != "csv" && extension != "pvtp")
  {
    throw Failure("-o " + args.Output + ": the output must end in .vtp, .pvtp or .csv", 2);
  }
  const double length = args.Integration->Number("MaximumPropagation");
  const double step = args.Integration->Number("InitialIntegrationStep");
  const double largestStep = args.Integration->Number("MaximumIntegrationStep");
  // Each number was checked while parsing; here, what depends on two of them.
  if (step > length)
  {
    throw Failure("--step " + FormatNumber(step) + ": must be at most --length " +
        FormatNumber(length),
      2);
  }
  if (length / step > 1e8)
  {
    throw Failure("--step: more than 1e8 steps per geodesic (--length / --step)", 2);
  }
  if (!args.Surface.empty() && Extension(args.Surface) != "vtp" &&
    Extension(args.Surface) != "pvtp")
  {
    throw Failure("--surface " + args.Surface + ": the surface must be a .vtp or .pvtp file", 2);
  }
  const OutputLayout pointsLayout = ChooseOutputLayout("-o", args.Output, args.Gather, "pvtp");
  const OutputLayout surfaceLayout = args.Surface.empty()
    ? OutputLayout::SingleFile
    : ChooseOutputLayout("--surface", args.Surface, args.Gather, "pvtp");
  const nlohmann::json settings = args.Settings->Given();
  const long long directions = args.Settings->Value("NumberOfDirections").get<long long>();
  const IntegratorType integrator = ParseIntegratorOption(args.Integration->Text("IntegratorType"));
  if (integrator == IntegratorType::DormandPrince45 && largestStep < step)
  {
    throw Failure("--max-step " + FormatNumber(largestStep) + ": must be at least --step " +
        FormatNumber(step) + " (the initial step of dp45)",
      2);
  }

  vtkSmartPointer<vtkRiemannMetric> metric = LoadMetric(args.Metric);
  vtkNew<vtkRiemannConjugateLocus> locus;
  vtkNew<ErrorCollector> errors;
  errors->Observe(locus);
  locus->SetMetric(metric);
  riemann::settings::ApplySettings(locus, settings);
  ApplyIntegrationOptions(*args.Integration, locus->GetIntegrationSettings());
  vtkNew<ProgressBar> progress;
  progress->Observe(locus, "riemann conjugate", ProgressBar::StderrIsTerminal());
  // This rank's share of the directions (all of them in a single process).
  UpdateThisRanksPiece(locus);
  progress->Finish();
  errors->ThrowIfAny("conjugate point search failed:");
  vtkPolyData* points = locus->GetOutput();
  AgreeToGoOn();

  // The job's figures. Each direction's points are in one piece.
  std::set<long long> withPoints;
  vtkDataArray* direction = points->GetPointData()->GetArray("DirectionId");
  for (vtkIdType i = 0; direction && i < direction->GetNumberOfTuples(); ++i)
  {
    withPoints.insert(static_cast<long long>(direction->GetTuple1(i)));
  }
  const std::vector<long long> found =
    SumOverRanks({ points->GetNumberOfPoints(), static_cast<long long>(withPoints.size()) });
  const std::vector<long long> sheets = CountSheets(locus->GetOutput(1), MaximumCountedSheets);

  WriteOutput(locus, 0, args.Output, pointsLayout, args.Compress, {},
    [&](vtkPolyData* all, const std::string& temporary)
    {
      return extension == "csv" ? WriteCsv(all, temporary)
                                : WritePolyDataFile(all, temporary, args.Compress);
    });
  if (!args.Surface.empty())
  {
    // A sheet triangle belongs to the piece that owns its smallest direction;
    // its other corners are ghost copies, named by these arrays.
    WriteOutput(locus, 1, args.Surface, surfaceLayout, args.Compress, { "Sheet", "DirectionId" });
  }
  if (Rank() != 0)
  {
    return;
  }
  std::cerr << "riemann conjugate: " << directions << " direction(s), " << found[0]
            << " conjugate point(s) found on " << found[1] << " of them up to arc length "
            << length << " -> " << args.Output;
  if (!args.Surface.empty())
  {
    std::cerr << ", caustic " << DescribeSheets(sheets) << " -> " << args.Surface;
  }
  if (IsDistributed())
  {
    std::cerr << " (" << NumberOfRanks() << " ranks)";
  }
  std::cerr << "\n";
}
} // namespace

void RegisterConjugateCommand(CLI::App& app)
{
  auto args = std::make_shared<ConjugateArguments>();
  CLI::App* command = app.add_subcommand(
    "conjugate", "Conjugate points of an observer along geodesics in many directions.");
  command->add_option("--metric,-m", args->Metric, "Metric definition (JSON file)")
    ->required()
    ->check(CLI::ExistingFile);
  args->Settings = std::make_unique<DeclaredOptions>(
    command, riemann::declared::vtkRiemannConjugateLocus::Settings);
  // MaximumError only caps the integration error, which follows --tolerance.
  args->Integration = AddIntegrationOptions(
    command, vtkNew<vtkRiemannConjugateLocus>()->GetIntegrationSettings(), "MaximumError");
  AddCompressOption(command, args->Compress);
  AddGatherOption(command, args->Gather);
  command
    ->add_option(
      "--output,-o", args->Output, std::string("Output file: .vtp, .csv, or .pvtp ") + PiecesHelp)
    ->required();
  command->add_option("--surface", args->Surface,
    "Also write the caustic as sheets over the direction grid (.vtp or .pvtp; cell data Sheet "
    "and Singularity: 1 cusp edge, 2 where two sheets meet)");
  command->callback([args]() { RunConjugate(*args); });
}
} // namespace cli
} // namespace riemann
