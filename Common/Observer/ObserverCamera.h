/**
 * @file ObserverCamera.h
 * @brief The observer of the inside view: a camera in a curved space.
 *
 * The observer sits at Position and looks towards LookAt. Its view frame is
 * made orthonormal in g at the observer (Gram-Schmidt with g: forward, then
 * up, then right), and every pixel's ray leaves with unit speed in g: the
 * paper's viewing sphere. Without this the picture would be sheared wherever
 * g is not the identity at the eye (MATH.md).
 *
 * The GPU pass, the CPU tracer and the ray-bundle filter all use this class,
 * so the same pixel gives the same initial ray everywhere.
 */
#ifndef RiemannObserverCamera_h
#define RiemannObserverCamera_h

#include "Metric.h"
#include "RiemannCommonObserverExport.h"

#include <string>

namespace riemann
{
enum class Projection : int
{
  Perspective = 0,
  /// 360 x 180 degrees: x is longitude about the up axis, y latitude.
  Equirectangular = 1
};

/**
 * The observer's camera. Plain defaults: the declared ones, with the valid
 * values, units and help, are vtkRiemannPictureSettings's
 * (Rendering/Scene/vtkRiemannPictureSettings.settings.json; a test keeps
 * them equal).
 */
struct CameraSettings
{
  Vec3 Position = Vec3(0, 0, 5);
  Vec3 LookAt = Vec3(0, 0, 0);
  Vec3 ViewUp = Vec3(0, 1, 0);
  /// Vertical field of view in degrees (perspective only).
  double ViewAngle = 60.0;
  Projection Mode = Projection::Perspective;
};

/**
 * Why a camera at `position` looking at `lookAt` with up `viewUp` defines no
 * view ("the camera is at the point it looks at", "the view up is along the
 * view direction"); "" when it does.
 */
RIEMANNCOMMONOBSERVER_EXPORT std::string CheckCameraView(
  const Vec3& position, const Vec3& lookAt, const Vec3& viewUp);

class RIEMANNCOMMONOBSERVER_EXPORT ObserverCamera
{
public:
  /**
   * Build the g-orthonormal frame at the observer. Throws std::runtime_error
   * when the metric is degenerate at the observer or the view direction is
   * zero or parallel to the view up.
   */
  ObserverCamera(const Metric& metric, const CameraSettings& settings);

  /// g-orthonormal frame at the observer: Forward, Up, Right (coordinate vectors).
  const Vec3& GetForward() const { return this->Forward; }
  const Vec3& GetUp() const { return this->Up; }
  const Vec3& GetRight() const { return this->Right; }
  const CameraSettings& GetSettings() const { return this->Settings; }

  /**
   * Unit-speed initial velocity of the ray through normalised image
   * coordinates (x, y) in [-1, 1]^2 (x right, y up; the pixel centre of
   * column i of W is x = (2 i + 1) / W - 1). `aspect` is width / height.
   */
  Vec3 Direction(double x, double y, double aspect) const;

  /// Direction() for the centre of pixel (column, row) of a width x height
  /// image, row 0 at the bottom (OpenGL's convention).
  Vec3 PixelDirection(int column, int row, int width, int height) const;

private:
  CameraSettings Settings;
  Vec3 Forward;
  Vec3 Up;
  Vec3 Right;
};
} // namespace riemann

#endif
