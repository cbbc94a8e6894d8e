// The packet form of TraceJacobiFields (JacobiField.h): the loop of the
// scalar form (JacobiField.cxx) with one trace per lane of a
// PacketJacobiStepper, as the geodesic packet tracer (PacketTrace.cxx) does
// for TraceGeodesic. The per-sample work (frame, singular values, phases)
// stays scalar, lane by lane: the Jacobi system's flow is what costs.
#include "JacobiField.h"
#include "JacobiFieldInternals.h"
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

Vec18 StateLane(const PacketJacobiState& y, int l)
{
  Vec18 lane;
  for (int i = 0; i < PacketJacobiState::Size; ++i)
  {
    lane[i] = y.Component(i)[l];
  }
  return lane;
}

void SetStateLane(PacketJacobiState& y, int l, const Vec18& lane)
{
  for (int i = 0; i < PacketJacobiState::Size; ++i)
  {
    y.Component(i)[l] = lane[i];
  }
}

/// One lane's trace: the scalar loop's local variables.
struct LaneTrace
{
  std::size_t Trace = 0;
  double Sign = 1.0;
  double S = 0.0;
  long long Steps = 0;
  std::size_t NextStop = 0;
};

/**
 * The lanes of a packet and the seeds still to trace, as named steps:
 * FillFreeLanes, EndFinishedLanes (with each lane's landing target),
 * StepAndVisit.
 */
class JacobiPacketTracer
{
public:
  JacobiPacketTracer(const Metric& metric, const JacobiSeed* seeds, std::size_t count,
    const GeodesicOptions& options, const std::vector<double>& landings, bool withPhases,
    JacobiVisitor& visitor)
    : TheMetric(metric)
    , Seeds(seeds)
    , Count(count)
    , Options(options)
    , Stops(jacobi_detail::LandingStops(landings, options.MaximumLength))
    , WithPhases(withPhases)
    , Visitor(visitor)
    , Stepper(options.Integrator, options.Tolerance)
    // Steps shorter than this (relative to the length) count as arriving.
    , Arrival(1e-12 * std::max(1.0, options.MaximumLength))
  {
    for (int l = 0; l < PacketWidth; ++l)
    {
      SetStateLane(this->State, l, Vec18::Zero());
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
        this->StepAndVisit(stepping);
      }
    }
  }

