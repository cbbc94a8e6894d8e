/**
 * @class riemann::VoxelChristoffelMetric
 * @brief A sampled metric whose geodesics run on its g and dg sampled once
 * at the voxels and interpolated trilinearly: the fast path of tractography
 * (issue 31; JSON "christoffel": "voxels").
 *
 * A geodesic step of the exact sampled metric (SampledTensorField) sums the
 * cubic B-spline of g and its first derivatives over 64 samples and solves
 * for the Christoffel symbols, four times a Runge-Kutta step. Here the
 * spline's g and d_k g are evaluated once at every voxel (exactly, through
 * the wrapped metric), and a step reads the 8 voxels around it (24 numbers
 * each: 6 of g, 18 of dg), interpolates them trilinearly and makes the
 * symbols of those by the 3 x 3 inverse: about a third of the arithmetic.
 * At the voxels the symbols are the spline's; between them they are within
 * O(h^2) of them, the order to which the spline itself approximates smooth
 * data. (Interpolating the symbols themselves was cheaper still, but
 * g^-1 dg is huge on the small side of a jump of g, and one step of a
 * geodesic near a repaired background voxel went 36 km.) dg is then not
 * exactly the derivative of the interpolated g, so g(v, v) drifts by O(h^2)
 * along a geodesic (SpeedDrift shows it). Everything else (derivatives of g, curvature,
 * Jacobi fields, Validate) is the wrapped metric's, and so is the field
 * beyond the samples' box.
 *
 * The shader (EmitGlsl, VoxelChristoffelMetricGlsl.cxx) reads the same 24
 * numbers from six RGBA float 3D textures with the texture unit's trilinear
 * filtering: six reads an evaluation, where the spline weighs 64 texels of
 * two textures. The texture unit's weights are float on Mesa's llvmpipe (the
 * GPU's g and dg are the CPU's to float rounding) and 8-bit fractions on
 * most GPUs.
 *
 * Stored in float (96 bytes a voxel, and as much again for the textures once
 * a shader asks for them); made in the constructor on all cores (about a
 * microsecond a voxel on one).
 */
#ifndef RiemannVoxelChristoffelMetric_h
#define RiemannVoxelChristoffelMetric_h

#include "Metric.h"
#include "RiemannCommonMetricExport.h"
#include "SampledTensorField.h"

#include <array>
#include <memory>
#include <mutex>
#include <vector>

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT VoxelChristoffelMetric : public Metric
{
public:
  /**
   * `exact`: the sampled metric on `grid`'s voxels, a TensorMetric of a
   * SampledTensorField (else std::invalid_argument).
   */
  VoxelChristoffelMetric(std::shared_ptr<const Metric> exact, const SampledTensorGrid& grid);

  std::string FamilyName() const override { return this->Exact->FamilyName(); }
  std::string Describe() const override;
  /// Trilinear g from the voxels (the wrapped metric's beyond the box).
  bool Tensor(const Vec3& p, Mat3& g) const override;
  bool TensorDerivatives(const Vec3& p, Mat3& g, Mat3Stack& dg) const override
  {
    return this->Exact->TensorDerivatives(p, g, dg);
  }
  bool TensorSecondDerivatives(
    const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const override
  {
    return this->Exact->TensorSecondDerivatives(p, g, dg, d2g);
  }
  LaneMask TensorSecondDerivativesPacket(
    const PacketVec3& x, PacketTensorJet& jet, LaneMask lanes) const override
  {
    return this->Exact->TensorSecondDerivativesPacket(x, jet, lanes);
  }
  /// The symbols of the trilinear g and dg (the wrapped metric's beyond the box).
  bool Christoffel(const Vec3& p, Mat3Stack& gamma) const override;
  bool Acceleration(const Vec3& p, const Vec3& v, Vec3& a) const override;
  /**
   * Acceleration() of PacketWidth geodesics: each lane gathers its 8 voxels,
   * then the symbols are contracted with v for all lanes at once (g^-1 by
   * the adjugate, a structure of arrays the compiler vectorises), without
   * the 27 symbols a lane's Christoffel() makes. Lanes beyond the box: the
   * wrapped metric's.
   */
  LaneMask AccelerationPacket(
    const PacketVec3& x, const PacketVec3& v, PacketVec3& a, LaneMask lanes) const override;
  bool InsideData(const Vec3& p) const override { return this->Exact->InsideData(p); }
  std::string Validate() const override { return this->Exact->Validate(); }
  /// The trilinear g and dg from six filtered texture reads; beyond the box
  /// the wrapped metric's (g = I, or with "outside": "stop" the spline's).
  void EmitGlsl(GlslBuilder& builder) const override;
  const Metric& GetExact() const { return *this->Exact; }
  /// The samples' spline (the wrapped metric's field).
  const SampledTensorField& GetField() const { return *this->Field; }

private:
  /// Of the 24 numbers of a voxel (g: XX YY ZZ XY YZ XZ, then d_k g in the
  /// same order, k = 0, 1, 2), those in [first, first + count) interpolated
  /// at p; false beyond the box.
  bool Interpolate(const Vec3& p, int first, int count, float* values) const;

  /// The 24 numbers of every voxel at texel (i, j, k), one RGBA texture per
  /// 4 of them: made on the first EmitGlsl().
  void MakeTexels() const;

  std::shared_ptr<const Metric> Exact;
  const SampledTensorField* Field = nullptr; // the spline, owned through Exact
  SampledTensorGrid Geometry; // the grid's placement (no components)
  Mat3 WorldToGrid;
  std::vector<float> Samples; // 24 per voxel
  mutable std::once_flag TexelsMade;
  mutable std::array<std::shared_ptr<const std::vector<float>>, 6> Texels;
};
} // namespace riemann

#endif
