// The packet kernels (PacketKernels.h), written once with Google Highway.
//
// Highway's foreach_target.h compiles this file once per x86 target (SSE4,
// AVX2, AVX-512, ...), each copy in its own namespace riemann::N_<TARGET>;
// the HWY_ONCE part at the end exports one table per kernel and calls the
// entry for the best target this CPU supports (HWY_DYNAMIC_DISPATCH).
//
// Every kernel walks a packet's PacketWidth lanes in vectors of N =
// Lanes(D) doubles (8 with AVX-512, 4 with AVX2, 2 with SSE4); the arrays of
// Packet.h are 64-byte aligned, so every chunk is an aligned load.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "PacketKernels.cxx"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include "DormandPrinceTableau.h"
#include "PacketKernels.h"

#include <cmath>

HWY_BEFORE_NAMESPACE();
namespace riemann
{
namespace HWY_NAMESPACE
{
namespace hn = hwy::HWY_NAMESPACE;
using D = hn::CappedTag<double, PacketWidth>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

// --- Lane masks --------------------------------------------------------------

/// The vector mask of lanes [offset, offset + N) of `lanes`.
HWY_INLINE M MaskAt(D d, LaneMask lanes, int offset)
{
  const uint8_t bits[8] = { static_cast<uint8_t>(lanes >> offset), 0, 0, 0, 0, 0, 0, 0 };
  return hn::LoadMaskBits(d, bits);
}

/// `mask` as the bits [offset, offset + N) of a LaneMask.
HWY_INLINE LaneMask BitsAt(D d, M mask, int offset)
{
  uint8_t bits[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
  hn::StoreMaskBits(d, mask, bits);
  const LaneMask chunk = (LaneMask{ 1 } << hn::Lanes(d)) - 1;
  return (LaneMask{ bits[0] } & chunk) << offset;
}

// --- Gaussian sums -----------------------------------------------------------

/// A scalar jet in registers: value, gradient and the 6 Hessian entries.
struct JetVectors
{
  V Value, Gx, Gy, Gz, Hxx, Hyy, Hzz, Hxy, Hxz, Hyz;
};

/// The 10 third derivatives of a jet in registers, indexed by ThirdEntry.
struct ThirdVectors
{
  V T[10];
};

/**
 * Add the bumps' value and derivatives up to Order at the points (x, y, z)
 * to `jet` (and, for ThirdDerivatives, to `third`), the formulas of
 * GaussianField::Accumulate: with u = w (p - c) and
 * f = a exp(-(p - c) . u / 2), d_i f = -u_i f,
 * d_i d_j f = u_i u_j f - delta_ij w_i f and
 * d_i d_j d_k f = f (delta_ij w_i u_k + delta_ik w_i u_j + delta_jk w_j u_i
 * - u_i u_j u_k).
 */
template <int Order>
HWY_INLINE void AddGaussianTerms(
  const GaussianTerms& terms, V x, V y, V z, JetVectors& jet, ThirdVectors* third = nullptr)
{
  const D d;
  const V minusHalf = hn::Set(d, -0.5);
  const size_t count = terms.Size();
  for (size_t k = 0; k < count; ++k)
  {
    const V dx = hn::Sub(x, hn::Set(d, terms.Center[0][k]));
    const V dy = hn::Sub(y, hn::Set(d, terms.Center[1][k]));
    const V dz = hn::Sub(z, hn::Set(d, terms.Center[2][k]));
    const V wx = hn::Set(d, terms.InverseVariance[0][k]);
    const V wy = hn::Set(d, terms.InverseVariance[1][k]);
    const V wz = hn::Set(d, terms.InverseVariance[2][k]);
    const V ux = hn::Mul(wx, dx);
    const V uy = hn::Mul(wy, dy);
    const V uz = hn::Mul(wz, dz);
    const V q = hn::MulAdd(dz, uz, hn::MulAdd(dy, uy, hn::Mul(dx, ux)));
    const V f = hn::Mul(hn::Set(d, terms.Amplitude[k]), hn::Exp(d, hn::Mul(minusHalf, q)));
    jet.Value = hn::Add(jet.Value, f);
    if (Order >= FirstDerivatives)
    {
      const V fux = hn::Mul(f, ux);
      const V fuy = hn::Mul(f, uy);
      const V fuz = hn::Mul(f, uz);
      jet.Gx = hn::Sub(jet.Gx, fux);
      jet.Gy = hn::Sub(jet.Gy, fuy);
      jet.Gz = hn::Sub(jet.Gz, fuz);
      if (Order >= SecondDerivatives)
      {
        jet.Hxx = hn::NegMulAdd(f, wx, hn::MulAdd(fux, ux, jet.Hxx));
        jet.Hyy = hn::NegMulAdd(f, wy, hn::MulAdd(fuy, uy, jet.Hyy));
        jet.Hzz = hn::NegMulAdd(f, wz, hn::MulAdd(fuz, uz, jet.Hzz));
        jet.Hxy = hn::MulAdd(fux, uy, jet.Hxy);
        jet.Hxz = hn::MulAdd(fux, uz, jet.Hxz);
        jet.Hyz = hn::MulAdd(fuy, uz, jet.Hyz);
      }
      if (Order >= ThirdDerivatives)
      {
        V(&t)[10] = third->T;
        // f (w_i - u_i^2) per axis: the factor of d_i d_i d_j for j != i.
        const V sx = hn::NegMulAdd(ux, ux, wx);
        const V sy = hn::NegMulAdd(uy, uy, wy);
        const V sz = hn::NegMulAdd(uz, uz, wz);
        // d_i^3 f = f u_i (3 w_i - u_i^2).
        const V three = hn::Set(d, 3.0);
        t[XXX] = hn::MulAdd(fux, hn::NegMulAdd(ux, ux, hn::Mul(three, wx)), t[XXX]);
        t[YYY] = hn::MulAdd(fuy, hn::NegMulAdd(uy, uy, hn::Mul(three, wy)), t[YYY]);
        t[ZZZ] = hn::MulAdd(fuz, hn::NegMulAdd(uz, uz, hn::Mul(three, wz)), t[ZZZ]);
        t[XXY] = hn::MulAdd(fuy, sx, t[XXY]);
        t[XXZ] = hn::MulAdd(fuz, sx, t[XXZ]);
        t[XYY] = hn::MulAdd(fux, sy, t[XYY]);
        t[YYZ] = hn::MulAdd(fuz, sy, t[YYZ]);
        t[XZZ] = hn::MulAdd(fux, sz, t[XZZ]);
        t[YZZ] = hn::MulAdd(fuy, sz, t[YZZ]);
        t[XYZ] = hn::NegMulAdd(hn::Mul(fux, uy), uz, t[XYZ]);
      }
    }
  }
}

HWY_INLINE JetVectors ZeroJet(D d)
{
  const V zero = hn::Zero(d);
  return { zero, zero, zero, zero, zero, zero, zero, zero, zero, zero };
}

/// AccumulateGaussianTerms for one order, so the loop carries no branch.
template <int Order>
void AccumulateGaussianTermsOfOrder(
  const GaussianTerms& terms, const PacketVec3& p, PacketScalarJet& jet)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  for (int o = 0; o < PacketWidth; o += n)
  {
    JetVectors sum = ZeroJet(d);
    const V x = hn::Load(d, p.C[0] + o);
    const V y = hn::Load(d, p.C[1] + o);
    const V z = hn::Load(d, p.C[2] + o);
    ThirdVectors third;
    for (V& t : third.T)
    {
      t = hn::Zero(d);
    }
    AddGaussianTerms<Order>(terms, x, y, z, sum, &third);
    for (int e = 0; Order >= ThirdDerivatives && e < 10; ++e)
    {
      double* entry = jet.Third[e] + o;
      hn::Store(hn::Add(hn::Load(d, entry), third.T[e]), d, entry);
    }
    hn::Store(hn::Add(hn::Load(d, jet.Value + o), sum.Value), d, jet.Value + o);
    if (Order >= FirstDerivatives)
    {
      const V g[3] = { sum.Gx, sum.Gy, sum.Gz };
      for (int i = 0; i < 3; ++i)
      {
        hn::Store(hn::Add(hn::Load(d, jet.Gradient[i] + o), g[i]), d, jet.Gradient[i] + o);
      }
    }
    if (Order >= SecondDerivatives)
    {
      V h[6];
      h[XX] = sum.Hxx;
      h[YY] = sum.Hyy;
      h[ZZ] = sum.Hzz;
      h[XY] = sum.Hxy;
      h[XZ] = sum.Hxz;
      h[YZ] = sum.Hyz;
      for (int e = 0; e < 6; ++e)
      {
        double* entry = jet.Hessian.C[e] + o;
        hn::Store(hn::Add(hn::Load(d, entry), h[e]), d, entry);
      }
    }
  }
}

void AccumulateGaussianTermsImpl(
  const GaussianTerms& terms, const PacketVec3& p, int order, PacketScalarJet& jet)
{
  switch (order)
  {
    case ValueOnly:
      AccumulateGaussianTermsOfOrder<ValueOnly>(terms, p, jet);
      break;
    case FirstDerivatives:
      AccumulateGaussianTermsOfOrder<FirstDerivatives>(terms, p, jet);
      break;
    case SecondDerivatives:
      AccumulateGaussianTermsOfOrder<SecondDerivatives>(terms, p, jet);
      break;
    default:
      AccumulateGaussianTermsOfOrder<ThirdDerivatives>(terms, p, jet);
      break;
  }
}

// --- Accelerations of the families from their providers' jets ----------------

HWY_INLINE M AllFinite(V ax, V ay, V az)
{
  return hn::And(hn::IsFinite(ax), hn::And(hn::IsFinite(ay), hn::IsFinite(az)));
}

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

/// The jet of PacketScalarJet's lanes [o, o + N) in registers.
HWY_INLINE JetVectors LoadJet(const PacketScalarJet& jet, int o)
{
  const D d;
  const PacketSym3& h = jet.Hessian;
  return { hn::Load(d, jet.Value + o), hn::Load(d, jet.Gradient[0] + o),
    hn::Load(d, jet.Gradient[1] + o), hn::Load(d, jet.Gradient[2] + o), hn::Load(d, h.C[XX] + o),
    hn::Load(d, h.C[YY] + o), hn::Load(d, h.C[ZZ] + o), hn::Load(d, h.C[XY] + o),
    hn::Load(d, h.C[XZ] + o), hn::Load(d, h.C[YZ] + o) };
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

// --- The Jacobi system's accelerations from the providers' jets -------------

/// A vector of lanes [o, o + N) in registers.
struct Vec3Vectors
{
  V X, Y, Z;
};

HWY_INLINE Vec3Vectors LoadVec3(const double (&c)[3][PacketWidth], int o)
{
  const D d;
  return { hn::Load(d, c[0] + o), hn::Load(d, c[1] + o), hn::Load(d, c[2] + o) };
}

HWY_INLINE void StoreVec3(const Vec3Vectors& v, PacketVec3& p, int o)
{
  const D d;
  hn::Store(v.X, d, p.C[0] + o);
  hn::Store(v.Y, d, p.C[1] + o);
  hn::Store(v.Z, d, p.C[2] + o);
}

HWY_INLINE V Dot(const Vec3Vectors& a, const Vec3Vectors& b)
{
  return hn::MulAdd(a.Z, b.Z, hn::MulAdd(a.Y, b.Y, hn::Mul(a.X, b.X)));
}

/// s a + t b.
HWY_INLINE Vec3Vectors Combine(V s, const Vec3Vectors& a, V t, const Vec3Vectors& b)
{
  return { hn::MulAdd(t, b.X, hn::Mul(s, a.X)), hn::MulAdd(t, b.Y, hn::Mul(s, a.Y)),
    hn::MulAdd(t, b.Z, hn::Mul(s, a.Z)) };
}

HWY_INLINE M AllFinite(const Vec3Vectors& a)
{
  return AllFinite(a.X, a.Y, a.Z);
}

/// A symmetric matrix (6 entries in SymmetricEntry order) times a vector.
HWY_INLINE Vec3Vectors SymmetricTimes(const V (&h)[6], const Vec3Vectors& x)
{
  return { hn::MulAdd(h[XZ], x.Z, hn::MulAdd(h[XY], x.Y, hn::Mul(h[XX], x.X))),
    hn::MulAdd(h[YZ], x.Z, hn::MulAdd(h[YY], x.Y, hn::Mul(h[XY], x.X))),
    hn::MulAdd(h[ZZ], x.Z, hn::MulAdd(h[YZ], x.Y, hn::Mul(h[XZ], x.X))) };
}

/// The third derivatives contracted with X: M_jk = sum_i d_i d_j d_k f X_i.
HWY_INLINE void ContractThird(const V (&t)[10], const Vec3Vectors& x, V (&m)[6])
{
  m[XX] = hn::MulAdd(t[XXZ], x.Z, hn::MulAdd(t[XXY], x.Y, hn::Mul(t[XXX], x.X)));
  m[YY] = hn::MulAdd(t[YYZ], x.Z, hn::MulAdd(t[YYY], x.Y, hn::Mul(t[XYY], x.X)));
  m[ZZ] = hn::MulAdd(t[ZZZ], x.Z, hn::MulAdd(t[YZZ], x.Y, hn::Mul(t[XZZ], x.X)));
  m[XY] = hn::MulAdd(t[XYZ], x.Z, hn::MulAdd(t[XYY], x.Y, hn::Mul(t[XXY], x.X)));
  m[XZ] = hn::MulAdd(t[XZZ], x.Z, hn::MulAdd(t[XYZ], x.Y, hn::Mul(t[XXZ], x.X)));
  m[YZ] = hn::MulAdd(t[YZZ], x.Z, hn::MulAdd(t[YYZ], x.Y, hn::Mul(t[XYZ], x.X)));
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

// --- The flows and the integrators' arithmetic -------------------------------

LaneMask GeodesicFlowPacketImpl(
  const PacketGeodesicSystem& metric, const PacketState& y, PacketState& dy, LaneMask lanes)
{
  // dx/dt = v, copied by vectors (a struct copy may become a memmove call).
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  for (int i = 0; i < 3; ++i)
  {
    for (int o = 0; o < PacketWidth; o += n)
    {
      hn::Store(hn::Load(d, y.V.C[i] + o), d, dy.X.C[i] + o);
    }
  }
  return metric.AccelerationPacket(y.X, y.V, dy.V, lanes);
}

/// The Jacobi system (JacobiField.h): dy = (v, a, DJ_0, A_0, DJ_1, A_1).
LaneMask JacobiFlowPacketImpl(
  const PacketGeodesicSystem& metric, const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  const PacketVec3* const from[3] = { &y.V, &y.DJ[0], &y.DJ[1] };
  PacketVec3* const to[3] = { &dy.X, &dy.J[0], &dy.J[1] };
  for (int b = 0; b < 3; ++b)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int o = 0; o < PacketWidth; o += n)
      {
        hn::Store(hn::Load(d, from[b]->C[i] + o), d, to[b]->C[i] + o);
      }
    }
  }
  return metric.JacobiAccelerationPacket(y, dy, lanes);
}

/// The flow of each state type: the integrators below are written once.
HWY_INLINE LaneMask Flow(
  const PacketGeodesicSystem& metric, const PacketState& y, PacketState& dy, LaneMask lanes)
{
  return GeodesicFlowPacketImpl(metric, y, dy, lanes);
}

HWY_INLINE LaneMask Flow(
  const PacketGeodesicSystem& metric, const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes)
{
  return JacobiFlowPacketImpl(metric, y, dy, lanes);
}

/// out = y + h * sum_j c_j k_j per lane, for every component (a
/// Runge-Kutta stage). The sum runs in the order of the coefficients, as
/// the scalar integrators' Eigen expressions do.
template <class State, int Count>
HWY_INLINE void Stage(const State& y, const double* h, const double (&c)[Count],
  const State* const (&k)[Count], State& out)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  for (int i = 0; i < State::Size; ++i)
  {
    const double* const yi = y.Component(i);
    double* const outi = out.Component(i);
    const double* ki[Count];
    for (int j = 0; j < Count; ++j)
    {
      ki[j] = k[j]->Component(i);
    }
    for (int o = 0; o < PacketWidth; o += n)
    {
      V sum = hn::Mul(hn::Set(d, c[0]), hn::Load(d, ki[0] + o));
      for (int j = 1; j < Count; ++j)
      {
        sum = hn::MulAdd(hn::Set(d, c[j]), hn::Load(d, ki[j] + o), sum);
      }
      hn::Store(hn::MulAdd(hn::Load(d, h + o), sum, hn::Load(d, yi + o)), d, outi + o);
    }
  }
}

