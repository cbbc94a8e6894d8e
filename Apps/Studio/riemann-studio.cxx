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

namespace
{
using riemann::studio::StudioMainWindow;

/// The command line, checked: what to open, and what to do with it.
struct StudioOptions
{
  QString File;
  bool Batch = false; // --screenshot: render, write the PNG and exit
  QString Screenshot;
  StudioMainWindow::Shot Shot = StudioMainWindow::WindowShot;
  bool SizeGiven = false;
  int Width = 1500;
  int Height = 900;
  bool PickGiven = false;
  int PickColumn = -1;
  int PickRow = -1;
  QString Script;
  bool ExitAfterScript = false;
};

/// Qt's xcb platform aborts the process without a display, after its own
/// message; say what to do instead (as `riemann render` does for the GPU).
bool HasDisplay()
{
  const bool platformChosen = !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
  if (!platformChosen && qEnvironmentVariableIsEmpty("DISPLAY") &&
    qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
  {
    std::fprintf(stderr, "riemann-studio: no display (DISPLAY is not set): run it in a desktop "
                         "session, or under xvfb-run for --screenshot (xvfb-run -a riemann-studio "
                         "FILE --screenshot out.png)\n");
    return false;
  }
  return true;
}

/// Prints "riemann-studio: <message>" and returns `status` (for `return Refuse(...)`).
int Refuse(int status, const QString& message)
{
  std::fprintf(stderr, "riemann-studio: %s\n", qPrintable(message));
  return status;
}

/// The options Qt parses (--help exits there).
void DeclareOptions(QCommandLineParser& parser)
{
  parser.setApplicationDescription(
    "Design a Riemannian metric on R^3 and see it from inside and outside.");
  parser.addHelpOption();
  parser.addPositionalArgument("file", "A project, metric or scene file (JSON) to open.", "[file]");
  parser.addOption({ "script",
    "Run this Python script in the Python shell once the file is open (the studio module drives "
    "the window; print goes to the shell and this terminal). The window stays open after it.",
    "S.py" });
  parser.addOption({ "exit", "With --script: exit with the script's status when it ends "
                             "(0, SystemExit's code, 1 after an uncaught exception)." });
  parser.addOption({ "screenshot", "Render the opened session, save it as PNG and exit.", "out.png" });
  parser.addOption({ "pick", "Pick this pixel of the inside view (column,row from the "
                             "bottom left) before the screenshot: its ray shows outside.",
    "column,row" });
  parser.addOption({ "view", "What --screenshot captures: window (default), inside, outside or both.",
    "what", "window" });
  parser.addOption({ "size",
    "Size of the --screenshot picture, WxH: the window's for --view window (default 1500x900), "
    "else the chosen view's, or both views' side by side.",
    "WxH", "1500x900" });
}

/// Reads and checks the parsed options into `options`: 0, or the status to exit with (2).
int CheckOptions(const QCommandLineParser& parser, StudioOptions& options)
{
  const QString what = parser.value("view");
  if (what != "window" && what != "inside" && what != "outside" && what != "both")
  {
    return Refuse(2, "--view: expected window, inside, outside or both, got \"" + what + "\"");
  }
  options.Shot = what == "inside" ? StudioMainWindow::InsideShot
    : what == "outside"           ? StudioMainWindow::OutsideShot
    : what == "both"              ? StudioMainWindow::BothShot
                                  : StudioMainWindow::WindowShot;
  const QStringList dimensions = parser.value("size").split('x');
  bool okWidth = false, okHeight = false;
  options.Width = dimensions.value(0).toInt(&okWidth);
  options.Height = dimensions.size() == 2 ? dimensions.value(1).toInt(&okHeight) : 0;
  if (!okWidth || !okHeight || options.Width < 320 || options.Height < 240 || options.Width > 8192 ||
    options.Height > 8192)
  {
    return Refuse(2, "--size: expected WxH between 320x240 and 8192x8192, got \"" +
        parser.value("size") + "\"");
  }
  options.SizeGiven = parser.isSet("size");
  options.Batch = parser.isSet("screenshot");
  options.Screenshot = parser.value("screenshot");
  options.Script = parser.value("script");
  options.ExitAfterScript = parser.isSet("exit");
  if (options.ExitAfterScript && !parser.isSet("script"))
  {
    return Refuse(2, "--exit ends a --script run: give --script S.py");
  }
  if (parser.isSet("script") && options.Batch)
  {
    return Refuse(2, "--script and --screenshot: take the screenshot in the script "
                     "(studio.screenshot(path, view=..., size=(w, h)))");
  }
  if (parser.isSet("script") && !QFileInfo(options.Script).isFile())
  {
    return Refuse(2, "--script " + options.Script + ": no such file");
  }
  const QStringList files = parser.positionalArguments();
  if (files.size() > 1)
  {
    return Refuse(2, QStringLiteral("give at most one file (got %1)").arg(files.size()));
  }
  options.File = files.value(0);
  options.PickGiven = parser.isSet("pick");
  if (options.PickGiven)
  {
    const QStringList pixel = parser.value("pick").split(',');
    bool okColumn = false, okRow = false;
    options.PickColumn = pixel.value(0).toInt(&okColumn);
    options.PickRow = pixel.size() == 2 ? pixel.value(1).toInt(&okRow) : -1;
    if (!okColumn || !okRow)
    {
      return Refuse(2, "--pick: expected COLUMN,ROW, got \"" + parser.value("pick") + "\"");
    }
  }
  return 0;
}

/// Sizes the window (or the picture) and opens the file: 0, or 1 when a
/// batch run could not open it (an interactive one shows why and goes on).
int OpenSession(StudioMainWindow& window, const StudioOptions& options)
{
  if (options.Batch && options.SizeGiven)
  {
    window.SetPictureSize(options.Shot, options.Width, options.Height);
  }
  else
  {
    window.resize(options.Width, options.Height);
  }
  if (!options.File.isEmpty())
  {
    const QString error = window.OpenFile(options.File, !options.Batch);
    if (!error.isEmpty() && options.Batch)
    {
      return Refuse(1, error);
    }
  }
  return 0;
}

/// --script: run it once the window has settled. With --exit, true and its
/// status in `status`; else false: the app goes on with the window open.
bool RunStartupScript(StudioMainWindow& window, const StudioOptions& options, int& status)
{
  // The script's prints show in the shell and in this terminal.
  riemann::studio::StudioPython::Instance().SetMirror(true);
  const QString path = options.Script;
  if (options.ExitAfterScript)
  {
    window.Settle();
    status = window.Shell()->RunScript(path);
    return true;
  }
  window.PythonShellDock()->show();
  QTimer::singleShot(0, &window, [&window, path]() {
    window.Settle();
    window.Shell()->RunScript(path);
  });
  return false;
}

/// --screenshot: every item computed, the --pick ray shown, the PNG written.
int TakeScreenshot(StudioMainWindow& window, const StudioOptions& options)
{
  window.Settle();
  if (options.PickGiven)
  {
    int viewWidth = 0, viewHeight = 0;
    window.Inside()->PixelSize(viewWidth, viewHeight);
    if (options.PickColumn < 0 || options.PickRow < 0 || options.PickColumn >= viewWidth ||
      options.PickRow >= viewHeight)
    {
      // Picking nothing would write a picture without the ray asked for.
      return Refuse(2, QStringLiteral("--pick %1,%2: outside the inside view, whose pixels are "
                                      "columns 0 to %3 and rows 0 to %4 (from the bottom left)")
                         .arg(options.PickColumn)
                         .arg(options.PickRow)
                         .arg(viewWidth - 1)
                         .arg(viewHeight - 1));
    }
    window.PickPixel(options.PickColumn, options.PickRow);
    window.Settle();
  }
  const QString error = window.SaveScreenshot(options.Screenshot, options.Shot);
  return error.isEmpty() ? 0 : Refuse(1, error);
}
} // namespace

int main(int argc, char* argv[])
{
  if (!HasDisplay())
  {
    return 1;
  }
  // The format QVTKOpenGLNativeWidget needs (OpenGL 3.2 core or later),
  // before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setApplicationName("Riemann Studio");
  QApplication::setOrganizationName("RiemannVTK");

  QCommandLineParser parser;
  DeclareOptions(parser);
  parser.process(app);
  StudioOptions options;
  if (const int refused = CheckOptions(parser, options))
  {
    return refused;
  }

  StudioMainWindow window;
  if (const int failed = OpenSession(window, options))
  {
    return failed;
  }
  // Shown once the file is open: the first frame is the file's, not the
  // default scene's (renders are scheduled, and run once the window shows).
  window.show();
  int scriptStatus = 0;
  if (!options.Script.isEmpty() && RunStartupScript(window, options, scriptStatus))
  {
    return scriptStatus;
  }
  return options.Batch ? TakeScreenshot(window, options) : app.exec();
}
