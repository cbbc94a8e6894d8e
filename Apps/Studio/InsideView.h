/**
 * @file InsideView.h
 * @brief The inside view: space as seen by the observer through the metric,
 * drawn per pixel by vtkRiemannRayTracePass (GPU) or vtkRiemannCPURayTracer
 * (CPU, off the GUI thread, with samples per pixel).
 *
 * The renderer's camera is the document's observer. Mouse navigation is
 * ParaView's and F3D's (vtkInteractorStyleTrackballCamera: left drag rotates
 * about the look-at point, right drag or the wheel dollies, middle or
 * Shift+left drag pans); while the camera moves, the pass traces fewer rays
 * to keep up, and the still frame at the end is full resolution. Ctrl+click (or a click in pick mode) picks a pixel:
 * PixelPicked(column, row), row 0 at the bottom as in VTK.
 */
#ifndef RiemannStudio_InsideView_h
#define RiemannStudio_InsideView_h

#include "QVTKOpenGLNativeWidget.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <QImage>
#include <QString>

class vtkImageActor;
class vtkImageData;
class vtkRenderer;
class vtkRiemannCPURayTracer;
class vtkRiemannRayTracePass;

namespace riemann
{
namespace studio
{
class StudioDocument;

class InsideView : public QVTKOpenGLNativeWidget
{
  Q_OBJECT
public:
  enum Backend
  {
    GPU,
    CPU
  };

  explicit InsideView(StudioDocument* document, QWidget* parent = nullptr);
  ~InsideView() override;

  vtkRenderer* Renderer() const { return this->ObserverRenderer; }
  vtkRiemannRayTracePass* Pass() const { return this->RayTracePass; }

  void SetBackend(Backend backend);
  Backend GetBackend() const { return this->CurrentBackend; }
  void SetSamplesPerPixel(int samples);
  int GetSamplesPerPixel() const { return this->Samples; }
  /// Clicks pick pixels (without Ctrl) while on.
  void SetPickMode(bool on) { this->PickMode = on; }
  bool GetPickMode() const { return this->PickMode; }

  /// Draw the view now (GPU: synchronously, finished on return; CPU: starts
  /// the trace, the picture arrives later).
  void RenderNow();
  /**
   * Something moves the view continuously (a parameter slider held, t
   * playing): until SetMoving(false), frames are drawn at the interactor's
   * desired update rate, as while the camera moves (the pass traces fewer
   * rays to keep up); then one full frame. Captures are always full frames.
   */
  void SetMoving(bool moving);
  /// The picture on screen, as the user sees it.
  /// Draw once the current event has been handled: many changes in a row
  /// (a project opening, a slider dragged) draw one frame.
  void ScheduleRender();
  /// The picture on screen (drawn first if a render is pending).
  QImage Capture();
  /// The render window's size in pixels (the size the rays are traced for).
  void PixelSize(int& width, int& height);
  /// Pick pixel (column, row) as a click there would.
  void PickPixel(int column, int row);
  /// Why the last GPU frame failed ("" when it drew).
  QString LastError() const { return this->Error; }

Q_SIGNALS:
  void PixelPicked(int column, int row);
  /// A frame was drawn; milliseconds of the render call (GPU) or trace (CPU).
  void FrameRendered(double milliseconds);
  void RenderFailed(const QString& message);
  /// The GPU pass drew the view with one ray per d x d pixels (d above 1
  /// while the camera moves: vtkRiemannRayTracePass::AutoAdjustSampleDistances).
  void ViewDrawn(double imageSampleDistance);

protected:
  void resizeEvent(QResizeEvent* event) override;

private:
  class Style;
  void SetUpRenderers();
  void StartCpuTrace();
  void ShowCpuImage(vtkImageData* image);
  void ReportPassErrors();

  StudioDocument* Document;
  vtkNew<vtkRenderer> ObserverRenderer;
  vtkNew<vtkRenderer> ImageRenderer;
  vtkNew<vtkRiemannRayTracePass> RayTracePass;
  vtkNew<vtkImageActor> CpuImage;
  Backend CurrentBackend = GPU;
  int Samples = 1;
  bool PickMode = false;
  QString Error;
  bool RenderPending = false;
  /// The observer is being moved by this view's own mouse interaction
  /// (which draws the frame itself).
  bool Interacting = false;
};
}
}

#endif
