// riemann connect: every geodesic from one point to another up to an arc
// length (vtkRiemannGeodesicConnector), written as trace writes geodesics
// (.vtp polylines with their arrays, or .csv seed_id,step,t,x,y,z,vx,vy,vz
// with one seed_id per geodesic); one line per geodesic on stdout (length,
// Morse index, whether q is conjugate, whether it is the shortest).
#include "CliUtilities.h"
#include "IntegrationOptions.h"
#include "Commands.h"
#include "CsvWriter.h"
#include "Distributed.h"
#include "GeodesicCsv.h"
#include "GeodesicTrace.h" // For the integration defaults
#include "ProgressBar.h"

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
  std::string From;
  std::string To;
  long long Directions = 2000;
  /// The integration options but MaximumError, with the connector's defaults
  /// (Newton needs dp45's error control). --tolerance is the connector's:
  /// what |end - q| must reach (dp45 then integrates to tolerance / 1000),
  /// as conjugate's is the accuracy of its answer.
  std::unique_ptr<DeclaredOptions> Integration;
  double Tolerance = 1e-9; // vtkRiemannGeodesicConnector's default
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
  // --tolerance is the connector's (what |end - q| reaches), not dp45's.
  if (!(args.Tolerance >= vtkRiemannGeodesicConnector::MinimumTolerance &&
        args.Tolerance <= vtkRiemannGeodesicConnector::MaximumTolerance))
  {
    throw Failure("--tolerance " + FormatNumber(args.Tolerance) + ": expected a number from " +
        FormatNumber(vtkRiemannGeodesicConnector::MinimumTolerance) + " to " +
        FormatNumber(vtkRiemannGeodesicConnector::MaximumTolerance) + " (what |end - q| reaches)",
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
  double from[3], to[3];
  ParseVector3(args.From, "--from", from);
  ParseVector3(args.To, "--to", to);
  if (from[0] == to[0] && from[1] == to[1] && from[2] == to[2])
  {
    throw Failure("--from and --to are the same point: give two points to join", 2);
  }

  vtkSmartPointer<vtkRiemannMetric> metric = LoadMetric(args.Metric);
  vtkNew<vtkRiemannGeodesicConnector> connector;
  vtkNew<ErrorCollector> errors;
  errors->Observe(connector);
  connector->SetMetric(metric);
  connector->SetStartPosition(from);
  connector->SetEndPosition(to);
  connector->SetTolerance(args.Tolerance);
  connector->SetNumberOfDirections(static_cast<int>(args.Directions));
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
            << args.From << " to " << args.To << " up to arc length " << FormatNumber(length)
            << " (" << args.Directions << " shooting directions) -> " << args.Output << "\n";
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
  command->add_option("--from", args->From, "The point p X,Y,Z the geodesics leave")
    ->required()
    ->check(Point3());
  command->add_option("--to", args->To, "The point q X,Y,Z they reach")->required()->check(Point3());
  command
    ->add_option("--directions,-n", args->Directions,
      "Directions of the shooting grid (a Fibonacci lattice, g-uniform at p; default 2000)")
    ->check(WholeNumber(1, 1000000));
  args->Integration = AddIntegrationOptions(
    command, vtkNew<vtkRiemannGeodesicConnector>()->GetIntegrationSettings(), "MaximumError");
  command->add_option("--tolerance", args->Tolerance,
    "What |end - q| each geodesic reaches (coordinate distance, from 1e-13 to 0.01); dp45 "
    "integrates to tolerance / 1000 (default 1e-09)");
  AddCompressOption(command, args->Compress);
  command->add_option("--output,-o", args->Output, "Output file: .vtp or .csv")->required();
  command->callback([args]() { RunConnect(*args); });
}
} // namespace cli
} // namespace riemann
