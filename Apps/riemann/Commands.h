// The `riemann` subcommands. Each Register* adds one subcommand to the app,
// with its options and a callback that does the work and throws
// riemann::cli::Failure on error.
#ifndef RiemannCommands_h
#define RiemannCommands_h

namespace CLI
{
class App;
}

namespace riemann
{
namespace cli
{
void RegisterTraceCommand(CLI::App& app);
void RegisterInfoCommand(CLI::App& app);
void RegisterRenderCommand(CLI::App& app);
void RegisterFieldsCommand(CLI::App& app);
void RegisterConjugateCommand(CLI::App& app);
void RegisterExpmapCommand(CLI::App& app);
void RegisterConnectCommand(CLI::App& app);
void RegisterDistanceCommand(CLI::App& app);
void RegisterConnectivityCommand(CLI::App& app);

/**
 * Every subcommand of `riemann` and `riemann-mpi` (CommandList.cxx): all but
 * render, which is only listed (with RenderCommandDescription) for --help:
 * riemann.cxx hands it to riemann-render before the command line is read.
 */
void RegisterComputeCommands(CLI::App& app);

/// The render subcommand's description, shared by riemann-render and the
/// listing of render in `riemann --help`.
constexpr const char* RenderCommandDescription =
  "Render the inside view of R^3 with a metric by Riemannian ray tracing (GPU, or CPU with\n"
  "--backend cpu: anti-aliasing, EXR channels of the rays' hits).\n"
  "Without --metric and --scene: the paper's grid with one Gaussian bump.";
}
}

#endif
