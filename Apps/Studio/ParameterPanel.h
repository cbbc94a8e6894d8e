/**
 * @file ParameterPanel.h
 * @brief A slider and a spin box for every plain-number parameter of the
 * metric. Moving one sets the value (StudioDocument::SetParameterValue):
 * same metric structure, so the inside view only gets new uniforms (no
 * shader compilation) and the derived items re-run.
 *
 * Animated parameters ({"from": a, "to": b}) follow t: the time bar moves them.
 */
#ifndef RiemannStudio_ParameterPanel_h
#define RiemannStudio_ParameterPanel_h

#include <QWidget>

#include <string>

class QDoubleSpinBox;
class QFormLayout;
class QSlider;

namespace riemann
{
namespace studio
{
class StudioDocument;

class ParameterPanel : public QWidget
{
  Q_OBJECT
public:
  explicit ParameterPanel(StudioDocument* document, QWidget* parent = nullptr);

  /// The controls of a parameter, by JSON pointer (null if none).
  QSlider* Slider(const std::string& pointer) const;
  QDoubleSpinBox* SpinBox(const std::string& pointer) const;
  /// Sliders have this many steps between their ends.
  static constexpr int SliderSteps = 1000;

Q_SIGNALS:
  /// A value was taken (ok) or refused (message).
  void ValueApplied(bool ok, const QString& message);
  /// A slider is held (true) or let go (false): the views may draw coarser
  /// frames meanwhile (InsideView::SetMoving).
  void Moving(bool moving);

private:
  void Rebuild();
  void AddRow(const std::string& pointer, const QString& label, double value);

  StudioDocument* Document;
  QFormLayout* Form;
};
}
}

#endif