/// y <- candidate on the lanes of `lanes`; the others keep y.
template <class State>
HWY_INLINE void Commit(const State& candidate, LaneMask lanes, State& y)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  for (int o = 0; o < PacketWidth; o += n)
  {
    const M take = MaskAt(d, lanes, o);
    for (int i = 0; i < State::Size; ++i)
    {
      const V next = hn::Load(d, candidate.Component(i) + o);
      hn::Store(hn::IfThenElse(take, next, hn::Load(d, y.Component(i) + o)), d, y.Component(i) + o);
    }
  }
}

template <class State>
LaneMask EulerStepOf(const PacketGeodesicSystem& metric, State& y, const double* h, LaneMask lanes)
{
  State k1, next;
  const LaneMask defined = Flow(metric, y, k1, lanes) & lanes;
  const State* const k[1] = { &k1 };
  Stage<State, 1>(y, h, { 1.0 }, k, next);
  Commit(next, defined, y);
  return defined;
}

template <class State>
LaneMask RungeKutta4StepOf(const PacketGeodesicSystem& metric, State& y, const double* h, LaneMask lanes)
{
  State k1, k2, k3, k4, t;
  alignas(64) double half[PacketWidth];
  alignas(64) double sixth[PacketWidth];
  for (int l = 0; l < PacketWidth; ++l)
  {
    half[l] = 0.5 * h[l];
    sixth[l] = h[l] / 6.0;
  }
  LaneMask defined = Flow(metric, y, k1, lanes) & lanes;
  const State* const s1[1] = { &k1 };
  Stage<State, 1>(y, half, { 1.0 }, s1, t);
  defined &= Flow(metric, t, k2, defined);
  const State* const s2[1] = { &k2 };
  Stage<State, 1>(y, half, { 1.0 }, s2, t);
  defined &= Flow(metric, t, k3, defined);
  const State* const s3[1] = { &k3 };
  Stage<State, 1>(y, h, { 1.0 }, s3, t);
  defined &= Flow(metric, t, k4, defined);
  const State* const all[4] = { &k1, &k2, &k3, &k4 };
  Stage<State, 4>(y, sixth, { 1.0, 2.0, 2.0, 1.0 }, all, t);
  Commit(t, defined, y);
  return defined;
}

