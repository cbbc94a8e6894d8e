/**
 * @file CameraPathFile.h
 * @brief The JSON file of a camera path (`riemann render --camera-path`,
 * riemann-studio's Export Animation, vtkRiemannCameraPath), read and written
 * with the same keys as the scene's camera block:
 *
 *   {"path": "geodesic", "position": [x,y,z], "look_at": [x,y,z],
 *    "view_up": [x,y,z], "length": L}
 *   {"path": "spline", "keys": [[x,y,z], [x,y,z], ...], "view_up": [x,y,z]}
 *
 * optional: "step" (largest integration step, g-arc length; default 0.002),
 * "fov" (degrees), "time": t or [t0, t1] (the metric's time over the film;
 * default [0, 1], as `--frames` without a path). See CameraPath.h for what
 * the frames are. Unknown keys and bad values are errors that name the key.
 */
#ifndef RiemannCameraPathFile_h
#define RiemannCameraPathFile_h

#include "CameraPath.h"
#include "JsonInputError.h"
#include "RiemannCommonObserverExport.h"

#include <stdexcept>
#include <string>

namespace riemann
{
class RIEMANNCOMMONOBSERVER_EXPORT CameraPathFileError : public JsonInputError
{
public:
  using JsonInputError::JsonInputError;
};

struct CameraPathFile
{
  /// Frames is not in the file: the caller sets it.
  CameraPathSettings Settings;
  /// The metric's time at the first and last frame.
  double TimeFrom = 0.0;
  double TimeTo = 1.0;
  /// Whether the file gives "fov" (else the picture's own view angle stays).
  bool ViewAngleGiven = false;
};

/// Parses the text of a camera path file; `where` names it in errors.
RIEMANNCOMMONOBSERVER_EXPORT CameraPathFile ParseCameraPathFile(
  const std::string& text, const std::string& where = "camera path");
/// Reads and parses a camera path file.
RIEMANNCOMMONOBSERVER_EXPORT CameraPathFile ReadCameraPathFile(const std::string& fileName);
/// The file's text (pretty-printed JSON) that ParseCameraPathFile reads back.
RIEMANNCOMMONOBSERVER_EXPORT std::string CameraPathFileText(const CameraPathFile& file);
} // namespace riemann

#endif
