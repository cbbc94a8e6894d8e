/**
 * @file PacketTrace.h
 * @brief The packet engine's integrators and tracer: PacketWidth geodesics
 * stepped in lock step, one SIMD lane each (PacketKernels.h).
 *
 * Lanes are independent: each has its own step, its own adaptive step
 * control (dp45 accepts or rejects per lane; a rejected lane retries with a
 * smaller step in the next attempt while the accepted ones go on, so no
 * lane waits for another), and finishes, fails or hits on its own;
 * TraceGeodesics refills a finished lane with the next seed. The sequence
 * of attempts of every lane is the scalar integrators' (RungeKutta.h), so
 * the results equal TraceGeodesic's to rounding.
 */
#ifndef RiemannPacketTrace_h
#define RiemannPacketTrace_h

#include "GeodesicTrace.h"
#include "PacketKernels.h"
#include "RiemannCommonMetricExport.h"

#include <cstddef>

namespace riemann
{
/**
 * @class BasicPacketStepper
 * @brief FlowStepper for a packet: fixed-step Euler or RK4, or adaptive
 * Dormand-Prince 5(4) with per-lane step control and first-same-as-last
 * cache, in the parameter of each lane's curve. State is PacketState (the
 * geodesic flow: PacketStepper) or PacketJacobiState (the Jacobi system:
 * PacketJacobiStepper); both are instantiated in PacketTrace.cxx.
 */
template <class State>
class BasicPacketStepper
{
public:
  /// `tolerance` is dp45's mixed absolute/relative error per step.
  BasicPacketStepper(IntegratorType type, double tolerance);

  /**
   * Start lane l on a new curve: `step` is its fixed step (the initial one
   * for dp45), bounded by [minimumStep, maximumStep] for dp45.
   */
  void StartLane(int l, double step, double minimumStep, double maximumStep);

  /**
   * One attempt to advance each lane of `lanes` by a step of at most
   * limit[l]. Returns the lanes to retry: dp45 rejected their step, kept
   * their state and set a smaller step (never with euler and rk4). On the
   * other lanes of `lanes`, taken[l] is the step used and status[l] the
   * outcome (IntegrationStep::Status); a lane that does not succeed keeps
   * its state.
   */
  LaneMask Advance(const Metric& metric, State& y, const double* limit, LaneMask lanes,
    double* taken, IntegrationStep::Status* status);

private:
  LaneMask AdvanceAdaptive(const Metric& metric, State& y, const double* limit, LaneMask lanes,
    double* taken, IntegrationStep::Status* status);

  IntegratorType Type;
  double Tolerance;
  alignas(64) double Step[PacketWidth];
  alignas(64) double MinimumStep[PacketWidth];
  alignas(64) double MaximumStep[PacketWidth];
  /// dp45's first-same-as-last derivative, valid on the lanes of HaveDerivative.
  State Derivative;
  LaneMask HaveDerivative = 0;
};

extern template class RIEMANNCOMMONMETRIC_EXPORT BasicPacketStepper<PacketState>;
extern template class RIEMANNCOMMONMETRIC_EXPORT BasicPacketStepper<PacketJacobiState>;
using PacketStepper = BasicPacketStepper<PacketState>;
using PacketJacobiStepper = BasicPacketStepper<PacketJacobiState>;

/// Where a geodesic starts: TraceGeodesic's p, v and backward.
struct GeodesicSeed
{
  Vec3 Point = Vec3::Zero();
  Vec3 Velocity = Vec3::Zero();
  bool Backward = false;
};

/**
 * TraceGeodesic for seeds[0, count) into paths[0, count), PacketWidth at a
 * time: the same paths, points, arc lengths, drifts and termination reasons,
 * to rounding. Single-threaded; callers split their seeds across threads.
 */
RIEMANNCOMMONMETRIC_EXPORT void TraceGeodesics(const Metric& metric, const GeodesicSeed* seeds,
  std::size_t count, const GeodesicOptions& options, GeodesicPath* paths);
} // namespace riemann

#endif
