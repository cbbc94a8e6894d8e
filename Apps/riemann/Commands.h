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
}
}

#endif
