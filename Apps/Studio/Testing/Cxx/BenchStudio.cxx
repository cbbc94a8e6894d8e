// Time from a parameter slider move to the updated inside view, in the real
// window (not a test: timings are reported, never asserted).
//
//   xvfb-run -a -s "-screen 0 1920x1080x24" build/bin/BenchStudio [WIDTHxHEIGHT] [moves]
//
// The inside view is given exactly WIDTHxHEIGHT pixels (default 640x480).
// Each move sets the slider of parameter a of the default metric (the
// paper's Gaussian bump): vtkRiemannMetric::SetDefinition with the new value,
// then the view drawn by vtkRiemannRayTracePass, finished on the GPU
// (glFinish) before the clock stops. Still frames are refined in pieces
// (ProgressiveRefinement): each move reports the time to the first picture
// (the coarse lattice) and to the full picture (every pixel traced), and the
// longest piece (the longest the window waits between input events).
// Reports the medians and ranges, the first frame (with the shader
// compilation), and that no move compiled a shader; then the same moves
// with the slider held (InsideView::SetMoving: the pass traces fewer rays to
// keep up with 15 frames/s). `--whole` turns the refinement off (whole
// frames, as before it existed), for the comparison.
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
#include <string>
#include <vector>

using namespace riemann::studio;

int main(int argc, char* argv[])
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  int width = 640, height = 480, moves = 20;
  bool whole = false;
  std::vector<const char*> positional;
  for (int i = 1; i < argc; ++i)
  {
    if (std::string(argv[i]) == "--whole")
    {
      whole = true;
    }
    else
    {
      positional.push_back(argv[i]);
    }
  }
  if (!positional.empty() && std::sscanf(positional[0], "%dx%d", &width, &height) != 2)
  {
    std::fprintf(stderr, "usage: BenchStudio [WIDTHxHEIGHT] [moves] [--whole]\n");
    return 2;
  }
  if (positional.size() > 1)
  {
    moves = std::max(1, std::atoi(positional[1]));
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
  vtkRiemannRayTracePass* pass = window.Inside()->Pass();
  pass->SetProgressiveRefinement(!whole);
  QElapsedTimer clock;
  clock.start();
  window.Settle();
  window.Inside()->Capture();
  const double first = clock.nsecsElapsed() * 1e-6;
  int pixelsWide, pixelsHigh;
  window.Inside()->PixelSize(pixelsWide, pixelsHigh);

  QSlider* slider = window.Parameters()->Slider("/parameters/a");
  const int compilations = window.Inside()->Pass()->GetNumberOfShaderCompilations();
  // Each move: the slider's new value to the first picture and to the full
  // one, drawn and finished; and the longest piece in between.
  struct Times
  {
    std::vector<double> First, Full, Piece;
  };
  const auto timeMoves = [&]()
  {
    Times times;
    for (int k = 0; k < moves; ++k)
    {
      const int position = (k % 2 == 0) ? 400 + k : 600 - k;
      int frames = 0;
      bool complete = false;
      double longest = 0.0;
      const QMetaObject::Connection watch = QObject::connect(window.Inside(),
        &InsideView::FrameRendered,
        [&](double milliseconds)
        {
          if (++frames == 1)
          {
            times.First.push_back(clock.nsecsElapsed() * 1e-6);
          }
          longest = std::max(longest, milliseconds);
          complete = pass->GetRefinementComplete();
        });
      clock.restart();
      slider->setValue(position); // parse and check the metric; the frame is scheduled
      while (!complete)
      {
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents); // a piece, then glFinish
      }
      times.Full.push_back(clock.nsecsElapsed() * 1e-6);
      times.Piece.push_back(longest);
      QObject::disconnect(watch);
    }
    for (std::vector<double>* list : { &times.First, &times.Full, &times.Piece })
    {
      std::sort(list->begin(), list->end());
    }
    return times;
  };
  const auto summary = [](const std::vector<double>& list)
  {
    char text[96];
    std::snprintf(text, sizeof(text), "median %.1f ms, min %.1f ms, max %.1f ms",
      list[list.size() / 2], list.front(), list.back());
    return std::string(text);
  };
  const Times times = timeMoves();
  // The same moves with the slider held: the interactor's 15 frames/s asked,
  // the pass tracing fewer rays (AutoAdjustSampleDistances).
  Q_EMIT slider->sliderPressed();
  const Times held = timeMoves();
  const double heldDistance = window.Inside()->Pass()->GetLastImageSampleDistance();
  Q_EMIT slider->sliderReleased();
  std::printf("inside view %dx%d, still frames %s\n", pixelsWide, pixelsHigh,
    whole ? "whole (--whole)" : "refined in pieces (ProgressiveRefinement)");
  std::printf("first frame (shader compilation included): %.1f ms\n", first);
  std::printf("slider release -> first picture: %s (%d moves)\n", summary(times.First).c_str(),
    moves);
  std::printf("slider release -> full picture: %s\n", summary(times.Full).c_str());
  std::printf("longest piece (the window's longest wait for input): %s\n",
    summary(times.Piece).c_str());
  std::printf("the same moves with the slider held: first picture %s; full picture %s; "
              "last frame at 1 ray per %.2f x %.2f pixels\n",
    summary(held.First).c_str(), summary(held.Full).c_str(), heldDistance, heldDistance);
  std::printf("shader compilations during the moves: %d\n",
    window.Inside()->Pass()->GetNumberOfShaderCompilations() - compilations);
  const char* capabilities = window.Inside()->renderWindow()->ReportCapabilities();
  std::printf("%.300s\n", capabilities ? capabilities : "");
  return 0;
}
