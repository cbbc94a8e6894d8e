// The packet kernels' shared register types and helpers (Google Highway),
// compiled once per target by every kernel file that includes it after
// <hwy/foreach_target.h>: Highway's "-inl.h" convention (the guard below
// flips with HWY_TARGET_TOGGLE so each target's pass sees it once).
//
// The kernels walk a packet's PacketWidth lanes in vectors of N = Lanes(D)
// doubles (8 with AVX-512, 4 with AVX2, 2 with SSE4); the arrays of
// Packet.h are 64-byte aligned, so every chunk is an aligned load.
#include "Packet.h"

#if defined(RIEMANN_PACKET_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef RIEMANN_PACKET_LANES_INL_H_
#undef RIEMANN_PACKET_LANES_INL_H_
#else
#define RIEMANN_PACKET_LANES_INL_H_
#endif

#include <hwy/highway.h>

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

// --- Jets in registers -------------------------------------------------------


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

HWY_INLINE JetVectors ZeroJet(D d)
{
  const V zero = hn::Zero(d);
  return { zero, zero, zero, zero, zero, zero, zero, zero, zero, zero };
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

HWY_INLINE M AllFinite(V ax, V ay, V az)
{
  return hn::And(hn::IsFinite(ax), hn::And(hn::IsFinite(ay), hn::IsFinite(az)));
}

// --- Vectors in registers (the Jacobi systems) --------------------------------


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
} // namespace HWY_NAMESPACE
} // namespace riemann
HWY_AFTER_NAMESPACE();

#endif // RIEMANN_PACKET_LANES_INL_H_