template <class State>
LaneMask DormandPrince45AttemptOf(const PacketGeodesicSystem& metric, const State& y, const State& k1,
  const double* step, double tolerance, LaneMask lanes, BasicPacketAttempt<State>& attempt)
{
  // The Butcher tableau of Dormand-Prince 5(4) (DormandPrinceTableau.h).
  using namespace riemann::dormand_prince;

  State k2, k3, k4, k5, k6, t, estimate;
  LaneMask defined = lanes;
  {
    const State* const k[1] = { &k1 };
    Stage<State, 1>(y, step, { a21 }, k, t);
    defined &= Flow(metric, t, k2, defined);
  }
  {
    const State* const k[2] = { &k1, &k2 };
    Stage<State, 2>(y, step, { a31, a32 }, k, t);
    defined &= Flow(metric, t, k3, defined);
  }
  {
    const State* const k[3] = { &k1, &k2, &k3 };
    Stage<State, 3>(y, step, { a41, a42, a43 }, k, t);
    defined &= Flow(metric, t, k4, defined);
  }
  {
    const State* const k[4] = { &k1, &k2, &k3, &k4 };
    Stage<State, 4>(y, step, { a51, a52, a53, a54 }, k, t);
    defined &= Flow(metric, t, k5, defined);
  }
  {
    const State* const k[5] = { &k1, &k2, &k3, &k4, &k5 };
    Stage<State, 5>(y, step, { a61, a62, a63, a64, a65 }, k, t);
    defined &= Flow(metric, t, k6, defined);
  }
  {
    const State* const k[5] = { &k1, &k3, &k4, &k5, &k6 };
    Stage<State, 5>(y, step, { b1, b3, b4, b5, b6 }, k, attempt.Next);
    defined &= Flow(metric, attempt.Next, attempt.Derivative, defined);
  }
  {
    // estimate = 0 + h sum e_j k_j, with y = 0 for Stage.
    State zero;
    for (int i = 0; i < State::Size; ++i)
    {
      for (int l = 0; l < PacketWidth; ++l)
      {
        zero.Component(i)[l] = 0.0;
      }
    }
    const State* const k[6] = { &k1, &k3, &k4, &k5, &k6, &attempt.Derivative };
    Stage<State, 6>(zero, step, { e1, e3, e4, e5, e6, e7 }, k, estimate);
  }

  // RMS of estimate / (tol + tol max(|y|, |next|)) over the components,
  // and the controller's factors 0.9 error^(-1/5) clamped to [0.2, 5].
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  const V tol = hn::Set(d, tolerance);
  const V infinity = hn::Set(d, HUGE_VAL);
  for (int o = 0; o < PacketWidth; o += n)
  {
    V sum = hn::Zero(d);
    for (int i = 0; i < State::Size; ++i)
    {
      const V scale = hn::MulAdd(tol,
        hn::Max(hn::Abs(hn::Load(d, y.Component(i) + o)),
          hn::Abs(hn::Load(d, attempt.Next.Component(i) + o))),
        tol);
      const V ratio = hn::Div(hn::Load(d, estimate.Component(i) + o), scale);
      sum = hn::MulAdd(ratio, ratio, sum);
    }
    V error = hn::Sqrt(hn::Div(sum, hn::Set(d, static_cast<double>(State::Size))));
    error = hn::IfThenElse(MaskAt(d, defined, o), error, infinity);
    error = hn::IfThenElse(hn::IsNaN(error), infinity, error);
    const V power =
      hn::Mul(hn::Set(d, 0.9), hn::Exp(d, hn::Mul(hn::Set(d, -0.2), hn::Log(d, error))));
    const V accept = hn::IfThenElse(hn::Gt(error, hn::Zero(d)),
      hn::Min(hn::Set(d, 5.0), hn::Max(hn::Set(d, 0.2), power)), hn::Set(d, 5.0));
    const V reject =
      hn::IfThenElse(hn::IsFinite(error), hn::Max(hn::Set(d, 0.2), power), hn::Set(d, 0.25));
    hn::Store(error, d, attempt.Error + o);
    hn::Store(accept, d, attempt.AcceptFactor + o);
    hn::Store(reject, d, attempt.RejectFactor + o);
  }
  return defined;
}

