#include "PacketTrace.h"

#include <algorithm>
#include <cmath>

namespace riemann
{
namespace
{
constexpr LaneMask Bit(int l)
{
  return LaneMask{ 1 } << l;
}

/// Lane l of a packet state as (x, v).
Vec6 StateLane(const PacketState& y, int l)
{
  Vec6 lane;
  for (int i = 0; i < 6; ++i)
  {
    lane[i] = y.Component(i)[l];
  }
  return lane;
}

void SetStateLane(PacketState& y, int l, const Vec6& lane)
{
  for (int i = 0; i < 6; ++i)
  {
    y.Component(i)[l] = lane[i];
  }
}

template <class State>
void CopyStateLane(const State& from, int l, State& to)
{
  for (int i = 0; i < State::Size; ++i)
  {
    to.Component(i)[l] = from.Component(i)[l];
  }
}

/// The flow of each state type.
LaneMask FlowPacket(const Metric& metric, const PacketState& y, PacketState& dy, LaneMask lanes)
{
  return GeodesicFlowPacket(metric, y, dy, lanes);
}

LaneMask FlowPacket(
  const Metric& metric, const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes)
{
  return JacobiFlowPacket(metric, y, dy, lanes);
}
} // namespace

// --- PacketStepper -------------------------------------------------------------

template <class State>
BasicPacketStepper<State>::BasicPacketStepper(IntegratorType type, double tolerance)
  : Type(type)
  , Tolerance(tolerance)
{
  for (int l = 0; l < PacketWidth; ++l)
  {
    this->Step[l] = this->MinimumStep[l] = this->MaximumStep[l] = 0.0;
  }
}

template <class State>
void BasicPacketStepper<State>::StartLane(
  int l, double step, double minimumStep, double maximumStep)
{
  this->Step[l] = step;
  this->MinimumStep[l] = minimumStep;
  this->MaximumStep[l] = maximumStep;
  this->HaveDerivative &= ~Bit(l);
}

template <class State>
LaneMask BasicPacketStepper<State>::Advance(const Metric& metric, State& y, const double* limit,
  LaneMask lanes, double* taken, IntegrationStep::Status* status)
{
  if (this->Type == IntegratorType::DormandPrince45)
  {
    return this->AdvanceAdaptive(metric, y, limit, lanes, taken, status);
  }
  alignas(64) double h[PacketWidth];
  for (int l = 0; l < PacketWidth; ++l)
  {
    h[l] = HasLane(lanes, l) ? std::min(this->Step[l], limit[l]) : 0.0;
  }
  const LaneMask stepped = this->Type == IntegratorType::Euler
    ? EulerPacketStep(metric, y, h, lanes)
    : RungeKutta4PacketStep(metric, y, h, lanes);
  for (int l = 0; l < PacketWidth; ++l)
  {
    if (HasLane(lanes, l))
    {
      taken[l] = h[l];
      status[l] = HasLane(stepped, l) ? IntegrationStep::Accepted : IntegrationStep::Degenerate;
    }
  }
  return 0;
}

template <class State>
LaneMask BasicPacketStepper<State>::AdvanceAdaptive(const Metric& metric, State& y,
  const double* limit, LaneMask lanes, double* taken, IntegrationStep::Status* status)
{
  // Step 1: the first-same-as-last derivative of lanes that start a curve.
  LaneMask pending = lanes;
  const LaneMask fresh = lanes & ~this->HaveDerivative;
  if (fresh != 0)
  {
    State derivative;
    const LaneMask defined = FlowPacket(metric, y, derivative, fresh);
    for (int l = 0; l < PacketWidth; ++l)
    {
      if (!HasLane(fresh, l))
      {
        continue;
      }
      if (HasLane(defined, l))
      {
        CopyStateLane(derivative, l, this->Derivative);
        this->HaveDerivative |= Bit(l);
      }
      else
      {
        status[l] = IntegrationStep::Degenerate;
        pending &= ~Bit(l);
      }
    }
  }
  if (pending == 0)
  {
    return 0;
  }

  // Step 2: one attempt of every pending lane, each with its own step.
  alignas(64) double step[PacketWidth];
  bool lastStep[PacketWidth];
  for (int l = 0; l < PacketWidth; ++l)
  {
    step[l] = 0.0;
    lastStep[l] = false;
    if (HasLane(pending, l))
    {
      this->Step[l] = std::min(std::max(this->Step[l], this->MinimumStep[l]), this->MaximumStep[l]);
      lastStep[l] = this->Step[l] >= limit[l];
      step[l] = lastStep[l] ? limit[l] : this->Step[l];
    }
  }
  BasicPacketAttempt<State> attempt;
  const LaneMask defined = DormandPrince45PacketAttempt(
    metric, y, this->Derivative, step, this->Tolerance, pending, attempt);

  // Step 3: each lane's controller, as DormandPrince45Of::Step; a rejected
  // lane keeps its state and retries with the smaller step.
  LaneMask retry = 0;
  for (int l = 0; l < PacketWidth; ++l)
  {
    if (!HasLane(pending, l))
    {
      continue;
    }
    if (attempt.Error[l] <= 1.0)
    {
      CopyStateLane(attempt.Next, l, y);
      CopyStateLane(attempt.Derivative, l, this->Derivative);
      taken[l] = step[l];
      const double factor = attempt.AcceptFactor[l];
      if (!lastStep[l] || factor < 1.0)
      {
        this->Step[l] =
          std::min(std::max(step[l] * factor, this->MinimumStep[l]), this->MaximumStep[l]);
      }
      status[l] = IntegrationStep::Accepted;
    }
    else if (step[l] <= this->MinimumStep[l])
    {
      // A stage still hits a degenerate point at the smallest step: report
      // it as such rather than as an accuracy failure.
      status[l] = HasLane(defined, l) ? IntegrationStep::StepTooSmall : IntegrationStep::Degenerate;
    }
    else
    {
      this->Step[l] = std::max(this->MinimumStep[l], step[l] * attempt.RejectFactor[l]);
      retry |= Bit(l);
    }
  }
  return retry;
}

// Exported by the extern declarations in PacketTrace.h.
template class BasicPacketStepper<PacketState>;
template class BasicPacketStepper<PacketJacobiState>;

// --- TraceGeodesics --------------------------------------------------------------

namespace
{
/// One lane's geodesic: TraceGeodesic's local variables.
struct LaneTrace
{
  GeodesicPath* Path = nullptr;
  double Sign = 1.0;
  double Speed = 1.0;
  /// Sign / Speed: dx/ds of the forward parametrisation from the state's v.
  double VelocityScale = 1.0;
  double InitialSquaredSpeed = 1.0;
  double ParameterEnd = 0.0;
  double Arrival = 0.0;
  double Tau = 0.0;
  long long Steps = 0;

