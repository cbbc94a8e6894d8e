// riemann-render: the `render` subcommand of `riemann`, in an executable of
// its own so that the other subcommands start without loading the rendering
// stack (see riemann.cxx). `riemann render ARGS` runs it with the same
// argument vector, so it parses `render ARGS` exactly as `riemann` would and
// prints the same usage and messages.
#include "CliMain.h"
#include "Commands.h"

int main(int argc, char** argv)
{
  return riemann::cli::RunCommandLine(argc, argv, riemann::cli::RegisterRenderCommand);
}
