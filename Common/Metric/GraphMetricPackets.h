/**
 * @file GraphMetricPackets.h
 * @brief The graph family's packet kernels (GraphMetricPackets.cxx, Google
 * Highway), next to its scalar form and GLSL (GraphMetric.h).
 */
#ifndef RiemannGraphMetricPackets_h
#define RiemannGraphMetricPackets_h

#include "GaussianTerms.h"
#include "Packet.h"
#include "RiemannCommonMetricExport.h"

namespace riemann
{
/**
 * The graph metric's acceleration a = -grad f (v^T H v) / (1 + |grad f|^2)
 * from the jet of f. Returns the lanes where a is finite.
 */
RIEMANNCOMMONMETRIC_EXPORT LaneMask GraphAccelerationFromJet(
  const PacketScalarJet& f, const PacketVec3& v, PacketVec3& a);

/**
 * GraphAccelerationFromJet of f = a sum of bumps, fused: the jet stays in
 * registers (GraphMetric's hot path when its f is such a sum).
 */
RIEMANNCOMMONMETRIC_EXPORT LaneMask GraphAccelerationOfGaussians(
  const GaussianTerms& terms, const PacketVec3& x, const PacketVec3& v, PacketVec3& a);

/**
 * The graph family's Jacobi accelerations from the jet of f to third order:
 * dy.V = a = -grad f (v^T H v) / (1 + |grad f|^2) and dy.DJ[k] = its
 * linearisation along (J_k, DJ_k) of y, i.e.
 * -(d_{J_k} Gamma)(v, v) - 2 Gamma(v, DJ_k). Returns the lanes where all
 * are finite.
 */
RIEMANNCOMMONMETRIC_EXPORT LaneMask GraphJacobiAccelerationsFromJet(
  const PacketScalarJet& f, const PacketJacobiState& y, PacketJacobiState& dy);
} // namespace riemann

#endif
