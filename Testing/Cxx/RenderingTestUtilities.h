// Shared by the rendering tests of this module: Mesa/Xvfb set-up and an
// ErrorEvent collector (ErrorObserver.h).
#ifndef RiemannRenderingTestUtilities_h
#define RiemannRenderingTestUtilities_h

#include "ErrorObserver.h"

#include "vtkFloatArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkRenderPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <gtest/gtest.h>

#include <array>

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

/// (x, y, z, s) of pixel (column, row) of a pass's hit image `width` pixels
/// wide. A failed frame empties the image: that is a test failure and
/// (-2, -2, -2, -2), never a read past the array's end.
inline std::array<double, 4> HitOfPixel(vtkFloatArray* hits, int width, int column, int row)
{
  std::array<double, 4> hit{ -2.0, -2.0, -2.0, -2.0 };
  const vtkIdType pixel = static_cast<vtkIdType>(row) * width + column;
  if (pixel >= hits->GetNumberOfTuples())
  {
    ADD_FAILURE() << "no hit for pixel (" << column << ", " << row << "): the hit image has "
                  << hits->GetNumberOfTuples() << " pixels";
    return hit;
  }
  for (int c = 0; c < 4; ++c)
  {
    hit[c] = hits->GetComponent(pixel, c);
  }
  return hit;
}
} // namespace testing
} // namespace riemann

#endif
