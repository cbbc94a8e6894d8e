/**
 * @file LegacyConjugateSearch.h
 * @brief The conjugate-point search the library used before the Maslov-phase
 * count (ConjugatePoints.h), kept only here as the benchmarks' reference.
 *
 * Why it exists: BenchConjugatePoints.cxx measures what the new detection
 * costs against "today's detection", the old one, on the same machine in the
 * same run (the cost ratio in Testing/Benchmarks/README.md), and how often
 * the old one misses or merges two close simple points. The old code left
 * the library with commit 336d349 (it was FindConjugatePoints in
 * Common/Metric/JacobiField.cxx at 48702d2); this is that algorithm rebuilt
 * on the library's public API only. It is NOT part of the library: nothing
 * outside Testing/Benchmarks may use it, and it is not maintained beyond
 * reproducing the old behaviour.
 *
 * The old method: trace the Jacobi fields (TraceJacobiFields with `options`
 * exactly as given, to the full options.MaximumLength whatever maximumCount
 * is), then over each interval of samples look for
 *  - a sign change of det J: bisection on det J, re-integrated by RK4 from
 *    the interval's start (ContinueJacobiFields, at least 8 sub-steps per
 *    sample interval), to `tolerance` in arc length;
 *  - a touching zero (|det J| at a local minimum without sign change): the
 *    golden-section minimum of the smallest singular value over the two
 *    neighbouring intervals, accepted below the rank threshold
 *    max(100 tolerance, 1e-6) (|DJ_0|_g + |DJ_1|_g).
 * Multiplicity 2 where the largest singular value is below 1e-3 (|DJ_0|_g +
 * |DJ_1|_g) too; roots closer than half a sample spacing to the previous one
 * are the same point seen twice; the search stops where |g(v, v) - 1| > 1e-4.
 * Its known flaw: two simple conjugate points inside one step cancel in the
 * sign of det J, so one of them is missed or the two are merged into one
 * point (of multiplicity 1 or 2).
 *
 * Differences from the old build that remain: the samples now also carry
 * Maslov phases (JacobiSample::Phases), which TraceJacobiFields and
 * ContinueJacobiFields compute at every sample; this search ignores them but
 * pays for them, so it runs somewhat slower than the old library did.
 * ConjugatePoint::Sheet and KernelDirection are left at their defaults (the
 * old search had neither).
 */
#ifndef RiemannLegacyConjugateSearch_h
#define RiemannLegacyConjugateSearch_h

#include "ConjugatePoints.h"

#include <vector>

namespace riemann
{
namespace bench
{
/**
 * The old FindConjugatePoints (file comment): conjugate points of p along the
 * geodesic in `direction` up to options.MaximumLength, roots to `tolerance`,
 * at most `maximumCount` (no limit when <= 0), in order of arc length.
 */
std::vector<ConjugatePoint> LegacyFindConjugatePoints(const Metric& metric, const Vec3& p,
  const Vec3& direction, const GeodesicOptions& options, double tolerance, int maximumCount);
} // namespace bench
} // namespace riemann

#endif
