/**
 * @file AnimationExport.h
 * @brief File > Export Animation: a film of the chosen view(s) at a chosen
 * size, with the metric's time t running and/or the observer flying along a
 * camera path item (vtkRiemannCameraPath: its frame carried by the metric),
 * written as numbered PNGs or one Ogg Theora film (riemann::FilmWriter),
 * with progress and Cancel; and the dialog that asks for it (also File >
 * Save Screenshot's, without the film's part).
 */
#ifndef RiemannStudio_AnimationExport_h
#define RiemannStudio_AnimationExport_h

#include "StudioMainWindow.h"

#include <QDialog>
#include <QString>

#include <functional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace riemann
{
namespace studio
{
struct AnimationSettings
{
  int Frames = 60;
  /// The picture's size (both views side by side share it).
  int Width = 640;
  int Height = 480;
  StudioMainWindow::Shot View = StudioMainWindow::InsideShot;
  /// t runs from TimeFrom to TimeTo over the frames (else it stays).
  bool AnimateTime = true;
  double TimeFrom = 0.0;
  double TimeTo = 1.0;
  /// A camera path item's name: the observer flies along it (else it stays).
  QString CameraPath;
  /// OUT.png: OUT_0000.png, ...; OUT.ogv: one film.
  QString Output;
};

/**
 * Writes the animation; returns an error message (empty on success). The
 * document's t, observer and the window's layout are put back afterwards.
 * `progress(done, total)` is called after each frame; returning false
 * cancels, and then nothing is left written ("cancelled").
 */
QString ExportAnimation(StudioMainWindow& window, const AnimationSettings& settings,
  const std::function<bool(int, int)>& progress = {});

/// The settings dialog. Picture-only (Save Screenshot): view and size.
class AnimationDialog : public QDialog
{
  Q_OBJECT
public:
  AnimationDialog(StudioDocument* document, bool animation, QWidget* parent = nullptr);
  /// The dialog's values (Output from its path field).
  AnimationSettings Settings() const;

private:
  void Browse();

  bool Animation = true;
  QComboBox* View = nullptr;
  QSpinBox* Width = nullptr;
  QSpinBox* Height = nullptr;
  QSpinBox* Frames = nullptr;
  QCheckBox* AnimateTime = nullptr;
  QDoubleSpinBox* TimeFrom = nullptr;
  QDoubleSpinBox* TimeTo = nullptr;
  QComboBox* CameraPath = nullptr;
  QLineEdit* Output = nullptr;
};
}
}

#endif
