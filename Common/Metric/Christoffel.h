/**
 * @file Christoffel.h
 * @brief The general Christoffel formula and the geodesic right-hand side,
 * shared by the tensor family and by every test of the specialised families.
 *
 * Gamma^m_ij = 1/2 g^mk (d_i g_jk + d_j g_ik - d_k g_ij)   (MATH.md; the
 * paper's printed index order is a typo). Stored as gamma[m](i, j).
 */
#ifndef RiemannChristoffel_h
#define RiemannChristoffel_h

#include "Jets.h"
#include "RiemannCommonMetricExport.h"

namespace riemann
{
/// dg[k](i, j) = d_k g_ij.
RIEMANNCOMMONMETRIC_EXPORT void ChristoffelFromMetricDerivatives(
  const Mat3& inverseMetric, const Mat3Stack& dg, Mat3Stack& gamma);

/// a^m = -Gamma^m_ij v^i v^j.
inline Vec3 ContractChristoffel(const Mat3Stack& gamma, const Vec3& v)
{
  return Vec3(-v.dot(gamma[0] * v), -v.dot(gamma[1] * v), -v.dot(gamma[2] * v));
}
} // namespace riemann

#endif
