/**
 * @file OutsideView.h
 * @brief The outside view: ordinary (Euclidean) VTK rendering of the scene
 * and the observer as `riemann render --bundle` draws them
 * (vtkRiemannOutsideScene: the scene translucent, an eye with its view
 * frustum, the same camera placement), every pipeline item, and the picked
 * ray.
 *
 * The view owns what it draws for each item (ItemDisplay): one display per
 * output, chosen by the output's data type, redrawn when the item's
 * results, settings or visibility change.
 *
 * The eye is a handle: dragging it moves the observer (position and look-at
 * point together), so the inside view follows; navigating the inside view
 * moves the eye here. Ctrl+click picks a point (on what is drawn there, else
 * on the plane through the camera's focal point): PointPicked, which the
 * selected item may take (the connector's ends, the distance field's seed).
 */
#ifndef RiemannStudio_OutsideView_h
#define RiemannStudio_OutsideView_h

#include "QVTKOpenGLNativeWidget.h"

#include "vtkCallbackCommand.h" // For vtkNew<vtkCallbackCommand>
#include "vtkNew.h"
#include "vtkSmartPointer.h" // For the key handles
#include "vtkTubeFilter.h" // For vtkNew<vtkTubeFilter>

#include <QImage>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <vector>

class vtkActor;
class vtkHandleWidget;
class vtkPolyData;
class vtkRenderer;
class vtkRiemannOutsideScene;
class vtkSphereSource;

namespace riemann
{
namespace studio
{
class ItemDisplay;
class PipelineItem;
class StudioDocument;

class OutsideView : public QVTKOpenGLNativeWidget
{
  Q_OBJECT
public:
  explicit OutsideView(StudioDocument* document, QWidget* parent = nullptr);
  ~OutsideView() override;

  vtkRenderer* Renderer() const { return this->SceneRenderer; }
  /// Frame the scene and the observer from above and to the side.
  void ResetCamera();
  void RenderNow();
  /// Draw once the current event has been handled: many changes in a row
  /// (a project opening, a slider dragged) draw one frame.
  void ScheduleRender();
  /// The picture on screen (drawn first if a render is pending).
  QImage Capture();

  /// Show `ray` (a polyline; null hides it) and a marker at its end.
  void ShowPickedRay(vtkPolyData* ray);
  /// What is shown for the picked ray (empty before a pick).
  vtkPolyData* PickedRay() const;
  /// The observer's frustum as drawn (for tests and inspection).
  vtkPolyData* Frustum() const;

  /**
   * The point under display position (x, y) (pixels, origin at the bottom
   * left): on the nearest drawn geometry, else on the plane through the
   * focal point facing the camera. Emits PointPicked. Ctrl+click calls it.
   */
  void PickPoint(int x, int y);

  ///@{
  /**
   * Key positions edited in this view (a camera path's): a handle at each of
   * `keys`, dragged with the mouse; when a drag ends, `moved` gets every
   * key's position. No keys hides the handles.
   */
  using Keys = std::vector<std::array<double, 3>>;
  void EditKeys(const Keys& keys, std::function<void(const Keys&)> moved);
  int NumberOfKeyHandles() const { return static_cast<int>(this->KeyHandles.size()); }
  /// Moves handle `key` to `position` as a drag ending there would (tests).
  void DragKey(int key, const double position[3]);
  /// What the view draws for `item` (null for an item not in the document).
  ItemDisplay* DisplayOf(const PipelineItem* item) const;
  ///@}

Q_SIGNALS:
  void PointPicked(double x, double y, double z);

private:
  void AddItem(PipelineItem* item);
  void RemoveItem(PipelineItem* item);
  void UpdateObserver();
  void MoveObserverToHandle();
  void KeysDragged();

  StudioDocument* Document;
  vtkNew<vtkRenderer> SceneRenderer;
  /// The scene, the observer's eye and frustum (Rendering/Scene).
  vtkNew<vtkRiemannOutsideScene> Picture;
  vtkNew<vtkHandleWidget> EyeHandle;
  vtkNew<vtkPolyData> Ray;
  vtkNew<vtkTubeFilter> RayTube;
  vtkNew<vtkActor> RayActor;
  vtkNew<vtkSphereSource> RayEnd;
  vtkNew<vtkActor> RayEndActor;
  vtkNew<vtkCallbackCommand> PickCommand;
  std::vector<vtkSmartPointer<vtkHandleWidget>> KeyHandles;
  std::function<void(const Keys&)> KeysMoved;
  /// The displays of the document's items.
  std::map<const PipelineItem*, std::unique_ptr<ItemDisplay>> Displays;
  bool MovingEye = false;
  bool RenderPending = false;
};
}
}

#endif
