#include "InsideView.h"

#include "InsideViewRays.h"
#include "StudioDocument.h"

#include "vtkRiemannCPURayTracer.h"
#include "vtkRiemannIntegrationSettings.h"
#include "vtkRiemannMetric.h"
#include "vtkRiemannRayTracePass.h"
#include "vtkRiemannScene.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageMapper3D.h"
#include "vtkImageProperty.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

#include <QElapsedTimer>
#include <QResizeEvent>
#include <QTimer>

#include <functional>

namespace riemann
{
namespace studio
{
/// Trackball navigation, plus picking on Ctrl+click or in pick mode.
class InsideView::Style : public vtkInteractorStyleTrackballCamera
{
public:
  static Style* New();
  vtkTypeMacro(Style, vtkInteractorStyleTrackballCamera);
  std::function<bool()> PickModeOn;
  std::function<void(int, int)> Pick;

  void OnLeftButtonDown() override
  {
    vtkRenderWindowInteractor* interactor = this->GetInteractor();
    if (interactor->GetControlKey() || (this->PickModeOn && this->PickModeOn()))
    {
      const int* position = interactor->GetEventPosition();
      this->Pick(position[0], position[1]);
      return;
    }
    this->Superclass::OnLeftButtonDown();
  }
};
vtkStandardNewMacro(InsideView::Style);

InsideView::InsideView(StudioDocument* document, QWidget* parent)
  : QVTKOpenGLNativeWidget(parent)
  , Document(document)
{
  this->setMinimumSize(200, 150);
  this->SetUpRenderers();

  // Navigation moves the observer: everything that follows it follows.
  vtkNew<Style> style;
  style->PickModeOn = [this]() { return this->PickMode; };
  style->Pick = [this](int column, int row) { Q_EMIT this->PixelPicked(column, row); };
  style->SetDefaultRenderer(this->ObserverRenderer);
  this->interactor()->SetInteractorStyle(style);
  vtkNew<vtkCallbackCommand> moved;
  moved->SetClientData(this);
  moved->SetCallback([](vtkObject*, unsigned long, void* clientData, void*) {
    auto* view = static_cast<InsideView*>(clientData);
    view->Interacting = true;
    view->Document->ObserverChanged();
    view->Interacting = false;
  });
  style->AddObserver(vtkCommand::InteractionEvent, moved);

  vtkNew<vtkCallbackCommand> rendered;
  rendered->SetClientData(this);
  rendered->SetCallback([](vtkObject*, unsigned long, void* clientData, void*) {
    auto* view = static_cast<InsideView*>(clientData);
    view->ReportPassErrors();
    if (view->CurrentBackend == GPU)
    {
      Q_EMIT view->ViewDrawn(view->RayTracePass->GetLastImageSampleDistance());
      // A still frame refined in pieces: the next piece once the events that
      // came meanwhile (a click, a key, the next slider value) are handled.
      if (!view->RayTracePass->GetRefinementComplete())
      {
        view->ScheduleRender();
      }
    }
  });
  this->ObserverRenderer->AddObserver(vtkCommand::EndEvent, rendered);

  QObject::connect(document, &StudioDocument::MetricChanged, this, &InsideView::ScheduleRender);
  QObject::connect(document, &StudioDocument::SceneChanged, this, &InsideView::ScheduleRender);
  QObject::connect(document, &StudioDocument::ObserverMoved, this, [this]() {
    // The trackball has drawn this view already; the CPU picture is redone.
    if (!this->Interacting || this->CurrentBackend == CPU)
    {
      this->ScheduleRender();
    }
  });
}

InsideView::~InsideView()
{
  this->Document->Jobs()->Cancel(this);
}

void InsideView::SetUpRenderers()
{
  vtkRenderWindow* window = this->renderWindow();
  window->SetNumberOfLayers(2);

  // Layer 0: the observer's renderer; its pass draws the whole view.
  this->RayTracePass->SetMetric(this->Document->Metric());
  this->RayTracePass->SetScene(this->Document->Scene());
  this->RayTracePass->SetIntegrationSettings(this->Document->RaySettings());
  this->RayTracePass->SetUseSceneSettings(this->Document->UseSceneSettings());
  // Still frames come in pieces (a coarse picture first, then finer ones),
  // so that the window answers between them instead of waiting for a whole
  // frame; Capture() finishes the picture.
  this->RayTracePass->ProgressiveRefinementOn();
  this->ObserverRenderer->SetPass(this->RayTracePass);
  this->ObserverRenderer->SetActiveCamera(this->Document->Observer());
  this->ObserverRenderer->SetLayer(0);
  window->AddRenderer(this->ObserverRenderer);

  // Layer 1: the CPU tracer's picture (CPU backend only), not interactive.
  this->ImageRenderer->SetLayer(1);
  this->ImageRenderer->InteractiveOff();
  this->ImageRenderer->AddActor(this->CpuImage);
  // The tracer's "Color" is float RGB in [0, 1], what the pass writes to the
  // framebuffer: shown as is (window 1, level 0.5), pixel for pixel.
  this->CpuImage->GetProperty()->SetColorWindow(1.0);
  this->CpuImage->GetProperty()->SetColorLevel(0.5);
  this->CpuImage->InterpolateOff();
  this->ImageRenderer->DrawOff();
  window->AddRenderer(this->ImageRenderer);
}

void InsideView::ReportPassErrors()
{
  if (this->CurrentBackend != GPU)
  {
    return;
  }
  const QString error = QString::fromUtf8(this->RayTracePass->GetLastError());
  if (error != this->Error)
  {
    this->Error = error;
    if (!error.isEmpty())
    {
      Q_EMIT this->RenderFailed(error);
    }
  }
}

void InsideView::SetBackend(Backend backend)
{
  if (backend == this->CurrentBackend)
  {
    return;
  }
  this->CurrentBackend = backend;
  // CPU: the observer's renderer only clears; the traced image is on top.
  this->ObserverRenderer->SetPass(backend == GPU ? this->RayTracePass.Get() : nullptr);
  this->ImageRenderer->SetDraw(backend == CPU);
  this->ScheduleRender();
}

void InsideView::SetSamplesPerPixel(int samples)
{
  this->Samples = std::max(1, samples);
  if (this->CurrentBackend == CPU)
  {
    this->ScheduleRender();
  }
}

void InsideView::ScheduleRender()
{
  if (!this->RenderPending)
  {
    this->RenderPending = true;
    QTimer::singleShot(0, this, [this]() {
      if (this->RenderPending)
      {
        this->RenderNow();
      }
    });
  }
}

void InsideView::RenderNow()
{
  this->RenderPending = false;
  this->RayTracePass->SetUseSceneSettings(this->Document->UseSceneSettings());
  if (this->CurrentBackend == CPU)
  {
    this->StartCpuTrace();
    this->renderWindow()->Render();
    return;
  }
  QElapsedTimer timer;
  timer.start();
  this->renderWindow()->Render();
  // Wait for the GPU so the time is the frame's, not the call's.
  if (auto* window = vtkGenericOpenGLRenderWindow::SafeDownCast(this->renderWindow()))
  {
    window->WaitForCompletion();
  }
  Q_EMIT this->FrameRendered(timer.nsecsElapsed() * 1e-6);
}

void InsideView::StartCpuTrace()
{
  int width, height;
  this->PixelSize(width, height);
  auto tracer = vtkSmartPointer<vtkRiemannCPURayTracer>::New();
  SetUpInsideViewRays(tracer.Get(), this->Document->MakeJobInputs(), width, height, true);
  tracer->SetSamplesPerPixel(this->Samples);
  auto timer = std::make_shared<QElapsedTimer>();
  timer->start();
  this->Document->Jobs()->Start(this, std::move(tracer), QStringLiteral("CPU render"),
    [this, timer](vtkAlgorithm* job, bool ok, const QString& error) {
      if (ok)
      {
        this->ShowCpuImage(vtkRiemannCPURayTracer::SafeDownCast(job)->GetOutput());
        Q_EMIT this->FrameRendered(timer->nsecsElapsed() * 1e-6);
      }
      else if (!error.isEmpty())
      {
        Q_EMIT this->RenderFailed(error);
      }
    });
}

void InsideView::ShowCpuImage(vtkImageData* image)
{
  if (this->CurrentBackend != CPU)
  {
    return;
  }
  vtkNew<vtkImageData> shown;
  shown->ShallowCopy(image);
  this->CpuImage->GetMapper()->SetInputData(shown);
  // Fit the picture to the viewport: a parallel camera looking at it.
  int dimensions[3];
  shown->GetDimensions(dimensions);
  vtkCamera* camera = this->ImageRenderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  const double cx = 0.5 * (dimensions[0] - 1), cy = 0.5 * (dimensions[1] - 1);
  camera->SetFocalPoint(cx, cy, 0.0);
  camera->SetPosition(cx, cy, 1000.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelScale(0.5 * dimensions[1]);
  this->ImageRenderer->ResetCameraClippingRange();
  this->renderWindow()->Render();
}

void InsideView::SetMoving(bool moving)
{
  vtkRenderWindowInteractor* interactor = this->interactor();
  this->renderWindow()->SetDesiredUpdateRate(
    moving ? interactor->GetDesiredUpdateRate() : interactor->GetStillUpdateRate());
  if (!moving)
  {
    this->ScheduleRender(); // the full frame
  }
}

QImage InsideView::Capture()
{
  // A full frame, even while something moves the view or a still frame is
  // being refined (the rays already traced are kept; larger pieces now).
  vtkRenderWindow* window = this->renderWindow();
  const double rate = window->GetDesiredUpdateRate();
  const double still = this->interactor()->GetStillUpdateRate();
  vtkRiemannRayTracePass* pass = this->RayTracePass;
  const bool gpu = this->CurrentBackend == GPU;
  if (this->RenderPending || rate > still || (gpu && !pass->GetRefinementComplete()))
  {
    window->SetDesiredUpdateRate(still);
    const double pieces = pass->GetRefinementSeconds();
    pass->SetRefinementSeconds(10.0);
    this->RenderNow();
    for (int guard = 0; gpu && !pass->GetRefinementComplete() && guard < 64; ++guard)
    {
      this->RenderNow(); // the finer lattices, up to 10 s a piece
    }
    pass->SetRefinementSeconds(pieces);
    window->SetDesiredUpdateRate(rate);
  }
  this->RenderPending = false;
  return this->grabFramebuffer();
}

void InsideView::PixelSize(int& width, int& height)
{
  const int* size = this->renderWindow()->GetSize();
  width = size[0];
  height = size[1];
}

void InsideView::PickPixel(int column, int row)
{
  Q_EMIT this->PixelPicked(column, row);
}

void InsideView::resizeEvent(QResizeEvent* event)
{
  QVTKOpenGLNativeWidget::resizeEvent(event);
  const qreal ratio = this->devicePixelRatioF();
  this->Document->SetViewSize(
    static_cast<int>(event->size().width() * ratio), static_cast<int>(event->size().height() * ratio));
}
}
}
