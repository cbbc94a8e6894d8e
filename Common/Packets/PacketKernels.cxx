// The packet engine's kernels (PacketKernels.h): the geodesic and Jacobi
// flows and the integrators' arithmetic, written once with Google Highway.
// The families' own kernels (graph, conformal, Gaussian sums) live with
// their scalar forms in Common/Metric (GraphMetricPackets.cxx, ...); the
// register types and helpers they share are PacketLanes-inl.h.
//
// Highway's foreach_target.h compiles this file once per x86 target (SSE4,
// AVX2, AVX-512, ...), each copy in its own namespace riemann::N_<TARGET>;
// the HWY_ONCE part at the end exports one table per kernel and calls the
// entry for the best target this CPU supports (HWY_DYNAMIC_DISPATCH).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "PacketKernels.cxx"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include "DormandPrinceTableau.h"
#include "PacketKernels.h"
#include "PacketLanes-inl.h"

#include <cmath>

HWY_BEFORE_NAMESPACE();
namespace riemann
{
namespace HWY_NAMESPACE
{
// --- The flows and the integrators' arithmetic -------------------------------

LaneMask GeodesicFlowPacketImpl(
  const PacketGeodesicSystem& metric, const PacketState& y, PacketState& dy, LaneMask lanes)
{
  // dx/dt = v, copied by vectors (a struct copy may become a memmove call).
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  for (int i = 0; i < 3; ++i)
  {
    for (int o = 0; o < PacketWidth; o += n)
    {
      hn::Store(hn::Load(d, y.V.C[i] + o), d, dy.X.C[i] + o);
    }
  }
  return metric.AccelerationPacket(y.X, y.V, dy.V, lanes);
}

/// The Jacobi system (JacobiField.h): dy = (v, a, DJ_0, A_0, DJ_1, A_1).
LaneMask JacobiFlowPacketImpl(
  const PacketGeodesicSystem& metric, const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  const PacketVec3* const from[3] = { &y.V, &y.DJ[0], &y.DJ[1] };
  PacketVec3* const to[3] = { &dy.X, &dy.J[0], &dy.J[1] };
  for (int b = 0; b < 3; ++b)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int o = 0; o < PacketWidth; o += n)
      {
        hn::Store(hn::Load(d, from[b]->C[i] + o), d, to[b]->C[i] + o);
      }
    }
  }
  return metric.JacobiAccelerationPacket(y, dy, lanes);
}

/// The flow of each state type: the integrators below are written once.
HWY_INLINE LaneMask Flow(
  const PacketGeodesicSystem& metric, const PacketState& y, PacketState& dy, LaneMask lanes)
{
  return GeodesicFlowPacketImpl(metric, y, dy, lanes);
}

HWY_INLINE LaneMask Flow(
  const PacketGeodesicSystem& metric, const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes)
{
  return JacobiFlowPacketImpl(metric, y, dy, lanes);
}

/// out = y + h * sum_j c_j k_j per lane, for every component (a
/// Runge-Kutta stage). The sum runs in the order of the coefficients, as
/// the scalar integrators' Eigen expressions do.
template <class State, int Count>
HWY_INLINE void Stage(const State& y, const double* h, const double (&c)[Count],
  const State* const (&k)[Count], State& out)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  for (int i = 0; i < State::Size; ++i)
  {
    const double* const yi = y.Component(i);
    double* const outi = out.Component(i);
    const double* ki[Count];
    for (int j = 0; j < Count; ++j)
    {
      ki[j] = k[j]->Component(i);
    }
    for (int o = 0; o < PacketWidth; o += n)
    {
      V sum = hn::Mul(hn::Set(d, c[0]), hn::Load(d, ki[0] + o));
      for (int j = 1; j < Count; ++j)
      {
        sum = hn::MulAdd(hn::Set(d, c[j]), hn::Load(d, ki[j] + o), sum);
      }
      hn::Store(hn::MulAdd(hn::Load(d, h + o), sum, hn::Load(d, yi + o)), d, outi + o);
    }
  }
}

