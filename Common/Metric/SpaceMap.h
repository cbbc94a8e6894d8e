/**
 * @class riemann::SpaceMap
 * @brief A smooth map Phi : R^3 -> R^3 with exact derivatives to third order;
 * the diffeomorphism family pulls Euclidean space back through it.
 *
 * Immutable after construction, thread-safe, no allocation in Evaluate().
 */
#ifndef RiemannSpaceMap_h
#define RiemannSpaceMap_h

#include "GlslSource.h"
#include "Jets.h"
#include "RiemannCommonMetricExport.h"

#include <string>
#include <vector>

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT SpaceMap
{
public:
  virtual ~SpaceMap() = default;

  /// Fill `jet` with Phi(p) and its derivatives up to `order` (a DerivativeOrder).
  virtual void Evaluate(const Vec3& p, int order, VectorJet& jet) const = 0;

  virtual std::string Describe() const = 0;

  /**
   * Solve Phi(p) = y. The default is damped Newton from `p = y` (the maps
   * here are perturbations of the identity); subclasses with a closed form
   * override it. Returns false when it does not converge to `tolerance`.
   */
  virtual bool Inverse(const Vec3& y, Vec3& p, double tolerance = 1e-13) const;

  /**
   * Check that the map is a diffeomorphism where it varies. Returns an empty
   * string when it is, otherwise a message that says where and why not.
   * The default samples det J > 0 at AppendSamplePoints().
   */
  virtual std::string CheckDiffeomorphism() const;

  /// Points where the map varies, for validation sampling.
  virtual void AppendSamplePoints(std::vector<Vec3>& points) const { (void)points; }

  /**
   * Emit a GLSL function
   *   void NAME(vec3 p, out vec3 y, out mat3 J, out mat3 H0, out mat3 H1, out mat3 H2)
   * giving Phi(p), its Jacobian (a GLSL mat3 whose column i is d_i Phi) and
   * the Hessians of the three components; returns NAME. The default refuses.
   */
  virtual std::string EmitGlsl(GlslBuilder& builder) const
  {
    (void)builder;
    throw GlslUnsupportedError(this->Describe() + " has no GLSL form");
  }
};
} // namespace riemann

#endif
