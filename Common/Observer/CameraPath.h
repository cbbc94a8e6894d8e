/**
 * @file CameraPath.h
 * @brief A flight of the observer through curved space: the frames of a
 * film where the camera moves along a geodesic or along a spline through key
 * positions, its view frame carried along the path by the metric's
 * connection.
 *
 * Along a geodesic the frame is parallel-transported (D_s X = 0): "straight
 * ahead" is the geodesic's own velocity, which the geodesic transports, and
 * the up and right vectors keep their angles to it, so the horizon does not
 * spin. Along a spline, which is not a geodesic, the forward vector must stay
 * the path's tangent T, so up and right are Fermi-Walker transported:
 *
 *   D_s X = g(X, T) A - g(X, A) T,   A = D_s T,
 *
 * the transport that turns X only as much as the tangent turns (for a
 * geodesic A = 0 and it is parallel transport). Both keep every g-inner
 * product of the frame: a frame g-orthonormal at the start stays so along
 * the path, up to the integration's error, without re-orthonormalising.
 *
 * The frames are evenly spaced in g-arc length (constant speed in the
 * curved space). Integration: classical Runge-Kutta 4 on the frame's
 * transport equations in arc length, with steps of at most Step.
 */
#ifndef RiemannCameraPath_h
#define RiemannCameraPath_h

#include "Metric.h"
#include "ObserverCamera.h"
#include "RiemannCommonObserverExport.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace riemann
{
/// Public numbering (JSON "path", VTK ivar): do not reorder.
enum class CameraPathKind : int
{
  /// The observer flies along the geodesic it looks along.
  Geodesic = 0,
  /// The observer flies through key positions on a cubic spline.
  Spline = 1
};

/// "geodesic", "spline".
RIEMANNCOMMONOBSERVER_EXPORT const char* CameraPathKindName(CameraPathKind kind);

struct CameraPathSettings
{
  CameraPathKind Kind = CameraPathKind::Geodesic;
  /**
   * The first frame. Geodesic: the observer starts at Position looking at
   * LookAt and flies that way. Spline: the path starts at the first key and
   * looks along the spline's tangent there; only ViewUp is used.
   */
  CameraSettings Start;
  /// Geodesic: the g-length flown.
  double Length = 1.0;
  /// Spline: the key positions (at least 2), passed in order.
  std::vector<Vec3> Keys;
  /// Frames of the film, the first and last included (at least 1).
  int Frames = 60;
  /// Largest integration step, in g-arc length.
  double Step = 0.002;
};

/// One frame: where the observer is and its view frame (coordinate vectors,
/// g-orthonormal up to the transport's error).
struct CameraFrame
{
  Vec3 Position = Vec3::Zero();
  Vec3 Forward = Vec3::UnitX();
  Vec3 Up = Vec3::UnitZ();
  Vec3 Right = Vec3::UnitY();
  /// g-arc length from the first frame.
  double ArcLength = 0.0;
};

/// Bad settings, a degenerate metric on the way, or a cancelled flight.
class RIEMANNCOMMONOBSERVER_EXPORT CameraPathError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/**
 * The Frames frames of the flight. `progress(fraction)` is called after each
 * frame; returning false cancels (CameraPathError "cancelled"). Throws
 * CameraPathError, saying why, for bad settings (fewer than 2 keys, coinciding
 * keys, a length or step that is not positive and finite) or where the metric
 * is degenerate on the path.
 */
RIEMANNCOMMONOBSERVER_EXPORT std::vector<CameraFrame> ComputeCameraPath(const Metric& metric,
  const CameraPathSettings& settings, const std::function<bool(double)>& progress = {});

/// The camera settings that show frame `frame` (LookAt one unit ahead along
/// Forward), for ObserverCamera or a vtkCamera; the rest from `base`.
RIEMANNCOMMONOBSERVER_EXPORT CameraSettings CameraSettingsOf(
  const CameraFrame& frame, const CameraSettings& base);
} // namespace riemann

#endif
