/**
 * @file MetricEditor.h
 * @brief The metric's JSON text, highlighted, checked as one types.
 *
 * Each edit restarts a short timer (debounce); when it fires the text goes
 * to StudioDocument::SetMetricText. A bad text is underlined where the
 * error is (the core's path or column, located by the parser as data: vtkRiemannMetric::GetLastErrorPlace) and
 * the message, with line and column, is shown under the text, while the last
 * good metric stays on screen.
 */
#ifndef RiemannStudio_MetricEditor_h
#define RiemannStudio_MetricEditor_h

#include <QWidget>

class QLabel;
class QPlainTextEdit;
class QTimer;

namespace riemann
{
namespace studio
{
class StudioDocument;
struct MetricStatus;

class MetricEditor : public QWidget
{
  Q_OBJECT
public:
  explicit MetricEditor(StudioDocument* document, QWidget* parent = nullptr);

  /// Show `text` (from a file, a project, an example) and apply it now.
  /// Returns the error message ("" when the metric was taken).
  QString SetText(const QString& text);
  QString Text() const;
  QPlainTextEdit* Editor() const { return this->TextEdit; }
  /// The message under the text ("" when the text is good).
  QString ErrorText() const;
  /// Check the text now instead of after the debounce delay.
  void ApplyNow();
  /// Milliseconds between the last keystroke and the check (default 400).
  void SetDebounceDelay(int milliseconds);

Q_SIGNALS:
  /// After each check: ok or not, and the message.
  void Checked(bool ok, const QString& message);

private:
  void ShowStatus(const MetricStatus& status);

  StudioDocument* Document;
  QPlainTextEdit* TextEdit;
  QLabel* Status;
  QTimer* Debounce;
  bool Loading = false;
};
}
}

#endif