/// y <- candidate on the lanes of `lanes`; the others keep y.
template <class State>
HWY_INLINE void Commit(const State& candidate, LaneMask lanes, State& y)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  for (int o = 0; o < PacketWidth; o += n)
  {
    const M take = MaskAt(d, lanes, o);
    for (int i = 0; i < State::Size; ++i)
    {
      const V next = hn::Load(d, candidate.Component(i) + o);
      hn::Store(hn::IfThenElse(take, next, hn::Load(d, y.Component(i) + o)), d, y.Component(i) + o);
    }
  }
}

template <class State>
LaneMask EulerStepOf(const PacketGeodesicSystem& metric, State& y, const double* h, LaneMask lanes)
{
  State k1, next;
  const LaneMask defined = Flow(metric, y, k1, lanes) & lanes;
  const State* const k[1] = { &k1 };
  Stage<State, 1>(y, h, { 1.0 }, k, next);
  Commit(next, defined, y);
  return defined;
}

template <class State>
LaneMask RungeKutta4StepOf(const PacketGeodesicSystem& metric, State& y, const double* h, LaneMask lanes)
{
  State k1, k2, k3, k4, t;
  alignas(64) double half[PacketWidth];
  alignas(64) double sixth[PacketWidth];
  for (int l = 0; l < PacketWidth; ++l)
  {
    half[l] = 0.5 * h[l];
    sixth[l] = h[l] / 6.0;
  }
  LaneMask defined = Flow(metric, y, k1, lanes) & lanes;
  const State* const s1[1] = { &k1 };
  Stage<State, 1>(y, half, { 1.0 }, s1, t);
  defined &= Flow(metric, t, k2, defined);
  const State* const s2[1] = { &k2 };
  Stage<State, 1>(y, half, { 1.0 }, s2, t);
  defined &= Flow(metric, t, k3, defined);
  const State* const s3[1] = { &k3 };
  Stage<State, 1>(y, h, { 1.0 }, s3, t);
  defined &= Flow(metric, t, k4, defined);
  const State* const all[4] = { &k1, &k2, &k3, &k4 };
  Stage<State, 4>(y, sixth, { 1.0, 2.0, 2.0, 1.0 }, all, t);
  Commit(t, defined, y);
  return defined;
}

