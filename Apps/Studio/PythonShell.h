/**
 * @class riemann::studio::PythonShell
 * @brief The Python shell docked in riemann-studio (View > Python Shell):
 * a console on the app's embedded interpreter (StudioPython.h) with the
 * `studio` module already imported, `import riemann` and VTK's modules as
 * in scripts, the output of print and of tracebacks, and the lines typed
 * before (Up and Down). Python starts when the shell is first shown or
 * used (a window that never uses it never starts the interpreter).
 */
#ifndef RiemannStudio_PythonShell_h
#define RiemannStudio_PythonShell_h

#include <QStringList>
#include <QWidget>

class QLabel;
class QLineEdit;
class QPlainTextEdit;

namespace riemann
{
namespace studio
{
class StudioMainWindow;

class PythonShell : public QWidget
{
  Q_OBJECT
public:
  PythonShell(StudioMainWindow* window, QWidget* parent = nullptr);
  ~PythonShell() override;

  /// Starts Python (once) and makes this window the one `studio` drives;
  /// false when Python could not start (the shell says why).
  bool Start();
  /// Runs `line` as if typed and entered; returns whether a block needs more.
  bool Enter(const QString& line);
  /// Runs a script file in this shell (--script): its exit status.
  int RunScript(const QString& path);
  /// Everything the console shows.
  QString Transcript() const;
  QLineEdit* Input() const { return this->Line; }

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;
  void showEvent(QShowEvent* event) override;

private:
  void Append(const QString& text, bool error);

  StudioMainWindow* Window;
  QPlainTextEdit* Output;
  QLabel* Prompt;
  QLineEdit* Line;
  QStringList History;
  int HistoryAt = 0;
  bool Started = false;
};
}
}

#endif
