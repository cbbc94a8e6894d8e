/**
 * @class riemann::ScalarFieldSum
 * @brief f = c + f_1 + ... + f_k (the paper's "summing functions"):
 * values and all derivatives add.
 */
#ifndef RiemannScalarFieldSum_h
#define RiemannScalarFieldSum_h

#include "GaussianTerms.h"
#include "ScalarField.h"
#include "RiemannCommonMetricExport.h"

#include <memory>

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT ScalarFieldSum : public ScalarField
{
public:
  ScalarFieldSum(double constant, std::vector<std::shared_ptr<const ScalarField>> terms);

  void Accumulate(const Vec3& p, int order, ScalarJet& jet) const override;
  void AccumulatePacket(
    const PacketVec3& p, int order, PacketScalarJet& jet, LaneMask lanes) const override;
  /// The bumps' table when every term is a Gaussian bump.
  const GaussianTerms* GaussianSum(double& constant) const override
  {
    constant = this->Constant;
    return this->OtherTerms.empty() ? &this->Bumps : nullptr;
  }
  std::string Describe() const override;
  std::string EmitGlsl(GlslBuilder& builder) const override;
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

  double GetConstant() const { return this->Constant; }
  const std::vector<std::shared_ptr<const ScalarField>>& GetTerms() const { return this->Terms; }

private:
  double Constant;
  std::vector<std::shared_ptr<const ScalarField>> Terms;
  // The hot path's view of Terms: the Gaussian bumps as one flat table
  // (one loop, no virtual call per bump), and the other terms.
  GaussianTerms Bumps;
  std::vector<const ScalarField*> OtherTerms;
};
} // namespace riemann

#endif