  void Record(const Vec6& y, double drift) const
  {
    this->Path->Points.push_back(y.head<3>());
    this->Path->Velocities.push_back(y.tail<3>() * this->VelocityScale);
    this->Path->ArcLength.push_back(this->Sign * this->Speed * this->Tau);
    this->Path->SpeedDrift.push_back(drift);
  }
};

/**
 * The lanes of a packet and the seeds still to trace: TraceGeodesic's loop
 * with one geodesic per lane, as named steps.
 */
class PacketTracer
{
public:
  PacketTracer(const Metric& metric, const GeodesicSeed* seeds, std::size_t count,
    const GeodesicOptions& options, GeodesicPath* paths)
    : TheMetric(metric)
    , Seeds(seeds)
    , Count(count)
    , Options(options)
    , Paths(paths)
    , Stepper(options.Integrator, options.Tolerance)
  {
    for (int l = 0; l < PacketWidth; ++l)
    {
      SetStateLane(this->State, l, Vec6::Zero());
    }
  }

  void Run()
  {
    for (;;)
    {
      this->FillFreeLanes();
      if (this->Active == 0)
      {
        return;
      }
      const LaneMask stepping = this->EndFinishedLanes();
      if (stepping != 0)
      {
        this->StepAndRecord(stepping);
      }
    }
  }

private:
  /// Step 1: start the next seeds in the free lanes. Seeds that end before
  /// their first step (as TraceGeodesic's early returns) take no lane.
  void FillFreeLanes()
  {
    for (int l = 0; l < PacketWidth && this->Next < this->Count; ++l)
    {
      while (!HasLane(this->Active, l) && this->Next < this->Count)
      {
        const std::size_t i = this->Next++;
        if (this->StartLane(l, this->Seeds[i], this->Paths[i]))
        {
          this->Active |= Bit(l);
        }
      }
    }
  }