// Each kernel per state type (HWY_EXPORT takes plain functions).

LaneMask EulerPacketStepImpl(const PacketGeodesicSystem& metric, PacketState& y, const double* h, LaneMask lanes)
{
  return EulerStepOf(metric, y, h, lanes);
}

LaneMask RungeKutta4PacketStepImpl(
  const PacketGeodesicSystem& metric, PacketState& y, const double* h, LaneMask lanes)
{
  return RungeKutta4StepOf(metric, y, h, lanes);
}

LaneMask DormandPrince45PacketAttemptImpl(const PacketGeodesicSystem& metric, const PacketState& y,
  const PacketState& k1, const double* step, double tolerance, LaneMask lanes,
  PacketAttempt& attempt)
{
  return DormandPrince45AttemptOf(metric, y, k1, step, tolerance, lanes, attempt);
}

LaneMask EulerJacobiPacketStepImpl(
  const PacketGeodesicSystem& metric, PacketJacobiState& y, const double* h, LaneMask lanes)
{
  return EulerStepOf(metric, y, h, lanes);
}

LaneMask RungeKutta4JacobiPacketStepImpl(
  const PacketGeodesicSystem& metric, PacketJacobiState& y, const double* h, LaneMask lanes)
{
  return RungeKutta4StepOf(metric, y, h, lanes);
}

