/**
 * @file GaussianTerms.h
 * @brief A sum of Gaussian bumps as flat arrays, and its packet kernel: the
 * Gaussian family's packet form (GaussianField.h has the scalar one;
 * GaussianFieldPackets.cxx the kernel, GaussianFieldLanes-inl.h its
 * registers, which the graph and conformal families' fused kernels share).
 */
#ifndef RiemannGaussianTerms_h
#define RiemannGaussianTerms_h

#include "Packet.h"
#include "RiemannCommonMetricExport.h"

#include <vector>

namespace riemann
{
/**
 * Gaussian bumps a exp(-sum_i w_i (p_i - c_i)^2 / 2) as flat arrays (one
 * array per parameter), so that a sum of bumps is one loop without a
 * virtual call per term (GaussianField, ScalarFieldSum).
 */
struct RIEMANNCOMMONMETRIC_EXPORT GaussianTerms
{
  std::vector<double> Amplitude;
  std::vector<double> Center[3];
  /// 1 / sigma_i^2.
  std::vector<double> InverseVariance[3];

  void Add(double amplitude, const Vec3& center, const Vec3& inverseVariance);
  size_t Size() const { return this->Amplitude.size(); }
};

/**
 * Add the value, and the derivatives up to `order` (up to
 * ThirdDerivatives), of the sum of `terms` at the W points `p` to `jet`:
 * the formulas of GaussianField::Accumulate, every lane at once.
 */
RIEMANNCOMMONMETRIC_EXPORT void AccumulateGaussianTerms(
  const GaussianTerms& terms, const PacketVec3& p, int order, PacketScalarJet& jet);
} // namespace riemann

#endif