template <class State>
LaneMask DormandPrince45AttemptOf(const PacketGeodesicSystem& metric, const State& y, const State& k1,
  const double* step, double tolerance, LaneMask lanes, BasicPacketAttempt<State>& attempt)
{
  // The Butcher tableau of Dormand-Prince 5(4) (DormandPrinceTableau.h).
  using namespace riemann::dormand_prince;

  State k2, k3, k4, k5, k6, t, estimate;
  LaneMask defined = lanes;
  {
    const State* const k[1] = { &k1 };
    Stage<State, 1>(y, step, { a21 }, k, t);
    defined &= Flow(metric, t, k2, defined);
  }
  {
    const State* const k[2] = { &k1, &k2 };
    Stage<State, 2>(y, step, { a31, a32 }, k, t);
    defined &= Flow(metric, t, k3, defined);
  }
  {
    const State* const k[3] = { &k1, &k2, &k3 };
    Stage<State, 3>(y, step, { a41, a42, a43 }, k, t);
    defined &= Flow(metric, t, k4, defined);
  }
  {
    const State* const k[4] = { &k1, &k2, &k3, &k4 };
    Stage<State, 4>(y, step, { a51, a52, a53, a54 }, k, t);
    defined &= Flow(metric, t, k5, defined);
  }
  {
    const State* const k[5] = { &k1, &k2, &k3, &k4, &k5 };
    Stage<State, 5>(y, step, { a61, a62, a63, a64, a65 }, k, t);
    defined &= Flow(metric, t, k6, defined);
  }
  {
    const State* const k[5] = { &k1, &k3, &k4, &k5, &k6 };
    Stage<State, 5>(y, step, { b1, b3, b4, b5, b6 }, k, attempt.Next);
    defined &= Flow(metric, attempt.Next, attempt.Derivative, defined);
  }
  {
    // estimate = 0 + h sum e_j k_j, with y = 0 for Stage.
    State zero;
    for (int i = 0; i < State::Size; ++i)
    {
      for (int l = 0; l < PacketWidth; ++l)
      {
        zero.Component(i)[l] = 0.0;
      }
    }
    const State* const k[6] = { &k1, &k3, &k4, &k5, &k6, &attempt.Derivative };
    Stage<State, 6>(zero, step, { e1, e3, e4, e5, e6, e7 }, k, estimate);
  }

  // RMS of estimate / (tol + tol max(|y|, |next|)) over the components,
  // and the controller's factors 0.9 error^(-1/5) clamped to [0.2, 5].
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  const V tol = hn::Set(d, tolerance);
  const V infinity = hn::Set(d, HUGE_VAL);
  for (int o = 0; o < PacketWidth; o += n)
  {
    V sum = hn::Zero(d);
    for (int i = 0; i < State::Size; ++i)
    {
      const V scale = hn::MulAdd(tol,
        hn::Max(hn::Abs(hn::Load(d, y.Component(i) + o)),
          hn::Abs(hn::Load(d, attempt.Next.Component(i) + o))),
        tol);
      const V ratio = hn::Div(hn::Load(d, estimate.Component(i) + o), scale);
      sum = hn::MulAdd(ratio, ratio, sum);
    }
    V error = hn::Sqrt(hn::Div(sum, hn::Set(d, static_cast<double>(State::Size))));
    error = hn::IfThenElse(MaskAt(d, defined, o), error, infinity);
    error = hn::IfThenElse(hn::IsNaN(error), infinity, error);
    const V power =
      hn::Mul(hn::Set(d, 0.9), hn::Exp(d, hn::Mul(hn::Set(d, -0.2), hn::Log(d, error))));
    const V accept = hn::IfThenElse(hn::Gt(error, hn::Zero(d)),
      hn::Min(hn::Set(d, 5.0), hn::Max(hn::Set(d, 0.2), power)), hn::Set(d, 5.0));
    const V reject =
      hn::IfThenElse(hn::IsFinite(error), hn::Max(hn::Set(d, 0.2), power), hn::Set(d, 0.25));
    hn::Store(error, d, attempt.Error + o);
    hn::Store(accept, d, attempt.AcceptFactor + o);
    hn::Store(reject, d, attempt.RejectFactor + o);
  }
  return defined;
}

// Each kernel per state type (HWY_EXPORT takes plain functions).

LaneMask EulerPacketStepImpl(const PacketGeodesicSystem& metric, PacketState& y, const double* h, LaneMask lanes)
{
  return EulerStepOf(metric, y, h, lanes);
}

LaneMask RungeKutta4PacketStepImpl(
  const PacketGeodesicSystem& metric, PacketState& y, const double* h, LaneMask lanes)
{
  return RungeKutta4StepOf(metric, y, h, lanes);
}

LaneMask DormandPrince45PacketAttemptImpl(const PacketGeodesicSystem& metric, const PacketState& y,
  const PacketState& k1, const double* step, double tolerance, LaneMask lanes,
  PacketAttempt& attempt)
{
  return DormandPrince45AttemptOf(metric, y, k1, step, tolerance, lanes, attempt);
}

LaneMask EulerJacobiPacketStepImpl(
  const PacketGeodesicSystem& metric, PacketJacobiState& y, const double* h, LaneMask lanes)
{
  return EulerStepOf(metric, y, h, lanes);
}

LaneMask RungeKutta4JacobiPacketStepImpl(
  const PacketGeodesicSystem& metric, PacketJacobiState& y, const double* h, LaneMask lanes)
{
  return RungeKutta4StepOf(metric, y, h, lanes);
}

