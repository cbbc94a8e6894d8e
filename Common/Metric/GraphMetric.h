/**
 * @class riemann::GraphMetric
 * @brief Family 1: the metric of the graph of f : R^3 -> R as a hypersurface
 * of R^4, g_ij = delta_ij + f_i f_j (MATH.md).
 *
 * Always positive definite; Gamma^m_ij = f_m f_ij / (1 + |grad f|^2), so the
 * geodesic acceleration is -grad f (v^T H v) / (1 + |grad f|^2).
 */
#ifndef RiemannGraphMetric_h
#define RiemannGraphMetric_h

#include "Metric.h"
#include "ScalarField.h"
#include "RiemannCommonMetricExport.h"

#include <memory>

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT GraphMetric : public Metric
{
public:
  explicit GraphMetric(std::shared_ptr<const ScalarField> f);

  std::string FamilyName() const override { return "graph"; }
  std::string Describe() const override;
  bool Tensor(const Vec3& p, Mat3& g) const override;
  bool TensorDerivatives(const Vec3& p, Mat3& g, Mat3Stack& dg) const override;
  bool TensorSecondDerivatives(
    const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const override;
  bool Christoffel(const Vec3& p, Mat3Stack& gamma) const override;
  void EmitGlsl(GlslBuilder& builder) const override;
  bool Acceleration(const Vec3& p, const Vec3& v, Vec3& a) const override;
  LaneMask AccelerationPacket(
    const PacketVec3& x, const PacketVec3& v, PacketVec3& a, LaneMask lanes) const override;
  LaneMask TensorPacket(const PacketVec3& x, PacketSym3& g, LaneMask lanes) const override;
  void VolumeFormPacket(const PacketVec3& x, double* volume, LaneMask lanes) const override;
  LaneMask TensorSecondDerivativesPacket(
    const PacketVec3& x, PacketTensorJet& jet, LaneMask lanes) const override;
  LaneMask JacobiAccelerationPacket(
    const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes) const override;
  /// Sherman-Morrison: g^ij = delta_ij - f_i f_j / (1 + |grad f|^2).
  bool InverseTensor(const Vec3& p, Mat3& inverse) const override;
  /// sqrt(1 + |grad f|^2).
  double VolumeForm(const Vec3& p) const override;

  const ScalarField& GetField() const { return *this->Field; }

  /**
   * g = I + grad f grad f^T is positive definite wherever grad f is finite.
   * For a sum of Gaussians that holds everywhere when the sum of the terms'
   * gradient bounds, |a| sqrt(max w) e^(-1/2) each, is finite with its
   * square: checked in O(N) for N bumps (sampling g around every bump, as
   * Metric::Validate does, evaluated the whole sum at 17^3 points per bump:
   * O(N^2), over 100 s for 1600 bumps). Other fields are sampled.
   */
  std::string Validate() const override;

protected:
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

private:
  std::shared_ptr<const ScalarField>
    Field; // The field's bumps when it is a sum of Gaussians (the fused packet kernel).
  const GaussianTerms* Bumps = nullptr;
  double BumpsConstant = 0.0;
};
} // namespace riemann

#endif