LaneMask DormandPrince45JacobiPacketAttemptImpl(const PacketGeodesicSystem& metric, const PacketJacobiState& y,
  const PacketJacobiState& k1, const double* step, double tolerance, LaneMask lanes,
  PacketJacobiAttempt& attempt)
{
  return DormandPrince45AttemptOf(metric, y, k1, step, tolerance, lanes, attempt);
}
} // namespace HWY_NAMESPACE
} // namespace riemann
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace riemann
{
HWY_EXPORT(AccumulateGaussianTermsImpl);
HWY_EXPORT(GraphAccelerationFromJetImpl);
HWY_EXPORT(ConformalAccelerationFromJetImpl);
HWY_EXPORT(GraphAccelerationOfGaussiansImpl);
HWY_EXPORT(ConformalAccelerationOfGaussiansImpl);
HWY_EXPORT(GraphJacobiAccelerationsFromJetImpl);
HWY_EXPORT(ConformalJacobiAccelerationsFromJetImpl);
HWY_EXPORT(GeodesicFlowPacketImpl);
HWY_EXPORT(JacobiFlowPacketImpl);
HWY_EXPORT(EulerPacketStepImpl);
HWY_EXPORT(RungeKutta4PacketStepImpl);
HWY_EXPORT(DormandPrince45PacketAttemptImpl);
HWY_EXPORT(EulerJacobiPacketStepImpl);
HWY_EXPORT(RungeKutta4JacobiPacketStepImpl);
HWY_EXPORT(DormandPrince45JacobiPacketAttemptImpl);

void GaussianTerms::Add(double amplitude, const Vec3& center, const Vec3& inverseVariance)
{
  this->Amplitude.push_back(amplitude);
  for (int i = 0; i < 3; ++i)
  {
    this->Center[i].push_back(center[i]);
    this->InverseVariance[i].push_back(inverseVariance[i]);
  }
}

std::string PacketTargetName()
{
  // The target HWY_DYNAMIC_DISPATCH chooses: the best of those compiled in
  // that this CPU supports.
  return hwy::TargetName(static_cast<int64_t>(hwy::SupportedAndGeneratedTargets()[0]));
}

void AccumulateGaussianTerms(
  const GaussianTerms& terms, const PacketVec3& p, int order, PacketScalarJet& jet)
{
  HWY_DYNAMIC_DISPATCH(AccumulateGaussianTermsImpl)(terms, p, order, jet);
}

LaneMask GraphAccelerationFromJet(const PacketScalarJet& f, const PacketVec3& v, PacketVec3& a)
{
  return HWY_DYNAMIC_DISPATCH(GraphAccelerationFromJetImpl)(f, v, a);
}

LaneMask ConformalAccelerationFromJet(const PacketScalarJet& n, const PacketVec3& v, PacketVec3& a)
{
  return HWY_DYNAMIC_DISPATCH(ConformalAccelerationFromJetImpl)(n, v, a);
}

LaneMask GraphAccelerationOfGaussians(
  const GaussianTerms& terms, const PacketVec3& x, const PacketVec3& v, PacketVec3& a)
{
  return HWY_DYNAMIC_DISPATCH(GraphAccelerationOfGaussiansImpl)(terms, x, v, a);
}

LaneMask ConformalAccelerationOfGaussians(const GaussianTerms& terms, double constant,
  const PacketVec3& x, const PacketVec3& v, PacketVec3& a)
{
  return HWY_DYNAMIC_DISPATCH(ConformalAccelerationOfGaussiansImpl)(terms, constant, x, v, a);
}

LaneMask GraphJacobiAccelerationsFromJet(
  const PacketScalarJet& f, const PacketJacobiState& y, PacketJacobiState& dy)
{
  return HWY_DYNAMIC_DISPATCH(GraphJacobiAccelerationsFromJetImpl)(f, y, dy);
}

LaneMask ConformalJacobiAccelerationsFromJet(
  const PacketScalarJet& n, const PacketJacobiState& y, PacketJacobiState& dy)
{
  return HWY_DYNAMIC_DISPATCH(ConformalJacobiAccelerationsFromJetImpl)(n, y, dy);
}

LaneMask JacobiFlowPacket(
  const PacketGeodesicSystem& metric, const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes)
{
  return HWY_DYNAMIC_DISPATCH(JacobiFlowPacketImpl)(metric, y, dy, lanes);
}

LaneMask EulerPacketStep(
  const PacketGeodesicSystem& metric, PacketJacobiState& y, const double* h, LaneMask lanes)
{
  return HWY_DYNAMIC_DISPATCH(EulerJacobiPacketStepImpl)(metric, y, h, lanes);
}

LaneMask RungeKutta4PacketStep(
  const PacketGeodesicSystem& metric, PacketJacobiState& y, const double* h, LaneMask lanes)
{
  return HWY_DYNAMIC_DISPATCH(RungeKutta4JacobiPacketStepImpl)(metric, y, h, lanes);
}

LaneMask DormandPrince45PacketAttempt(const PacketGeodesicSystem& metric, const PacketJacobiState& y,
  const PacketJacobiState& k1, const double* step, double tolerance, LaneMask lanes,
  PacketJacobiAttempt& attempt)
{
  return HWY_DYNAMIC_DISPATCH(DormandPrince45JacobiPacketAttemptImpl)(
    metric, y, k1, step, tolerance, lanes, attempt);
}

LaneMask GeodesicFlowPacket(
  const PacketGeodesicSystem& metric, const PacketState& y, PacketState& dy, LaneMask lanes)
{
  return HWY_DYNAMIC_DISPATCH(GeodesicFlowPacketImpl)(metric, y, dy, lanes);
}

LaneMask EulerPacketStep(const PacketGeodesicSystem& metric, PacketState& y, const double* h, LaneMask lanes)
{
  return HWY_DYNAMIC_DISPATCH(EulerPacketStepImpl)(metric, y, h, lanes);
}

LaneMask RungeKutta4PacketStep(
  const PacketGeodesicSystem& metric, PacketState& y, const double* h, LaneMask lanes)
{
  return HWY_DYNAMIC_DISPATCH(RungeKutta4PacketStepImpl)(metric, y, h, lanes);
}

LaneMask DormandPrince45PacketAttempt(const PacketGeodesicSystem& metric, const PacketState& y,
  const PacketState& k1, const double* step, double tolerance, LaneMask lanes,
  PacketAttempt& attempt)
{
  return HWY_DYNAMIC_DISPATCH(DormandPrince45PacketAttemptImpl)(
    metric, y, k1, step, tolerance, lanes, attempt);
}
} // namespace riemann
#endif
