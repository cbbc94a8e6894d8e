// The conformal family's packet kernels (ConformalMetric.h has its scalar
// form and GLSL): accelerations and Jacobi accelerations from the jet of
// the index n, and the acceleration of a constant plus Gaussians fused with
// its jet. Written once with Google Highway, compiled once per x86 target.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "ConformalMetricPackets.cxx"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include "ConformalMetricPackets.h"
#include "GaussianFieldLanes-inl.h"
#include "PacketLanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace riemann
{
namespace HWY_NAMESPACE
{
/// a = |v|^2 l - 2 (l . v) v with l = grad n / n, stored at lanes [o, o + N)
/// of `a`; returns the lanes where n > 0 and a is finite.
HWY_INLINE LaneMask StoreConformalAcceleration(
  const JetVectors& index, V vx, V vy, V vz, PacketVec3& a, int o)
{
  const D d;
  const V lx = hn::Div(index.Gx, index.Value);
  const V ly = hn::Div(index.Gy, index.Value);
  const V lz = hn::Div(index.Gz, index.Value);
  const V speedSquared = hn::MulAdd(vz, vz, hn::MulAdd(vy, vy, hn::Mul(vx, vx)));
  const V twiceLv =
    hn::Mul(hn::Set(d, 2.0), hn::MulAdd(lz, vz, hn::MulAdd(ly, vy, hn::Mul(lx, vx))));
  const V ax = hn::NegMulAdd(twiceLv, vx, hn::Mul(speedSquared, lx));
  const V ay = hn::NegMulAdd(twiceLv, vy, hn::Mul(speedSquared, ly));
  const V az = hn::NegMulAdd(twiceLv, vz, hn::Mul(speedSquared, lz));
  hn::Store(ax, d, a.C[0] + o);
  hn::Store(ay, d, a.C[1] + o);
  hn::Store(az, d, a.C[2] + o);
  return BitsAt(d, hn::And(hn::Gt(index.Value, hn::Zero(d)), AllFinite(ax, ay, az)), o);
}

LaneMask ConformalAccelerationFromJetImpl(
  const PacketScalarJet& index, const PacketVec3& v, PacketVec3& a)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  LaneMask defined = 0;
  for (int o = 0; o < PacketWidth; o += n)
  {
    // Only the value and gradient are filled (first order).
    JetVectors jet = ZeroJet(d);
    jet.Value = hn::Load(d, index.Value + o);
    jet.Gx = hn::Load(d, index.Gradient[0] + o);
    jet.Gy = hn::Load(d, index.Gradient[1] + o);
    jet.Gz = hn::Load(d, index.Gradient[2] + o);
    defined |= StoreConformalAcceleration(
      jet, hn::Load(d, v.C[0] + o), hn::Load(d, v.C[1] + o), hn::Load(d, v.C[2] + o), a, o);
  }
  return defined;
}

LaneMask ConformalAccelerationOfGaussiansImpl(const GaussianTerms& terms, double constant,
  const PacketVec3& x, const PacketVec3& v, PacketVec3& a)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  LaneMask defined = 0;
  for (int o = 0; o < PacketWidth; o += n)
  {
    JetVectors index = ZeroJet(d);
    index.Value = hn::Set(d, constant);
    AddGaussianTerms<FirstDerivatives>(
      terms, hn::Load(d, x.C[0] + o), hn::Load(d, x.C[1] + o), hn::Load(d, x.C[2] + o), index);
    defined |= StoreConformalAcceleration(
      index, hn::Load(d, v.C[0] + o), hn::Load(d, v.C[1] + o), hn::Load(d, v.C[2] + o), a, o);
  }
  return defined;
}

/**
 * The conformal family's Jacobi accelerations at lanes [o, o + N). With
 * l = grad n / n: a = |v|^2 l - 2 (l . v) v. Along a variation (X, V):
 * dl = H X / n - l (l . X) and
 * A = 2 (v . V) l + |v|^2 dl - 2 (dl . v + l . V) v - 2 (l . v) V.
 * Returns the lanes where n > 0 and all are finite.
 */
