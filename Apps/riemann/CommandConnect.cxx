// riemann connect: every geodesic from one point to another up to an arc
// length (vtkRiemannGeodesicConnector), written as trace writes geodesics
// (.vtp polylines with their arrays, or .csv seed_id,step,t,x,y,z,vx,vy,vz
// with one seed_id per geodesic); one line per geodesic on stdout (length,
// Morse index, whether q is conjugate, whether it is the shortest).
#include "CliUtilities.h"
#include "DeclaredOptions.h"
#include "IntegrationOptions.h"
#include "Commands.h"
#include "CsvWriter.h"
#include "Distributed.h"
#include "GeodesicCsv.h"
#include "ProgressBar.h"
#include "vtkRiemannGeodesicConnectorSettingAccess.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRiemannGeodesicConnector.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <string>

namespace riemann
{
namespace cli
{
namespace
{
struct ConnectArguments
{
  std::string Metric;
  /// The connector's settings (vtkRiemannGeodesicConnector.settings.json):
  /// --from and --to are required; --tolerance is what |end - q| must reach
  /// (dp45 then integrates to tolerance / 1000), as conjugate's is the
  /// accuracy of its answer.
  std::unique_ptr<DeclaredOptions> Settings;
  /// The integration options but MaximumError, with the connector's defaults
  /// (Newton needs dp45's error control).
  std::unique_ptr<DeclaredOptions> Integration;
  std::string Compress = "lz4";
  std::string Output;
};

/// One line per geodesic on stdout, a CSV a script can read.
void PrintGeodesics(vtkPolyData* geodesics)
{
  vtkCellData* cd = geodesics->GetCellData();
  vtkDataArray* length = cd->GetArray("Length");
  vtkDataArray* morse = cd->GetArray("MorseIndex");
  vtkDataArray* conjugate = cd->GetArray("ConjugateMultiplicity");
  vtkDataArray* shortest = cd->GetArray("Shortest");
  vtkDataArray* miss = cd->GetArray("Miss");
  vtkDataArray* direction = cd->GetArray("InitialDirection");
  std::cout << "seed_id,length,morse_index,conjugate_multiplicity,shortest,miss,dx,dy,dz\n";
  CsvWriter csv(std::cout);
  for (vtkIdType i = 0; length && i < geodesics->GetNumberOfCells(); ++i)
  {
    const double* d = direction->GetTuple3(i);
    csv.Add(static_cast<long long>(i))
      .Add(length->GetTuple1(i))
      .Add(static_cast<long long>(morse->GetTuple1(i)))
      .Add(static_cast<long long>(conjugate->GetTuple1(i)))
      .Add(static_cast<long long>(shortest->GetTuple1(i)))
      .Add(miss->GetTuple1(i))
      .Add(d[0])
      .Add(d[1])
      .Add(d[2]);
    csv.EndRow();
  }
  csv.Finish();
}

void RunConnect(const ConnectArguments& args)
{
  CheckFilePaths({ { "-m", args.Metric } }, { { "-o", args.Output } });
  const std::string extension = Extension(args.Output);
  if (extension != "vtp" && extension != "csv")
  {
    throw Failure("-o " + args.Output + ": the output must end in .vtp or .csv", 2);
  }
  if (IsDistributed())
  {
    throw Failure("connect runs in one process (it uses every core): run it without mpirun "
                  "(the Newton refinements need the candidates of every direction)",
      2);
  }
  const double length = args.Integration->Number("MaximumPropagation");
  const double step = args.Integration->Number("InitialIntegrationStep");
  if (step > length)
  {
    throw Failure("--step " + FormatNumber(step) + ": must be at most --length " +
        FormatNumber(length),
      2);
  }
  const nlohmann::json settings = args.Settings->Given();
  const nlohmann::json from = settings.at("StartPosition");
  const nlohmann::json to = settings.at("EndPosition");
  if (from == to)
  {
    throw Failure("--from and --to are the same point: give two points to join", 2);
  }

  vtkSmartPointer<vtkRiemannMetric> metric = LoadMetric(args.Metric);
  vtkNew<vtkRiemannGeodesicConnector> connector;
  vtkNew<ErrorCollector> errors;
  errors->Observe(connector);
  connector->SetMetric(metric);
  riemann::settings::ApplySettings(connector, settings);
  ApplyIntegrationOptions(*args.Integration, connector->GetIntegrationSettings());
  vtkNew<ProgressBar> progress;
  progress->Observe(connector, "riemann connect", ProgressBar::StderrIsTerminal());
  connector->Update();
  progress->Finish();
  errors->ThrowIfAny("connecting the points failed:");
  vtkPolyData* geodesics = connector->GetOutput();
  WriteAtomically(args.Output,
    [&](const std::string& temporary)
    {
      return extension == "csv" ? WriteGeodesicCsv(geodesics, temporary)
                                : WritePolyDataFile(geodesics, temporary, args.Compress);
    });
  PrintGeodesics(geodesics);
  std::cerr << "riemann connect: " << connector->GetNumberOfGeodesics() << " geodesic(s) from "
            << connector->GetStartPosition()[0] << "," << connector->GetStartPosition()[1] << ","
            << connector->GetStartPosition()[2] << " to " << connector->GetEndPosition()[0] << ","
            << connector->GetEndPosition()[1] << "," << connector->GetEndPosition()[2]
            << " up to arc length " << FormatNumber(length) << " ("
            << connector->GetNumberOfDirections() << " shooting directions) -> " << args.Output
            << "\n";
}
} // namespace

void RegisterConnectCommand(CLI::App& app)
{
  auto args = std::make_shared<ConnectArguments>();
  CLI::App* command = app.add_subcommand(
    "connect", "Every geodesic from one point to another up to an arc length (shooting, then "
               "Newton on the direction with the Jacobi fields), with Morse indices.");
  command->add_option("--metric,-m", args->Metric, "Metric definition (JSON file)")
    ->required()
    ->check(CLI::ExistingFile);
  args->Settings = std::make_unique<DeclaredOptions>(
    command, riemann::declared::vtkRiemannGeodesicConnector::Settings);
  args->Settings->OptionOf("StartPosition")->required();
  args->Settings->OptionOf("EndPosition")->required();
  args->Integration = AddIntegrationOptions(
    command, vtkNew<vtkRiemannGeodesicConnector>()->GetIntegrationSettings(), "MaximumError");
  AddCompressOption(command, args->Compress);
  command->add_option("--output,-o", args->Output, "Output file: .vtp or .csv")->required();
  command->callback([args]() { RunConnect(*args); });
}
} // namespace cli
} // namespace riemann
