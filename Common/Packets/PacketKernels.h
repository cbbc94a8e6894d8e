/**
 * @file PacketKernels.h
 * @brief The SIMD kernels of the packet engine: sums of Gaussian bumps, the
 * graph and conformal accelerations, and the arithmetic of the packet
 * integrators, each a loop over the PacketWidth lanes of a packet.
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


/**
 * Gaussian bumps a exp(-sum_i w_i (p_i - c_i)^2 / 2) as flat arrays (one
 * array per parameter), so that a sum of bumps is one loop without a
 * virtual call per term (GaussianField, ScalarFieldSum).
 */
struct RIEMANNCOMMONPACKETS_EXPORT GaussianTerms
{
  std::vector<double> Amplitude;
  std::vector<double> Center[3];
  /// 1 / sigma_i^2.
  std::vector<double> InverseVariance[3];

  void Add(double amplitude, const Vec3& center, const Vec3& inverseVariance);
  size_t Size() const { return this->Amplitude.size(); }
};

/// The Highway target the kernels run on here ("AVX3", "AVX2", "SSE4", ...).
RIEMANNCOMMONPACKETS_EXPORT std::string PacketTargetName();

/**
 * Add the value, and the derivatives up to `order` (up to
 * ThirdDerivatives), of the sum of `terms` at the W points `p` to `jet`:
 * the formulas of GaussianField::Accumulate, every lane at once.
 */
RIEMANNCOMMONPACKETS_EXPORT void AccumulateGaussianTerms(
  const GaussianTerms& terms, const PacketVec3& p, int order, PacketScalarJet& jet);

/**
 * The graph metric's acceleration a = -grad f (v^T H v) / (1 + |grad f|^2)
 * from the jet of f. Returns the lanes where a is finite.
 */
RIEMANNCOMMONPACKETS_EXPORT LaneMask GraphAccelerationFromJet(
  const PacketScalarJet& f, const PacketVec3& v, PacketVec3& a);

/**
 * The conformal metric's acceleration a = |v|^2 l - 2 (l . v) v with
 * l = grad n / n, from the jet of n (first order). Returns the lanes where
 * n > 0 and a is finite.
 */
RIEMANNCOMMONPACKETS_EXPORT LaneMask ConformalAccelerationFromJet(
  const PacketScalarJet& n, const PacketVec3& v, PacketVec3& a);

/**
 * GraphAccelerationFromJet of f = a sum of bumps, fused: the jet stays in
 * registers (GraphMetric's hot path when its f is such a sum).
 */
RIEMANNCOMMONPACKETS_EXPORT LaneMask GraphAccelerationOfGaussians(
  const GaussianTerms& terms, const PacketVec3& x, const PacketVec3& v, PacketVec3& a);

/// ConformalAccelerationFromJet of n = constant + a sum of bumps, fused.
RIEMANNCOMMONPACKETS_EXPORT LaneMask ConformalAccelerationOfGaussians(const GaussianTerms& terms,
  double constant, const PacketVec3& x, const PacketVec3& v, PacketVec3& a);

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
 * The graph family's Jacobi accelerations from the jet of f to third order:
 * dy.V = a = -grad f (v^T H v) / (1 + |grad f|^2) and dy.DJ[k] = its
 * linearisation along (J_k, DJ_k) of y, i.e.
 * -(d_{J_k} Gamma)(v, v) - 2 Gamma(v, DJ_k). Returns the lanes where all
 * are finite.
 */
RIEMANNCOMMONPACKETS_EXPORT LaneMask GraphJacobiAccelerationsFromJet(
  const PacketScalarJet& f, const PacketJacobiState& y, PacketJacobiState& dy);

/// The conformal family's, from the jet of n to second order; the lanes where n > 0 and all are
/// finite.
RIEMANNCOMMONPACKETS_EXPORT LaneMask ConformalJacobiAccelerationsFromJet(
  const PacketScalarJet& n, const PacketJacobiState& y, PacketJacobiState& dy);

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
