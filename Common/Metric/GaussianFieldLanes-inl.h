// The Gaussian family's packet form in registers: a sum of bumps and its
// derivatives at N points at once (GaussianField.h has the scalar form;
// GaussianFieldPackets.cxx and the graph and conformal families' fused
// kernels use this). Highway's "-inl.h" convention, as PacketLanes-inl.h.
// `Terms` is a GaussianTerms (GaussianTerms.h, which the including kernel
// files include first): a template, so that this header, included by the
// GaussianTerms kernel itself, does not include its header back.
#include "PacketLanes-inl.h"

#if defined(RIEMANN_GAUSSIAN_FIELD_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef RIEMANN_GAUSSIAN_FIELD_LANES_INL_H_
#undef RIEMANN_GAUSSIAN_FIELD_LANES_INL_H_
#else
#define RIEMANN_GAUSSIAN_FIELD_LANES_INL_H_
#endif

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace riemann
{
namespace HWY_NAMESPACE
{
/**
 * Add the bumps' value and derivatives up to Order at the points (x, y, z)
 * to `jet` (and, for ThirdDerivatives, to `third`), the formulas of
 * GaussianField::Accumulate: with u = w (p - c) and
 * f = a exp(-(p - c) . u / 2), d_i f = -u_i f,
 * d_i d_j f = u_i u_j f - delta_ij w_i f and
 * d_i d_j d_k f = f (delta_ij w_i u_k + delta_ik w_i u_j + delta_jk w_j u_i
 * - u_i u_j u_k).
 */
template <int Order, class Terms>
HWY_INLINE void AddGaussianTerms(
  const Terms& terms, V x, V y, V z, JetVectors& jet, ThirdVectors* third = nullptr)
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
} // namespace HWY_NAMESPACE
} // namespace riemann
HWY_AFTER_NAMESPACE();

#endif // RIEMANN_GAUSSIAN_FIELD_LANES_INL_H_
