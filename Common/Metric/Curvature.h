/**
 * @file Curvature.h
 * @brief The curvature of a metric at a point, from its exact first and
 * second derivatives (Metric::TensorSecondDerivatives): Riemann, Ricci and
 * scalar curvature, sectional curvatures, |Rm| and the volume form.
 *
 * Convention (MATH.md "Curvature"):
 *   R(X, Y)Z = nabla_X nabla_Y Z - nabla_Y nabla_X Z - nabla_[X,Y] Z,
 *   R(d_j, d_k) d_i = R^l_ijk d_l, stored as Riemann[l][i][j][k], so
 *   R^l_ijk = d_j Gamma^l_ik - d_k Gamma^l_ij + Gamma^l_jm Gamma^m_ik - Gamma^l_km Gamma^m_ij,
 *   Ric_ik = R^j_ijk, S = g^ik Ric_ik,
 *   K(u, w) = <R(u, w)w, u> / (|u|^2 |w|^2 - <u, w>^2) with
 *   R(u, w)w = R^l_ijk w^i u^j w^k d_l.
 * Signs: the round unit 3-sphere has K = +1, Ric = 2 g, S = +6; hyperbolic
 * space K = -1, S = -6. With R_mijk = g_ml R^l_ijk, K(d_a, d_b) =
 * R_abab / (g_aa g_bb - g_ab^2), and the Gauss equation of a graph reads
 * R_mijk = h_mj h_ik - h_mk h_ij.
 */
#ifndef RiemannCurvature_h
#define RiemannCurvature_h

#include "Metric.h"
#include "PacketCurvature.h"
#include "RiemannCommonMetricExport.h"

namespace riemann
{
struct CurvatureSample
{
  Mat3 g = Mat3::Identity();
  Mat3 ginv = Mat3::Identity();
  /// Riemann[l][i][j][k] = R^l_ijk (convention above).
  double Riemann[3][3][3][3] = {};
  /// Ric_ik = R^j_ijk.
  Mat3 Ricci = Mat3::Zero();
  /// S = g^ik Ric_ik.
  double Scalar = 0.0;
  /// Sectional curvatures of the coordinate planes (d_x, d_y), (d_x, d_z), (d_y, d_z).
  double SectionalXY = 0.0;
  double SectionalXZ = 0.0;
  double SectionalYZ = 0.0;
  /// Extremes of the sectional curvature over all planes at the point: the
  /// extreme eigenvalues of the curvature operator on Lambda^2 in a
  /// g-orthonormal frame (in 3D every bivector is a plane).
  double SectionalMin = 0.0;
  double SectionalMax = 0.0;
  /// sqrt(R_abcd R^abcd).
  double RiemannNorm = 0.0;
  /// sqrt(det g).
  double VolumeForm = 0.0;
};

/**
 * Fill `sample` at p. Returns false where the metric refuses second
 * derivatives, is degenerate (not positive definite) or a result is not
 * finite; `sample` is then unspecified.
 */
RIEMANNCOMMONMETRIC_EXPORT bool ComputeCurvature(
  const Metric& metric, const Vec3& p, CurvatureSample& sample);

/**
 * The same at the lanes of `lanes` of PacketWidth points (the packet
 * engine's form, PacketCurvature.h): the metric's
 * TensorSecondDerivativesPacket, then CurvatureFromTensorJet. Returns the
 * lanes where it is defined (as the scalar ComputeCurvature's true).
 */
RIEMANNCOMMONMETRIC_EXPORT LaneMask ComputeCurvature(
  const Metric& metric, const PacketVec3& x, LaneMask lanes, PacketCurvature& curvature);

/**
 * g, g^-1, the Christoffel symbols gamma[m](i, j) = Gamma^m_ij and their exact
 * derivatives dGamma[l][m](i, j) = d_l Gamma^m_ij at p, from
 * Metric::TensorSecondDerivatives:
 *   d_l Gamma^m_ij = -g^ma (d_l g_ab) Gamma^b_ij
 *                    + g^mk 1/2 (d_l d_i g_jk + d_l d_j g_ik - d_l d_k g_ij).
 * Shared by ComputeCurvature and the Jacobi-field equations (JacobiField.h).
 * Returns false where the metric refuses second derivatives or g is not
 * finite and positive definite.
 */
RIEMANNCOMMONMETRIC_EXPORT bool ChristoffelAndDerivatives(const Metric& metric, const Vec3& p,
  Mat3& g, Mat3& ginv, Mat3Stack& gamma, std::array<Mat3Stack, 3>& dGamma);
} // namespace riemann

#endif
