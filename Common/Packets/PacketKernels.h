/**
 * @file PacketKernels.h
 * @brief The SIMD kernels of the packet engine: the geodesic and Jacobi
 * flows and the arithmetic of the packet integrators, each a loop over the
 * PacketWidth lanes of a packet. The metric families' own kernels live with
 * the families (Common/Metric: GraphMetricPackets.h, ConformalMetricPackets.h,
 * GaussianTerms.h), on the register helpers of PacketLanes-inl.h.
 *
 * They are written once with Google Highway and compiled for every x86
 * target Highway knows (SSE4, AVX2, AVX-512, ...); the first call picks the
 * best one this CPU runs (runtime dispatch, PacketKernels.cxx), so one
 * Debian binary uses AVX-512 where there is AVX-512 and SSE4 on an old
 * machine, with no -march flag. PacketTargetName() says which was picked.
 */
#ifndef RiemannPacketKernels_h
#define RiemannPacketKernels_h

#include "Packet.h"
#include "PacketGeodesicSystem.h"
#include "RiemannCommonPacketsExport.h"

#include <string>
#include <vector>

namespace riemann
{

/// The Highway target the kernels run on here ("AVX3", "AVX2", "SSE4", ...).
RIEMANNCOMMONPACKETS_EXPORT std::string PacketTargetName();

/**
 * The geodesic flow of W geodesics: dy = (v, a(x, v)) on the lanes in
 * `lanes`; returns those where it is defined (PacketGeodesicSystem::AccelerationPacket).
 */
RIEMANNCOMMONPACKETS_EXPORT LaneMask GeodesicFlowPacket(
  const PacketGeodesicSystem& metric, const PacketState& y, PacketState& dy, LaneMask lanes);

/// y <- y + h F(y) per lane; lanes where F is undefined keep y. Returns the lanes stepped.
RIEMANNCOMMONPACKETS_EXPORT LaneMask EulerPacketStep(
  const PacketGeodesicSystem& metric, PacketState& y, const double* h, LaneMask lanes);

/// Classical RK4 per lane (step h[l]); lanes where F is undefined keep y. Returns the lanes
/// stepped.
RIEMANNCOMMONPACKETS_EXPORT LaneMask RungeKutta4PacketStep(
  const PacketGeodesicSystem& metric, PacketState& y, const double* h, LaneMask lanes);

/**
 * One Dormand-Prince 5(4) attempt per lane, the arithmetic of
 * DormandPrince45Of::Step: from y and its derivative k1, with step step[l],
 * the fifth-order `next`, its derivative k7, the scaled RMS error and the
 * step factors the controller applies on acceptance (grow at most 5x,
 * shrink at most 5x, safety 0.9) and on rejection. Returns the lanes where
 * every stage was defined; error is +inf on the others.
 */
template <class State>
struct BasicPacketAttempt
{
  State Next;
  State Derivative;
  alignas(64) double Error[PacketWidth];
  alignas(64) double AcceptFactor[PacketWidth];
  alignas(64) double RejectFactor[PacketWidth];
};
using PacketAttempt = BasicPacketAttempt<PacketState>;
using PacketJacobiAttempt = BasicPacketAttempt<PacketJacobiState>;
RIEMANNCOMMONPACKETS_EXPORT LaneMask DormandPrince45PacketAttempt(const PacketGeodesicSystem& metric,
  const PacketState& y, const PacketState& k1, const double* step, double tolerance, LaneMask lanes,
  PacketAttempt& attempt);

// --- The Jacobi system (JacobiField.h) on packets ----------------------------

/**
 * The Jacobi system of W geodesics: dy = (v, a, DJ_0, A_0, DJ_1, A_1) on the
 * lanes of `lanes` (PacketGeodesicSystem::JacobiAccelerationPacket); returns those where
 * it is defined.
 */
RIEMANNCOMMONPACKETS_EXPORT LaneMask JacobiFlowPacket(
  const PacketGeodesicSystem& metric, const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes);

/// EulerPacketStep of the Jacobi system.
RIEMANNCOMMONPACKETS_EXPORT LaneMask EulerPacketStep(
  const PacketGeodesicSystem& metric, PacketJacobiState& y, const double* h, LaneMask lanes);

/// RungeKutta4PacketStep of the Jacobi system.
RIEMANNCOMMONPACKETS_EXPORT LaneMask RungeKutta4PacketStep(
  const PacketGeodesicSystem& metric, PacketJacobiState& y, const double* h, LaneMask lanes);

/// DormandPrince45PacketAttempt of the Jacobi system (error RMS over the 18 components).
RIEMANNCOMMONPACKETS_EXPORT LaneMask DormandPrince45PacketAttempt(const PacketGeodesicSystem& metric,
  const PacketJacobiState& y, const PacketJacobiState& k1, const double* step, double tolerance,
  LaneMask lanes, PacketJacobiAttempt& attempt);
} // namespace riemann

#endif