  bool StartLane(int l, const GeodesicSeed& seed, GeodesicPath& path)
  {
    path.Clear();
    const Vec3& p = seed.Point;
    const Vec3& v = seed.Velocity;
    const double initialSquaredSpeed = this->TheMetric.InnerProduct(p, v, v);
    if (!p.allFinite() || !v.allFinite() || !std::isfinite(initialSquaredSpeed) ||
      !(initialSquaredSpeed > 0))
    {
      path.Reason = std::isfinite(initialSquaredSpeed) || !p.allFinite() || !v.allFinite()
        ? NotInitialized
        : DegenerateMetric;
      return false;
    }
    LaneTrace& lane = this->Lanes[l];
    lane.Path = &path;
    lane.Sign = seed.Backward ? -1.0 : 1.0;
    lane.Speed = std::sqrt(initialSquaredSpeed);
    lane.VelocityScale = lane.Sign / lane.Speed;
    lane.InitialSquaredSpeed = initialSquaredSpeed;
    // Work in the curve parameter tau (arc length = speed * tau).
    lane.ParameterEnd = this->Options.MaximumLength / lane.Speed;
    // Steps shorter than this (relative to the length) count as arriving.
    lane.Arrival = 1e-12 * std::max(1.0, lane.ParameterEnd);
    lane.Tau = 0.0;
    lane.Steps = 0;
    Vec6 y;
    y << p, lane.Sign * v;
    lane.Record(y, 0.0);
    if (const int stop = ReasonToStopAt(this->TheMetric, this->Options, p))
    {
      path.Reason = stop;
      return false;
    }
    SetStateLane(this->State, l, y);
    this->Stepper.StartLane(l, this->Options.Step / lane.Speed,
      this->Options.MinimumStep / lane.Speed, this->Options.MaximumStep / lane.Speed);
    return true;
  }

  /// Free lane l with `reason`; its state becomes finite filler.
  void EndLane(int l, int reason)
  {
    this->Lanes[l].Path->Reason = reason;
    this->Active &= ~Bit(l);
    SetStateLane(this->State, l, Vec6::Zero());
  }

  /// Step 2: end the lanes that reached their length or step budget; the
  /// others step. Returns those.
  LaneMask EndFinishedLanes()
  {
    LaneMask stepping = 0;
    for (int l = 0; l < PacketWidth; ++l)
    {
      if (!HasLane(this->Active, l))
      {
        continue;
      }
      const LaneTrace& lane = this->Lanes[l];
      this->Remaining[l] = lane.ParameterEnd - lane.Tau;
      if (this->Remaining[l] <= lane.Arrival)
      {
        this->EndLane(l, OutOfLength);
      }
      else if (lane.Steps >= this->Options.MaximumSteps)
      {
        this->EndLane(l, OutOfSteps);
      }
      else
      {
        stepping |= Bit(l);
      }
    }
    return stepping;
  }

