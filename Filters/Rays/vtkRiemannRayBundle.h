/**
 * @class   vtkRiemannRayBundle
 * @brief   The rays of the inside view, for chosen pixels, as polylines.
 *
 * vtkRiemannRayBundle traces, on the CPU, the same rays that
 * vtkRiemannRayTracePass traces per pixel: same observer frame
 * (riemann::ObserverCamera, g-orthonormal at the eye), same integrator and
 * step, same scene intersection (riemann::TraceRay). Plot them next to the
 * inside view to see how the metric bends each pixel's line of sight.
 *
 * Pixels: an N x N sub-grid of the Width x Height image (SubgridResolution,
 * the centres of N x N equal blocks), or every PixelStride-th pixel of a
 * region (SetPixelRegion, UsePixelRegion). Row 0 is the bottom row. The
 * user-facing settings, their defaults and ranges are declared in
 * vtkRiemannRayBundle.settings.json (Documentation/Settings.md).
 *
 * Output: one polyline per pixel, from the observer to the hit (or to the end
 * of the ray), with point data `ArcLength` and cell data `PixelIndex`
 * (column, row), `Hit` (0/1), `HitPosition` (NaN without hit), `EndColor`
 * (RGB, unsigned char: the hit surface's material colour, or the
 * background: the rays "coloured by where they end"), `Length` and
 * `ReasonForTermination` (vtkRiemannGeodesicTracer's codes; 9 = hit).
 *
 * The camera is a vtkCamera (SetCamera); without one, the scene's camera,
 * else the default scene's. The integration (the scene's "integrator" block)
 * and the projection of the scene's camera come from the scene unless
 * UseSceneSettings is off; then GetIntegrationSettings() (defaults as the
 * pass's: RUNGE_KUTTA4, step 0.02, MaximumPropagation 30, 1000 steps,
 * MaximumError 1e-4) and Projection apply, exactly as for
 * vtkRiemannRayTracePass (vtkRiemannObserverSettings.h).
 *
 * Pieces: asked for piece p of N (as an MPI job asks), the filter traces the
 * p-th contiguous share of its pixels, [n p / N, n (p + 1) / N) of the n in
 * output order: the pieces appended in order are the one-piece output.
 */
#ifndef vtkRiemannRayBundle_h
#define vtkRiemannRayBundle_h

#include "RiemannFiltersRaysModule.h" // For export macro
#include "vtkRiemannGeodesicAlgorithm.h"

#include <utility> // For SelectPixels
#include <vector>  // For SelectPixels

namespace riemann
{
struct RaySettings;
}
class vtkCamera;
class vtkRiemannScene;

class RIEMANNFILTERSRAYS_EXPORT vtkRiemannRayBundle : public vtkRiemannGeodesicAlgorithm
{
public:
  static vtkRiemannRayBundle* New();
  vtkTypeMacro(vtkRiemannRayBundle, vtkRiemannGeodesicAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Projections
  {
    PERSPECTIVE = 0,
    EQUIRECTANGULAR = 1
  };

  ///@{
  /// The scene (optional: the default scene) and the camera (the metric: SetMetric).
  virtual void SetScene(vtkRiemannScene* scene);
  vtkGetObjectMacro(Scene, vtkRiemannScene);
  virtual void SetCamera(vtkCamera* camera);
  vtkGetObjectMacro(Camera, vtkCamera);
  ///@}

  ///@{
  /// Image size in pixels (default 640 x 480): fixes the aspect ratio and
  /// pixel centres. Each side 1 to 65536; other values are kept and refused
  /// with an error when the filter runs (not clamped in silence).
  vtkSetMacro(Width, int);
  vtkGetMacro(Width, int);
  vtkSetMacro(Height, int);
  vtkGetMacro(Height, int);
  ///@}

  /// The most points a bundle holds (rays times their steps plus one): 10^8,
  /// about 4 GB with the arrays. Larger bundles are refused with an error.
  static constexpr double MaximumNumberOfPoints = 1e8;

  ///@{
  /// PERSPECTIVE (default) or EQUIRECTANGULAR, as the pass.
  vtkSetClampMacro(Projection, int, PERSPECTIVE, EQUIRECTANGULAR);
  vtkGetMacro(Projection, int);
  ///@}

  ///@{
  /// N for an N x N sub-grid of pixels (default 8; 1 to 4096, checked when
  /// the filter runs, as the sides: 1 to 65536).
  vtkSetMacro(SubgridResolution, int);
  vtkGetMacro(SubgridResolution, int);
  ///@}

  ///@{
  /// A pixel region (column0, column1, row0, row1; inclusive) and stride, used when UsePixelRegion.
  vtkSetVector4Macro(PixelRegion, int);
  vtkGetVector4Macro(PixelRegion, int);
  vtkSetClampMacro(PixelStride, int, 1, 1 << 16);
  vtkGetMacro(PixelStride, int);
  vtkSetMacro(UsePixelRegion, bool);
  vtkGetMacro(UsePixelRegion, bool);
  vtkBooleanMacro(UsePixelRegion, bool);
  ///@}

  ///@{
  /// Take the integration settings from the scene (default on), else GetIntegrationSettings().
  vtkSetMacro(UseSceneSettings, bool);
  vtkGetMacro(UseSceneSettings, bool);
  vtkBooleanMacro(UseSceneSettings, bool);
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  vtkRiemannRayBundle();
  ~vtkRiemannRayBundle() override;

  int FillDataPortInformation(int port, vtkInformation* info) override;
  /// The integration settings are checked only when they apply (UseSceneSettings off).
  bool UsesIntegrationSettings() const override { return !this->UseSceneSettings; }
  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  vtkRiemannScene* Scene = nullptr;
  vtkCamera* Camera = nullptr;
  // The declared settings' defaults (vtkRiemannRayBundle.settings.json) are set by the constructor.
  int Width;
  int Height;
  int Projection;
  int SubgridResolution;
  int PixelRegion[4] = { 0, 0, 0, 0 };
  int PixelStride = 1;
  bool UsePixelRegion = false;
  bool UseSceneSettings;

private:
  /// The sides, sub-grid and stride in range, and the points the bundle
  /// would hold within MaximumNumberOfPoints; else ReportError and false.
  bool CheckSizes(const riemann::RaySettings& rays);
  /// The bundle's pixels, (column, row): the strided PixelRegion when
  /// UsePixelRegion, else the centres of a SubgridResolution^2 grid of blocks.
  void SelectPixels(std::vector<std::pair<int, int>>& pixels) const;

  vtkRiemannRayBundle(const vtkRiemannRayBundle&) = delete;
  void operator=(const vtkRiemannRayBundle&) = delete;
};

#endif
