/**
 * @file RiemannShading.h
 * @brief The colour of a traced ray on the CPU, exactly as the GPU pass's
 * fragment shader computes it (RiemannRayTraceFS.glsl, main()): VTK-free.
 *
 * - A hit: the material colour (SurfaceColor); with the scene's "observer"
 *   lighting times the Lambert cosine measured with g at the hit
 *   (ObserverCosine); then fog by arc length s: mix(colour, fog, 1 - exp(-density s)).
 * - A failed integration (a degenerate metric, a non-finite value, an
 *   adaptive step below its minimum): FailureColor, magenta.
 * - An escaped ray (length or steps used up): the environment image looked
 *   up by the final velocity (EnvironmentMap::Lookup, bilinear as the GPU's
 *   texture), or the background colour.
 */
#ifndef RiemannShading_h
#define RiemannShading_h

#include "RiemannImage.h"
#include "RiemannRenderingCoreExport.h" // For export macro
#include "RiemannSceneIntersection.h" // For SceneHit

#include "Metric.h"

#include <string>
#include <vector>

namespace riemann
{
/// Shown where a ray cannot go on (rt_failure_color in the GLSL).
RIEMANNRENDERINGCORE_EXPORT Vec3 FailureColor();

/// True for the termination reasons that the GPU shows as a failure (magenta).
RIEMANNRENDERINGCORE_EXPORT bool IsFailure(int reason);

/**
 * An equirectangular environment image, float RGB rows, top row first, as
 * the GPU pass uploads it: +y up; longitude atan2(d_x, -d_z) across the
 * width (u = 0.5 looks down -z), latitude asin(d_y) from the top row (+90
 * degrees). Sampled bilinearly with texel centres at (i + 0.5) / width,
 * repeating in u and clamped in v (the texture's Repeat / ClampToEdge).
 */
struct RIEMANNRENDERINGCORE_EXPORT EnvironmentMap
{
  int Width = 0;
  int Height = 0;
  std::vector<float> Rgb;

  bool Empty() const { return this->Width <= 0 || this->Height <= 0; }
  /// The colour seen in coordinate direction d; `background` for d == 0.
  Vec3 Lookup(const Vec3& direction, const Vec3& background) const;
  /**
   * Take `image`'s pixels (grey repeated). Throws std::invalid_argument for
   * an image without pixels (a caller's bug: ReadImage never returns one).
   */
  void SetImage(const Image& image);
};

/**
 * Lambert with the light at the eye: |nu(v)| / (|nu|_{g^-1} |v|_g) at p, nu
 * the coordinate normal covector, clamped to [0, 1]; 1 where g cannot be
 * evaluated (as rt_observer_cosine).
 */
RIEMANNRENDERINGCORE_EXPORT double ObserverCosine(
  const Metric& metric, const Vec3& p, const Vec3& nu, const Vec3& v);

/**
 * The pixel colour of a ray that ended with `reason` at `position` with
 * arc length `length` and final velocity `velocity`; `hit` describes the
 * surface when reason is HitSurface. `environment` may be null.
 */
RIEMANNRENDERINGCORE_EXPORT Vec3 ShadeRay(const Metric& metric, const Scene& scene,
  bool isHit, const SceneHit& hit, int reason, double length, const Vec3& velocity,
  const EnvironmentMap* environment);
/**
 * The material colour at a hit (before lighting and fog); black for an
 * object index out of range.
 * - Position: clamp((p - lo) / (hi - lo), 0, 1) per component (0.5 on an
 *   axis with hi <= lo).
 * - Solid: Color.
 * - Checker: Color where floor(q_x / s) + floor(q_y / s) + floor(q_z / s) is
 *   even, else Color2, at q = p - 1e-6 s n (n the unit Normal): a point just
 *   inside the surface, so that a face lying on a checker plane (a box
 *   [-1,1]^3 with size 1) gets one colour rather than rounding noise.
 * - A mesh with vertex colours: the colours of the hit triangle's vertices
 *   interpolated with the hit's barycentric weights (the material otherwise).
 */
RIEMANNRENDERINGCORE_EXPORT Vec3 SurfaceColor(const Scene& scene, const SceneHit& hit);
} // namespace riemann

#endif
