/**
 * @class riemann::ConformalMetric
 * @brief Family 3: g = n(x)^2 I, light in a medium of refractive index n
 * (Fermat's principle; the paper's mirages). Volume form n^3.
 *
 * With L = grad ln n: Gamma^m_ij = delta_mi L_j + delta_mj L_i - delta_ij L_m,
 * so the acceleration is a = |v|^2 L - 2 (L . v) v. Degenerate where n <= 0.
 */
#ifndef RiemannConformalMetric_h
#define RiemannConformalMetric_h

#include "Metric.h"
#include "ScalarField.h"
#include "RiemannCommonMetricExport.h"

#include <memory>

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT ConformalMetric : public Metric
{
public:
  explicit ConformalMetric(std::shared_ptr<const ScalarField> index);

  std::string FamilyName() const override { return "conformal"; }
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
  bool InverseTensor(const Vec3& p, Mat3& inverse) const override;
  double VolumeForm(const Vec3& p) const override;
  /// Checks n > 0 (and finite) at the sample points, naming the value found.
  std::string Validate() const override;

  const ScalarField& GetIndex() const { return *this->Index; }

protected:
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

private:
  std::shared_ptr<const ScalarField>
    Index; // The field's bumps when it is a sum of Gaussians (the fused packet kernel).
  const GaussianTerms* Bumps = nullptr;
  double BumpsConstant = 0.0;
};
} // namespace riemann

#endif
