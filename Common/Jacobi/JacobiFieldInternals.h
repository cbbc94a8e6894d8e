/**
 * @file JacobiFieldInternals.h
 * @brief The steps of TraceJacobiFields shared by its scalar form
 * (JacobiField.cxx) and its packet form (JacobiPacketTrace.cxx), so that
 * both start, sample and land the same way. Not installed.
 */
#ifndef RiemannJacobiFieldInternals_h
#define RiemannJacobiFieldInternals_h

#include "JacobiField.h"

#include <vector>

namespace riemann
{
/// The Jacobi system's state (x, v, X_0, V_0, X_1, V_1).
using Vec18 = Eigen::Matrix<double, 18, 1>;

namespace jacobi_detail
{
/// The sample of state y at arc length s; with `withPhases`, its Maslov
/// phases too. False where g is degenerate at y's point.
bool FillSample(
  const Metric& metric, double s, const Vec18& y, JacobiSample& sample, bool withPhases);

/// The state (x, v, J0, J0', J1, J1') at the seed: v the unit-speed
/// direction, J = 0 and J' an orthonormal transverse frame. False, with
/// `reason` DegenerateMetric, where g is not a metric (`reason` unchanged
/// for a zero direction).
bool InitialState(
  const Metric& metric, const Vec3& p, const Vec3& direction, Vec18& y, int& reason);

/// The arc lengths strictly inside (0, length) that a trace must land on, sorted.
std::vector<double> LandingStops(const std::vector<double>& landings, double length);
} // namespace jacobi_detail
} // namespace riemann

#endif
