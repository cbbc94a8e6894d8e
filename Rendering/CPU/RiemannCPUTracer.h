/**
 * @file RiemannCPUTracer.h
 * @brief The inside view traced on the CPU, tile by tile (VTK-free): the
 * engine of vtkRiemannCPURayTracer, which runs the tiles in parallel.
 *
 * Same camera (ObserverCamera), same ray rules (RayMarcher: TraceRay's),
 * same scene intersection (IntersectSegment, plus the meshes in Embree:
 * MeshIntersector) and same shading (ShadeRay) as the GPU pass, so a pixel
 * of the CPU image is the GPU's pixel up to float rounding. Pixels are
 * addressed as on the GPU: column i, row j (row 0 at the bottom) has its
 * centre at (i + 0.5, j + 0.5), normalised image coordinates
 * ((2 i + 1) / W - 1, (2 j + 1) / H - 1).
 *
 * A tile's rays are advanced together, one step at a time (a wavefront):
 * after each step the segments of all its live rays go to Embree in one
 * stream query, then each is tested against the analytic objects; the
 * nearer hit wins.
 *
 * Anti-aliasing: with N > 1 samples per pixel the colour is the mean of N
 * rays through stratified, jittered points of the pixel (a deterministic
 * hash of Seed, pixel and sample: the same image on any number of threads).
 * The arbitrary output variables always describe the pixel-centre ray (traced
 * in addition when N > 1), so they compare with the GPU's hit capture and
 * with the exact reference at any N.
 */
#ifndef RiemannCPUTracer_h
#define RiemannCPUTracer_h

#include "RiemannRenderingCPUModule.h" // For export macro
#include "RiemannSceneIntersection.h"
#include "RiemannScene.h"

#include "Metric.h"
#include "ObserverCamera.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace riemann
{
class EmbreeMeshIntersector;
class RayMarcher;
struct EnvironmentMap;

/// One pixel of the CPU image: colour and arbitrary output variables (AOVs).
struct PixelResult
{
  /// Linear RGB, as the GPU writes it (before 8-bit quantisation).
  float Color[3] = { 0, 0, 0 };
  /// Hit position of the centre ray; NaN when it hit nothing.
  float HitPosition[3] = { 0, 0, 0 };
  /// Arc length of the centre ray (at the hit, or where it stopped).
  float ArcLength = 0;
  /// Integration steps of the centre ray.
  int Steps = 0;
  /// TerminationReason of the centre ray (HitSurface, OutOfLength, ...).
  int Reason = 0;
  /// g(v, v) - 1 at the centre ray's end (its initial speed is 1); NaN where g is degenerate.
  float SpeedDrift = 0;
  /**
   * With ComputeHitError for a diffeomorphism metric: distance from the
   * centre ray's hit to the exact hit of the same pixel; +inf when exactly
   * one of the two hits; NaN when neither does (or no reference).
   */
  float HitError = 0;
};

struct CPUTracerSettings
{
  int Width = 640;
  int Height = 480;
  int SamplesPerPixel = 1;
  std::uint32_t Seed = 0;
  /// Embree ray streams (rtcIntersect1M) per step of a tile, else one query per segment.
  bool UseRayStreams = false;
  /// Compare each centre ray with the exact geodesic (diffeomorphism metrics only).
  bool ComputeHitError = false;
  /// Chord of the exact reference's march, refined near a hit to 1e-6 of it.
  double ExactChord = 0.01;
};

class RIEMANNRENDERINGCPU_EXPORT CPUTracer
{
public:
  /**
   * Throws std::runtime_error when the observer cannot be placed (a
   * degenerate metric at the eye), when the scene's meshes cannot be built
   * in Embree, or when the settings make no sense.
   */
  CPUTracer(std::shared_ptr<const Metric> metric, std::shared_ptr<const Scene> scene,
    const CameraSettings& camera, const RaySettings& rays, const CPUTracerSettings& settings,
    std::shared_ptr<const EnvironmentMap> environment = nullptr);
  ~CPUTracer();
  CPUTracer(const CPUTracer&) = delete;
  CPUTracer& operator=(const CPUTracer&) = delete;

  /**
   * Trace the pixels [x0, x1) x [y0, y1) into `image` (Width x Height,
   * row 0 at the bottom). Thread-safe for disjoint tiles. Returns the
   * number of integration steps taken (all rays of the tile).
   */
  long long RenderTile(int x0, int y0, int x1, int y1, PixelResult* image) const;

  /// True when the metric is a diffeomorphism metric (an exact reference exists).
  bool HasExactReference() const;

  /**
   * The exact first hit of the geodesic leaving the eye with unit-speed v,
   * gamma(s) = Phi^-1(Phi(eye) + s J(eye) v) (MATH.md, Family 2), marched
   * in chords of ExactChord against the scene and refined around the first
   * hit. False when it hits nothing within the maximum length or when there
   * is no exact reference.
   */
  bool ExactHit(const Vec3& v, Vec3& position, double& length) const;

  /// The unit-speed initial velocity through image point (px, py) in pixels (0..W, 0..H).
  Vec3 Direction(double px, double py) const;

  const ObserverCamera& GetCamera() const { return *this->Camera; }
  const CPUTracerSettings& GetSettings() const { return this->Settings; }
  /// Triangles in the Embree scene (0 without meshes).
  std::size_t NumberOfTriangles() const;

private:
  struct Exact;
  /// One ray of a tile: which pixel, which sample (-1: the pixel-centre ray).
  struct TileRay
  {
    int Pixel;
    int Sample;
  };

  ///@{
  /// RenderTile's steps, in order (RiemannCPUTracer.cxx says why each is one).
  void StartRays(int x0, int y0, int x1, int y1, std::vector<TileRay>& rays,
    std::vector<RayMarcher>& marchers) const;
  long long MarchWavefront(std::vector<RayMarcher>& marchers) const;
  void GatherPixels(const std::vector<TileRay>& rays, const std::vector<RayMarcher>& marchers,
    PixelResult* image) const;
  void WriteCentreRay(const RayMarcher& ray, int pixelIndex, PixelResult& pixel) const;
  ///@}
  std::shared_ptr<const Metric> MetricPointer;
  std::shared_ptr<const Scene> ScenePointer;
  std::shared_ptr<const EnvironmentMap> Environment;
  RaySettings Rays;
  CPUTracerSettings Settings;
  std::unique_ptr<ObserverCamera> Camera;
  std::unique_ptr<EmbreeMeshIntersector> Meshes;
  std::unique_ptr<Exact> Reference;
};
} // namespace riemann

#endif
