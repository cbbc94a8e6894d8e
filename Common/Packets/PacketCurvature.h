/**
 * @file PacketCurvature.h
 * @brief Curvature and the metric's own fields at PacketWidth points at once
 * (the packet engine's form of Curvature.h), for the field filters.
 *
 * CurvatureFromTensorJet below gives what the curvature field stores: Ricci,
 * scalar curvature, the coordinate sectional curvatures, the extremes of the
 * sectional curvature, |Rm| and the volume form, from g and its
 * derivatives (ComputeCurvature in Curvature.h takes them from a metric).
 * Every step after the metric's derivatives is SIMD arithmetic on the lanes (Highway, with the
 * runtime dispatch of PacketKernels.h): Cholesky of g, g^-1, Gamma, d Gamma,
 * Ricci, then two identities of dimension 3 (the Weyl tensor vanishes),
 * exact, so the results equal the scalar ComputeCurvature's to rounding:
 * - the sectional curvature of the plane g-orthogonal to a unit vector n is
 *   S / 2 - Ric(n, n), so its extremes over all planes are S / 2 minus the
 *   extreme eigenvalues of Ric in a g-orthonormal frame;
 * - |Rm|^2 = 4 |Ric|^2 - S^2.
 * The eigenvalues come from cyclic Jacobi sweeps on the 3x3 symmetric
 * matrices, a fixed number per packet (no per-lane branch), which converge
 * quadratically to full double precision.
 */
#ifndef RiemannPacketCurvature_h
#define RiemannPacketCurvature_h

#include "Packet.h"
#include "RiemannCommonPacketsExport.h"

namespace riemann
{
/// What the curvature field stores, at PacketWidth points.
struct alignas(64) PacketCurvature
{
  double Scalar[PacketWidth];
  /// Ric, in SymmetricEntry order.
  PacketSym3 Ricci;
  double SectionalXY[PacketWidth];
  double SectionalXZ[PacketWidth];
  double SectionalYZ[PacketWidth];
  double SectionalMin[PacketWidth];
  double SectionalMax[PacketWidth];
  double RiemannNorm[PacketWidth];
  double VolumeForm[PacketWidth];
};

/**
 * The curvature from g and its first and second derivatives. Returns the
 * lanes where g is positive definite and every result is finite.
 */
RIEMANNCOMMONPACKETS_EXPORT LaneMask CurvatureFromTensorJet(
  const PacketTensorJet& jet, PacketCurvature& curvature);

/**
 * The Jacobi system's accelerations (Metric::JacobiAccelerationPacket) from
 * g and its first and second derivatives, through the Christoffel symbols
 * and their derivatives on the packet: what every family without a closed
 * form of its own runs. Returns the lanes where g is positive definite and
 * all are finite.
 */
RIEMANNCOMMONPACKETS_EXPORT LaneMask JacobiAccelerationsFromTensorJet(
  const PacketTensorJet& jet, const PacketJacobiState& y, PacketJacobiState& dy);

/**
 * The eigenvalues of a symmetric matrix per lane, ascending:
 * eigenvalues[0] <= eigenvalues[1] <= eigenvalues[2].
 */
RIEMANNCOMMONPACKETS_EXPORT void SymmetricEigenvalues(
  const PacketSym3& a, double (&eigenvalues)[3][PacketWidth]);

/**
 * g^-1 per lane by Cholesky (as Eigen::LLT's solve). Returns the lanes where
 * g is positive definite and the inverse finite; the others hold NaN.
 */
RIEMANNCOMMONPACKETS_EXPORT LaneMask InverseTensor(const PacketSym3& g, PacketSym3& inverse);

/**
 * The graph family's g, d g and d d g from the jet of f to third order:
 * g_ij = delta_ij + f_i f_j, d_k g_ij = f_ik f_j + f_i f_jk,
 * d_k d_l g_ij = f_ikl f_j + f_ik f_jl + f_il f_jk + f_i f_jkl. Returns the
 * lanes where all are finite.
 */
RIEMANNCOMMONPACKETS_EXPORT LaneMask GraphTensorJetFromJet(
  const PacketScalarJet& f, PacketTensorJet& jet);

/**
 * The conformal family's, from the jet of n to second order: g = n^2 delta,
 * d_k g = 2 n n_k delta, d_k d_l g = 2 (n_k n_l + n n_kl) delta. Returns
 * the lanes where n > 0 and all are finite.
 */
RIEMANNCOMMONPACKETS_EXPORT LaneMask ConformalTensorJetFromJet(
  const PacketScalarJet& n, PacketTensorJet& jet);
} // namespace riemann

#endif
