/**
 * @file ConformalMetricPackets.h
 * @brief The conformal family's packet kernels (ConformalMetricPackets.cxx,
 * Google Highway), next to its scalar form and GLSL (ConformalMetric.h).
 */
#ifndef RiemannConformalMetricPackets_h
#define RiemannConformalMetricPackets_h

#include "GaussianTerms.h"
#include "Packet.h"
#include "RiemannCommonMetricExport.h"

namespace riemann
{
/**
 * The conformal metric's acceleration a = |v|^2 l - 2 (l . v) v with
 * l = grad n / n, from the jet of n (first order). Returns the lanes where
 * n > 0 and a is finite.
 */
RIEMANNCOMMONMETRIC_EXPORT LaneMask ConformalAccelerationFromJet(
  const PacketScalarJet& n, const PacketVec3& v, PacketVec3& a);

/// ConformalAccelerationFromJet of n = constant + a sum of bumps, fused.
RIEMANNCOMMONMETRIC_EXPORT LaneMask ConformalAccelerationOfGaussians(const GaussianTerms& terms,
  double constant, const PacketVec3& x, const PacketVec3& v, PacketVec3& a);

/// The conformal family's, from the jet of n to second order; the lanes where n > 0 and all are
/// finite.
RIEMANNCOMMONMETRIC_EXPORT LaneMask ConformalJacobiAccelerationsFromJet(
  const PacketScalarJet& n, const PacketJacobiState& y, PacketJacobiState& dy);
} // namespace riemann

#endif
