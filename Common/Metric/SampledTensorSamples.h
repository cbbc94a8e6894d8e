/**
 * @file SampledTensorSamples.h
 * @brief From the tensors a file holds to the metric samples of a
 * SampledTensorField (issue 17): checked, optionally repaired, inverted and
 * scaled, with a report of what was wrong and where.
 *
 * Diffusion MRI gives the diffusion tensor D; geodesic tractography uses
 * g = D^-1 (`inverse`), so that geodesics run along the fibres, where
 * diffusion is fast and g small. Background voxels hold zero or tiny
 * tensors: `repair` clamps every eigenvalue to a floor (a fraction of the
 * largest eigenvalue in the data), after which their inverse is a wall of
 * large g rather than an error.
 */
#ifndef RiemannSampledTensorSamples_h
#define RiemannSampledTensorSamples_h

#include "SampledTensorField.h"
#include "RiemannCommonMetricExport.h"

#include <memory>
#include <string>

namespace riemann
{
/**
 * Which metric a tensor D of the data gives (JSON "tensor_metric"), through
 * its eigenvalues l_i (same eigenvectors):
 * - Tensor: g = D (the data is a metric already);
 * - Inverse: g = D^-1, eigenvalues 1 / l_i (O'Donnell, Haker and Westin
 *   2002): moving along the principal diffusion direction is cheap;
 * - Adjugate: g = det(D) D^-1, eigenvalues l_j l_k (Fuster, Dela Haije et
 *   al. 2016): a geodesic of the adjugate metric is a geodesic of D^-1
 *   reparametrised only where det D is constant; elsewhere the factor
 *   det D draws geodesics away from where diffusion is slow overall;
 * - Sharpened: g = det(D)^((p-1)/3) D^-p, eigenvalues (1 / l_i)
 *   (l_i / l_geo)^(1-p), l_geo = (l_1 l_2 l_3)^(1/3) and p =
 *   Sharpening >= 1: D^-1 with its anisotropy raised to the power p and its
 *   volume form kept (det g = det D^-1). FA grows with p, so geodesics keep
 *   to the principal direction more tightly in moderately anisotropic
 *   voxels (the tensor sharpening of Lenglet et al. 2009 and of the
 *   adaptive metrics of Hao, Whitaker and Fletcher 2011); p = 1 is Inverse.
 */
enum class TensorMetricKind
{
  Tensor,
  Inverse,
  Adjugate,
  Sharpened
};

/// The JSON name of each kind: "tensor", "inverse", "adjugate", "sharpened".
RIEMANNCOMMONMETRIC_EXPORT const char* TensorMetricName(TensorMetricKind kind);

/**
 * The exponent q with which the diffusion tensor a metric of `kind` stands
 * for is, up to a scale at each point, g^q: 1 for Tensor, -1 for Inverse
 * and Adjugate, -1/p for Sharpened. Fractional anisotropy is scale
 * invariant, so the FA of that tensor is the FA of g's eigenvalues to the
 * power q (FractionalAnisotropyOfMetric).
 */
RIEMANNCOMMONMETRIC_EXPORT double DiffusionExponent(TensorMetricKind kind, double sharpening);

/// What the "sampled" family does to the data's tensors, in this order.
struct RIEMANNCOMMONMETRIC_EXPORT SampledTensorOptions
{
  /// Clamp eigenvalues to `RelativeFloor` times the data's largest one,
  /// instead of refusing samples that are not positive definite.
  bool Repair = false;
  double RelativeFloor = 1e-3;
  /// The metric of each sample (after any repair): the tensor, its
  /// inverse, its adjugate or its sharpened inverse (TensorMetricKind).
  TensorMetricKind Kind = TensorMetricKind::Tensor;
  /// The power p of Sharpened (>= 1; JSON "sharpening", default 2).
  double Sharpening = 2.0;
  /// Multiply the metric by this (after the tensor's metric is made).
  double Scale = 1.0;
  /**
   * Also multiply it so that a sample equal to the data's median mean
   * diffusivity m times I becomes I (by 1 / f(m), f(m) I the metric Kind
   * makes of m I: m, 1 / m, m^2 or 1 / m): arc length is then Euclidean length where the data
   * is isotropic, whatever the tensors' units (mm^2/s, um^2/ms), so steps
   * and lengths are in the units of the voxels' positions (mm). The median
   * is over the positive definite samples (JSON "scale": "mean-diffusivity").
   */
  bool ScaleToMeanDiffusivity = false;
  /// "outside": "stop": geodesics and rays stop where they leave the volume
  /// (else g = I there).
  bool StopOutside = false;
  /// "christoffel": "voxels" (the default): geodesics and rays, on the CPU
  /// and the GPU, run on g and its derivatives sampled at the voxels and
  /// interpolated trilinearly (VoxelChristoffelMetric: the fast reading);
  /// else ("spline") on the spline's own, exact.
  bool ChristoffelAtVoxels = true;

  /// What is wrong with the options, or "".
  std::string Check() const;
};

/// What PrepareTensorSamples found.
struct RIEMANNCOMMONMETRIC_EXPORT SampledTensorReport
{
  long long NonFinite = 0;
  /// Samples with an eigenvalue <= 0 (before any repair).
  long long NotPositiveDefinite = 0;
  /// Samples whose eigenvalues were clamped (with Repair).
  long long Repaired = 0;
  /// Grid index of the first bad sample (non-finite, else not positive definite).
  std::array<int, 3> FirstBad = { -1, -1, -1 };
  /// The smallest eigenvalue found there, NaN when not finite.
  double FirstBadEigenvalue = 0.0;
  /// The median mean diffusivity (trace / 3) of the positive definite samples.
  double MedianMeanDiffusivity = 0.0;
  /// What the metric was multiplied by in all (Scale, and the median's part).
  double AppliedScale = 1.0;
};

/**
 * Check every sample of `grid` and turn it into a metric sample in place,
 * as `options` say. Returns "" on success, else what is wrong: how many
 * samples are not finite or not positive definite, and where the first one
 * is (its grid index, its position in space and its smallest eigenvalue),
 * with the "repair" hint for the latter. `report` (optional) gets the counts.
 */
RIEMANNCOMMONMETRIC_EXPORT std::string PrepareTensorSamples(SampledTensorGrid& grid,
  const SampledTensorOptions& options, SampledTensorReport* report = nullptr);

/**
 * The metric of a tensor volume: PrepareTensorSamples, then TensorMetric
 * over the SampledTensorField of the samples. What {"type": "sampled"} and
 * vtkRiemannMetric::SetTensorData build. Throws std::invalid_argument with
 * PrepareTensorSamples' message.
 */
RIEMANNCOMMONMETRIC_EXPORT std::shared_ptr<const Metric> MakeSampledTensorMetric(
  SampledTensorGrid grid, const SampledTensorOptions& options);

/**
 * The samples' field of a metric MakeSampledTensorMetric made, read either
 * way ("christoffel": "voxels" or "spline"); null for any other metric.
 * Where tractography finds the grid, its placement and the diffusion
 * exponent.
 */
RIEMANNCOMMONMETRIC_EXPORT const SampledTensorField* SampledFieldOf(const Metric& metric);
} // namespace riemann

#endif
