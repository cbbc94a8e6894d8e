/**
 * @file TimeBar.h
 * @brief The play bar of animated metrics: t from 0 to 1 with a slider, a
 * spin box, play/pause (looping) and the export of frames.
 */
#ifndef RiemannStudio_TimeBar_h
#define RiemannStudio_TimeBar_h

#include <QToolBar>

class QAction;
class QDoubleSpinBox;
class QSlider;
class QTimer;

namespace riemann
{
namespace studio
{
class StudioDocument;

class TimeBar : public QToolBar
{
  Q_OBJECT
public:
  explicit TimeBar(StudioDocument* document, QWidget* parent = nullptr);

  void SetPlaying(bool playing);
  bool IsPlaying() const;
  /// Seconds for t to go from 0 to 1 while playing (default 4).
  void SetPeriod(double seconds) { this->Period = seconds; }
  QSlider* Slider() const { return this->TimeSlider; }
  QAction* ExportAction() const { return this->Export; }

Q_SIGNALS:
  void TimeApplied(bool ok, const QString& message);
  /// The user asked for frames to be written (the window does it).
  void ExportFramesRequested();
  /// t plays or its slider is held (true), or neither any more (false): the
  /// views may draw coarser frames meanwhile (InsideView::SetMoving).
  void Moving(bool moving);

private:
  void Apply(double t);
  void Step();

  StudioDocument* Document;
  QAction* Play;
  QAction* Export;
  QSlider* TimeSlider;
  QDoubleSpinBox* TimeSpin;
  QTimer* Ticker;
  double Period = 4.0;
  static constexpr int Steps = 1000;
};
}
}

#endif
