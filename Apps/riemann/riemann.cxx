// riemann: the RiemannVTK command-line tool. Design a Riemannian metric on R^3
// (a JSON file) and compute with it: `riemann trace`, `riemann info`, ...
#include "CliUtilities.h"
#include "Commands.h"

#include "vtkObject.h"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv)
{
  CLI::App app{ "riemann: design Riemannian metrics on R^3 and compute with them.\n"
                "Metrics are JSON files (see Data/metrics/, README.md and Common/Metric/MetricDefinition.h)." };
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("riemann 0.1.0"));
  riemann::cli::RegisterTraceCommand(app);
  riemann::cli::RegisterInfoCommand(app);
  riemann::cli::RegisterRenderCommand(app);
  riemann::cli::RegisterFieldsCommand(app);
  riemann::cli::RegisterConjugateCommand(app);
  riemann::cli::RegisterExpmapCommand(app);
  // Warnings and errors of VTK objects without an explicit observer still reach
  // stderr through VTK's output window; no global switch is changed here.
  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& e)
  {
    // --help and --version exit 0; every usage error exits 2, as in the
    // subcommands (CLI11's own codes, 100 and up, mean nothing to a shell user).
    return app.exit(e) == 0 ? 0 : 2;
  }
  catch (const riemann::cli::Failure& e)
  {
    std::cerr << "riemann: error: " << e.what() << "\n";
    return e.Status;
  }
  catch (const std::exception& e)
  {
    std::cerr << "riemann: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
