// riemann: the RiemannVTK command-line tool. Design a Riemannian metric on R^3
// (a JSON file) and compute with it: `riemann trace`, `riemann info`, ...
// Errors: see the convention at the top of CliUtilities.h.
//
// Start-up time is the point of this file's shape. `render` needs the
// rendering stack (OpenGL, Embree, and OpenImageIO, which alone loads some
// 260 shared libraries and took 0.4 s of every start); the other subcommands
// need the metric core, the filters and VTK's XML writers (about 35
// libraries). So `riemann` links only the latter, and `riemann render ...`
// replaces itself (execv, same arguments) with `riemann-render`, installed
// next to it, which holds the render subcommand (riemann-render.cxx).
#include "CliMain.h"
#include "Commands.h"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <string>

#include <unistd.h>

namespace
{
/// The subcommand named on the command line: the first argument that is
/// not an option of `riemann` itself (--verbose, --help, --version).
std::string SubcommandName(int argc, char** argv)
{
  for (int i = 1; i < argc; ++i)
  {
    if (argv[i][0] != '-')
    {
      return argv[i];
    }
  }
  return std::string();
}

/// `riemann-render` in the folder of this executable (build/bin or the
/// install's bin).
std::string RenderToolPath()
{
  std::string self(4096, '\0');
  const ssize_t length = readlink("/proc/self/exe", &self[0], self.size() - 1);
  if (length <= 0)
  {
    return "riemann-render";
  }
  self.resize(static_cast<size_t>(length));
  const size_t slash = self.rfind('/');
  return (slash == std::string::npos ? std::string() : self.substr(0, slash + 1)) +
    "riemann-render";
}

/// Replace this process by riemann-render with the same arguments; returns
/// only on failure, with the exit status.
int RunRenderTool(char** argv)
{
  const std::string tool = RenderToolPath();
  execv(tool.c_str(), argv);
  std::cerr << "riemann: error: cannot run " << tool << " (" << std::strerror(errno)
            << "): the render command lives there; install it next to riemann\n";
  return 1;
}

/// `render` in `riemann --help`, with its one-line description; it never
/// runs here (main hands render to riemann-render first).
void RegisterRenderListing(CLI::App& app)
{
  app.add_subcommand("render", riemann::cli::RenderCommandDescription);
}
}

int main(int argc, char** argv)
{
  if (SubcommandName(argc, argv) == "render")
  {
    return RunRenderTool(argv);
  }
  return riemann::cli::RunCommandLine(argc, argv,
    [](CLI::App& app)
    {
      riemann::cli::RegisterTraceCommand(app);
      riemann::cli::RegisterInfoCommand(app);
      RegisterRenderListing(app);
      riemann::cli::RegisterFieldsCommand(app);
      riemann::cli::RegisterConjugateCommand(app);
      riemann::cli::RegisterExpmapCommand(app);
    });
}
