/**
 * @class riemann::TensorMetric
 * @brief Family 4: any symmetric positive-definite tensor field g_ij(x),
 * with Christoffel symbols from the general formula (Christoffel.h).
 *
 * The field comes from a TensorField provider: a constant matrix here,
 * component expressions (ExpressionFields.h), samples on a grid
 * (SampledTensorField.h). Every
 * specialised family must agree with this general path.
 */
#ifndef RiemannTensorMetric_h
#define RiemannTensorMetric_h

#include "Metric.h"
#include "RiemannCommonMetricExport.h"

#include <memory>

namespace riemann
{
/// A symmetric tensor field and its derivatives dg[k](i, j) = d_k g_ij (and, optionally, second
/// ones).
class RIEMANNCOMMONMETRIC_EXPORT TensorField
{
public:
  virtual ~TensorField() = default;
  /// Fill g, and dg when `withDerivatives`.
  virtual void Evaluate(const Vec3& p, bool withDerivatives, Mat3& g, Mat3Stack& dg) const = 0;
  /**
   * Fill g, dg and d2g[k][l](i, j) = d_k d_l g_ij. Returns false where the
   * field has no second derivatives: the default refuses.
   */
  virtual bool EvaluateSecond(
    const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const
  {
    (void)p;
    (void)g;
    (void)dg;
    (void)d2g;
    return false;
  }
  /**
   * EvaluateSecond at PacketWidth points into `jet` (Packet.h); returns the
   * lanes of `lanes` where it succeeds. The default calls EvaluateSecond()
   * lane by lane; typed fields run their tape on the packet.
   */
  virtual LaneMask EvaluateSecondPacket(
    const PacketVec3& x, PacketTensorJet& jet, LaneMask lanes) const;
  virtual std::string Describe() const = 0;
  /// Where the field's data holds (Metric::InsideData); everywhere by default.
  virtual bool InsideData(const Vec3& p) const
  {
    (void)p;
    return true;
  }
  virtual void AppendSamplePoints(std::vector<Vec3>& points) const { (void)points; }
  /**
   * Emit a GLSL function
   *   void NAME(vec3 p, out mat3 g, out mat3 dg0, out mat3 dg1, out mat3 dg2)
   * giving g and its derivatives dg_k = d_k g; returns NAME. The default refuses.
   */
  virtual std::string EmitGlsl(GlslBuilder& builder) const
  {
    (void)builder;
    throw GlslUnsupportedError("the tensor field " + this->Describe() + " has no GLSL form");
  }
};

/// g_ij = constant (symmetrised on construction).
class RIEMANNCOMMONMETRIC_EXPORT ConstantTensorField : public TensorField
{
public:
  explicit ConstantTensorField(const Mat3& value);
  void Evaluate(const Vec3& p, bool withDerivatives, Mat3& g, Mat3Stack& dg) const override;
  bool EvaluateSecond(
    const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const override;
  std::string Describe() const override;
  std::string EmitGlsl(GlslBuilder& builder) const override;

private:
  Mat3 Value;
};

class RIEMANNCOMMONMETRIC_EXPORT TensorMetric : public Metric
{
public:
  explicit TensorMetric(std::shared_ptr<const TensorField> field);

  std::string FamilyName() const override { return "tensor"; }
  std::string Describe() const override;
  /// False where g is not finite or not positive definite (Cholesky fails).
  bool Tensor(const Vec3& p, Mat3& g) const override;
  bool TensorDerivatives(const Vec3& p, Mat3& g, Mat3Stack& dg) const override;
  /// False where the field has no second derivatives (TensorField::EvaluateSecond refuses).
  bool TensorSecondDerivatives(
    const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const override;
  LaneMask TensorSecondDerivativesPacket(
    const PacketVec3& x, PacketTensorJet& jet, LaneMask lanes) const override;
  bool Christoffel(const Vec3& p, Mat3Stack& gamma) const override;
  bool InsideData(const Vec3& p) const override { return this->Field->InsideData(p); }
  void EmitGlsl(GlslBuilder& builder) const override;
  const TensorField& GetField() const { return *this->Field; }

protected:
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

private:
  std::shared_ptr<const TensorField> Field;
};

/**
 * rt_metric_tensor and rt_metric_acceleration (GlslSource.h) of the metric
 * whose g and first derivatives the GLSL function `field` gives (the
 * signature of TensorField::EmitGlsl): the general formula of the
 * Christoffel symbols, contracted with v twice. TensorMetric's shader, and
 * that of metrics that read g and dg another way (VoxelChristoffelMetric).
 */
RIEMANNCOMMONMETRIC_EXPORT void EmitTensorMetricGlsl(GlslBuilder& builder, const std::string& field);
} // namespace riemann

#endif
