/**
 * @file IntegrationOptions.h
 * @brief The integration options of every command that integrates (trace,
 * expmap, conjugate, connect, connectivity, render): one option per
 * declared setting of vtkRiemannIntegrationSettings
 * (Common/Core/vtkRiemannIntegrationSettings.settings.json), named after
 * the property with the old spellings (--step, --length/-l, --tolerance,
 * --max-steps, --integrator, ...), checked against the declared range.
 * Only the defaults are the command's: those of the filter it runs.
 */
#ifndef RiemannCliIntegrationOptions_h
#define RiemannCliIntegrationOptions_h

#include "DeclaredOptions.h"

#include <memory>
#include <string>

class vtkRiemannIntegrationSettings;

namespace riemann
{
namespace cli
{
/**
 * Add the integration options to `command`, but those named in `leftOut`
 * (comma-separated properties the command sets otherwise). Their defaults
 * are `defaults`' values (the integration settings of a new filter of the
 * command); with `defaultWords`, the help says that instead ("the scene's").
 */
std::unique_ptr<DeclaredOptions> AddIntegrationOptions(CLI::App* command,
  vtkRiemannIntegrationSettings* defaults, const std::string& leftOut = "",
  const std::string& defaultWords = "");

/// Set on `settings` the integration options the command line gave.
void ApplyIntegrationOptions(const DeclaredOptions& options, vtkRiemannIntegrationSettings* settings);
} // namespace cli
} // namespace riemann

#endif
