/**
 * @class   vtkRiemannCPURayTracer
 * @brief   Render the inside view of R^3 with a Riemannian metric on the CPU:
 * any triangle mesh (Embree), exact colours, arbitrary output variables.
 *
 * The CPU counterpart of vtkRiemannRayTracePass, with the same scene
 * (vtkRiemannScene), metric (vtkRiemannMetric), camera model
 * (riemann::ObserverCamera), ray rules and shading, so both render the same
 * analytic scene the same, pixel for pixel (float against double aside).
 * In addition it draws triangle meshes: the scene's mesh objects (read by
 * vtkRiemannScene) and any vtkPolyData given with AddMesh(). Each
 * integration step's segment is one Embree query; the segments of all rays
 * of a tile can go to Embree together as a ray stream (UseRayStreams). Tiles
 * run in parallel with vtkSMPTools.
 *
 * @code{.py}
 * tracer = riemann.vtkRiemannCPURayTracer()
 * tracer.SetMetric(metric); tracer.SetScene(scene)
 * tracer.SetWidth(1920); tracer.SetHeight(1080); tracer.SetSamplesPerPixel(4)
 * tracer.AddMesh(vtk.vtkSphereSource().GetOutput())   # any vtkPolyData
 * tracer.Update(); image = tracer.GetOutput()
 * @endcode
 *
 * Output: a vtkImageData of Width x Height points, row 0 at the bottom
 * (OpenGL's and VTK's convention), with point data
 * - "Color" (3 floats, the active scalars): the pixel colour, the mean of
 *   SamplesPerPixel stratified, jittered rays (deterministic with Seed);
 * and, for the ray through the pixel centre,
 * - "HitPosition" (3 floats; NaN where the ray hit nothing),
 * - "ArcLength" (float): at the hit, or where the ray stopped,
 * - "Steps" (int): integration steps,
 * - "ReasonForTermination" (int): vtkStreamTracer's codes and ours
 *   (riemann::TerminationReason: 9 hit a surface, 4 out of length, 5 out of
 *   steps, 6 stagnation, 8 degenerate metric),
 * - "SpeedDrift" (float): g(v, v) - 1 at the end (0 for an exact geodesic),
 * - "HitError" (float, only with ComputeHitError for a diffeomorphism
 *   metric): distance to the exact hit (Phi^-1 of the straight line), +inf
 *   where only one of the two hits, NaN where neither does.
 *
 * Camera: SetCamera() (a vtkCamera: position, focal point, view up, view
 * angle, as the pass reads its renderer's), else the scene's camera.
 * Integration and projection: from the scene when UseSceneSettings is on
 * (the default), else from GetIntegrationSettings() and Projection, as the
 * pass (vtkRiemannObserverSettings.h; the same defaults).
 *
 * Pieces: the image honours VTK's piece requests (as an MPI job or a
 * streaming pipeline makes them): it declares CAN_PRODUCE_SUB_EXTENT and
 * traces only the requested extent (the tiles of the whole image's tiling
 * that meet it). Every pixel's rays are its own, so a piece is bitwise the
 * whole image's pixels there, anti-aliasing included.
 *
 * Errors (no metric, a degenerate metric at the eye, a mesh that cannot be
 * built, bad sizes) are reported with vtkErrorMacro and give an empty
 * output. Progress is reported between batches of tiles, where AbortExecute
 * is honoured too.
 *
 * @sa vtkRiemannRayTracePass vtkRiemannScene vtkRiemannMetric
 */
#ifndef vtkRiemannCPURayTracer_h
#define vtkRiemannCPURayTracer_h

#include "RiemannRenderingCPUModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <memory> // For std::unique_ptr
#include <string> // For LastError
#include <vector> // For PixelResultsOf

namespace riemann
{
class CPUTracer;
class Metric;
struct PixelResult;
struct Scene;
}
class vtkActor;
class vtkCamera;
class vtkRiemannIntegrationSettings;
class vtkPolyData;
class vtkRiemannMetric;
class vtkRiemannScene;

