/**
 * @class riemann::Metric
 * @brief A Riemannian metric g on (a region of) R^3: one of the families of
 * MATH.md (graph, diffeomorphism, conformal, tensor, Euclidean).
 *
 * Every family gives g, g^-1, d g, the Christoffel symbols by its own
 * specialised formula, the geodesic acceleration and the volume form.
 * Evaluation methods return false where the metric is degenerate or not
 * finite (not positive definite, det J = 0, n <= 0, NaN): a geodesic reaching
 * such a point stops there with its own termination reason.
 *
 * The packet integrators see a metric as a PacketGeodesicSystem (the
 * interface of the packet engine's library, which lies below this one).
 *
 * Metrics are immutable after construction: one instance may be evaluated
 * from any number of threads at once, and evaluation never allocates.
 */
#ifndef RiemannMetric_h
#define RiemannMetric_h

#include "GlslSource.h"
#include "Jets.h"
#include "Packet.h"
#include "PacketGeodesicSystem.h"
#include "RiemannCommonMetricExport.h"

#include <string>
#include <vector>

namespace riemann
{
class RIEMANNCOMMONMETRIC_EXPORT Metric : public PacketGeodesicSystem
{
public:
  virtual ~Metric() = default;

  /// "graph", "diffeo", "conformal", "tensor" or "euclidean".
  virtual std::string FamilyName() const = 0;
  /// One line: the family and its providers.
  virtual std::string Describe() const = 0;

  /// g_ij at p.
  virtual bool Tensor(const Vec3& p, Mat3& g) const = 0;
  /// g_ij and dg[k](i, j) = d_k g_ij at p.
  virtual bool TensorDerivatives(const Vec3& p, Mat3& g, Mat3Stack& dg) const = 0;
  /**
   * g_ij, dg[k](i, j) = d_k g_ij and d2g[k][l](i, j) = d_k d_l g_ij at p,
   * exact (from the providers' third derivatives): what curvature needs
   * (Curvature.h). The default refuses (returns false); every family of
   * the metric core overrides it.
   */
  virtual bool TensorSecondDerivatives(
    const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const;
  /**
   * TensorSecondDerivatives at PacketWidth points (Packet.h's
   * PacketTensorJet), on the lanes of `lanes`; returns those where it
   * succeeds. The default calls TensorSecondDerivatives() lane by lane; the
   * graph and conformal families override it with SIMD kernels on their
   * providers' packet jets (PacketCurvature.h).
   */
  virtual LaneMask TensorSecondDerivativesPacket(
    const PacketVec3& x, PacketTensorJet& jet, LaneMask lanes) const;
  /// gamma[m](i, j) = Gamma^m_ij at p, by the family's specialised formula.
  virtual bool Christoffel(const Vec3& p, Mat3Stack& gamma) const = 0;
  /**
   * Geodesic acceleration a^m = -Gamma^m_ij v^i v^j: the hot path of every
   * integrator. The default contracts Christoffel(); families override it with
   * a cheaper closed form.
   */
  virtual bool Acceleration(const Vec3& p, const Vec3& v, Vec3& a) const;
  /**
   * The acceleration of PacketWidth geodesics at once (Packet.h), the hot
   * path of the packet integrators: a on the lanes of `lanes`, returning
   * those where it is defined and finite. The default calls Acceleration()
   * lane by lane; families whose providers have SIMD forms override it, with
   * results equal to Acceleration()'s to rounding.
   */
  LaneMask AccelerationPacket(
    const PacketVec3& x, const PacketVec3& v, PacketVec3& a, LaneMask lanes) const override;
  /**
   * The Jacobi system's accelerations of PacketWidth geodesics with their
   * two variations (JacobiField.h): dy.V = a = -Gamma(v, v) and, for each
   * variation (y.J[k], y.DJ[k]), dy.DJ[k] = -(d_J Gamma)(v, v)
   * - 2 Gamma(v, DJ), the linearisation of a. Only dy.V and dy.DJ are
   * written. Returns the lanes of `lanes` where all are defined and finite.
   * The default takes TensorSecondDerivativesPacket() and computes the
   * Christoffel symbols, their derivatives and the contractions on the
   * packet (PacketCurvature.h); the graph and conformal families override
   * it with the derivatives of their closed-form accelerations.
   */
  LaneMask JacobiAccelerationPacket(
    const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes) const override;
  /// g at PacketWidth points; the default calls Tensor() lane by lane.
  virtual LaneMask TensorPacket(const PacketVec3& x, PacketSym3& g, LaneMask lanes) const;
  /// g^ij at p. The default inverts Tensor() by Cholesky.
  virtual bool InverseTensor(const Vec3& p, Mat3& inverse) const;
  /// sqrt(det g) at p; NaN where the metric is degenerate.
  virtual double VolumeForm(const Vec3& p) const;
  /**
   * VolumeForm() at PacketWidth points into volume[0, PacketWidth) (lanes
   * outside `lanes` are left as they are). The default calls VolumeForm()
   * lane by lane; the graph and conformal families evaluate their
   * providers on the packet.
   */
  virtual void VolumeFormPacket(const PacketVec3& x, double* volume, LaneMask lanes) const;

  /// g_p(u, w); NaN where the metric is degenerate.
  double InnerProduct(const Vec3& p, const Vec3& u, const Vec3& w) const;

  /**
   * Whether p is where the metric's data holds. A sampled metric with
   * "outside": "stop" is false beyond its volume, and geodesics and rays
   * stop there (TerminationReason OutOfData); every other metric is defined
   * everywhere (true). g stays defined beyond, so a step that crosses the
   * boundary completes before the stop.
   */
  virtual bool InsideData(const Vec3& p) const
  {
    (void)p;
    return true;
  }

  /**
   * Check the definition where its providers vary (and on a coarse grid over
   * [-5, 5]^3): g finite and positive definite, maps diffeomorphisms. Returns
   * an empty string when valid, else a message that says where and why not.
   */
  virtual std::string Validate() const;

  /**
   * Emit the metric part of the ray-tracing shader (GlslSource.h):
   * rt_metric_tensor and rt_metric_acceleration. The default refuses with
   * GlslUnsupportedError naming the metric.
   */
  virtual void EmitGlsl(GlslBuilder& builder) const;

protected:
  /// Points where Validate() samples g: the providers' features.
  virtual void AppendSamplePoints(std::vector<Vec3>& points) const { (void)points; }
};
} // namespace riemann

#endif
