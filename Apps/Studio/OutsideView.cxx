#include "OutsideView.h"

#include "ItemDisplay.h"

#include "ColorMaps.h"
#include "PipelineItem.h"
#include "StudioDocument.h"

#include "vtkRiemannScene.h"
#include "vtkRiemannOutsideScene.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellPicker.h"
#include "vtkCellArray.h"
#include "vtkHandleWidget.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkMath.h"
#include "vtkPointHandleRepresentation3D.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTubeFilter.h"

#include <QTimer>

#include <algorithm>
#include <cmath>

namespace riemann
{
namespace studio
{
namespace
{
void SetUpActor(vtkActor* actor, vtkAlgorithmOutput* input, const double color[3])
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(input);
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
}

}

OutsideView::OutsideView(StudioDocument* document, QWidget* parent)
  : QVTKOpenGLNativeWidget(parent)
  , Document(document)
{
  this->setMinimumSize(200, 150);
  this->renderWindow()->AddRenderer(this->SceneRenderer);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  this->interactor()->SetInteractorStyle(style);

  // The scene, the observer's eye (a handle to drag) and its view frustum:
  // the outside view's picture as `riemann render --bundle` draws it.
  this->Picture->SetScene(document->Scene());
  this->Picture->SetObserver(document->Observer());
  this->Picture->AddToRenderer(this->SceneRenderer);
  vtkNew<vtkPointHandleRepresentation3D> handle;
  handle->AllOff();
  handle->SetHandleSize(12);
  this->EyeHandle->SetInteractor(this->interactor());
  this->EyeHandle->SetRepresentation(handle);
  this->EyeHandle->SetCurrentRenderer(this->SceneRenderer);
  vtkNew<vtkCallbackCommand> dragged;
  dragged->SetClientData(this);
  dragged->SetCallback([](vtkObject*, unsigned long, void* clientData, void*) {
    static_cast<OutsideView*>(clientData)->MoveObserverToHandle();
  });
  this->EyeHandle->AddObserver(vtkCommand::InteractionEvent, dragged);

  // The picked ray: a tube, and a ball where it ended.
  this->RayTube->SetInputData(this->Ray);
  this->RayTube->SetNumberOfSides(8);
  SetUpActor(this->RayActor, this->RayTube->GetOutputPort(), PickedRayColor);
  SetUpActor(this->RayEndActor, this->RayEnd->GetOutputPort(), PickedRayColor);
  // One colour: the bundle's arrays on the ray must not colour it.
  this->RayActor->GetMapper()->ScalarVisibilityOff();
  this->RayEnd->SetRadius(0.06);
  this->RayActor->VisibilityOff();
  this->RayEndActor->VisibilityOff();
  this->SceneRenderer->AddActor(this->RayActor);
  this->SceneRenderer->AddActor(this->RayEndActor);

  // Ctrl+click picks a point; any other click goes on to the camera.
  this->PickCommand->SetClientData(this);
  this->PickCommand->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void*) {
    auto* interactor = static_cast<vtkRenderWindowInteractor*>(caller);
    if (!interactor->GetControlKey())
    {
      return;
    }
    auto* self = static_cast<OutsideView*>(clientData);
    const int* position = interactor->GetEventPosition();
    self->PickPoint(position[0], position[1]);
    // Taken: the interactor style (a lower priority) does not rotate the camera.
    self->PickCommand->SetAbortFlag(1);
  });
  this->interactor()->AddObserver(vtkCommand::LeftButtonPressEvent, this->PickCommand, 1.0);

  for (const auto& item : document->Items())
  {
    this->AddItem(item.get());
  }
  QObject::connect(document, &StudioDocument::ItemAdded, this, &OutsideView::AddItem);
  QObject::connect(document, &StudioDocument::ItemRemoved, this, &OutsideView::RemoveItem);
  QObject::connect(document, &StudioDocument::ObserverMoved, this, [this]() {
    this->UpdateObserver();
    this->ScheduleRender();
  });
  QObject::connect(document, &StudioDocument::SceneChanged, this, [this]() {
    this->UpdateObserver();
    this->ResetCamera();
    this->ScheduleRender();
  });
  this->UpdateObserver();
  this->ResetCamera();
  this->EyeHandle->On();
}

