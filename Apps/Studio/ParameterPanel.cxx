#include "ParameterPanel.h"

#include "StudioDocument.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>

#include <cmath>

namespace riemann
{
namespace studio
{
namespace
{
/// The slider spans value +- max(|value|, 1) around the value it started at.
struct SliderRange
{
  double Low, High;
  explicit SliderRange(double start)
  {
    const double half = std::max(std::abs(start), 1.0);
    this->Low = start - half;
    this->High = start + half;
  }
  int ToSlider(double value) const
  {
    const double f = (value - this->Low) / (this->High - this->Low);
    return static_cast<int>(std::lround(std::clamp(f, 0.0, 1.0) * ParameterPanel::SliderSteps));
  }
  double FromSlider(int position) const
  {
    return this->Low + (this->High - this->Low) * position / ParameterPanel::SliderSteps;
  }
};
}

ParameterPanel::ParameterPanel(StudioDocument* document, QWidget* parent)
  : QWidget(parent)
  , Document(document)
  , Form(new QFormLayout(this))
{
  this->Form->setContentsMargins(4, 4, 4, 4);
  QObject::connect(document, &StudioDocument::ParametersChanged, this, &ParameterPanel::Rebuild);
  // Values set elsewhere (a project, a script) show on the controls.
  QObject::connect(document, &StudioDocument::MetricChanged, this, [this]() {
    for (const MetricParameter& parameter : this->Document->Parameters())
    {
      if (QDoubleSpinBox* spin = this->SpinBox(parameter.Pointer))
      {
        const double value = this->Document->ParameterValue(parameter.Pointer);
        if (spin->value() != value)
        {
          {
            const QSignalBlocker block(spin);
            spin->setValue(value);
          }
          Q_EMIT spin->editingFinished(); // the slider follows (AddRow)
        }
      }
    }
  });
  this->Rebuild();
}

void ParameterPanel::Rebuild()
{
  while (this->Form->rowCount() > 0)
  {
    this->Form->removeRow(0);
  }
  int rows = 0;
  for (const MetricParameter& parameter : this->Document->Parameters())
  {
    if (parameter.Animated)
    {
      continue;
    }
    // Nested parameters carry their composition path in the label.
    const std::string path = parameter.Pointer.substr(0, parameter.Pointer.rfind("/parameters/"));
    const QString label = path.empty()
      ? QString::fromStdString(parameter.Name)
      : QString::fromStdString(parameter.Name + " (" + path + ")");
    this->AddRow(parameter.Pointer, label, this->Document->ParameterValue(parameter.Pointer));
    ++rows;
  }
  if (rows == 0)
  {
    auto* empty = new QLabel(this);
    empty->setWordWrap(true);
    empty->setText(QStringLiteral(
      "<i>No parameters. Name numbers in a \"parameters\" object of the metric to get sliders "
      "here; animate them with {\"from\": a, \"to\": b} and the time bar.</i>"));
    this->Form->addRow(empty);
  }
}

void ParameterPanel::AddRow(const std::string& pointer, const QString& label, double value)
{
  auto* row = new QWidget(this);
  auto* layout = new QHBoxLayout(row);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* slider = new QSlider(Qt::Horizontal, row);
  slider->setObjectName(QString::fromStdString("Slider:" + pointer));
  slider->setRange(0, SliderSteps);
  auto* spin = new QDoubleSpinBox(row);
  spin->setObjectName(QString::fromStdString("Spin:" + pointer));
  spin->setDecimals(4);
  spin->setRange(-1e6, 1e6);
  spin->setSingleStep(0.01);
  spin->setKeyboardTracking(false);
  layout->addWidget(slider, 1);
  layout->addWidget(spin);
  this->Form->addRow(label, row);

  auto range = std::make_shared<SliderRange>(value);
  slider->setValue(range->ToSlider(value));
  spin->setValue(value);
  auto apply = [this, pointer, slider, spin, range](double v) {
    const MetricStatus status = this->Document->SetParameterValue(pointer, v);
    const QSignalBlocker blockSlider(slider);
    const QSignalBlocker blockSpin(spin);
    const double shown = this->Document->ParameterValue(pointer);
    if (shown < range->Low || shown > range->High)
    {
      *range = SliderRange(shown);
    }
    slider->setValue(range->ToSlider(shown));
    spin->setValue(shown);
    spin->setToolTip(status.Ok() ? QString() : status.Message);
    Q_EMIT this->ValueApplied(status.Ok(), status.Message);
  };
  QObject::connect(slider, &QSlider::valueChanged, this,
    [range, apply](int position) { apply(range->FromSlider(position)); });
  QObject::connect(slider, &QSlider::sliderPressed, this, [this]() { Q_EMIT this->Moving(true); });
  QObject::connect(slider, &QSlider::sliderReleased, this, [this]() { Q_EMIT this->Moving(false); });
  QObject::connect(spin, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, apply);
  QObject::connect(spin, &QDoubleSpinBox::editingFinished, this, [slider, spin, range]() {
    const QSignalBlocker block(slider);
    if (spin->value() < range->Low || spin->value() > range->High)
    {
      *range = SliderRange(spin->value());
    }
    slider->setValue(range->ToSlider(spin->value()));
  });
}

QSlider* ParameterPanel::Slider(const std::string& pointer) const
{
  return this->findChild<QSlider*>(QString::fromStdString("Slider:" + pointer));
}

QDoubleSpinBox* ParameterPanel::SpinBox(const std::string& pointer) const
{
  return this->findChild<QDoubleSpinBox*>(QString::fromStdString("Spin:" + pointer));
}
}
}
