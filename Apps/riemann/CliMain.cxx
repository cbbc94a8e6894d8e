// The shared main of the command-line tools: `riemann` (every subcommand but
// render) and `riemann-render` (render), which `riemann render` runs in its
// place (riemann.cxx). Errors: see the convention at the top of CliUtilities.h.
#include "CliMain.h"

#include "CliUtilities.h"
#include "Distributed.h"
#include "Interrupts.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace
{
/// The hint printed under a usage error: the --help of the command at fault.
std::string HelpHint(const CLI::App& app)
{
  const std::vector<CLI::App*> commands = app.get_subcommands();
  return "Run 'riemann" + (commands.empty() ? std::string() : " " + commands.front()->get_name()) +
    " --help' for the options.";
}

/// "riemann: error: ", or in a job where a rank other than 0 reports,
/// "riemann (rank 2 of 4): error: ".
std::string ErrorPrefix(const std::string& kind = "error")
{
  const int rank = riemann::cli::Rank();
  return (rank == 0 ? std::string("riemann")
                    : "riemann (rank " + std::to_string(rank) + " of " +
               std::to_string(riemann::cli::NumberOfRanks()) + ")") +
    ": " + kind + ": ";
}

/// Hands VTK's output window and vtkLogger back before static destruction.
struct VtkMessageRouting
{
  riemann::cli::CliOutputWindow* Window = riemann::cli::CliOutputWindow::Install();
  ~VtkMessageRouting() { riemann::cli::CliOutputWindow::Uninstall(); }
};
}

namespace riemann
{
namespace cli
{
int RunCommandLine(int argc, char** argv, const std::function<void(CLI::App&)>& registerCommands)
{
  // Before any other thread starts (they inherit the blocked signals):
  // SIGINT and SIGTERM stop the command and remove its partial files.
  InterruptHandling interrupts;
  // Before anything else: VTK's messages go to the CLI's output window, which
  // keeps them (and prints them plainly with --verbose), never to the terminal
  // as raw log lines.
  VtkMessageRouting routing;

  CLI::App app{ "riemann: design Riemannian metrics on R^3 and compute with them.\n"
                "Metrics are JSON files (see Data/metrics/ and Documentation/MetricFormat.md)." };
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("riemann 0.1.0"));
  app.add_flag_callback(
    "--verbose", [&routing]() { routing.Window->SetVerbose(true); },
    "Also print VTK's own errors and warnings on stderr, plainly, as they come (by default "
    "they are kept and the tool says what failed in one sentence); may follow the command");
  // --verbose (an option of `riemann` itself) may also be written after the
  // command's name; set before the commands are added, which inherit it.
  app.fallthrough();
  registerCommands(app);
  int status = 0;
  try
  {
    app.parse(argc, argv);
    // The finish line: no rank leaves while another may still tell of a failure.
    AgreeToGoOn();
  }
  catch (const CLI::ParseError& e)
  {
    // --help and --version exit 0 (printed once in a job); every usage error
    // exits 2, as in the commands (CLI11's own codes, 100 and up, mean
    // nothing to a shell user).
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success))
    {
      return Rank() == 0 ? app.exit(e) : 0;
    }
    if (TellOthersOfFailure())
    {
      std::cerr << ErrorPrefix() << e.what() << "\n" << HelpHint(app) << "\n";
    }
    return 2;
  }
  catch (const Interrupted&)
  {
    // Concluded below: SIGINT or SIGTERM stopped the command (Interrupts.h).
  }
  catch (const StoppedByAnotherRank&)
  {
    status = 1; // the rank that failed says why
  }
  catch (const riemann::cli::Failure& e)
  {
    if (TellOthersOfFailure())
    {
      std::cerr << ErrorPrefix() << e.what() << "\n";
      if (e.Status == 2)
      {
        std::cerr << HelpHint(app) << "\n";
      }
    }
    status = e.Status;
  }
  catch (const std::exception& e)
  {
    if (TellOthersOfFailure())
    {
      std::cerr << ErrorPrefix("internal error") << e.what() << "\n";
    }
    status = 1;
  }
  if (InterruptHandling::Interrupted())
  {
    // Whatever the command was doing (a failure may follow from a stopped
    // filter's empty output): the interrupt is the answer.
    return InterruptHandling::Conclude();
  }
  if (Rank() != 0)
  {
    return status; // rank 0 speaks for the job
  }
  // What VTK said and the tool kept: one line that it exists, not VTK's
  // words (they name the filters' settings, not the options). The errors
  // behind a failure are what its sentence tells.
  if (!routing.Window->GetVerbose())
  {
    const int errors = routing.Window->GetNumberOfErrors();
    const int warnings = routing.Window->GetNumberOfWarnings();
    if (status == 0 && errors > 0)
    {
      std::cerr << "riemann: warning: VTK reported " << errors
                << (errors == 1 ? " error that did not stop the command; --verbose prints it\n"
                                : " errors that did not stop the command; --verbose prints them\n");
    }
    if (warnings > 0)
    {
      std::cerr << "riemann: note: VTK also reported " << warnings
                << (warnings == 1 ? " warning; --verbose prints it\n"
                                  : " warnings; --verbose prints them\n");
    }
  }
  return status;
}
} // namespace cli
} // namespace riemann
