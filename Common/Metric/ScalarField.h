/**
 * @class riemann::ScalarField
 * @brief A smooth scalar field f : R^3 -> R with exact derivatives to third order.
 *
 * Providers are immutable after construction and therefore safe to evaluate
 * from many threads at once. Evaluate() must not allocate: it sits in the
 * innermost loop of every geodesic step.
 */
#ifndef RiemannScalarField_h
#define RiemannScalarField_h

#include "GlslSource.h"
#include "Jets.h"
#include "Packet.h"
#include "RiemannCommonMetricExport.h"

#include <string>
#include <vector>

namespace riemann
{
struct GaussianTerms;

class RIEMANNCOMMONMETRIC_EXPORT ScalarField
{
public:
  virtual ~ScalarField() = default;

  /// Fill `jet` with the value and derivatives up to `order` (a DerivativeOrder).
  void Evaluate(const Vec3& p, int order, ScalarJet& jet) const
  {
    jet.SetZero(order);
    this->Accumulate(p, order, jet);
  }

  /**
   * Add the value and derivatives up to `order` to `jet`. This, not
   * Evaluate, is what providers implement: a sum of many terms then adds
   * each in place instead of writing a temporary jet and reading it back,
   * which measured 1.7x faster geodesic steps on the 8-Gaussian benchmark.
   */
  virtual void Accumulate(const Vec3& p, int order, ScalarJet& jet) const = 0;

  /**
   * Add the value and derivatives up to `order` (any DerivativeOrder)
   * at the PacketWidth points of `p` to `jet`, for the packet engine. Lanes
   * outside `lanes` may be left as they are. The default calls Accumulate()
   * lane by lane; the built-in providers override it with SIMD loops
   * (PacketKernels.h) whose results equal Accumulate()'s to rounding.
   */
  virtual void AccumulatePacket(
    const PacketVec3& p, int order, PacketScalarJet& jet, LaneMask lanes) const
  {
    ScalarJet lane;
    for (int l = 0; l < PacketWidth; ++l)
    {
      if (!HasLane(lanes, l))
      {
        continue;
      }
      lane.SetZero(order);
      this->Accumulate(p.Lane(l), order, lane);
      jet.Value[l] += lane.Value;
      if (order >= FirstDerivatives)
      {
        for (int i = 0; i < 3; ++i)
        {
          jet.Gradient[i][l] += lane.Gradient[i];
        }
      }
      if (order >= SecondDerivatives)
      {
        PacketSym3 h;
        h.SetLane(l, lane.Hessian);
        for (int e = 0; e < 6; ++e)
        {
          jet.Hessian.C[e][l] += h.C[e][l];
        }
      }
      if (order >= ThirdDerivatives)
      {
        AddThirdLane(lane, l, jet);
      }
    }
  }

  /**
   * If this field is exactly `constant` plus a sum of Gaussian bumps, their
   * table (and the constant); else null. Lets the families call the fused
   * kernels of PacketKernels.h, which keep the jet in registers.
   */
  virtual const GaussianTerms* GaussianSum(double& constant) const
  {
    constant = 0.0;
    return nullptr;
  }

  /// AccumulatePacket onto a zeroed jet.
  void EvaluatePacket(const PacketVec3& p, int order, PacketScalarJet& jet, LaneMask lanes) const
  {
    jet.SetZero(order);
    this->AccumulatePacket(p, order, jet, lanes);
  }

  /// Add the third derivatives of `lane` to lane l of `jet`.
  static void AddThirdLane(const ScalarJet& lane, int l, PacketScalarJet& jet)
  {
    for (int e = 0; e < 10; ++e)
    {
      const int(&i)[3] = ThirdEntryIndices[e];
      jet.Third[e][l] += lane.Third[i[0]](i[1], i[2]);
    }
  }

  /// One line saying what the field is, for `riemann info` and error messages.
  virtual std::string Describe() const = 0;

  /**
   * Append points where the field varies, dense enough to resolve its
   * features: definitions are validated (positive definiteness,
   * diffeomorphism conditions) at these points.
   */
  virtual void AppendSamplePoints(std::vector<Vec3>& points) const { (void)points; }

  /**
   * Emit a GLSL function
   *   void NAME(vec3 p, inout float f, inout vec3 grad, inout mat3 hess)
   * that adds this field's value, gradient and Hessian (as Accumulate does),
   * with every number a uniform; returns NAME. The default refuses.
   */
  virtual std::string EmitGlsl(GlslBuilder& builder) const
  {
    (void)builder;
    throw GlslUnsupportedError(this->Describe() + " has no GLSL form");
  }
};
} // namespace riemann

#endif
