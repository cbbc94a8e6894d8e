/**
 * @class riemann::QuadraticField
 * @brief f(p) = p^T A p + b . p + c, e.g. the paper's x^2+y^2+z^2 (A = I)
 * and x^2+y^2-z^2 (A = diag(1,1,-1)). A is symmetrised on construction.
 */
#ifndef RiemannQuadraticField_h
#define RiemannQuadraticField_h

#include "ScalarField.h"
#include "RiemannCommonMetricExport.h"

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT QuadraticField : public ScalarField
{
public:
  QuadraticField(const Mat3& matrix, const Vec3& linear, double constant);

  void Accumulate(const Vec3& p, int order, ScalarJet& jet) const override;
  std::string Describe() const override;
  std::string EmitGlsl(GlslBuilder& builder) const override;
  /// A 9^3 grid over [-4, 4]^3: a quadratic has no localized feature.
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

private:
  Mat3 Matrix;
  Vec3 Linear;
  double Constant;
};
} // namespace riemann

#endif
