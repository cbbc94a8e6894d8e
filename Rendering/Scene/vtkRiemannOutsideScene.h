/**
 * @class   vtkRiemannOutsideScene
 * @brief   The outside view's picture: the scene as ordinary geometry, the
 * observer with its view frustum, the observer's curved rays, and the
 * camera that looks at them.
 *
 * One builder for every outside view (`riemann render --bundle` and
 * riemann-studio's outside view), so both show the same thing the same way:
 *
 * - the scene (vtkRiemannSceneSource) translucent, in its material colours,
 *   so a ray's colour in the inside view names the object it ends on;
 * - the observer: a white ball at the inside camera's position and its view
 *   frustum (four edges and the rim, as long as FrustumLength, with the
 *   inside view's AspectRatio);
 * - optionally rays (vtkRiemannRayBundle's output) as tubes: a ray that hit
 *   is coloured by its cell array `EndColor`, one that escaped light grey;
 * - PlaceCamera(): the scene and the observer framed from above and to the
 *   side of the observer's own view, so the bending of the rays shows. The
 *   scene's planes (large square patches) are left out of the frame unless
 *   the scene has nothing else: they would shrink everything to a speck.
 *
 * Sizes follow the scene (SceneSize: the largest side of the framed box), so
 * the picture reads the same at any scale. Call Update() after the scene,
 * the observer or the rays changed; AddToRenderer() adds the actors once.
 */
#ifndef vtkRiemannOutsideScene_h
#define vtkRiemannOutsideScene_h

#include "RiemannRenderingSceneModule.h" // For export macro
#include "vtkNew.h"                      // For the members
#include "vtkObject.h"

class vtkActor;
class vtkCamera;
class vtkPolyData;
class vtkRenderer;
class vtkRiemannScene;
class vtkRiemannSceneSource;
class vtkSphereSource;
class vtkTubeFilter;

class RIEMANNRENDERINGSCENE_EXPORT vtkRiemannOutsideScene : public vtkObject
{
public:
  static vtkRiemannOutsideScene* New();
  vtkTypeMacro(vtkRiemannOutsideScene, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The scene drawn (default: the built-in default scene).
  virtual void SetScene(vtkRiemannScene* scene);
  vtkRiemannScene* GetScene();
  ///@}

  ///@{
  /// The observer: the inside view's camera (required for the eye, the
  /// frustum and PlaceCamera).
  virtual void SetObserver(vtkCamera* camera);
  vtkGetObjectMacro(Observer, vtkCamera);
  ///@}

  ///@{
  /// The inside view's width over its height: the frustum's. Default 4/3.
  vtkSetClampMacro(AspectRatio, double, 1e-3, 1e3);
  vtkGetMacro(AspectRatio, double);
  ///@}

  ///@{
  /// Rays drawn as tubes (lines with cell arrays `Hit` and `EndColor`, as
  /// vtkRiemannRayBundle makes them); null (the default) for none.
  virtual void SetRays(vtkPolyData* rays);
  vtkGetObjectMacro(Rays, vtkPolyData);
  ///@}

  /// Bring the geometry up to date with the scene, observer and rays.
  void Update();

  /// Add the actors to `renderer`, give it the outside view's background
  /// (a dark gradient), and Update().
  void AddToRenderer(vtkRenderer* renderer);

  /// Frame the scene and the observer in `renderer`'s active camera, seen
  /// from above and to the side of the observer's view.
  void PlaceCamera(vtkRenderer* renderer);

  /// The box PlaceCamera frames, without the observer: the scene's bounds
  /// without its planes (all of it when it has nothing but planes; the cube
  /// [-1, 1]^3 when it is empty).
  void GetFramedBounds(double bounds[6]);

  /// The largest side of GetFramedBounds, at least 1: the unit of the
  /// picture's sizes.
  double GetSceneSize();

  /// The frustum's length: a fifth of SceneSize. The eye's radius is 0.06 of
  /// it, the rays' tubes 0.015 of it.
  double GetFrustumLength();

  ///@{
  /// What is drawn (for a caller's own styling and picking: the eye and the
  /// frustum are not pickable).
  vtkActor* GetSceneActor();
  vtkActor* GetEyeActor();
  vtkActor* GetFrustumActor();
  vtkActor* GetRaysActor();
  /// The frustum's lines: point 0 the eye, then the four far corners.
  vtkPolyData* GetFrustum();
  ///@}

protected:
  vtkRiemannOutsideScene();
  ~vtkRiemannOutsideScene() override;

  vtkCamera* Observer = nullptr;
  vtkPolyData* Rays = nullptr;
  double AspectRatio = 4.0 / 3.0;

private:
  vtkRiemannOutsideScene(const vtkRiemannOutsideScene&) = delete;
  void operator=(const vtkRiemannOutsideScene&) = delete;

  // Update's steps.
  void UpdateObserver(double frustumLength);
  void UpdateRays(double frustumLength);
  /// GetFramedBounds' walk over the scene's cells, into Framed.
  void ComputeFramedBounds(vtkPolyData* geometry);

  double Framed[6] = { -1, 1, -1, 1, -1, 1 };
  vtkMTimeType FramedGeometryTime = 0;

  vtkNew<vtkRiemannSceneSource> SceneGeometry;
  vtkNew<vtkActor> SceneActor;
  vtkNew<vtkSphereSource> Eye;
  vtkNew<vtkActor> EyeActor;
  vtkNew<vtkPolyData> FrustumLines;
  vtkNew<vtkActor> FrustumActor;
  vtkNew<vtkPolyData> ColouredRays;
  vtkNew<vtkTubeFilter> RayTubes;
  vtkNew<vtkActor> RaysActor;
};

#endif
