// riemann expmap: the exponential map at an observer (vtkRiemannExponentialMap):
// the ray bundle over a grid of directions (.vtp polylines with the transverse
// Jacobian) and, with --radii and --wavefronts, the geodesic spheres (.vtp).
#include "CliUtilities.h"
#include "Commands.h"
#include "Distributed.h"
#include "GeodesicTrace.h" // For the integration defaults
#include "ProgressBar.h"

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
  std::string Seed = "0,0,0";
  long long Directions = 400;
  std::string ConeAxis = "0,0,1";
  double ConeAngle = 180.0;
  // The integration defaults are the schema's for curves (IntegrationSchema.h).
  double Length = riemann::CurveDefault(riemann::IntegrationSettingId::Length);
  std::string Radii;
  std::string Integrator = riemann::IntegratorName(riemann::GeodesicOptions().Integrator);
  double Step = riemann::CurveDefault(riemann::IntegrationSettingId::Step);
  double Tolerance = riemann::CurveDefault(riemann::IntegrationSettingId::Tolerance);
  long long MaximumSteps = riemann::GeodesicOptions().MaximumSteps;
  std::string Compress = "lz4";
  bool Gather = false;
  std::string Output;
  std::string Wavefronts;
};

constexpr long long MaximumDirections = 1000000;

/// What is wrong with "1,2.5,3" as positive finite numbers, or "" (then `radii` holds them).
std::string CheckRadii(const std::string& text, std::vector<double>& radii)
{
  radii.clear();
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    std::size_t used = 0;
    double value = 0.0;
    try
    {
      value = std::stod(item, &used);
    }
    catch (const std::exception&)
    {
      used = 0;
    }
    if (used == 0 || used != item.size() || !std::isfinite(value) || value <= 0.0)
    {
      return "\"" + item + "\" is not a positive number (write R1,R2,...)";
    }
    radii.push_back(value);
  }
  if (radii.empty() || text.back() == ',')
  {
    return "expected R1,R2,... (finite positive arc lengths), got \"" + text + "\"";
  }
  return {};
}

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
  if (!args.Wavefronts.empty() && args.Radii.empty())
  {
    throw Failure("--wavefronts needs --radii R1,R2,...", 2);
  }
  // Each number was checked while parsing; here, what depends on two of them.
  if (args.Step > args.Length)
  {
    throw Failure("--step " + FormatNumber(args.Step) + ": must be at most --length " +
        FormatNumber(args.Length),
      2);
  }
  if (args.Length / args.Step * static_cast<double>(args.Directions) >
    vtkRiemannExponentialMap::MaximumNumberOfSamples)
  {
    std::ostringstream message;
    message << "--directions x --length / --step = "
            << args.Length / args.Step * static_cast<double>(args.Directions)
            << " samples, more than " << vtkRiemannExponentialMap::MaximumNumberOfSamples
            << " (about 8 GiB of memory): use fewer directions or a longer step";
    throw Failure(message.str(), 2);
  }
  double seed[3], axis[3];
  ParseVector3(args.Seed, "--seed", seed);
  ParseVector3(args.ConeAxis, "--cone-axis", axis);
  const IntegratorType integrator = ParseIntegratorOption(args.Integrator);
  std::vector<double> radii; // checked while parsing; parsed here
  const std::string badRadii = args.Radii.empty() ? std::string() : CheckRadii(args.Radii, radii);
  if (!badRadii.empty())
  {
    throw Failure("--radii: " + badRadii, 2);
  }
  for (double r : radii)
  {
    if (r > args.Length)
    {
      std::ostringstream message;
      message << "--radii: " << r << " is beyond --length " << args.Length;
      throw Failure(message.str(), 2);
    }
  }

  vtkSmartPointer<vtkRiemannMetric> metric = LoadMetric(args.Metric);
  vtkNew<vtkRiemannExponentialMap> expmap;
  vtkNew<ErrorCollector> errors;
  errors->Observe(expmap);
  expmap->SetMetric(metric);
  expmap->SetObserver(seed);
  expmap->SetNumberOfDirections(static_cast<int>(args.Directions));
  expmap->SetConeAxis(axis);
  expmap->SetConeAngle(args.ConeAngle);
  expmap->GetIntegrationSettings()->SetMaximumPropagation(args.Length);
  expmap->GetIntegrationSettings()->SetIntegratorType(static_cast<int>(integrator));
  expmap->GetIntegrationSettings()->SetInitialIntegrationStep(args.Step);
  expmap->GetIntegrationSettings()->SetMaximumError(args.Tolerance);
  expmap->GetIntegrationSettings()->SetMaximumNumberOfSteps(args.MaximumSteps);
  for (double r : radii)
  {
    expmap->AddRadius(r);
  }
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
  std::cerr << "riemann expmap: " << counts[0] << " geodesic(s) up to arc length " << args.Length
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
  command->add_option("--seed", args->Seed, "Observer X,Y,Z (default 0,0,0)")->check(Point3());
  command
    ->add_option("--directions,-n", args->Directions,
      "Number of directions, a Fibonacci lattice on the sphere or cone (default 400)")
    ->check(WholeNumber(1, MaximumDirections));
  command->add_option("--cone-axis", args->ConeAxis, "Axis X,Y,Z of the cone (default 0,0,1)")
    ->check(Direction3());
  command
    ->add_option("--cone-angle", args->ConeAngle,
      "Half-angle of the cone of directions in degrees (default 180: every direction)")
    ->check(FiniteNumber(0.0, 180.0));
  command->add_option("--radii", args->Radii, "Radii R1,R2,... of the wavefronts")
    ->check(Checked(
      [](const std::string& text)
      {
        std::vector<double> radii;
        return CheckRadii(text, radii);
      },
      "R1,R2,..."));
  AddIntegrationOptions(command,
    { &args->Integrator, &args->Step, &args->Length, &args->Tolerance, &args->MaximumSteps });
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