private:
  /// Step 1: start the next seeds in the free lanes; seeds that end before
  /// their first step (the scalar form's early returns) take no lane.
  void FillFreeLanes()
  {
    for (int l = 0; l < PacketWidth && this->Next < this->Count; ++l)
    {
      while (!HasLane(this->Active, l) && this->Next < this->Count)
      {
        const std::size_t i = this->Next++;
        this->Visitor.Start(l, i);
        const int reason = this->StartLane(l, i);
        if (reason < 0)
        {
          this->Active |= Bit(l);
        }
        else
        {
          this->Visitor.End(l, i, reason);
        }
      }
    }
  }

  /// -1 when lane l traces seed i, else the reason it ended at once.
  int StartLane(int l, std::size_t i)
  {
    const JacobiSeed& seed = this->Seeds[i];
    const GeodesicOptions& options = this->Options;
    if (!seed.Point.allFinite() || !seed.Direction.allFinite() || !(options.Step > 0.0) ||
      !(options.MaximumLength >= 0.0) || std::isnan(options.MaximumLength))
    {
      return NotInitialized;
    }
    Vec18 y;
    int reason = NotInitialized;
    if (!jacobi_detail::InitialState(this->TheMetric, seed.Point,
          seed.Backward ? Vec3(-seed.Direction) : seed.Direction, y, reason))
    {
      return reason;
    }
    LaneTrace& lane = this->Lanes[l];
    lane.Trace = i;
    lane.Sign = seed.Backward ? -1.0 : 1.0;
    lane.S = 0.0;
    lane.Steps = 0;
    lane.NextStop = 0;
    JacobiSample sample;
    if (jacobi_detail::FillSample(this->TheMetric, 0.0, y, sample, this->WithPhases) &&
      !this->Visitor.Visit(l, i, sample))
    {
      return 0;
    }
    if (const int stop = ReasonToStopAt(this->TheMetric, options, seed.Point))
    {
      return stop;
    }
    SetStateLane(this->State, l, y);
    this->Stepper.StartLane(l, options.Step, options.MinimumStep, options.MaximumStep);
    return -1;
  }

  void EndLane(int l, int reason)
  {
    this->Visitor.End(l, this->Lanes[l].Trace, reason);
    this->Active &= ~Bit(l);
    SetStateLane(this->State, l, Vec18::Zero());
  }

  /// Step 2: end the lanes that reached their length or step budget; the
  /// others step towards their next landing (or the length). Returns those.
  LaneMask EndFinishedLanes()
  {
    LaneMask stepping = 0;
    for (int l = 0; l < PacketWidth; ++l)
    {
      if (!HasLane(this->Active, l))
      {
        continue;
      }
      LaneTrace& lane = this->Lanes[l];
      while (
        lane.NextStop < this->Stops.size() && this->Stops[lane.NextStop] - lane.S <= this->Arrival)
      {
        ++lane.NextStop;
      }
      this->Target[l] = lane.NextStop < this->Stops.size() ? this->Stops[lane.NextStop]
                                                           : this->Options.MaximumLength;
      this->Remaining[l] = this->Target[l] - lane.S;
      if (this->Options.MaximumLength - lane.S <= this->Arrival)
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

  /// Step 3: one attempt of every stepping lane; each lane that stepped is
  /// checked, sampled, visited and bounds-checked as in the scalar loop.
  void StepAndVisit(LaneMask stepping)
  {
    alignas(64) double taken[PacketWidth] = {};
    IntegrationStep::Status status[PacketWidth] = {};
    const LaneMask retry =
      this->Stepper.Advance(this->TheMetric, this->State, this->Remaining, stepping, taken, status);
    JacobiSample sample;
    for (int l = 0; l < PacketWidth; ++l)
    {
      // A lane to retry (dp45 rejected its step) tries again next round.
      if (!HasLane(stepping & ~retry, l))
      {
        continue;
      }
      LaneTrace& lane = this->Lanes[l];
      ++lane.Steps;
      if (status[l] != IntegrationStep::Accepted)
      {
        this->EndLane(
          l, status[l] == IntegrationStep::StepTooSmall ? Stagnation : DegenerateMetric);
        continue;
      }
      const Vec18 y = StateLane(this->State, l);
      if (!y.allFinite())
      {
        this->EndLane(l, UnexpectedValue);
        continue;
      }
      // Land exactly on a landing or on the length (no rounding drift).
      lane.S =
        (this->Remaining[l] - taken[l] <= this->Arrival) ? this->Target[l] : lane.S + taken[l];
      if (!jacobi_detail::FillSample(
            this->TheMetric, lane.Sign * lane.S, y, sample, this->WithPhases))
      {
        // The step landed where g is degenerate: not a point of the manifold.
        this->EndLane(l, DegenerateMetric);
      }
      else if (!this->Visitor.Visit(l, lane.Trace, sample))
      {
        this->EndLane(l, 0);
      }
      else if (const int stop = ReasonToStopAt(this->TheMetric, this->Options, y.head<3>()))
      {
        this->EndLane(l, stop);
      }
    }
  }

  const Metric& TheMetric;
  const JacobiSeed* Seeds;
  std::size_t Count;
  const GeodesicOptions& Options;
  const std::vector<double> Stops;
  bool WithPhases;
  JacobiVisitor& Visitor;
  PacketJacobiStepper Stepper;
  const double Arrival;
  PacketJacobiState State;
  LaneTrace Lanes[PacketWidth];
  alignas(64) double Remaining[PacketWidth] = {};
  double Target[PacketWidth] = {};
  LaneMask Active = 0;
  std::size_t Next = 0;
};

/// Keeps every sample of every trace (the JacobiTrace form).
class CollectingVisitor : public JacobiVisitor
{
public:
  explicit CollectingVisitor(JacobiTrace* traces)
    : Traces(traces)
  {
  }
  void Start(int, std::size_t trace) override
  {
    this->Traces[trace].Samples.clear();
    this->Traces[trace].Reason = NotInitialized;
  }
  bool Visit(int, std::size_t trace, const JacobiSample& sample) override
  {
    this->Traces[trace].Samples.push_back(sample);
    return true;
  }
  void End(int, std::size_t trace, int reason) override { this->Traces[trace].Reason = reason; }

private:
  JacobiTrace* Traces;
};
} // namespace

void TraceJacobiFields(const Metric& metric, const JacobiSeed* seeds, std::size_t count,
  const GeodesicOptions& options, const std::vector<double>& landings, bool withPhases,
  JacobiVisitor& visitor)
{
  JacobiPacketTracer tracer(metric, seeds, count, options, landings, withPhases, visitor);
  tracer.Run();
}

void TraceJacobiFields(const Metric& metric, const JacobiSeed* seeds, std::size_t count,
  const GeodesicOptions& options, JacobiTrace* traces, const std::vector<double>& landings)
{
  CollectingVisitor visitor(traces);
  TraceJacobiFields(metric, seeds, count, options, landings, false, visitor);
}
} // namespace riemann
