// The main of the tools under an MPI launcher (CliMpi.cxx): riemann-mpi, which
// `riemann` hands its work to under mpirun/srun, and riemann-render.
#ifndef RiemannCliMpi_h
#define RiemannCliMpi_h

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
 * RunCommandLine with VTK's vtkMPIController as the global controller: MPI
 * initialised before the command line is read and finalised after the
 * command, whatever its outcome (Distributed.h says how a failing rank stops
 * the others). Returns the process's exit status.
 */
int RunCommandLineUnderMpi(
  int argc, char** argv, const std::function<void(CLI::App&)>& registerCommands);
}
}

#endif
