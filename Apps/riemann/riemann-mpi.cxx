// riemann-mpi: `riemann` under an MPI launcher. `mpirun -np 4 riemann fields
// ...` starts four `riemann` processes; each sees the launcher's environment
// and replaces itself (execv, same arguments) by this tool, which holds the
// same subcommands linked with MPI (riemann.cxx says why `riemann` itself is
// not: its start-up time). Each rank computes its piece (Distributed.h).
#include "CliMpi.h"
#include "Commands.h"

int main(int argc, char** argv)
{
  return riemann::cli::RunCommandLineUnderMpi(argc, argv, riemann::cli::RegisterComputeCommands);
}
