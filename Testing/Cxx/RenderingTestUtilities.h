// Shared by the rendering tests of this module: Mesa/Xvfb set-up and an
// ErrorEvent collector.
#ifndef RiemannRenderingTestUtilities_h
#define RiemannRenderingTestUtilities_h

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkRenderWindow.h"

#include <string>
#include <vector>

namespace riemann
{
namespace testing
{
// Mesa's llvmpipe may raise floating-point exceptions in the driver; VTK's
// own test drivers disable them too.
inline const bool FloatingPointExceptionsDisabled = []()
{
  vtkFloatingPointExceptions::Disable();
  return true;
}();

// Xvfb resets itself whenever its last client disconnects, and refuses
// connections meanwhile: a test that closes one window and opens the next
// could find no X server ("bad X server connection"). One window, opened by
// the first rendering test (not at start-up: listing the tests needs no
// display) and never closed, keeps a connection for the process.
inline void KeepXServerConnection()
{
  // Deliberately never deleted, and held by a static pointer: still
  // reachable at exit, so LeakSanitizer does not report it as a leak.
  static vtkRenderWindow* const kept = []()
  {
    vtkRenderWindow* window = vtkRenderWindow::New();
    window->SetOffScreenRendering(1);
    window->SetSize(1, 1);
    window->Render(); // opens the display
    return window;
  }();
  (void)kept;
}

/// Collects the ErrorEvents of an object.
struct ErrorObserver
{
  vtkNew<vtkCallbackCommand> Command;
  std::vector<std::string> Messages;

  explicit ErrorObserver(vtkObject* object)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback(
      [](vtkObject*, unsigned long, void* clientData, void* callData)
      {
        auto* self = static_cast<ErrorObserver*>(clientData);
        self->Messages.emplace_back(callData ? static_cast<const char*>(callData) : "");
      });
    object->AddObserver(vtkCommand::ErrorEvent, this->Command);
  }
  std::string All() const
  {
    std::string all;
    for (const std::string& m : this->Messages)
    {
      all += m + "\n";
    }
    return all;
  }
};
} // namespace testing
} // namespace riemann

#endif
