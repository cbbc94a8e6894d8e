// Time from a parameter slider move to the updated inside view, in the real
// window (not a test: timings are reported, never asserted).
//
//   xvfb-run -a -s "-screen 0 1920x1080x24" build/bin/BenchStudio [WIDTHxHEIGHT] [moves]
//
// The inside view is given exactly WIDTHxHEIGHT pixels (default 640x480).
// Each move sets the slider of parameter a of the default metric (the
// paper's Gaussian bump): vtkRiemannMetric::SetDefinition with the new value,
// then the view drawn by vtkRiemannRayTracePass, finished on the GPU
// (glFinish) before the clock stops. Reports the median and range, the
// first frame (with the shader compilation), and that no move compiled a
// shader; then the same moves with the slider held (InsideView::SetMoving:
// the pass traces fewer rays to keep up with 15 frames/s).
#include "InsideView.h"
#include "ParameterPanel.h"
#include "StudioDocument.h"
#include "StudioMainWindow.h"

#include "vtkRiemannRayTracePass.h"

#include "QVTKOpenGLNativeWidget.h"
#include "vtkRenderWindow.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QSlider>
#include <QtTest/QtTest>

#include <algorithm>
#include <cstdio>
#include <vector>

using namespace riemann::studio;

int main(int argc, char* argv[])
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  int width = 640, height = 480, moves = 20;
  if (argc > 1 && std::sscanf(argv[1], "%dx%d", &width, &height) != 2)
  {
    std::fprintf(stderr, "usage: BenchStudio [WIDTHxHEIGHT] [moves]\n");
    return 2;
  }
  if (argc > 2)
  {
    moves = std::max(1, std::atoi(argv[2]));
  }
  StudioMainWindow window;
  window.SetViewLayout(StudioMainWindow::InsideOnly);
  window.Inside()->setFixedSize(width, height);
  window.show();
  if (!QTest::qWaitForWindowExposed(&window))
  {
    std::fprintf(stderr, "BenchStudio: the window was not shown (no display?)\n");
    return 1;
  }
  QElapsedTimer clock;
  clock.start();
  window.Settle();
  window.Inside()->RenderNow();
  const double first = clock.nsecsElapsed() * 1e-6;
  int pixelsWide, pixelsHigh;
  window.Inside()->PixelSize(pixelsWide, pixelsHigh);

  QSlider* slider = window.Parameters()->Slider("/parameters/a");
  const int compilations = window.Inside()->Pass()->GetNumberOfShaderCompilations();
  // Each move: the slider's new value to the view drawn and finished.
  const auto timeMoves = [&]()
  {
    std::vector<double> times;
    for (int k = 0; k < moves; ++k)
    {
      const int position = (k % 2 == 0) ? 400 + k : 600 - k;
      bool drawn = false;
      const QMetaObject::Connection watch = QObject::connect(
        window.Inside(), &InsideView::FrameRendered, [&drawn](double) { drawn = true; });
      clock.restart();
      slider->setValue(position); // parse and check the metric; the frame is scheduled
      while (!drawn)
      {
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents); // the frame, then glFinish
      }
      times.push_back(clock.nsecsElapsed() * 1e-6);
      QObject::disconnect(watch);
    }
    std::sort(times.begin(), times.end());
    return times;
  };
  const std::vector<double> times = timeMoves();
  // The same moves with the slider held: the interactor's 15 frames/s asked,
  // the pass tracing fewer rays (AutoAdjustSampleDistances).
  Q_EMIT slider->sliderPressed();
  const std::vector<double> held = timeMoves();
  const double heldDistance = window.Inside()->Pass()->GetLastImageSampleDistance();
  Q_EMIT slider->sliderReleased();
  std::printf("inside view %dx%d\n", pixelsWide, pixelsHigh);
  std::printf("first frame (shader compilation included): %.1f ms\n", first);
  std::printf("slider move -> updated inside view: median %.1f ms, min %.1f ms, max %.1f ms (%d moves)\n",
    times[times.size() / 2], times.front(), times.back(), moves);
  std::printf("the same moves with the slider held: median %.1f ms, min %.1f ms, max %.1f ms, "
              "last frame at 1 ray per %.2f x %.2f pixels\n",
    held[held.size() / 2], held.front(), held.back(), heldDistance, heldDistance);
  std::printf("shader compilations during the moves: %d\n",
    window.Inside()->Pass()->GetNumberOfShaderCompilations() - compilations);
  const char* capabilities = window.Inside()->renderWindow()->ReportCapabilities();
  std::printf("%.300s\n", capabilities ? capabilities : "");
  return 0;
}
