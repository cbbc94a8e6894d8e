// riemann distance: the geodesic distance from one or several seeds on a
// grid (vtkRiemannDistanceField), written as .vti with point data Distance,
// ArrivalDirection and SeedId; with --cut-locus, where the minimal geodesics
// stop being unique (vtkRiemannCutLocus) as .vtp; with --to and --geodesics,
// the minimal geodesic from each of those points back to its seed
// (vtkRiemannMinimalGeodesics), written as trace writes geodesics.
#include "CliUtilities.h"
#include "Commands.h"
#include "CsvColumns.h"
#include "GeodesicCsv.h"
#include "Distributed.h"
#include "DeclaredOptions.h"
#include "GridOptions.h"
#include "vtkRiemannDistanceFieldSettingAccess.h"
#include "ProgressBar.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRiemannCutLocus.h"
#include "vtkRiemannCutLocusSettingAccess.h"
#include "vtkRiemannMinimalGeodesicsSettingAccess.h"
#include "vtkRiemannDistanceField.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannMinimalGeodesics.h"
#include "vtkXMLImageDataWriter.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace riemann
{
namespace cli
{
namespace
{
struct DistanceArguments
{
  std::string Metric;
  std::vector<std::string> Seeds;
  std::string SeedsFile;
  /// The field's grid and seed radius (vtkRiemannDistanceField.settings.json).
  std::unique_ptr<DeclaredOptions> Field;
  std::string CutLocus;
  /// The cut locus's settings (vtkRiemannCutLocus.settings.json).
  std::unique_ptr<DeclaredOptions> Cut;
  std::vector<std::string> Targets;
  std::string Geodesics;
  /// The minimal geodesics' settings (vtkRiemannMinimalGeodesics.settings.json).
  std::unique_ptr<DeclaredOptions> Minimal;
  std::string Compress = "lz4";
  std::string Output;
};

/// The most seeds a run takes (each is a point of the grid's box).
constexpr long long MaximumSeeds = 1000000;

/// --seed points, then the --seeds file's, as one list of x,y,z.
std::vector<double> ReadSeedPoints(const DistanceArguments& args)
{
  std::vector<double> seeds;
  for (const std::string& text : args.Seeds)
  {
    double p[3];
    ParseVector3(text, "--seed", p);
    seeds.insert(seeds.end(), p, p + 3);
  }
  if (!args.SeedsFile.empty())
  {
    for (const std::vector<double>& row :
      ReadCsvColumns(args.SeedsFile, { "x", "y", "z" }, "seeds", MaximumSeeds))
    {
      seeds.insert(seeds.end(), row.begin(), row.end());
    }
  }
  if (seeds.empty())
  {
    throw Failure("no seed: give --seed X,Y,Z (one or more) or --seeds FILE.csv", 2);
  }
  return seeds;
}

/// Refuses, before any work, a seed outside the grid's box.
void CheckSeedsInBox(const std::vector<double>& seeds, const double box[6])
{
  for (std::size_t s = 0; s + 2 < seeds.size(); s += 3)
  {
    for (int a = 0; a < 3; ++a)
    {
      const double x = seeds[s + static_cast<std::size_t>(a)];
      if (x < box[2 * a] || x > box[2 * a + 1])
      {
        throw Failure("seed " + std::to_string(s / 3) + " (" + FormatNumber(seeds[s]) + "," +
            FormatNumber(seeds[s + 1]) + "," + FormatNumber(seeds[s + 2]) +
            ") is outside --bounds: the distance is computed on the grid, from seeds in it",
          2);
      }
    }
  }
}

/// "from 0 to 3.2 (12 points unreached)".
std::string DescribeRange(vtkImageData* field)
{
  vtkDataArray* distance = field->GetPointData()->GetArray("Distance");
  double lowest = INFINITY, highest = -INFINITY;
  long long unreached = 0;
  for (vtkIdType n = 0; distance && n < distance->GetNumberOfTuples(); ++n)
  {
    const double u = distance->GetTuple1(n);
    if (std::isnan(u))
    {
      ++unreached;
      continue;
    }
    lowest = std::min(lowest, u);
    highest = std::max(highest, u);
  }
  std::string text = "distance from " + FormatNumber(lowest) + " to " + FormatNumber(highest);
  if (unreached > 0)
  {
    text += " (" + std::to_string(unreached) +
      " points unreached: outside the metric's data, or where it fails)";
  }
  return text;
}

/// Refuse missing inputs, outputs of the wrong kind and an MPI launch
/// before any work.
void CheckDistancePaths(const DistanceArguments& args)
{
  CheckFilePaths({ { "-m", args.Metric }, { "--seeds", args.SeedsFile } },
    { { "-o", args.Output }, { "--cut-locus", args.CutLocus }, { "--geodesics", args.Geodesics } });
  if (Extension(args.Output) != "vti")
  {
    throw Failure("-o " + args.Output + ": the output must end in .vti", 2);
  }
  if (!args.CutLocus.empty() && Extension(args.CutLocus) != "vtp")
  {
    throw Failure("--cut-locus " + args.CutLocus + ": the cut locus must be a .vtp file", 2);
  }
  if (args.Targets.empty() != args.Geodesics.empty())
  {
    throw Failure("--to and --geodesics go together: the points whose minimal geodesics are "
                  "wanted, and the file they go to",
      2);
  }
  const std::string geodesicsExtension = Extension(args.Geodesics);
  if (!args.Geodesics.empty() && geodesicsExtension != "vtp" && geodesicsExtension != "csv")
  {
    throw Failure("--geodesics " + args.Geodesics + ": the geodesics go to a .vtp or .csv file", 2);
  }
  if (IsDistributed())
  {
    throw Failure("distance runs in one process (it uses every core): run it without mpirun "
                  "(a point's distance depends on the whole grid between it and its seed, so "
                  "the grid is not split into pieces)",
      2);
  }
}

/// The distance field from `seeds` (x,y,z each), with a progress bar; sets
/// how long it took.
vtkSmartPointer<vtkRiemannDistanceField> ComputeDistanceField(const DistanceArguments& args,
  vtkRiemannMetric* metric, const std::vector<double>& seeds, ErrorCollector* errors,
  double& seconds)
{
  auto field = vtkSmartPointer<vtkRiemannDistanceField>::New();
  errors->Observe(field);
  field->SetMetric(metric);
  riemann::settings::ApplySettings(field, args.Field->Given());
  for (std::size_t s = 0; s + 2 < seeds.size(); s += 3)
  {
    field->AddSeed(seeds.data() + s);
  }
  vtkNew<ProgressBar> progress;
  progress->Observe(field, "riemann distance", ProgressBar::StderrIsTerminal());
  const auto start = std::chrono::steady_clock::now();
  field->Update();
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress->Finish();
  errors->ThrowIfAny("the distance field failed:");
  return field;
}

/// The cut locus of the field `image` (--cut-locus and its settings).
vtkSmartPointer<vtkRiemannCutLocus> ComputeCutLocus(const DistanceArguments& args,
  vtkRiemannMetric* metric, vtkImageData* image, ErrorCollector* errors)
{
  auto cut = vtkSmartPointer<vtkRiemannCutLocus>::New();
  errors->Observe(cut);
  cut->SetMetric(metric);
  riemann::settings::ApplySettings(cut, args.Cut->Given());
  cut->SetInputData(image);
  cut->Update();
  errors->ThrowIfAny("the cut locus failed:");
  return cut;
}

/// The minimal geodesics from the field's seeds to the --to points.
vtkSmartPointer<vtkRiemannMinimalGeodesics> ComputeMinimalGeodesics(const DistanceArguments& args,
  vtkRiemannMetric* metric, vtkImageData* image, ErrorCollector* errors)
{
  auto minimal = vtkSmartPointer<vtkRiemannMinimalGeodesics>::New();
  errors->Observe(minimal);
  minimal->SetMetric(metric);
  riemann::settings::ApplySettings(minimal, args.Minimal->Given());
  minimal->SetInputData(image);
  for (const std::string& text : args.Targets)
  {
    double p[3];
    ParseVector3(text, "--to", p);
    minimal->AddTarget(p);
  }
  minimal->Update();
  errors->ThrowIfAny("the minimal geodesics failed:");
  return minimal;
}

/// The field, then the cut locus and the geodesics where asked, each file
/// written whole or not at all.
void WriteDistanceOutputs(const DistanceArguments& args, vtkImageData* image,
  vtkRiemannCutLocus* cut, vtkRiemannMinimalGeodesics* minimal)
{
  WriteAtomically(args.Output,
    [&](const std::string& temporary)
    {
      vtkNew<vtkXMLImageDataWriter> writer;
      writer->SetInputData(image);
      writer->SetFileName(temporary.c_str());
      SetCompressor(writer, args.Compress);
      return writer->Write() == 1;
    });
  if (cut)
  {
    WritePolyDataAtomically(cut->GetOutput(), args.CutLocus, args.Compress);
  }
  if (minimal)
  {
    vtkPolyData* lines = minimal->GetOutput();
    const bool csv = Extension(args.Geodesics) == "csv";
    WriteAtomically(args.Geodesics,
      [&](const std::string& temporary)
      {
        return csv ? WriteGeodesicCsv(lines, temporary)
                   : WritePolyDataFile(lines, temporary, args.Compress);
      });
  }
}

/// The one-line summary on stderr: the grid, the range, the work, the files.
void PrintDistanceSummary(const DistanceArguments& args, const int dims[3], std::size_t seeds,
  vtkRiemannDistanceField* field, double seconds, vtkRiemannCutLocus* cut,
  vtkRiemannMinimalGeodesics* minimal)
{
  std::cerr << "riemann distance: " << dims[0] << "x" << dims[1] << "x" << dims[2] << " grid, "
            << seeds << " seed(s): " << DescribeRange(vtkImageData::SafeDownCast(field->GetOutput()))
            << "; " << field->GetNumberOfRounds() << " rounds, " << field->GetNumberOfUpdates()
            << " point updates in " << FormatNumber(std::round(seconds * 100) / 100) << " s -> "
            << args.Output;
  if (cut)
  {
    std::cerr << "; cut locus " << cut->GetOutput()->GetNumberOfPolys() << " squares -> "
              << args.CutLocus;
  }
  if (minimal)
  {
    std::cerr << "; " << minimal->GetOutput()->GetNumberOfLines() << " of " << args.Targets.size()
              << " minimal geodesic(s)";
    if (minimal->GetNumberOfUnrefined() > 0)
    {
      std::cerr << " (" << minimal->GetNumberOfUnrefined()
                << " not refined by Newton: the descent path instead)";
    }
    std::cerr << " -> " << args.Geodesics;
  }
  std::cerr << "\n";
}

void RunDistance(const DistanceArguments& args)
{
  CheckDistancePaths(args);
  // Checked while parsing (the declared ranges, at least 2 points per axis, and LimitGridPoints).
  double box[6];
  int dims[3];
  GridOf(*args.Field, box, dims);
  const std::vector<double> seeds = ReadSeedPoints(args);
  CheckSeedsInBox(seeds, box);

  vtkSmartPointer<vtkRiemannMetric> metric = LoadMetric(args.Metric);
  vtkNew<ErrorCollector> errors;
  double seconds = 0.0;
  vtkSmartPointer<vtkRiemannDistanceField> field =
    ComputeDistanceField(args, metric, seeds, errors, seconds);
  vtkImageData* image = vtkImageData::SafeDownCast(field->GetOutput());
  vtkSmartPointer<vtkRiemannCutLocus> cut;
  if (!args.CutLocus.empty())
  {
    cut = ComputeCutLocus(args, metric, image, errors);
  }
  vtkSmartPointer<vtkRiemannMinimalGeodesics> minimal;
  if (!args.Geodesics.empty())
  {
    minimal = ComputeMinimalGeodesics(args, metric, image, errors);
  }
  WriteDistanceOutputs(args, image, cut, minimal);
  PrintDistanceSummary(args, dims, seeds.size() / 3, field, seconds, cut, minimal);
}
} // namespace

void RegisterDistanceCommand(CLI::App& app)
{
  auto args = std::make_shared<DistanceArguments>();
  CLI::App* command = app.add_subcommand("distance",
    "The geodesic distance from seeds on a grid (anisotropic eikonal solver), with arrival "
    "directions, Voronoi regions and the cut locus.");
  command->add_option("--metric,-m", args->Metric, "Metric definition (JSON file)")
    ->required()
    ->check(CLI::ExistingFile);
  command
    ->add_option("--seed", args->Seeds,
      "A seed X,Y,Z the distance is measured from; repeat it for several (SeedId numbers them "
      "in order, then the --seeds file's)")
    ->check(Point3());
  command->add_option("--seeds", args->SeedsFile, "CSV of seeds with a header x,y,z")
    ->check(CLI::ExistingFile);
  args->Field = std::make_unique<DeclaredOptions>(
    command, riemann::declared::vtkRiemannDistanceField::Settings);
  LimitGridPoints(*args->Field, false);
  command->add_option("--cut-locus", args->CutLocus,
    "Also write the cut locus (.vtp squares; cell data Angle, Kind: 1 two minimal geodesics "
    "from one seed meet, 2 the closest seed changes; Distance)");
  args->Cut = std::make_unique<DeclaredOptions>(
    command, riemann::declared::vtkRiemannCutLocus::Settings);
  command
    ->add_option("--to", args->Targets,
      "A point X,Y,Z whose minimal geodesic back to its closest seed is wanted (with "
      "--geodesics); repeat it for several")
    ->check(Point3());
  command->add_option("--geodesics", args->Geodesics,
    "Write the minimal geodesics from the seeds to the --to points (.vtp or .csv as trace writes "
    "them: the descent along the field, refined by Newton with the Jacobi fields)");
  args->Minimal = std::make_unique<DeclaredOptions>(
    command, riemann::declared::vtkRiemannMinimalGeodesics::Settings);
  AddCompressOption(command, args->Compress);
  command
    ->add_option("--output,-o", args->Output,
      "Output file: .vti (point data Distance, ArrivalDirection, SeedId)")
    ->required();
  command->callback([args]() { RunDistance(*args); });
}
} // namespace cli
} // namespace riemann
