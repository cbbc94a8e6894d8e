// Shared by the rendering tests of this module: Mesa/Xvfb set-up and an
// ErrorEvent collector (ErrorObserver.h).
#ifndef RiemannRenderingTestUtilities_h
#define RiemannRenderingTestUtilities_h

#include "ErrorObserver.h"

#include "vtkFloatingPointExceptions.h"
#include "vtkRenderPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

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
/// Ready `window` as the tests draw: offscreen, width x height, no
/// multisampling (pixels compare exactly), `renderer` drawing with `pass`.
inline void SetUpOffscreenView(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkRenderPass* pass, int width, int height)
{
  KeepXServerConnection();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  renderer->SetPass(pass);
}
} // namespace testing
} // namespace riemann

#endif
