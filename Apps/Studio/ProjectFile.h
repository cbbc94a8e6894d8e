/**
 * @file ProjectFile.h
 * @brief The project file: a whole session as one JSON document.
 *
 * @code{.json}
 * {
 *   "riemann-studio": 1,
 *   "metric": {"text": "...", "parameter-values": {"/parameters/a": 0.7}, "time": 0.25,
 *              "folder": "/data/dti"},  // where a sampled metric's relative "file" is
 *   "scene": {"file": "scene.json", "text": "..."},  // file relative to the project's folder;
 *                                                    // both "" for the default grid
 *   "observer": {"position": [0, 0, 7.5], "focal-point": [0, 0, 0], "view-up": [0, 1, 0], "view-angle": 60},
 *   "inside": {"backend": "gpu", "samples": 1, "use-scene-settings": true,
 *              "integration": {"IntegratorType": "rk4", "InitialIntegrationStep": 0.02, ...}},
 *   "items": [{"kind": "geodesics", "name": "Geodesics1", "visible": true, "settings": {...}}],
 *   "layout": {"views": "both", "outside-camera": {...}}
 * }
 * @endcode
 *
 * ParseProject checks the whole document (structure, the metric, the scene,
 * every item's settings) before anything is applied, so a bad project
 * changes nothing; errors name the place ("items[2].settings: Cone angle:
 * must be in [0, 180]"). Files are written whole or not at all (QSaveFile).
 */
#ifndef RiemannStudio_ProjectFile_h
#define RiemannStudio_ProjectFile_h

#include <nlohmann/json.hpp>

#include <QString>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

class vtkCamera;

namespace riemann
{
namespace studio
{
class StudioDocument;

struct CameraState
{
  /// The declared defaults (vtkRiemannPictureSettings), as a scene's camera.
  CameraState();
  /// Position, LookAt, ViewUp, ViewAngle (PictureValues.h: CameraValues).
  nlohmann::json Values;
  void From(vtkCamera* camera);
  /// Give `camera` these values (a view checked when they were read).
  void To(vtkCamera* camera) const;
};

struct ItemState
{
  std::string Kind;
  std::string Name;
  bool Visible = true;
  nlohmann::json Settings = nlohmann::json::object();
};

struct ProjectData
{
  std::string MetricText;
  /// The folder relative data files of the metric (a sampled volume) are
  /// read from: "metric": {"folder"} (relative to the project's), else the
  /// project's folder.
  std::string MetricFolder;
  std::map<std::string, double> ParameterValues;
  double Time = 0.0;
  std::string SceneFile;
  std::string SceneText;
  CameraState Observer;
  bool UseSceneSettings = true;
  nlohmann::json Integration = nlohmann::json::object();
  std::string Backend = "gpu";
  int Samples = 1;
  std::vector<ItemState> Items;
  std::string Views = "both";
  bool HasOutsideCamera = false;
  CameraState OutsideCamera;
};

class ProjectError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// The document's part of a project (metric, scene, observer, rays, items).
ProjectData CaptureProject(const StudioDocument& document);
/**
 * The project file's JSON. `folder` is the folder the project file is
 * written to: the scene file and the metric's data folder are written
 * relative to it, so that a project copied with its files opens elsewhere
 * ("" keeps them as they are).
 */
nlohmann::json ProjectToJson(const ProjectData& project, const std::string& folder = "");
/**
 * What a project saves of the document (CaptureProject), as text, without
 * the window's part (layout, outside camera, inside view's backend and
 * samples): equal texts, equal documents (ProjectSession's modified mark).
 */
std::string ProjectFingerprint(const StudioDocument& document);
/**
 * Parse and check a project; throws ProjectError saying where and why. A
 * relative scene file name is resolved against `folder` (the project file's).
 */
ProjectData ParseProject(const std::string& text, const std::string& folder = ".");
/// Make `document` hold `project` (checked by ParseProject: this cannot fail
/// halfway; returns "" or why it refused, changing nothing).
QString ApplyProject(const ProjectData& project, StudioDocument& document);
/// True when the JSON text is a project (has the "riemann-studio" key).
bool LooksLikeProject(const std::string& text);

/// Write `bytes` to `path` whole or not at all; "" or why not.
QString WriteFileAtomically(const QString& path, const QByteArray& bytes);
}
}

#endif
