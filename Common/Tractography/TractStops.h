/**
 * @file TractStops.h
 * @brief Tractography's rules on geodesics (issue 31): where they stop (a
 * stop mask, an anisotropy threshold, a sharp turn) and which tracts are
 * kept (through an include region, avoiding an exclude region, long
 * enough). VTK-free: vtkRiemannGeodesicTracer and `riemann trace` apply them.
 *
 * Every length and angle here is Euclidean, in the units that place the
 * voxels (mm for a scan), whatever the metric's scale: a tractography user
 * thinks of a tract's length in mm, and of its turning in degrees per mm.
 */
#ifndef RiemannTractStops_h
#define RiemannTractStops_h

#include "GeodesicTrace.h"
#include "RiemannCommonTractographyExport.h"

#include <array>
#include <vector>

namespace riemann
{
/**
 * The voxel of an axis of n voxels that holds grid coordinate u (the nearest
 * centre), or -1 beyond the outer voxels' faces (or NaN). A point up to
 * SampledTensorField::FaceTolerance beyond a face is on it, as the sampled
 * metric's box says: tracts end on its faces (EndOnTheDataFace) to that.
 */
RIEMANNCOMMONTRACTOGRAPHY_EXPORT int VoxelOnAxis(double u, int n);

/**
 * A binary image on a regular grid: voxel (i, j, k) is centred at
 * Origin + Direction * (i Spacing_x, j Spacing_y, k Spacing_z), VTK's image
 * geometry. A point belongs to the voxel it is nearest to (the voxel whose
 * box holds it), as DIPY's binary stopping criterion and tract selection
 * read masks.
 */
struct RIEMANNCOMMONTRACTOGRAPHY_EXPORT VoxelMask
{
  Vec3 Origin = Vec3::Zero();
  Vec3 Spacing = Vec3::Ones();
  Mat3 Direction = Mat3::Identity();
  std::array<int, 3> Dimensions = { 0, 0, 0 };
  /// One per voxel, i fastest: 1 where the image is not 0.
  std::vector<unsigned char> Set;

  bool Empty() const { return this->Set.empty(); }
  /// Whether the voxel holding x is set; false beyond the grid's outer voxel faces.
  bool Contains(const Vec3& x) const;
};

/**
 * Fractional anisotropy of a tensor with these eigenvalues:
 * sqrt(3/2) |l - mean(l)| / |l|, 0 for an isotropic tensor, 1 for a line.
 */
RIEMANNCOMMONTRACTOGRAPHY_EXPORT double FractionalAnisotropy(const Vec3& eigenvalues);

/**
 * The fractional anisotropy of the diffusion tensor that `metric` stands
 * for at x: for a sampled metric, g^q with q its tensor_metric's
 * DiffusionExponent (SampledTensorSamples.h: D for the inverse, adjugate
 * and sharpened metrics of D); for any other metric, g^-1 (the metric read
 * as a diffusion tensor's inverse). False where g fails.
 */
RIEMANNCOMMONTRACTOGRAPHY_EXPORT bool FractionalAnisotropyOfMetric(
  const Metric& metric, const Vec3& x, double& anisotropy);

/// The q of FractionalAnisotropyOfMetric for `metric` (found once: the
/// stops ask for the anisotropy at every step).
RIEMANNCOMMONTRACTOGRAPHY_EXPORT double DiffusionExponentOf(const Metric& metric);

/// FractionalAnisotropyOfMetric with the metric's q already known.
RIEMANNCOMMONTRACTOGRAPHY_EXPORT bool FractionalAnisotropyOfMetric(
  const Metric& metric, double exponent, const Vec3& x, double& anisotropy);

/**
 * The stops that are properties of a point: StopMask (stop where it is 0,
 * StoppedByMask; outside its grid counts as 0) and MinimumAnisotropy (stop
 * where FractionalAnisotropyOfMetric is below it, or fails: LowAnisotropy).
 * Put in GeodesicOptions::Stop; the metric must outlive it.
 */
class RIEMANNCOMMONTRACTOGRAPHY_EXPORT TractStopRules : public StopCondition
{
public:
  explicit TractStopRules(const Metric& metric)
    : TheMetric(metric)
    , Exponent(DiffusionExponentOf(metric))
  {
  }
  /// Empty: no stop mask.
  VoxelMask StopMask;
  /// 0: no threshold.
  double MinimumAnisotropy = 0.0;

  /// Whether any rule is set (else the rules need not be consulted).
  bool Any() const { return !this->StopMask.Empty() || this->MinimumAnisotropy > 0.0; }
  int ReasonToStop(const Vec3& x) const override;

private:
  const Metric& TheMetric;
  double Exponent;
};

/**
 * Cut `path` at its first turn sharper than `degreesPerMillimetre`: between
 * consecutive points k and k + 1 the angle between their velocities,
 * divided by the chord's length, may not exceed it (step-size independent:
 * the tract's Euclidean curvature, in degrees per mm). The path keeps its
 * points up to k and the Reason SharpTurn. Returns whether it was cut.
 */
RIEMANNCOMMONTRACTOGRAPHY_EXPORT bool CutAtSharpTurn(GeodesicPath& path, double degreesPerMillimetre);

/// The Euclidean length of a path's polyline.
RIEMANNCOMMONTRACTOGRAPHY_EXPORT double EuclideanLength(const GeodesicPath& path);

/// Which tracts are kept; a tract is a seed's paths (both halves for a two-way trace).
struct RIEMANNCOMMONTRACTOGRAPHY_EXPORT TractSelection
{
  /// Keep only tracts with a point in it (empty: no such rule).
  VoxelMask Include;
  /// Drop tracts with a point in it (empty: no such rule).
  VoxelMask Exclude;
  /// Drop tracts whose Euclidean length (all halves) is below it (0: none).
  double MinimumLength = 0.0;

  bool Any() const
  {
    return !this->Include.Empty() || !this->Exclude.Empty() || this->MinimumLength > 0.0;
  }
};

/// Why a tract is dropped (TractSelection), 0 when it is kept.
enum TractRejection : int
{
  TractKept = 0,
  TractTooShort = 1,
  TractMissedInclude = 2,
  TractCrossedExclude = 3
};
constexpr int LastTractRejection = TractCrossedExclude;

/// A short English name of a TractRejection ("shorter than the minimum length", ...).
RIEMANNCOMMONTRACTOGRAPHY_EXPORT const char* TractRejectionName(int rejection);

/**
 * Whether the tract made of `paths[0..count)` is kept, or why not: first an
 * exclude region it enters, then an include region it misses, then its length.
 */
RIEMANNCOMMONTRACTOGRAPHY_EXPORT int SelectTract(
  const GeodesicPath* const* paths, int count, const TractSelection& selection);
} // namespace riemann

#endif
