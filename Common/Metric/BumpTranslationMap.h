/**
 * @class riemann::BumpTranslationMap
 * @brief The paper's local deformation Phi(p) = p + f(p) V(p), with
 * V(p) = A (p - c) + b: a constant direction v (A = 0, b = v) or an affine
 * field (a local twist or stretch around c).
 *
 * It is a diffeomorphism only while det J = det(I + V grad f^T + f A) > 0
 * everywhere; for a constant direction det J = 1 + grad f . v.
 */
#ifndef RiemannBumpTranslationMap_h
#define RiemannBumpTranslationMap_h

#include "ScalarField.h"
#include "SpaceMap.h"
#include "RiemannCommonMetricExport.h"

#include <memory>

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT BumpTranslationMap : public SpaceMap
{
public:
  /// Constant direction: Phi(p) = p + f(p) v.
  BumpTranslationMap(std::shared_ptr<const ScalarField> f, const Vec3& direction);
  /// Affine field: Phi(p) = p + f(p) (A (p - c) + b).
  BumpTranslationMap(std::shared_ptr<const ScalarField> f, const Mat3& matrix, const Vec3& center,
    const Vec3& offset);

  void Evaluate(const Vec3& p, int order, VectorJet& jet) const override;
  std::string Describe() const override;
  std::string EmitGlsl(GlslBuilder& builder) const override;
  /**
   * For a Gaussian f and a constant v the minimum of grad f . v is known in
   * closed form (-|a| |w| e^{-1/2}, w_i = v_i / s_i), so the check is exact;
   * otherwise det J is sampled where f varies.
   */
  std::string CheckDiffeomorphism() const override;
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

private:
  std::shared_ptr<const ScalarField> Field;
  Mat3 Matrix;
  Vec3 Center;
  Vec3 Offset;
  bool ConstantDirection;
};
} // namespace riemann

#endif
