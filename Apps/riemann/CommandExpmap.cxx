// riemann expmap: the exponential map at an observer (vtkRiemannExponentialMap):
// the ray bundle over a grid of directions (.vtp polylines with the transverse
// Jacobian) and, with --radii and --wavefronts, the geodesic spheres (.vtp).
#include "CliUtilities.h"
#include "Commands.h"
#include "DeclaredOptions.h"
#include "IntegrationOptions.h"
#include "Distributed.h"
#include "ProgressBar.h"
#include "vtkRiemannExponentialMapSettingAccess.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRiemannExponentialMap.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

namespace riemann
{
namespace cli
{
namespace
{
struct ExpmapArguments
{
  std::string Metric;
  /// The filter's settings (vtkRiemannExponentialMap.settings.json).
  std::unique_ptr<DeclaredOptions> Settings;
  /// The integration options, with the filter's own defaults (a bundle of moderate length).
  std::unique_ptr<DeclaredOptions> Integration;
  std::string Compress = "lz4";
  bool Gather = false;
  std::string Output;
  std::string Wavefronts;
};

void RunExpmap(const ExpmapArguments& args)
{
  CheckFilePaths(
    { { "-m", args.Metric } }, { { "-o", args.Output }, { "--wavefronts", args.Wavefronts } });
  if (Extension(args.Output) != "vtp" && Extension(args.Output) != "pvtp")
  {
    throw Failure("-o " + args.Output + ": the ray bundle must be a .vtp or .pvtp file", 2);
  }
  if (!args.Wavefronts.empty() && Extension(args.Wavefronts) != "vtp" &&
    Extension(args.Wavefronts) != "pvtp")
  {
    throw Failure(
      "--wavefronts " + args.Wavefronts + ": the wavefronts must be a .vtp or .pvtp file", 2);
  }
  const OutputLayout raysLayout = ChooseOutputLayout("-o", args.Output, args.Gather, "pvtp");
  const OutputLayout wavefrontsLayout = args.Wavefronts.empty()
    ? OutputLayout::SingleFile
    : ChooseOutputLayout("--wavefronts", args.Wavefronts, args.Gather, "pvtp");
  const nlohmann::json settings = args.Settings->Given();
  const double length = args.Integration->Number("MaximumPropagation");
  const double step = args.Integration->Number("InitialIntegrationStep");
  const std::vector<double> radii = args.Settings->Value("Radii").get<std::vector<double>>();
  const long long directions = args.Settings->Value("NumberOfDirections").get<long long>();
  if (!args.Wavefronts.empty() && radii.empty())
  {
    throw Failure("--wavefronts needs --radii R1,R2,...", 2);
  }
  // Each setting was checked while parsing; here, what depends on two of them.
  if (step > length)
  {
    throw Failure("--step " + FormatNumber(step) + ": must be at most --length " +
        FormatNumber(length),
      2);
  }
  if (length / step * static_cast<double>(directions) >
    vtkRiemannExponentialMap::MaximumNumberOfSamples)
  {
    std::ostringstream message;
    message << "--directions x --length / --step = "
            << length / step * static_cast<double>(directions)
            << " samples, more than " << vtkRiemannExponentialMap::MaximumNumberOfSamples
            << " (about 8 GiB of memory): use fewer directions or a longer step";
    throw Failure(message.str(), 2);
  }
  for (double r : radii)
  {
    if (r > length)
    {
      std::ostringstream message;
      message << "--radii: " << r << " is beyond --length " << length;
      throw Failure(message.str(), 2);
    }
  }

  vtkSmartPointer<vtkRiemannMetric> metric = LoadMetric(args.Metric);
  vtkNew<vtkRiemannExponentialMap> expmap;
  vtkNew<ErrorCollector> errors;
  errors->Observe(expmap);
  expmap->SetMetric(metric);
  riemann::settings::ApplySettings(expmap, settings);
  ApplyIntegrationOptions(*args.Integration, expmap->GetIntegrationSettings());
  vtkNew<ProgressBar> progress;
  progress->Observe(expmap, "riemann expmap", ProgressBar::StderrIsTerminal());
  // This rank's share of the directions (all of them in a single process).
  UpdateThisRanksPiece(expmap);
  progress->Finish();
  errors->ThrowIfAny("exponential map failed:");
  AgreeToGoOn();

  const std::vector<long long> counts = SumOverRanks(
    { expmap->GetOutput(0)->GetNumberOfLines(), expmap->GetOutput(1)->GetNumberOfPolys() });
  WriteOutput(expmap, 0, args.Output, raysLayout, args.Compress);
  if (!args.Wavefronts.empty())
  {
    // A wavefront triangle belongs to the piece that owns its smallest
    // direction; its other corners are ghost copies, named by these arrays.
    WriteOutput(
      expmap, 1, args.Wavefronts, wavefrontsLayout, args.Compress, { "DirectionId", "Radius" });
  }
  if (Rank() != 0)
  {
    return;
  }
  std::cerr << "riemann expmap: " << counts[0] << " geodesic(s) up to arc length " << length
            << " -> " << args.Output;
  if (!args.Wavefronts.empty())
  {
    std::cerr << ", " << radii.size() << " wavefront(s) (" << counts[1] << " triangles) -> "
              << args.Wavefronts;
  }
  if (IsDistributed())
  {
    std::cerr << " (" << NumberOfRanks() << " ranks)";
  }
  std::cerr << "\n";
}
} // namespace

void RegisterExpmapCommand(CLI::App& app)
{
  auto args = std::make_shared<ExpmapArguments>();
  CLI::App* command = app.add_subcommand("expmap",
    "The exponential map at an observer: geodesics over a grid of directions with the "
    "transverse Jacobian, and geodesic spheres (wavefronts).");
  command->add_option("--metric,-m", args->Metric, "Metric definition (JSON file)")
    ->required()
    ->check(CLI::ExistingFile);
  args->Settings = std::make_unique<DeclaredOptions>(
    command, riemann::declared::vtkRiemannExponentialMap::Settings);
  args->Integration =
    AddIntegrationOptions(command, vtkNew<vtkRiemannExponentialMap>()->GetIntegrationSettings());
  AddCompressOption(command, args->Compress);
  AddGatherOption(command, args->Gather);
  command
    ->add_option(
      "--output,-o", args->Output, std::string("Ray bundle: .vtp, or .pvtp ") + PiecesHelp)
    ->required();
  command->add_option(
    "--wavefronts", args->Wavefronts, "Geodesic spheres at --radii (triangles): .vtp or .pvtp");
  command->callback([args]() { RunExpmap(*args); });
}
} // namespace cli
} // namespace riemann