OutsideView::~OutsideView()
{
  this->EyeHandle->Off();
  this->EditKeys({}, nullptr);
}

void OutsideView::EditKeys(const Keys& keys, std::function<void(const Keys&)> moved)
{
  this->KeysMoved = std::move(moved);
  // No handles before or after (every other selection): nothing to draw.
  if (keys.empty() && this->KeyHandles.empty())
  {
    return;
  }
  // Same count: the handles move (a drag's end must not rebuild the widget
  // it came from); else they are made again.
  if (keys.size() != this->KeyHandles.size())
  {
    for (const auto& handle : this->KeyHandles)
    {
      handle->Off();
    }
    this->KeyHandles.clear();
    for (size_t k = 0; k < keys.size(); ++k)
    {
      vtkNew<vtkPointHandleRepresentation3D> representation;
      representation->SetHandleSize(10);
      representation->GetProperty()->SetColor(0.3, 0.85, 0.95);
      representation->GetSelectedProperty()->SetColor(1.0, 1.0, 1.0);
      auto handle = vtkSmartPointer<vtkHandleWidget>::New();
      handle->SetInteractor(this->interactor());
      handle->SetRepresentation(representation);
      handle->SetCurrentRenderer(this->SceneRenderer);
      vtkNew<vtkCallbackCommand> released;
      released->SetClientData(this);
      released->SetCallback([](vtkObject*, unsigned long, void* clientData, void*) {
        static_cast<OutsideView*>(clientData)->KeysDragged();
      });
      handle->AddObserver(vtkCommand::EndInteractionEvent, released);
      this->KeyHandles.push_back(handle);
    }
  }
  for (size_t k = 0; k < keys.size(); ++k)
  {
    double position[3] = { keys[k][0], keys[k][1], keys[k][2] };
    vtkHandleRepresentation::SafeDownCast(this->KeyHandles[k]->GetRepresentation())
      ->SetWorldPosition(position);
    this->KeyHandles[k]->On();
  }
  this->ScheduleRender();
}

void OutsideView::KeysDragged()
{
  if (!this->KeysMoved)
  {
    return;
  }
  Keys keys;
  for (const auto& handle : this->KeyHandles)
  {
    double position[3];
    vtkHandleRepresentation::SafeDownCast(handle->GetRepresentation())->GetWorldPosition(position);
    keys.push_back({ position[0], position[1], position[2] });
  }
  // A copy: the callback may edit the keys again (and so this view's handles).
  const std::function<void(const Keys&)> moved = this->KeysMoved;
  moved(keys);
}

void OutsideView::DragKey(int key, const double position[3])
{
  if (key < 0 || key >= this->NumberOfKeyHandles())
  {
    return;
  }
  double moved[3] = { position[0], position[1], position[2] };
  vtkHandleRepresentation::SafeDownCast(this->KeyHandles[static_cast<size_t>(key)]->GetRepresentation())
    ->SetWorldPosition(moved);
  this->KeysDragged();
}

void OutsideView::AddItem(PipelineItem* item)
{
  auto display = std::make_unique<ItemDisplay>(*item);
  display->Show(*item);
  this->SceneRenderer->AddViewProp(display->Prop());
  this->SceneRenderer->AddViewProp(display->ScalarBar());
  ItemDisplay* shown = display.get();
  this->Displays[item] = std::move(display);
  // Redrawn at once (the panel and tests read it back), rendered once the event is handled.
  auto redraw = [this, item, shown]() {
    shown->Show(*item);
    this->ScheduleRender();
  };
  QObject::connect(item, &PipelineItem::ResultChanged, this, redraw);
  QObject::connect(item, &PipelineItem::VisibilityChanged, this, redraw);
  QObject::connect(item, &PipelineItem::SettingsChanged, this, redraw);
  QObject::connect(item, &PipelineItem::DisplayChanged, this, redraw);
  this->ScheduleRender();
}

