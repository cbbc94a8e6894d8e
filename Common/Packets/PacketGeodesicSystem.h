/**
 * @class riemann::PacketGeodesicSystem
 * @brief What the packet integrators (PacketKernels.h) ask of a metric: the
 * geodesic and Jacobi accelerations of PacketWidth states at once.
 *
 * riemann::Metric implements it. The interface is here, in the packet
 * engine's library, so that the SIMD integrators do not depend on the
 * metric families that are built on the engine's kernels (dependency
 * inversion: Riemann::CommonPackets sits below Riemann::CommonMetric).
 */
#ifndef RiemannPacketGeodesicSystem_h
#define RiemannPacketGeodesicSystem_h

#include "Packet.h"
#include "RiemannCommonPacketsExport.h"

namespace riemann
{
class RIEMANNCOMMONPACKETS_EXPORT PacketGeodesicSystem
{
public:
  virtual ~PacketGeodesicSystem() = default;

  /**
   * The acceleration a = -Gamma(v, v) of PacketWidth geodesics on the lanes
   * of `lanes`; returns those where it is defined and finite.
   */
  virtual LaneMask AccelerationPacket(
    const PacketVec3& x, const PacketVec3& v, PacketVec3& a, LaneMask lanes) const = 0;

  /**
   * The Jacobi system's accelerations (dy.V and dy.DJ only) on the lanes of
   * `lanes`; returns those where all are defined and finite.
   */
  virtual LaneMask JacobiAccelerationPacket(
    const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes) const = 0;
};
} // namespace riemann

#endif
