// The graph family's packet kernels (GraphMetric.h has its scalar form and
// GLSL): accelerations and Jacobi accelerations from the jet of f, and the
// acceleration of a sum of Gaussians fused with its jet. Written once with
// Google Highway, compiled once per x86 target.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "GraphMetricPackets.cxx"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include "GraphMetricPackets.h"
#include "GaussianFieldLanes-inl.h"
#include "PacketLanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace riemann
{
namespace HWY_NAMESPACE
{
/// a = -grad f (v^T H v) / (1 + |grad f|^2), stored at lanes [o, o + N) of
/// `a`; returns the lanes where a is finite.
HWY_INLINE LaneMask StoreGraphAcceleration(
  const JetVectors& f, V vx, V vy, V vz, PacketVec3& a, int o)
{
  const D d;
  // v^T H v = sum_i h_ii v_i^2 + 2 (h_xy vx vy + h_xz vx vz + h_yz vy vz).
  const V diagonal = hn::MulAdd(
    hn::Mul(f.Hzz, vz), vz, hn::MulAdd(hn::Mul(f.Hyy, vy), vy, hn::Mul(hn::Mul(f.Hxx, vx), vx)));
  const V offDiagonal = hn::MulAdd(
    hn::Mul(f.Hyz, vy), vz, hn::MulAdd(hn::Mul(f.Hxz, vx), vz, hn::Mul(hn::Mul(f.Hxy, vx), vy)));
  const V vHv = hn::MulAdd(hn::Set(d, 2.0), offDiagonal, diagonal);
  const V gradientSquared = hn::MulAdd(f.Gz, f.Gz, hn::MulAdd(f.Gy, f.Gy, hn::Mul(f.Gx, f.Gx)));
  const V s = hn::Neg(hn::Div(vHv, hn::Add(hn::Set(d, 1.0), gradientSquared)));
  const V ax = hn::Mul(s, f.Gx);
  const V ay = hn::Mul(s, f.Gy);
  const V az = hn::Mul(s, f.Gz);
  hn::Store(ax, d, a.C[0] + o);
  hn::Store(ay, d, a.C[1] + o);
  hn::Store(az, d, a.C[2] + o);
  return BitsAt(d, AllFinite(ax, ay, az), o);
}

LaneMask GraphAccelerationFromJetImpl(const PacketScalarJet& f, const PacketVec3& v, PacketVec3& a)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  LaneMask finite = 0;
  for (int o = 0; o < PacketWidth; o += n)
  {
    finite |= StoreGraphAcceleration(LoadJet(f, o), hn::Load(d, v.C[0] + o),
      hn::Load(d, v.C[1] + o), hn::Load(d, v.C[2] + o), a, o);
  }
  return finite;
}

LaneMask GraphAccelerationOfGaussiansImpl(
  const GaussianTerms& terms, const PacketVec3& x, const PacketVec3& v, PacketVec3& a)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  LaneMask finite = 0;
  for (int o = 0; o < PacketWidth; o += n)
  {
    JetVectors f = ZeroJet(d);
    AddGaussianTerms<SecondDerivatives>(
      terms, hn::Load(d, x.C[0] + o), hn::Load(d, x.C[1] + o), hn::Load(d, x.C[2] + o), f);
    finite |= StoreGraphAcceleration(
      f, hn::Load(d, v.C[0] + o), hn::Load(d, v.C[1] + o), hn::Load(d, v.C[2] + o), a, o);
  }
  return finite;
}

/**
 * The graph family's Jacobi accelerations at lanes [o, o + N). With
 * q = v^T H v, W = 1 + |grad f|^2 and s = -q / W: a = s grad f. Along a
 * variation (X, V): dq = T(X, v, v) + 2 v^T H V, dW = 2 grad f . H X,
 * ds = (-dq - s dW) / W and A = ds grad f + s H X: the linearisation of a,
 * which is -(d_X Gamma)(v, v) - 2 Gamma(v, V). Returns the lanes where all
 * are finite.
 */
HWY_INLINE LaneMask StoreGraphJacobiAccelerations(
  const PacketScalarJet& f, const PacketJacobiState& y, PacketJacobiState& dy, int o)
{
  const D d;
  const Vec3Vectors gradient = LoadVec3(f.Gradient, o);
  V h[6];
  V t[10];
  for (int e = 0; e < 6; ++e)
  {
    h[e] = hn::Load(d, f.Hessian.C[e] + o);
  }
  for (int e = 0; e < 10; ++e)
  {
    t[e] = hn::Load(d, f.Third[e] + o);
  }
  const Vec3Vectors v = LoadVec3(y.V.C, o);
  const Vec3Vectors hv = SymmetricTimes(h, v);
  const V w = hn::Add(hn::Set(d, 1.0), Dot(gradient, gradient));
  const V s = hn::Neg(hn::Div(Dot(v, hv), w));
  const Vec3Vectors a = { hn::Mul(s, gradient.X), hn::Mul(s, gradient.Y), hn::Mul(s, gradient.Z) };
  StoreVec3(a, dy.V, o);
  M finite = AllFinite(a);
  const V two = hn::Set(d, 2.0);
  for (int k = 0; k < 2; ++k)
  {
    const Vec3Vectors x = LoadVec3(y.J[k].C, o);
    const Vec3Vectors variation = LoadVec3(y.DJ[k].C, o);
    V m[6];
    ContractThird(t, x, m);
    const Vec3Vectors hx = SymmetricTimes(h, x);
    const V dq = hn::MulAdd(two, Dot(hv, variation), Dot(v, SymmetricTimes(m, v)));
    const V dw = hn::Mul(two, Dot(gradient, hx));
    const V ds = hn::Div(hn::NegMulSub(s, dw, dq), w);
    const Vec3Vectors acceleration = Combine(ds, gradient, s, hx);
    StoreVec3(acceleration, dy.DJ[k], o);
    finite = hn::And(finite, AllFinite(acceleration));
  }
  return BitsAt(d, finite, o);
}

LaneMask GraphJacobiAccelerationsFromJetImpl(
  const PacketScalarJet& f, const PacketJacobiState& y, PacketJacobiState& dy)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  LaneMask finite = 0;
  for (int o = 0; o < PacketWidth; o += n)
  {
    finite |= StoreGraphJacobiAccelerations(f, y, dy, o);
  }
  return finite;
}
} // namespace HWY_NAMESPACE
} // namespace riemann
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace riemann
{
HWY_EXPORT(GraphAccelerationFromJetImpl);
HWY_EXPORT(GraphAccelerationOfGaussiansImpl);
HWY_EXPORT(GraphJacobiAccelerationsFromJetImpl);

LaneMask GraphAccelerationFromJet(const PacketScalarJet& f, const PacketVec3& v, PacketVec3& a)
{
  return HWY_DYNAMIC_DISPATCH(GraphAccelerationFromJetImpl)(f, v, a);
}

LaneMask GraphAccelerationOfGaussians(
  const GaussianTerms& terms, const PacketVec3& x, const PacketVec3& v, PacketVec3& a)
{
  return HWY_DYNAMIC_DISPATCH(GraphAccelerationOfGaussiansImpl)(terms, x, v, a);
}

LaneMask GraphJacobiAccelerationsFromJet(
  const PacketScalarJet& f, const PacketJacobiState& y, PacketJacobiState& dy)
{
  return HWY_DYNAMIC_DISPATCH(GraphJacobiAccelerationsFromJetImpl)(f, y, dy);
}
} // namespace riemann
#endif
