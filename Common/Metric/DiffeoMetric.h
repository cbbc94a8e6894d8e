/**
 * @class riemann::DiffeoMetric
 * @brief Family 2: Euclidean space pulled back through a diffeomorphism Phi,
 * g = J^T J (MATH.md). Flat; its geodesics are Phi^-1 of straight lines,
 * which ExactGeodesic() evaluates as the reference for every integrator.
 *
 * Gamma^m_ij = sum_s (d_i d_j Phi_s) [J^-1]_ms, so the acceleration is
 * -J^-1 w with w_s = v^T H_s v.
 */
#ifndef RiemannDiffeoMetric_h
#define RiemannDiffeoMetric_h

#include "Metric.h"
#include "SpaceMap.h"
#include "RiemannCommonMetricExport.h"

#include <memory>

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT DiffeoMetric : public Metric
{
public:
  explicit DiffeoMetric(std::shared_ptr<const SpaceMap> map);

  std::string FamilyName() const override { return "diffeo"; }
  std::string Describe() const override;
  bool Tensor(const Vec3& p, Mat3& g) const override;
  bool TensorDerivatives(const Vec3& p, Mat3& g, Mat3Stack& dg) const override;
  bool TensorSecondDerivatives(
    const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const override;
  bool Christoffel(const Vec3& p, Mat3Stack& gamma) const override;
  void EmitGlsl(GlslBuilder& builder) const override;
  bool Acceleration(const Vec3& p, const Vec3& v, Vec3& a) const override;
  /// |det J|.
  double VolumeForm(const Vec3& p) const override;
  /// The map's own diffeomorphism check, then the sampled positive-definiteness check.
  std::string Validate() const override;

  /**
   * The exact geodesic from p with initial velocity v at parameter t:
   * Phi^-1(Phi(p) + t J(p) v). Returns false if the inversion fails.
   */
  bool ExactGeodesic(const Vec3& p, const Vec3& v, double t, Vec3& point) const;

  const SpaceMap& GetMap() const { return *this->Map; }

protected:
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

private:
  std::shared_ptr<const SpaceMap> Map;
};
} // namespace riemann

#endif
