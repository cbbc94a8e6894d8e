/**
 * @class   vtkRiemannPictureSettings
 * @brief   The settings of a picture of the inside view: the observer's
 *          camera, the picture's size and samples, and which renderer draws it.
 *
 * What `riemann render` takes as options, a scene's "camera" block, the
 * studio's inside-view form and a project's "observer" and "inside" objects
 * all are these properties, declared once with their defaults, ranges, units
 * and help in vtkRiemannPictureSettings.settings.json
 * (Documentation/Settings.md):
 *
 * - Position, LookAt, ViewUp, ViewAngle: the observer's camera (vtkCamera's
 *   Position, FocalPoint, ViewUp and ViewAngle: ApplyTo(), SetFromCamera()).
 *   The view angle is in (0, 179] degrees, because vtkCamera clamps larger
 *   ones silently.
 * - Projection: PERSPECTIVE or EQUIRECTANGULAR (riemann::Projection's numbering).
 * - Width, Height: the picture's size in pixels.
 * - SamplesPerPixel: stratified rays per pixel of vtkRiemannCPURayTracer.
 * - Backend: GPU (vtkRiemannRayTracePass) or CPU (vtkRiemannCPURayTracer).
 * - GPUPath: the pass's shader path (vtkRiemannRayTracePass::GPUPath's numbering).
 *
 * Values are stored as given; CheckSettings() names the first one outside
 * its declared range, or a camera that defines no view.
 *
 * @code{.py}
 * picture = riemann.vtkRiemannPictureSettings()
 * picture.SetPosition(0, 0, 8)
 * picture.ApplyTo(renderer.GetActiveCamera())
 * @endcode
 */
#ifndef vtkRiemannPictureSettings_h
#define vtkRiemannPictureSettings_h

#include "RiemannRenderingSceneModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <string> // For std::string

class vtkCamera;

namespace riemann
{
struct CameraSettings;
}

class RIEMANNRENDERINGSCENE_EXPORT vtkRiemannPictureSettings : public vtkObject
{
public:
  static vtkRiemannPictureSettings* New();
  vtkTypeMacro(vtkRiemannPictureSettings, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Projections (riemann::Projection's numbering).
  enum Projections
  {
    PERSPECTIVE = 0,
    EQUIRECTANGULAR = 1
  };
  /// Renderers of the inside view.
  enum Backends
  {
    GPU = 0,
    CPU = 1
  };
  /// The GPU pass's shader paths (vtkRiemannRayTracePass's numbering).
  enum GPUPaths
  {
    GPU_PATH_AUTO = 0,
    GPU_PATH_FRAGMENT = 1,
    GPU_PATH_COMPUTE = 2
  };

  ///@{
  /// Where the observer stands. Default (0, 0, 5).
  vtkSetVector3Macro(Position, double);
  vtkGetVector3Macro(Position, double);
  ///@}

  ///@{
  /// The point the observer looks at. Default the origin.
  vtkSetVector3Macro(LookAt, double);
  vtkGetVector3Macro(LookAt, double);
  ///@}

  ///@{
  /// Up in the picture (not along the view). Default (0, 1, 0).
  vtkSetVector3Macro(ViewUp, double);
  vtkGetVector3Macro(ViewUp, double);
  ///@}

  ///@{
  /// Vertical field of view of a perspective picture, in degrees. Default 60.
  vtkSetMacro(ViewAngle, double);
  vtkGetMacro(ViewAngle, double);
  ///@}

  ///@{
  /// PERSPECTIVE (the default) or EQUIRECTANGULAR.
  vtkSetClampMacro(Projection, int, PERSPECTIVE, EQUIRECTANGULAR);
  vtkGetMacro(Projection, int);
  ///@}

  ///@{
  /// The picture's size in pixels. Defaults 640 and 480.
  vtkSetMacro(Width, int);
  vtkGetMacro(Width, int);
  vtkSetMacro(Height, int);
  vtkGetMacro(Height, int);
  ///@}

  ///@{
  /// Rays per pixel of the CPU renderer. Default 1.
  vtkSetMacro(SamplesPerPixel, int);
  vtkGetMacro(SamplesPerPixel, int);
  ///@}

  ///@{
  /// The renderer: GPU (the default) or CPU.
  vtkSetClampMacro(Backend, int, GPU, CPU);
  vtkGetMacro(Backend, int);
  ///@}

  ///@{
  /// The GPU pass's shader path: GPU_PATH_AUTO (the default), _FRAGMENT or _COMPUTE.
  vtkSetClampMacro(GPUPath, int, GPU_PATH_AUTO, GPU_PATH_COMPUTE);
  vtkGetMacro(GPUPath, int);
  ///@}

  /**
   * "" when every setting is in its declared range and the camera defines a
   * view; otherwise one sentence naming the first that is not ("ViewAngle
   * is 180: expected a number above 0 and at most 179 (degrees)", "the
   * camera is at the point it looks at").
   */
  std::string CheckSettings() const;

  /// Give `camera` the observer's position, focal point, view up and view angle.
  void ApplyTo(vtkCamera* camera) const;

  /// Take the observer's settings from `camera` (the others keep their values).
  void SetFromCamera(vtkCamera* camera);

  /// True for the settings ApplyTo() gives a vtkCamera (Position, LookAt,
  /// ViewUp, ViewAngle): the observer's, which a project stores per camera.
  static bool IsCameraSetting(const std::string& name);

  /// The observer as the core's camera settings (position, look-at, up, angle, projection).
  VTK_WRAPEXCLUDE riemann::CameraSettings GetCameraSettings() const;

  /// Copy every setting of `other` (nothing when it is null).
  void DeepCopy(vtkRiemannPictureSettings* other);

protected:
  vtkRiemannPictureSettings();
  ~vtkRiemannPictureSettings() override = default;

  double Position[3];
  double LookAt[3];
  double ViewUp[3];
  double ViewAngle;
  int Projection;
  int Width;
  int Height;
  int SamplesPerPixel;
  int Backend;
  int GPUPath;

private:
  vtkRiemannPictureSettings(const vtkRiemannPictureSettings&) = delete;
  void operator=(const vtkRiemannPictureSettings&) = delete;
};

#endif