  /// Step 3: one attempt of every stepping lane, then the checks and record
  /// of each lane that stepped, as TraceGeodesic's loop body.
  void StepAndRecord(LaneMask stepping)
  {
    alignas(64) double taken[PacketWidth] = {};
    IntegrationStep::Status status[PacketWidth] = {};
    const LaneMask retry =
      this->Stepper.Advance(this->TheMetric, this->State, this->Remaining, stepping, taken, status);
    LaneMask stepped = 0;
    for (int l = 0; l < PacketWidth; ++l)
    {
      // A lane to retry (dp45 rejected its step) tries again next round.
      if (!HasLane(stepping & ~retry, l))
      {
        continue;
      }
      if (status[l] != IntegrationStep::Accepted)
      {
        this->EndLane(
          l, status[l] == IntegrationStep::StepTooSmall ? Stagnation : DegenerateMetric);
      }
      else
      {
        this->Stepped[l] = StateLane(this->State, l);
        if (!this->Stepped[l].allFinite())
        {
          this->EndLane(l, UnexpectedValue);
          continue;
        }
        if (StepOutranItsSpeed(*this->Lanes[l].Path, this->Stepped[l].head<3>(),
              this->Lanes[l].Speed * taken[l]))
        {
          this->EndLane(l, OutranStep);
          continue;
        }
        this->Lanes[l].Tau += taken[l];
        ++this->Lanes[l].Steps;
        stepped |= Bit(l);
      }
    }
    this->RecordStepped(stepped);
  }

  /// Step 4: the speed drift (one TensorPacket for the whole packet), the
  /// record and the bounds check of the lanes that stepped.
  void RecordStepped(LaneMask stepped)
  {
    PacketSym3 g;
    LaneMask metricDefined = stepped;
    if (this->Options.RecordSpeedDrift && stepped != 0)
    {
      metricDefined = this->TheMetric.TensorPacket(this->State.X, g, stepped);
    }
    for (int l = 0; l < PacketWidth; ++l)
    {
      if (!HasLane(stepped, l))
      {
        continue;
      }
      const Vec6& y = this->Stepped[l];
      double drift = 0.0;
      if (this->Options.RecordSpeedDrift)
      {
        const Vec3 velocity = y.tail<3>();
        const double squaredSpeed =
          HasLane(metricDefined, l) ? velocity.dot(g.Lane(l) * velocity) : std::nan("");
        if (!std::isfinite(squaredSpeed))
        {
          // The step landed where g is degenerate: the point is not on the
          // manifold, so it is not recorded.
          this->EndLane(l, DegenerateMetric);
          continue;
        }
        drift = squaredSpeed / this->Lanes[l].InitialSquaredSpeed - 1.0;
      }
      const LaneTrace& lane = this->Lanes[l];
      const int stop = ReasonToStopAt(this->TheMetric, this->Options, y.head<3>());
      if (stop == OutOfData)
      {
        EndOnTheDataFace(this->TheMetric, *lane.Path, y.head<3>(),
          y.tail<3>() * lane.VelocityScale, lane.Sign * lane.Speed * lane.Tau, drift);
        this->EndLane(l, OutOfData);
        continue;
      }
      lane.Record(y, drift);
      if (stop)
      {
        this->EndLane(l, stop);
      }
    }
  }

  const Metric& TheMetric;
  const GeodesicSeed* Seeds;
  std::size_t Count;
  const GeodesicOptions& Options;
  GeodesicPath* Paths;
  PacketStepper Stepper;
  PacketState State;
  LaneTrace Lanes[PacketWidth];
  /// The state of each lane after its last step (StepAndRecord -> RecordStepped).
  Vec6 Stepped[PacketWidth];
  alignas(64) double Remaining[PacketWidth] = {};
  LaneMask Active = 0;
  std::size_t Next = 0;
};
} // namespace

void TraceGeodesics(const Metric& metric, const GeodesicSeed* seeds, std::size_t count,
  const GeodesicOptions& options, GeodesicPath* paths)
{
  PacketTracer tracer(metric, seeds, count, options, paths);
  tracer.Run();
}
} // namespace riemann
