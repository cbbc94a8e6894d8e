// riemann-render: the `render` subcommand of `riemann`, in an executable of
// its own so that the other subcommands start without loading the rendering
// stack (see riemann.cxx). `riemann render ARGS` runs it with the same
// argument vector, so it parses `render ARGS` exactly as `riemann` would and
// prints the same usage and messages. Under an MPI launcher it runs with
// MPI: each rank traces its piece of the picture (--backend cpu) and rank 0
// gathers and writes it.
#include "CliMain.h"
#include "CliMpi.h"
#include "Commands.h"
#include "Distributed.h"

int main(int argc, char** argv)
{
  if (riemann::cli::LaunchedByMpiLauncher())
  {
    return riemann::cli::RunCommandLineUnderMpi(argc, argv, riemann::cli::RegisterRenderCommand);
  }
  return riemann::cli::RunCommandLine(argc, argv, riemann::cli::RegisterRenderCommand);
}
