/**
 * @file HandPacketReference.h
 * @brief The benchmarks' hand-written SIMD reference: 8 geodesics of the
 * graph metric of a sum of Gaussian bumps stepped at once, RK4 or
 * Dormand-Prince 5(4) written out in one function each with Highway vectors
 * (the flow inlined into the stages, no virtual call, no jet in memory,
 * no mask but the controller's), dispatched at run time to the best target
 * of this CPU, as the library is. It is what a person would write for this
 * one metric; the library's packet engine is measured against it.
 */
#ifndef RiemannHandPacketReference_h
#define RiemannHandPacketReference_h

#include <cstddef>

namespace riemann_bench
{
constexpr int HandLanes = 8;
constexpr int HandMaximumBumps = 16;

/// The bumps, structure of arrays (1 / sigma^2 as InverseVariance).
struct HandBumps
{
  int Count = 0;
  double Amplitude[HandMaximumBumps];
  double Center[3][HandMaximumBumps];
  double InverseVariance[3][HandMaximumBumps];
};

/// 8 geodesics' (x, v), y[component][lane].
struct alignas(64) HandState
{
  double Y[6][HandLanes];
};

/**
 * `steps` RK4 steps of h from y, storing the 8 points after each step in
 * points[(step * 3 + component) * 8 + lane] (steps * 24 doubles).
 */
void HandPacketRungeKutta4(
  const HandBumps& bumps, HandState& y, int steps, double h, double* points);

/**
 * Dormand-Prince 5(4) from y over parameter length `length` per lane (the
 * library's controller: first-same-as-last, RMS error with mixed tolerance,
 * 0.9 error^(-1/5) clamped to [0.2, 5], last step cut to the end), storing
 * each lane's accepted points in points[lane][step * 3 + component] up to
 * `capacity` points per lane. Returns the accepted steps of every lane in
 * stepCounts[lane].
 */
void HandPacketDormandPrince45(const HandBumps& bumps, HandState& y, double length, double h0,
  double tolerance, double minimumStep, double maximumStep, double* const* points,
  std::size_t capacity, long long* stepCounts);

/// The Highway target the reference runs on.
const char* HandPacketTargetName();
} // namespace riemann_bench

#endif
