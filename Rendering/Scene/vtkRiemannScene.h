/**
 * @class   vtkRiemannScene
 * @brief   The scene of an inside view of R^3 with a metric, defined by its JSON text.
 *
 * vtkRiemannScene is the VTK handle on a riemann::Scene (RiemannScene.h):
 * the paper's grid of bars, spheres, planes and boxes with their materials,
 * the background (a colour or an equirectangular environment image), fog,
 * lighting, an optional camera, the ray integration settings and optionally
 * the metric the scene is meant for. vtkRiemannRayTracePass (and the CPU
 * tracer) take it with SetScene().
 *
 * Mesh objects ({"type": "mesh", "file": ...}, CPU tracer only) are read
 * here with VTK's readers (RiemannPolyDataMesh.h); a file that cannot be read
 * or holds no triangles makes the definition fail like any other error.
 *
 * SetDefinition() parses and validates the text; on bad input it returns
 * false, GetLastError() says where and why, and the previous definition is
 * kept. Without a definition the scene is riemann::DefaultScene(): the
 * paper's regular grid.
 *
 * @code{.py}
 * scene = riemann.vtkRiemannScene()
 * if not scene.SetDefinitionFile("Data/scenes/grid.json"):
 *     raise ValueError(scene.GetLastError())
 * metric = riemann.vtkRiemannMetric()
 * if scene.HasMetricDefinition():
 *     metric.SetDefinition(scene.GetMetricDefinition())
 * scene.ApplyCamera(renderer.GetActiveCamera())
 * @endcode
 *
 * @sa vtkRiemannRayTracePass vtkRiemannMetric
 */
#ifndef vtkRiemannScene_h
#define vtkRiemannScene_h

#include "JsonInputError.h"              // For riemann::JsonErrorPlace
#include "RiemannRenderingSceneModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <memory> // For std::shared_ptr
#include <string> // For std::string

class vtkCamera;

namespace riemann
{
struct Scene;
}

class RIEMANNRENDERINGSCENE_EXPORT vtkRiemannScene : public vtkObject
{
public:
  static vtkRiemannScene* New();
  vtkTypeMacro(vtkRiemannScene, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Set the scene from its JSON text, or from a file holding it. Relative
   * file names inside the scene (metric, environment image) resolve against
   * the current directory for SetDefinition() and against the scene file's
   * folder for SetDefinitionFile(). Returns true on success; on failure the
   * current scene is unchanged and GetLastError() explains the problem.
   */
  bool SetDefinition(const char* json);
  bool SetDefinitionFile(const char* path);
  ///@}

  /**
   * Make this scene the same as `other`, sharing its (immutable) parsed
   * scene and meshes: a computation on another thread gets its own handle
   * this way while the original may be redefined.
   */
  void ShallowCopy(vtkRiemannScene* other);

  /// The JSON text of the current definition ("" when none has been set).
  const char* GetDefinition() const { return this->Definition.c_str(); }

  /// The file of the current definition ("" when it came from text or none is set).
  const char* GetDefinitionFile() const { return this->DefinitionFile.c_str(); }

  /// Why the last SetDefinition/SetDefinitionFile failed ("" after a success).
  const char* GetLastError() const { return this->LastError.c_str(); }

  ///@{
  /**
   * Where in the scene's text the last error is, as data (as
   * vtkRiemannMetric's): 1-based line and column in characters, byte
   * offset, and the failing value's JSON pointer; 0, -1 and "" when the
   * error has no place in the text.
   */
  int GetLastErrorLine() const { return this->LastErrorPlace.Text.Known ? this->LastErrorPlace.Text.Line : 0; }
  int GetLastErrorColumn() const { return this->LastErrorPlace.Text.Known ? this->LastErrorPlace.Text.Column : 0; }
  int GetLastErrorOffset() const { return this->LastErrorPlace.Text.Known ? this->LastErrorPlace.Text.Offset : -1; }
  const char* GetLastErrorPointer() const { return this->LastErrorPlace.Pointer.c_str(); }
  VTK_WRAPEXCLUDE const riemann::JsonErrorPlace& GetLastErrorPlace() const { return this->LastErrorPlace; }
  ///@}

  /// True once a valid definition is set (otherwise the scene is the default one).
  bool HasDefinition() const;

  /// Number of objects in the current scene (the default scene's without a definition).
  int GetNumberOfObjects() const;

  ///@{
  /**
   * The metric definition (JSON text) that the scene names, "" if none.
   * Pass it to vtkRiemannMetric::SetDefinition().
   */
  bool HasMetricDefinition() const;
  std::string GetMetricDefinition() const;
  ///@}

  /// True if the scene defines a camera.
  bool HasCamera() const;

  /**
   * Copy the scene's camera (position, focal point, view up, vertical view
   * angle) to `camera`. Returns false (and leaves the camera alone) when the
   * scene has no camera or `camera` is null. The projection mode is read by
   * vtkRiemannRayTracePass itself (see its UseSceneSettings).
   */
  bool ApplyCamera(vtkCamera* camera) const;

  /**
   * Give `camera` the observer's defaults (those of a scene camera block
   * that sets nothing: a new vtkRiemannPictureSettings's, declared in
   * vtkRiemannPictureSettings.settings.json), in place of vtkCamera's own
   * (which look from (0, 0, 1) with 30 degrees).
   */
  static void ApplyDefaultCamera(vtkCamera* camera);

  /**
   * The current scene, immutable; riemann::DefaultScene() when no
   * definition is set. The reference stays valid until the next successful
   * SetDefinition/SetDefinitionFile; hold GetSceneSnapshot() to keep a scene
   * across redefinitions (e.g. on another thread).
   */
  VTK_WRAPEXCLUDE const riemann::Scene& GetScene() const;
  VTK_WRAPEXCLUDE std::shared_ptr<const riemann::Scene> GetSceneSnapshot() const;

protected:
  vtkRiemannScene();
  ~vtkRiemannScene() override;

private:
  vtkRiemannScene(const vtkRiemannScene&) = delete;
  void operator=(const vtkRiemannScene&) = delete;

  bool Install(std::shared_ptr<const riemann::Scene> scene, const std::string& definition,
    const std::string& file);

  std::shared_ptr<const riemann::Scene> Scene;
  std::string Definition;
  std::string DefinitionFile;
  std::string LastError;
  riemann::JsonErrorPlace LastErrorPlace;
};

#endif
