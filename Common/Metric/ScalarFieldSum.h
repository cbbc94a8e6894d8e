/**
 * @class riemann::ScalarFieldSum
 * @brief f = c + f_1 + ... + f_k (the paper's "summing functions"):
 * values and all derivatives add.
 */
#ifndef RiemannScalarFieldSum_h
#define RiemannScalarFieldSum_h

#include "ScalarField.h"

#include <memory>

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT ScalarFieldSum : public ScalarField
{
public:
  ScalarFieldSum(double constant, std::vector<std::shared_ptr<const ScalarField>> terms);

  void Accumulate(const Vec3& p, int order, ScalarJet& jet) const override;
  std::string Describe() const override;
  std::string EmitGlsl(GlslBuilder& builder) const override;
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

  double GetConstant() const { return this->Constant; }
  const std::vector<std::shared_ptr<const ScalarField>>& GetTerms() const { return this->Terms; }

private:
  double Constant;
  std::vector<std::shared_ptr<const ScalarField>> Terms;
};
} // namespace riemann

#endif
