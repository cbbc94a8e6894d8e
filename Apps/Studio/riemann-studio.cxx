// riemann-studio: the desktop app where a metric is designed and seen live.
//
//   riemann-studio [project.json | metric.json | scene.json]
//   riemann-studio FILE --screenshot out.png [--view window|inside|outside|both] [--size WxH]
//                  [--pick COLUMN,ROW]
//   riemann-studio [FILE] --script S.py [--exit]
//
// --screenshot renders the opened session (after every item has been
// computed), writes the PNG and exits: 0 on success, 1 when the file could
// not be opened or the picture not written, 2 for bad options. --script runs
// S.py in the Python shell once FILE is open (the studio module drives the
// window, StudioPython.h); with --exit the app then exits with the script's
// status, so every Studio test can be a script.
#include "InsideView.h"
#include "PythonShell.h"
#include "StudioMainWindow.h"
#include "StudioPython.h"

#include "QVTKOpenGLNativeWidget.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QFileInfo>
#include <QSurfaceFormat>
#include <QTimer>

#include <cstdio>

int main(int argc, char* argv[])
{
  // Without a display Qt's xcb platform aborts the process after its own
  // message; say what to do instead (as `riemann render` does for the GPU).
  const bool platformChosen = !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
  if (!platformChosen && qEnvironmentVariableIsEmpty("DISPLAY") &&
    qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
  {
    std::fprintf(stderr, "riemann-studio: no display (DISPLAY is not set): run it in a desktop "
                         "session, or under xvfb-run for --screenshot (xvfb-run -a riemann-studio "
                         "FILE --screenshot out.png)\n");
    return 1;
  }
  // The format QVTKOpenGLNativeWidget needs (OpenGL 3.2 core or later),
  // before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setApplicationName("Riemann Studio");
  QApplication::setOrganizationName("RiemannVTK");

  QCommandLineParser parser;
  parser.setApplicationDescription(
    "Design a Riemannian metric on R^3 and see it from inside and outside.");
  parser.addHelpOption();
  parser.addPositionalArgument("file", "A project, metric or scene file (JSON) to open.", "[file]");
  QCommandLineOption screenshot("screenshot", "Render the opened session, save it as PNG and exit.", "out.png");
  QCommandLineOption view("view", "What --screenshot captures: window (default), inside, outside or both.", "what", "window");
  QCommandLineOption size("size",
    "Size of the --screenshot picture, WxH: the window's for --view window (default 1500x900), "
    "else the chosen view's, or both views' side by side.", "WxH", "1500x900");
  QCommandLineOption pick("pick", "Pick this pixel of the inside view (column,row from the "
                                  "bottom left) before the screenshot: its ray shows outside.", "column,row");
  QCommandLineOption script("script",
    "Run this Python script in the Python shell once the file is open (the studio module drives "
    "the window; print goes to the shell and this terminal). The window stays open after it.",
    "S.py");
  QCommandLineOption exitAfter("exit", "With --script: exit with the script's status when it ends "
                                       "(0, SystemExit's code, 1 after an uncaught exception).");
  parser.addOption(script);
  parser.addOption(exitAfter);
  parser.addOption(screenshot);
  parser.addOption(pick);
  parser.addOption(view);
  parser.addOption(size);
  parser.process(app);

  using riemann::studio::StudioMainWindow;
  const QString what = parser.value(view);
  const StudioMainWindow::Shot shot = what == "inside" ? StudioMainWindow::InsideShot
    : what == "outside"                                ? StudioMainWindow::OutsideShot
    : what == "both"                                   ? StudioMainWindow::BothShot
                                                       : StudioMainWindow::WindowShot;
  if (what != "window" && what != "inside" && what != "outside" && what != "both")
  {
    std::fprintf(stderr, "riemann-studio: --view: expected window, inside, outside or both, got \"%s\"\n",
      qPrintable(what));
    return 2;
  }
  const QStringList dimensions = parser.value(size).split('x');
  bool okWidth = false, okHeight = false;
  const int width = dimensions.value(0).toInt(&okWidth);
  const int height = dimensions.size() == 2 ? dimensions.value(1).toInt(&okHeight) : 0;
  if (!okWidth || !okHeight || width < 320 || height < 240 || width > 8192 || height > 8192)
  {
    std::fprintf(stderr, "riemann-studio: --size: expected WxH between 320x240 and 8192x8192, got \"%s\"\n",
      qPrintable(parser.value(size)));
    return 2;
  }
  const bool batch = parser.isSet(screenshot);
  if (parser.isSet(exitAfter) && !parser.isSet(script))
  {
    std::fprintf(stderr, "riemann-studio: --exit ends a --script run: give --script S.py\n");
    return 2;
  }
  if (parser.isSet(script) && batch)
  {
    std::fprintf(stderr, "riemann-studio: --script and --screenshot: take the screenshot in the "
                         "script (studio.screenshot(path, view=..., size=(w, h)))\n");
    return 2;
  }
  if (parser.isSet(script) && !QFileInfo(parser.value(script)).isFile())
  {
    std::fprintf(stderr, "riemann-studio: --script %s: no such file\n", qPrintable(parser.value(script)));
    return 2;
  }

  StudioMainWindow window;
  if (batch && parser.isSet(size))
  {
    window.SetPictureSize(shot, width, height);
  }
  else
  {
    window.resize(width, height);
  }
  const QStringList files = parser.positionalArguments();
  if (files.size() > 1)
  {
    std::fprintf(stderr, "riemann-studio: give at most one file (got %d)\n", int(files.size()));
    return 2;
  }
  if (!files.isEmpty())
  {
    const QString error = window.OpenFile(files.first(), !batch);
    if (!error.isEmpty() && batch)
    {
      std::fprintf(stderr, "riemann-studio: %s\n", qPrintable(error));
      return 1;
    }
  }
  // Shown once the file is open: the first frame is the file's, not the
  // default scene's (renders are scheduled, and run once the window shows).
  window.show();
  if (parser.isSet(script))
  {
    // The script's prints show in the shell and in this terminal.
    riemann::studio::StudioPython& python = riemann::studio::StudioPython::Instance();
    python.SetMirror(true);
    const QString path = parser.value(script);
    if (parser.isSet(exitAfter))
    {
      window.Settle();
      return window.Shell()->RunScript(path);
    }
    window.PythonShellDock()->show();
    QTimer::singleShot(0, &window, [&window, path]() {
      window.Settle();
      window.Shell()->RunScript(path);
    });
  }
  if (!batch)
  {
    return app.exec();
  }
  window.Settle();
  if (parser.isSet(pick))
  {
    const QStringList pixel = parser.value(pick).split(',');
    bool okColumn = false, okRow = false;
    const int column = pixel.value(0).toInt(&okColumn);
    const int row = pixel.size() == 2 ? pixel.value(1).toInt(&okRow) : -1;
    if (!okColumn || !okRow)
    {
      std::fprintf(stderr, "riemann-studio: --pick: expected COLUMN,ROW, got \"%s\"\n",
        qPrintable(parser.value(pick)));
      return 2;
    }
    int viewWidth = 0, viewHeight = 0;
    window.Inside()->PixelSize(viewWidth, viewHeight);
    if (column < 0 || row < 0 || column >= viewWidth || row >= viewHeight)
    {
      // Picking nothing would write a picture without the ray asked for.
      std::fprintf(stderr,
        "riemann-studio: --pick %d,%d: outside the inside view, whose pixels are columns 0 to %d "
        "and rows 0 to %d (from the bottom left)\n",
        column, row, viewWidth - 1, viewHeight - 1);
      return 2;
    }
    window.PickPixel(column, row);
    window.Settle();
  }
  const QString error = window.SaveScreenshot(parser.value(screenshot), shot);
  if (!error.isEmpty())
  {
    std::fprintf(stderr, "riemann-studio: %s\n", qPrintable(error));
    return 1;
  }
  return 0;
}
