/**
 * @class riemann::MapComposition
 * @brief Phi = Phi_1 o Phi_2 o ... o Phi_k, differentiated by forward-mode
 * propagation of value, Jacobian, Hessians and third derivatives from the
 * innermost map (Phi_k) outwards (MATH.md, Family 2).
 */
#ifndef RiemannMapComposition_h
#define RiemannMapComposition_h

#include "SpaceMap.h"
#include "RiemannCommonMetricExport.h"

#include <memory>

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT MapComposition : public SpaceMap
{
public:
  /// maps[0] is the outermost (applied last), as in Phi_1 o Phi_2.
  explicit MapComposition(std::vector<std::shared_ptr<const SpaceMap>> maps);

  void Evaluate(const Vec3& p, int order, VectorJet& jet) const override;
  std::string Describe() const override;
  std::string EmitGlsl(GlslBuilder& builder) const override;
  /// Inverts each map in turn, outermost first.
  bool Inverse(const Vec3& y, Vec3& p, double tolerance = 1e-13) const override;
  /// A composition of diffeomorphisms is one: each map is checked on its own.
  std::string CheckDiffeomorphism() const override;
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

private:
  std::vector<std::shared_ptr<const SpaceMap>> Maps;
};
} // namespace riemann

#endif
