#include "TimeBar.h"

#include "StudioDocument.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QTimer>

#include <cmath>

namespace riemann
{
namespace studio
{
TimeBar::TimeBar(StudioDocument* document, QWidget* parent)
  : QToolBar(QStringLiteral("Time"), parent)
  , Document(document)
  , TimeSlider(new QSlider(Qt::Horizontal, this))
  , TimeSpin(new QDoubleSpinBox(this))
  , Ticker(new QTimer(this))
{
  this->setObjectName("TimeBar");
  this->Play = this->addAction(this->style()->standardIcon(QStyle::SP_MediaPlay), "Play");
  this->Play->setCheckable(true);
  this->Play->setToolTip("Play t from 0 to 1 (loops)");
  this->addWidget(new QLabel(QStringLiteral(" t "), this));
  this->TimeSlider->setRange(0, Steps);
  this->TimeSlider->setObjectName("TimeSlider");
  this->TimeSlider->setMinimumWidth(200);
  this->addWidget(this->TimeSlider);
  this->TimeSpin->setRange(0.0, 1.0);
  this->TimeSpin->setDecimals(3);
  this->TimeSpin->setSingleStep(0.01);
  this->TimeSpin->setKeyboardTracking(false);
  this->addWidget(this->TimeSpin);
  this->Export = this->addAction(
    this->style()->standardIcon(QStyle::SP_DialogSaveButton), "Export Animation...");
  this->Export->setToolTip("A film of t from 0 to 1 and/or a camera path: PNG pictures or an .ogv film");

  this->Ticker->setInterval(40);
  QObject::connect(this->Ticker, &QTimer::timeout, this, &TimeBar::Step);
  QObject::connect(this->Play, &QAction::toggled, this, &TimeBar::SetPlaying);
  QObject::connect(this->Export, &QAction::triggered, this, &TimeBar::ExportFramesRequested);
  QObject::connect(this->TimeSlider, &QSlider::valueChanged, this,
    [this](int position) { this->Apply(static_cast<double>(position) / Steps); });
  QObject::connect(this->TimeSlider, &QSlider::sliderPressed, this, [this]() { Q_EMIT this->Moving(true); });
  QObject::connect(this->TimeSlider, &QSlider::sliderReleased, this,
    [this]() { Q_EMIT this->Moving(this->IsPlaying()); });
  QObject::connect(this->TimeSpin, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    &TimeBar::Apply);
  QObject::connect(document, &StudioDocument::MetricChanged, this, [this]() {
    const QSignalBlocker blockSlider(this->TimeSlider);
    const QSignalBlocker blockSpin(this->TimeSpin);
    const double t = this->Document->Time();
    this->TimeSlider->setValue(static_cast<int>(std::lround(t * Steps)));
    this->TimeSpin->setValue(t);
  });
}

void TimeBar::SetPlaying(bool playing)
{
  {
    const QSignalBlocker block(this->Play);
    this->Play->setChecked(playing);
  }
  this->Play->setIcon(this->style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
  const bool was = this->IsPlaying();
  if (playing)
  {
    this->Ticker->start();
  }
  else
  {
    this->Ticker->stop();
  }
  if (playing != was)
  {
    Q_EMIT this->Moving(playing);
  }
}

bool TimeBar::IsPlaying() const
{
  return this->Ticker->isActive();
}

void TimeBar::Step()
{
  double t = this->Document->Time() + this->Ticker->interval() * 1e-3 / this->Period;
  if (t > 1.0)
  {
    t = 0.0;
  }
  this->Apply(t);
}

void TimeBar::Apply(double t)
{
  const MetricStatus status = this->Document->SetTime(std::clamp(t, 0.0, 1.0));
  if (!status.Ok())
  {
    this->SetPlaying(false);
  }
  Q_EMIT this->TimeApplied(status.Ok(), status.Message);
}
}
}
