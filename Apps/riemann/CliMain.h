// The shared main of `riemann` and `riemann-render` (CliMain.cxx).
#ifndef RiemannCliMain_h
#define RiemannCliMain_h

#include <functional>

namespace CLI
{
class App;
}

namespace riemann
{
namespace cli
{
/**
 * Parse argv with the subcommands that `registerCommands` adds and run the
 * one chosen: VTK's messages routed to the CLI's output window, usage errors
 * exit 2, failures print "riemann: error: ..." and exit with their status.
 * Returns the process's exit status.
 */
int RunCommandLine(int argc, char** argv, const std::function<void(CLI::App&)>& registerCommands);
}
}

#endif
