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
 * Jacobi fields, the shader, Validate) is the wrapped metric's, and so is
 * the field beyond the samples' box.
 *
 * Stored in float (96 bytes a voxel); made in the constructor, serially
 * (about a microsecond a voxel).
 */
#ifndef RiemannVoxelChristoffelMetric_h
#define RiemannVoxelChristoffelMetric_h

#include "Metric.h"
#include "RiemannCommonMetricExport.h"
#include "SampledTensorField.h"

#include <memory>
#include <vector>

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT VoxelChristoffelMetric : public Metric
{
public:
  /// `exact`: the sampled metric on `grid`'s voxels (TensorMetric of a SampledTensorField).
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
  bool InsideData(const Vec3& p) const override { return this->Exact->InsideData(p); }
  std::string Validate() const override { return this->Exact->Validate(); }
  void EmitGlsl(GlslBuilder& builder) const override { this->Exact->EmitGlsl(builder); }
  const Metric& GetExact() const { return *this->Exact; }

private:
  /// Of the 24 numbers of a voxel (g: XX YY ZZ XY YZ XZ, then d_k g in the
  /// same order, k = 0, 1, 2), those in [first, first + count) interpolated
  /// at p; false beyond the box.
  bool Interpolate(const Vec3& p, int first, int count, float* values) const;

  std::shared_ptr<const Metric> Exact;
  SampledTensorGrid Geometry; // the grid's placement (no components)
  Mat3 WorldToGrid;
  std::vector<float> Samples; // 24 per voxel
};
} // namespace riemann

#endif
