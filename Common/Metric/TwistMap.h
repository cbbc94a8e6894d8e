/**
 * @class riemann::TwistMap
 * @brief The paper's twist: rotate each plane z = const by the angle k z,
 * Phi(x,y,z) = (cos(kz) x - sin(kz) y, sin(kz) x + cos(kz) y, z), k = rate.
 * A diffeomorphism for every k; its inverse is the rotation by -k z.
 */
#ifndef RiemannTwistMap_h
#define RiemannTwistMap_h

#include "SpaceMap.h"
#include "RiemannCommonMetricExport.h"

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT TwistMap : public SpaceMap
{
public:
  explicit TwistMap(double rate);

  void Evaluate(const Vec3& p, int order, VectorJet& jet) const override;
  std::string Describe() const override;
  std::string EmitGlsl(GlslBuilder& builder) const override;
  bool Inverse(const Vec3& y, Vec3& p, double tolerance = 1e-13) const override;
  std::string CheckDiffeomorphism() const override { return {}; }

  double GetRate() const { return this->Rate; }

private:
  double Rate;
};
} // namespace riemann

#endif
