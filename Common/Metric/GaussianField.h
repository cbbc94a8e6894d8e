/**
 * @class riemann::GaussianField
 * @brief The paper's anisotropic Gaussian bump
 * f(p) = a exp(-sum_i (p_i - c_i)^2 / (2 s_i^2)).
 */
#ifndef RiemannGaussianField_h
#define RiemannGaussianField_h

#include "GaussianTerms.h"
#include "ScalarField.h"
#include "RiemannCommonMetricExport.h"

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT GaussianField : public ScalarField
{
public:
  /// `sigma` must be positive in every component (checked by the JSON parser).
  GaussianField(double amplitude, const Vec3& center, const Vec3& sigma);

  void Accumulate(const Vec3& p, int order, ScalarJet& jet) const override;
  void AccumulatePacket(
    const PacketVec3& p, int order, PacketScalarJet& jet, LaneMask lanes) const override;
  const GaussianTerms* GaussianSum(double& constant) const override
  {
    constant = 0.0;
    return &this->Term;
  }
  std::string Describe() const override;
  std::string EmitGlsl(GlslBuilder& builder) const override;
  /// A 17^3 grid over center +- 4 sigma (spacing sigma/2 resolves the bump).
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

  double GetAmplitude() const { return this->Amplitude; }
  const Vec3& GetCenter() const { return this->Center; }
  const Vec3& GetSigma() const { return this->Sigma; }

private:
  double Amplitude;
  Vec3 Center;
  Vec3 Sigma;
  Vec3 InverseVariance; // 1 / sigma^2, precomputed for the hot path
  GaussianTerms Term;   // this bump as a table of one, for the packet kernel
};

/**
 * Add the value and derivatives up to `order` of the sum of `terms` at p to
 * `jet`: GaussianField::Accumulate's formulas in one loop over a table
 * (ScalarFieldSum's bumps, without a virtual call per bump).
 */
RIEMANNCOMMONMETRIC_EXPORT void AccumulateGaussianTerms(
  const GaussianTerms& terms, const Vec3& p, int order, ScalarJet& jet);
} // namespace riemann

#endif
