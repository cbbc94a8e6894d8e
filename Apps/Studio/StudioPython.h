/**
 * @file StudioPython.h
 * @brief riemann-studio's embedded Python (CPython, the interpreter
 * /usr/bin/python3 is): the Python shell's console and `--script`, with the
 * same `riemann` and VTK modules as scripts (the build's or install's
 * Python package folder is put on sys.path) and the `studio` module, which
 * drives the window's document (StudioScripting.h):
 *
 *   studio.open(path)                 studio.items() -> [names]
 *   studio.add(kind, **properties)    -> the new item's name
 *   studio.set(item, **properties)    studio.get(item) -> {settings}
 *   studio.remove(item)               studio.show(item, visible=True)
 *   studio.rename(item, name)         studio.parameter(pointer, value=None)
 *   studio.observer(position=None, look_at=None, view_up=None) -> {camera}
 *   studio.metric(text=None) -> text  studio.time(t=None) -> t
 *   studio.undo() / studio.redo() -> the step's name, or None
 *   studio.save(path)                 studio.project() -> {project}
 *   studio.screenshot(path, view="inside", size=None)
 *   studio.export_animation(path, frames=60, view="inside", size=(640, 480),
 *                           time=(0, 1), camera_path=None)
 *   studio.render()                   (draw, and wait for every job)
 *   studio.cancel()                   studio.running() -> jobs running
 *   studio.wait(seconds)              (the window goes on meanwhile)
 *   studio.select(item=None)          studio.dock("python"|"spreadsheet", visible)
 *
 * Failures raise studio.StudioError with the window's message. One
 * interpreter per process (CPython's rule); it drives whichever window was
 * set last.
 */
#ifndef RiemannStudio_StudioPython_h
#define RiemannStudio_StudioPython_h

#include <QString>

#include <functional>

namespace riemann
{
namespace studio
{
class StudioMainWindow;

class StudioPython
{
public:
  /// The process's interpreter, started on first use.
  static StudioPython& Instance();

  /// "3.11.2": the interpreter's version.
  static QString Version();
  /// Whether Python started; else Error() says why.
  bool Available() const { return this->Started; }
  QString Error() const { return this->Problem; }

  /// The window `studio` drives, and where printed text goes (`error`:
  /// written to sys.stderr). With `mirror`, text also goes to this
  /// process's stdout and stderr (a --script run).
  void Attach(StudioMainWindow* window, std::function<void(const QString&, bool)> output);
  void Detach(StudioMainWindow* window);
  void SetMirror(bool mirror) { this->Mirror = mirror; }
  bool GetMirror() const { return this->Mirror; }

  /// One line typed in the console; true when a block needs more lines.
  bool Push(const QString& line);
  /// Runs a file as __main__; its exit status: 0, SystemExit's code, or 1
  /// after an uncaught exception (its traceback printed to the output).
  int RunScript(const QString& path);
  /// Whether a line or script is running (the console waits).
  bool Busy() const { return this->Running > 0; }

  /// Called by the `_studio` module's functions.
  StudioMainWindow* Window() const { return this->Target; }
  void Write(const QString& text, bool error);

private:
  StudioPython();
  bool Start();

  bool Started = false;
  QString Problem;
  StudioMainWindow* Target = nullptr;
  std::function<void(const QString&, bool)> Output;
  bool Mirror = false;
  int Running = 0;
};
}
}

#endif
