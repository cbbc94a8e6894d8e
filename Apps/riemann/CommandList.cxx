// The subcommands of `riemann` and `riemann-mpi`, in the order of --help.
#include "Commands.h"

#include <CLI/CLI.hpp>

namespace riemann
{
namespace cli
{
void RegisterComputeCommands(CLI::App& app)
{
  RegisterTraceCommand(app);
  RegisterInfoCommand(app);
  // `render` in `riemann --help`, with its one-line description; it never
  // runs here (riemann's main hands render to riemann-render first).
  app.add_subcommand("render", RenderCommandDescription);
  RegisterFieldsCommand(app);
  RegisterConjugateCommand(app);
  RegisterExpmapCommand(app);
  RegisterConnectCommand(app);
  RegisterDistanceCommand(app);
  RegisterConnectivityCommand(app);
}
} // namespace cli
} // namespace riemann