LaneMask DormandPrince45JacobiPacketAttemptImpl(const PacketGeodesicSystem& metric, const PacketJacobiState& y,
  const PacketJacobiState& k1, const double* step, double tolerance, LaneMask lanes,
  PacketJacobiAttempt& attempt)
{
  return DormandPrince45AttemptOf(metric, y, k1, step, tolerance, lanes, attempt);
}
} // namespace HWY_NAMESPACE
} // namespace riemann
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace riemann
{
HWY_EXPORT(GeodesicFlowPacketImpl);
HWY_EXPORT(JacobiFlowPacketImpl);
HWY_EXPORT(EulerPacketStepImpl);
HWY_EXPORT(RungeKutta4PacketStepImpl);
HWY_EXPORT(DormandPrince45PacketAttemptImpl);
HWY_EXPORT(EulerJacobiPacketStepImpl);
HWY_EXPORT(RungeKutta4JacobiPacketStepImpl);
HWY_EXPORT(DormandPrince45JacobiPacketAttemptImpl);

std::string PacketTargetName()
{
  // The target HWY_DYNAMIC_DISPATCH chooses: the best of those compiled in
  // that this CPU supports.
  return hwy::TargetName(static_cast<int64_t>(hwy::SupportedAndGeneratedTargets()[0]));
}

LaneMask JacobiFlowPacket(
  const PacketGeodesicSystem& metric, const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes)
{
  return HWY_DYNAMIC_DISPATCH(JacobiFlowPacketImpl)(metric, y, dy, lanes);
}

LaneMask EulerPacketStep(
  const PacketGeodesicSystem& metric, PacketJacobiState& y, const double* h, LaneMask lanes)
{
  return HWY_DYNAMIC_DISPATCH(EulerJacobiPacketStepImpl)(metric, y, h, lanes);
}

LaneMask RungeKutta4PacketStep(
  const PacketGeodesicSystem& metric, PacketJacobiState& y, const double* h, LaneMask lanes)
{
  return HWY_DYNAMIC_DISPATCH(RungeKutta4JacobiPacketStepImpl)(metric, y, h, lanes);
}

LaneMask DormandPrince45PacketAttempt(const PacketGeodesicSystem& metric, const PacketJacobiState& y,
  const PacketJacobiState& k1, const double* step, double tolerance, LaneMask lanes,
  PacketJacobiAttempt& attempt)
{
  return HWY_DYNAMIC_DISPATCH(DormandPrince45JacobiPacketAttemptImpl)(
    metric, y, k1, step, tolerance, lanes, attempt);
}

LaneMask GeodesicFlowPacket(
  const PacketGeodesicSystem& metric, const PacketState& y, PacketState& dy, LaneMask lanes)
{
  return HWY_DYNAMIC_DISPATCH(GeodesicFlowPacketImpl)(metric, y, dy, lanes);
}

LaneMask EulerPacketStep(const PacketGeodesicSystem& metric, PacketState& y, const double* h, LaneMask lanes)
{
  return HWY_DYNAMIC_DISPATCH(EulerPacketStepImpl)(metric, y, h, lanes);
}

LaneMask RungeKutta4PacketStep(
  const PacketGeodesicSystem& metric, PacketState& y, const double* h, LaneMask lanes)
{
  return HWY_DYNAMIC_DISPATCH(RungeKutta4PacketStepImpl)(metric, y, h, lanes);
}

LaneMask DormandPrince45PacketAttempt(const PacketGeodesicSystem& metric, const PacketState& y,
  const PacketState& k1, const double* step, double tolerance, LaneMask lanes,
  PacketAttempt& attempt)
{
  return HWY_DYNAMIC_DISPATCH(DormandPrince45PacketAttemptImpl)(
    metric, y, k1, step, tolerance, lanes, attempt);
}
} // namespace riemann
#endif