HWY_INLINE LaneMask StoreConformalJacobiAccelerations(
  const PacketScalarJet& n, const PacketJacobiState& y, PacketJacobiState& dy, int o)
{
  const D d;
  const V index = hn::Load(d, n.Value + o);
  const V inverse = hn::Div(hn::Set(d, 1.0), index);
  const Vec3Vectors gradient = LoadVec3(n.Gradient, o);
  const Vec3Vectors l = { hn::Mul(gradient.X, inverse), hn::Mul(gradient.Y, inverse),
    hn::Mul(gradient.Z, inverse) };
  V h[6];
  for (int e = 0; e < 6; ++e)
  {
    h[e] = hn::Mul(hn::Load(d, n.Hessian.C[e] + o), inverse);
  }
  const Vec3Vectors v = LoadVec3(y.V.C, o);
  const V two = hn::Set(d, 2.0);
  const V speedSquared = Dot(v, v);
  const V lv = Dot(l, v);
  const Vec3Vectors a = Combine(speedSquared, l, hn::Mul(hn::Set(d, -2.0), lv), v);
  StoreVec3(a, dy.V, o);
  M defined = hn::And(hn::Gt(index, hn::Zero(d)), AllFinite(a));
  for (int k = 0; k < 2; ++k)
  {
    const Vec3Vectors x = LoadVec3(y.J[k].C, o);
    const Vec3Vectors variation = LoadVec3(y.DJ[k].C, o);
    // dl = (H / n) X - l (l . X).
    const Vec3Vectors dl = Combine(hn::Set(d, 1.0), SymmetricTimes(h, x), hn::Neg(Dot(l, x)), l);
    const V alongV = hn::Mul(two, hn::Add(Dot(dl, v), Dot(l, variation)));
    const Vec3Vectors first = Combine(hn::Mul(two, Dot(v, variation)), l, speedSquared, dl);
    const Vec3Vectors second = Combine(alongV, v, hn::Mul(two, lv), variation);
    const Vec3Vectors acceleration = { hn::Sub(first.X, second.X), hn::Sub(first.Y, second.Y),
      hn::Sub(first.Z, second.Z) };
    StoreVec3(acceleration, dy.DJ[k], o);
    defined = hn::And(defined, AllFinite(acceleration));
  }
  return BitsAt(d, defined, o);
}

LaneMask ConformalJacobiAccelerationsFromJetImpl(
  const PacketScalarJet& index, const PacketJacobiState& y, PacketJacobiState& dy)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  LaneMask defined = 0;
  for (int o = 0; o < PacketWidth; o += n)
  {
    defined |= StoreConformalJacobiAccelerations(index, y, dy, o);
  }
  return defined;
}
} // namespace HWY_NAMESPACE
} // namespace riemann
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace riemann
{
HWY_EXPORT(ConformalAccelerationFromJetImpl);
HWY_EXPORT(ConformalAccelerationOfGaussiansImpl);
HWY_EXPORT(ConformalJacobiAccelerationsFromJetImpl);

LaneMask ConformalAccelerationFromJet(const PacketScalarJet& n, const PacketVec3& v, PacketVec3& a)
{
  return HWY_DYNAMIC_DISPATCH(ConformalAccelerationFromJetImpl)(n, v, a);
}

LaneMask ConformalAccelerationOfGaussians(const GaussianTerms& terms, double constant,
  const PacketVec3& x, const PacketVec3& v, PacketVec3& a)
{
  return HWY_DYNAMIC_DISPATCH(ConformalAccelerationOfGaussiansImpl)(terms, constant, x, v, a);
}

LaneMask ConformalJacobiAccelerationsFromJet(
  const PacketScalarJet& n, const PacketJacobiState& y, PacketJacobiState& dy)
{
  return HWY_DYNAMIC_DISPATCH(ConformalJacobiAccelerationsFromJetImpl)(n, y, dy);
}
} // namespace riemann
#endif
