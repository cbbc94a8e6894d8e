/**
 * @class riemann::EuclideanMetric
 * @brief g = I: straight lines, the baseline every picture is compared with.
 */
#ifndef RiemannEuclideanMetric_h
#define RiemannEuclideanMetric_h

#include "Metric.h"
#include "RiemannCommonMetricExport.h"

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT EuclideanMetric : public Metric
{
public:
  std::string FamilyName() const override { return "euclidean"; }
  std::string Describe() const override { return "euclidean"; }
  bool Tensor(const Vec3& p, Mat3& g) const override;
  bool TensorDerivatives(const Vec3& p, Mat3& g, Mat3Stack& dg) const override;
  bool TensorSecondDerivatives(
    const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const override;
  bool Christoffel(const Vec3& p, Mat3Stack& gamma) const override;
  void EmitGlsl(GlslBuilder& builder) const override;
  bool Acceleration(const Vec3& p, const Vec3& v, Vec3& a) const override;
  bool InverseTensor(const Vec3& p, Mat3& inverse) const override;
  double VolumeForm(const Vec3& p) const override;
};
} // namespace riemann

#endif
