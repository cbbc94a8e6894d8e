// The Gaussian family's packet kernel: a sum of bumps and its derivatives
// at a packet's points (GaussianTerms.h), written once with Google Highway
// and compiled once per x86 target (<hwy/foreach_target.h>); the HWY_ONCE
// part calls the best target this CPU supports.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "GaussianFieldPackets.cxx"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include "GaussianTerms.h"
#include "GaussianFieldLanes-inl.h"
#include "PacketLanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace riemann
{
namespace HWY_NAMESPACE
{
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
} // namespace HWY_NAMESPACE
} // namespace riemann
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace riemann
{
HWY_EXPORT(AccumulateGaussianTermsImpl);

void GaussianTerms::Add(double amplitude, const Vec3& center, const Vec3& inverseVariance)
{
  this->Amplitude.push_back(amplitude);
  for (int i = 0; i < 3; ++i)
  {
    this->Center[i].push_back(center[i]);
    this->InverseVariance[i].push_back(inverseVariance[i]);
  }
}

void AccumulateGaussianTerms(
  const GaussianTerms& terms, const PacketVec3& p, int order, PacketScalarJet& jet)
{
  HWY_DYNAMIC_DISPATCH(AccumulateGaussianTermsImpl)(terms, p, order, jet);
}
} // namespace riemann
#endif