void OutsideView::RemoveItem(PipelineItem* item)
{
  const auto found = this->Displays.find(item);
  if (found != this->Displays.end())
  {
    this->SceneRenderer->RemoveViewProp(found->second->Prop());
    this->SceneRenderer->RemoveViewProp(found->second->ScalarBar());
    this->Displays.erase(found);
  }
  QObject::disconnect(item, nullptr, this, nullptr);
  this->ScheduleRender();
}

ItemDisplay* OutsideView::DisplayOf(const PipelineItem* item) const
{
  const auto found = this->Displays.find(item);
  return found == this->Displays.end() ? nullptr : found->second.get();
}

void OutsideView::UpdateObserver()
{
  this->Picture->SetAspectRatio(
    static_cast<double>(this->Document->ViewWidth()) / std::max(1, this->Document->ViewHeight()));
  this->Picture->Update();
  if (!this->MovingEye)
  {
    vtkHandleRepresentation::SafeDownCast(this->EyeHandle->GetRepresentation())
      ->SetWorldPosition(this->Document->Observer()->GetPosition());
  }
}

void OutsideView::MoveObserverToHandle()
{
  double target[3];
  vtkHandleRepresentation::SafeDownCast(this->EyeHandle->GetRepresentation())
    ->GetWorldPosition(target);
  vtkCamera* camera = this->Document->Observer();
  double eye[3], focal[3];
  camera->GetPosition(eye);
  camera->GetFocalPoint(focal);
  // Move eye and look-at point together: the view direction is kept.
  for (int i = 0; i < 3; ++i)
  {
    focal[i] += target[i] - eye[i];
  }
  this->MovingEye = true;
  camera->SetPosition(target);
  camera->SetFocalPoint(focal);
  this->Document->ObserverChanged();
  this->MovingEye = false;
}

void OutsideView::ResetCamera()
{
  this->Picture->PlaceCamera(this->SceneRenderer);
}

void OutsideView::ScheduleRender()
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

void OutsideView::RenderNow()
{
  this->RenderPending = false;
  this->renderWindow()->Render();
}

QImage OutsideView::Capture()
{
  if (this->RenderPending)
  {
    this->RenderNow();
  }
  return this->grabFramebuffer();
}

void OutsideView::ShowPickedRay(vtkPolyData* ray)
{
  const bool shown = ray && ray->GetNumberOfPoints() > 0;
  if (shown)
  {
    this->Ray->ShallowCopy(ray);
    double end[3];
    ray->GetPoint(ray->GetNumberOfPoints() - 1, end);
    this->RayEnd->SetCenter(end);
    // Sized with the scene, like the frustum: visible at any scale.
    const double length = this->Picture->GetFrustumLength();
    this->RayEnd->SetRadius(0.04 * length);
    this->RayTube->SetRadius(0.012 * length);
  }
  else
  {
    this->Ray->Initialize();
  }
  this->RayActor->SetVisibility(shown);
  this->RayEndActor->SetVisibility(shown);
  this->ScheduleRender();
}

vtkPolyData* OutsideView::PickedRay() const
{
  return this->Ray;
}

void OutsideView::PickPoint(int x, int y)
{
  double point[3];
  vtkNew<vtkCellPicker> picker;
  picker->SetTolerance(0.002);
  if (picker->Pick(x, y, 0.0, this->SceneRenderer))
  {
    picker->GetPickPosition(point);
  }
  else
  {
    // Nothing drawn there: the plane through the focal point, facing the camera.
    double focal[4];
    this->SceneRenderer->GetActiveCamera()->GetFocalPoint(focal);
    focal[3] = 1.0;
    this->SceneRenderer->SetWorldPoint(focal);
    this->SceneRenderer->WorldToDisplay();
    const double depth = this->SceneRenderer->GetDisplayPoint()[2];
    this->SceneRenderer->SetDisplayPoint(x, y, depth);
    this->SceneRenderer->DisplayToWorld();
    const double* world = this->SceneRenderer->GetWorldPoint();
    for (int a = 0; a < 3; ++a)
    {
      point[a] = world[a] / world[3];
    }
  }
  Q_EMIT this->PointPicked(point[0], point[1], point[2]);
}

vtkPolyData* OutsideView::Frustum() const
{
  return this->Picture->GetFrustum();
}
}
}
