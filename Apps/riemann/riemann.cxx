// riemann: the RiemannVTK command-line tool. Design a Riemannian metric on R^3
// (a JSON file) and compute with it: `riemann trace`, `riemann info`, ...
// Errors: see the convention at the top of CliUtilities.h.
//
// Start-up time is the point of this file's shape. `render` needs the
// rendering stack (OpenGL, Embree, and OpenImageIO, which alone loads some
// 260 shared libraries and took 0.4 s of every start); the other subcommands
// need the metric core, the filters and VTK's XML writers (about 38
// libraries). So `riemann` links only the latter, and `riemann render ...`
// replaces itself (execv, same arguments) with `riemann-render`, installed
// next to it, which holds the render subcommand (riemann-render.cxx).
//
// Under an MPI launcher (mpirun, srun) the same holds for MPI, whose library
// and its own start-up `riemann` does without: every other subcommand
// replaces itself by `riemann-mpi` (riemann-mpi.cxx), the same subcommands
// linked with MPI. riemann-render handles the launcher itself.
#include "CliMain.h"
#include "Commands.h"
#include "Distributed.h"

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

/// The tool `name` in the folder of this executable (build/bin or the
/// install's bin).
std::string SiblingToolPath(const std::string& name)
{
  std::string self(4096, '\0');
  const ssize_t length = readlink("/proc/self/exe", &self[0], self.size() - 1);
  if (length <= 0)
  {
    return name;
  }
  self.resize(static_cast<size_t>(length));
  const size_t slash = self.rfind('/');
  return (slash == std::string::npos ? std::string() : self.substr(0, slash + 1)) + name;
}

/// Replace this process by the tool `name` with the same arguments; returns
/// only on failure, with the exit status.
int RunSiblingTool(const std::string& name, const std::string& why, char** argv)
{
  const std::string tool = SiblingToolPath(name);
  execv(tool.c_str(), argv);
  std::cerr << "riemann: error: cannot run " << tool << " (" << std::strerror(errno) << "): " << why
            << "; install it next to riemann\n";
  return 1;
}
}

int main(int argc, char** argv)
{
  if (SubcommandName(argc, argv) == "render")
  {
    return RunSiblingTool("riemann-render", "the render command lives there", argv);
  }
  if (riemann::cli::LaunchedByMpiLauncher())
  {
    return RunSiblingTool("riemann-mpi", "it runs the commands under an MPI launcher", argv);
  }
  return riemann::cli::RunCommandLine(argc, argv, riemann::cli::RegisterComputeCommands);
}
