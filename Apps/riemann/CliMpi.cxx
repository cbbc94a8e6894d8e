#include "CliMpi.h"

#include "CliMain.h"
#include "Interrupts.h"

#include "vtkMPIController.h"
#include "vtkNew.h"

namespace riemann
{
namespace cli
{
int RunCommandLineUnderMpi(
  int argc, char** argv, const std::function<void(CLI::App&)>& registerCommands)
{
  // Before MPI starts its threads: they inherit the blocked signals.
  InterruptHandling interrupts;
  vtkNew<vtkMPIController> controller;
  // MPI_Init may consume launcher arguments; the command line is read after.
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  const int status = RunCommandLine(argc, argv, registerCommands);
  controller->Finalize();
  vtkMultiProcessController::SetGlobalController(nullptr);
  return status;
}
} // namespace cli
} // namespace riemann