class RIEMANNRENDERINGCPU_EXPORT vtkRiemannCPURayTracer : public vtkImageAlgorithm
{
public:
  static vtkRiemannCPURayTracer* New();
  vtkTypeMacro(vtkRiemannCPURayTracer, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The modification time of this object, its metric, scene and camera.
  vtkMTimeType GetMTime() override;

  ///@{
  /// The metric of the space (required).
  void SetMetric(vtkRiemannMetric* metric);
  vtkGetObjectMacro(Metric, vtkRiemannMetric);
  ///@}

  ///@{
  /// The scene (a vtkRiemannScene without a definition is the default grid; none: the default).
  void SetScene(vtkRiemannScene* scene);
  vtkGetObjectMacro(Scene, vtkRiemannScene);
  ///@}

  ///@{
  /// The observer; null (the default) to use the scene's camera.
  void SetCamera(vtkCamera* camera);
  vtkGetObjectMacro(Camera, vtkCamera);
  ///@}

  ///@{
  /**
   * Add any vtkPolyData to the scene as a triangle mesh (polygons and strips
   * are triangulated). Its colours: the named point array through the colour
   * map ("cool-to-warm", "viridis", "grayscale", "rainbow") when
   * `colorArray` is given, else its unsigned-char RGB scalars, else the
   * position pseudo-colour over its bounds. The data is read at the next
   * Update (a copy is kept).
   */
  void AddMesh(vtkPolyData* mesh, const char* colorArray = nullptr,
    const char* colorMap = "cool-to-warm");
  void RemoveAllMeshes();
  int GetNumberOfAddedMeshes() const;
  ///@}

  ///@{
  /**
   * Add a vtkActor to the scene as the GPU pass draws a renderer's actors
   * with UseRendererProps on (riemann::MeshFromActor, RiemannActorMesh.h):
   * its mapper's polydata moved by its matrix, coloured per vertex by its
   * mapped point scalars or its property's colour; hidden actors and actors
   * of opacity 0 are skipped. The actor is read at each Update.
   */
  void AddActor(vtkActor* actor);
  void RemoveAllActors();
  int GetNumberOfAddedActors() const;
  ///@}

  /// Largest Width x Height accepted (64 Mi pixels, e.g. 8192 x 8192: about
  /// 6 GiB of results); larger images are refused with an error.
  static constexpr double MaximumNumberOfPixels = 67108864.0;

  ///@{
  /// Image size in pixels (default 640 x 480). Each side 1 to 65536 and
  /// the whole at most MaximumNumberOfPixels: other values are kept and
  /// refused with an error when the filter runs (not clamped in silence).
  vtkSetMacro(Width, int);
  vtkGetMacro(Width, int);
  vtkSetMacro(Height, int);
  vtkGetMacro(Height, int);
  ///@}

  ///@{
  /// Rays per pixel for the colour (anti-aliasing; default 1: the pixel centre, as the GPU).
  vtkSetClampMacro(SamplesPerPixel, int, 1, 4096);
  vtkGetMacro(SamplesPerPixel, int);
  ///@}

  ///@{
  /// Seed of the sample jitter (default 0): the same seed gives the same image.
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  ///@{
  /// Tile edge in pixels (default 16): the unit of parallel work and of a ray stream.
  vtkSetClampMacro(TileSize, int, 1, 1024);
  vtkGetMacro(TileSize, int);
  ///@}

  ///@{
  /**
   * Send a tile's segments to Embree as one stream (rtcIntersect1M) rather
   * than one rtcIntersect1 each. Default off: on this project's machine the
   * stream did not pay (1920x1080, 1M triangles: 6.42e6 against 6.43e6 rays x
   * steps / s on a quiet machine, 6.1e6 against 6.7e6 under load;
   * RiemannCpuRayTraceBenchmark), the segments of one step being short and
   * scattered after a few bends.
   */
  vtkSetMacro(UseRayStreams, bool);
  vtkGetMacro(UseRayStreams, bool);
  vtkBooleanMacro(UseRayStreams, bool);
  ///@}

  ///@{
  /// Add the "HitError" array (diffeomorphism metrics; costs an exact ray per pixel). Default off.
  vtkSetMacro(ComputeHitError, bool);
  vtkGetMacro(ComputeHitError, bool);
  vtkBooleanMacro(ComputeHitError, bool);
  ///@}

  /// Projections (the pass's numbering).
  enum Projections
  {
    PERSPECTIVE = 0,
    EQUIRECTANGULAR = 1
  };

  ///@{
  /// Integration and projection from the scene (default on), else from the settings below.
  vtkSetMacro(UseSceneSettings, bool);
  vtkGetMacro(UseSceneSettings, bool);
  vtkBooleanMacro(UseSceneSettings, bool);
  ///@}

  ///@{
  /// How rays are integrated when UseSceneSettings is off (shareable, never null).
  void SetIntegrationSettings(vtkRiemannIntegrationSettings* settings);
  vtkGetObjectMacro(IntegrationSettings, vtkRiemannIntegrationSettings);
  ///@}

  ///@{
  /// PERSPECTIVE (default) or EQUIRECTANGULAR, when UseSceneSettings is off or the scene has no camera.
  vtkSetClampMacro(Projection, int, PERSPECTIVE, EQUIRECTANGULAR);
  vtkGetMacro(Projection, int);
  ///@}

  ///@{
  /// Statistics of the last update: rays traced, integration steps, seconds spent tracing.
  vtkGetMacro(NumberOfRays, vtkIdType);
  vtkGetMacro(NumberOfIntegrationSteps, vtkIdType);
  vtkGetMacro(TraceTime, double);
  vtkGetMacro(NumberOfTriangles, vtkIdType);
  ///@}

  /// Whether the last update computed the "HitError" array (ComputeHitError with an exact reference).
  vtkGetMacro(HitErrorComputed, bool);

  /**
   * The pixels of an output of this filter (the whole image or a piece), row
   * by row from the bottom of its extent, read from its point arrays into the
   * core's form (RiemannCPUImage.h turns them into pictures): the inverse of
   * what RequestData writes, so the output port is the only way out of the
   * filter. Empty when `output` lacks the arrays (an empty output after an
   * error). "HitError" is NaN where the output has no such array.
   */
  VTK_WRAPEXCLUDE static std::vector<riemann::PixelResult> PixelResultsOf(vtkImageData* output);

  /**
   * The last error this filter reported (also raised through vtkErrorMacro),
   * or "" when its last update succeeded (ErrorConventions.md).
   */
  const char* GetLastError() const { return this->LastError.c_str(); }

protected:
  vtkRiemannCPURayTracer();
  ~vtkRiemannCPURayTracer() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkRiemannMetric* Metric = nullptr;
  vtkRiemannScene* Scene = nullptr;
  vtkCamera* Camera = nullptr;
  int Width = 640;
  int Height = 480;
  int SamplesPerPixel = 1;
  unsigned int Seed = 0;
  int TileSize = 16;
  bool UseRayStreams = false;
  bool ComputeHitError = false;
  bool UseSceneSettings = true;
  vtkRiemannIntegrationSettings* IntegrationSettings = nullptr;
  int Projection = PERSPECTIVE;
  vtkIdType NumberOfRays = 0;
  vtkIdType NumberOfIntegrationSteps = 0;
  double TraceTime = 0.0;
  vtkIdType NumberOfTriangles = 0;
  bool HitErrorComputed = false;

  /// GetLastError(): set by vtkRiemannReportErrorMacro, cleared where RequestData starts.
  std::string LastError;

private:
  ///@{
  /// The steps of RequestData, in order; each reports its own errors.
  std::shared_ptr<riemann::Scene> MakeScene();
  bool CheckImageSize();
  std::unique_ptr<riemann::CPUTracer> MakeCoreTracer(
    const std::shared_ptr<const riemann::Metric>& metric,
    const std::shared_ptr<riemann::Scene>& scene);
  void TraceTiles(const riemann::CPUTracer& tracer);
  void FillOutput(vtkImageData* output);
  ///@}

  vtkRiemannCPURayTracer(const vtkRiemannCPURayTracer&) = delete;
  void operator=(const vtkRiemannCPURayTracer&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
