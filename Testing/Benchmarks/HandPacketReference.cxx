// The hand-written SIMD reference of BenchGeodesicSteps (HandPacketReference.h),
// compiled by Highway for every x86 target and dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "HandPacketReference.cxx"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include "DormandPrinceTableau.h"
#include "HandPacketReference.h"

#include <algorithm>
#include <cmath>

HWY_BEFORE_NAMESPACE();
namespace riemann_bench
{
namespace HWY_NAMESPACE
{
namespace hn = hwy::HWY_NAMESPACE;
using D = hn::CappedTag<double, HandLanes>;
using V = hn::Vec<D>;

/// a = -grad f (v^T H v) / (1 + |grad f|^2) for one vector of lanes.
HWY_INLINE void Acceleration(const HandBumps& b, V x, V y, V z, V vx, V vy, V vz, V& ax, V& ay,
  V& az)
{
  const D d;
  V gx = hn::Zero(d), gy = hn::Zero(d), gz = hn::Zero(d);
  V hxx = hn::Zero(d), hyy = hn::Zero(d), hzz = hn::Zero(d);
  V hxy = hn::Zero(d), hxz = hn::Zero(d), hyz = hn::Zero(d);
  for (int k = 0; k < b.Count; ++k)
  {
    const V dx = hn::Sub(x, hn::Set(d, b.Center[0][k]));
    const V dy = hn::Sub(y, hn::Set(d, b.Center[1][k]));
    const V dz = hn::Sub(z, hn::Set(d, b.Center[2][k]));
    const V wx = hn::Set(d, b.InverseVariance[0][k]);
    const V wy = hn::Set(d, b.InverseVariance[1][k]);
    const V wz = hn::Set(d, b.InverseVariance[2][k]);
    const V ux = hn::Mul(wx, dx), uy = hn::Mul(wy, dy), uz = hn::Mul(wz, dz);
    const V q = hn::MulAdd(dz, uz, hn::MulAdd(dy, uy, hn::Mul(dx, ux)));
    const V f = hn::Mul(hn::Set(d, b.Amplitude[k]), hn::Exp(d, hn::Mul(hn::Set(d, -0.5), q)));
    const V fux = hn::Mul(f, ux), fuy = hn::Mul(f, uy), fuz = hn::Mul(f, uz);
    gx = hn::Sub(gx, fux);
    gy = hn::Sub(gy, fuy);
    gz = hn::Sub(gz, fuz);
    hxx = hn::NegMulAdd(f, wx, hn::MulAdd(fux, ux, hxx));
    hyy = hn::NegMulAdd(f, wy, hn::MulAdd(fuy, uy, hyy));
    hzz = hn::NegMulAdd(f, wz, hn::MulAdd(fuz, uz, hzz));
    hxy = hn::MulAdd(fux, uy, hxy);
    hxz = hn::MulAdd(fux, uz, hxz);
    hyz = hn::MulAdd(fuy, uz, hyz);
  }
  const V diagonal = hn::MulAdd(hn::Mul(hzz, vz), vz,
    hn::MulAdd(hn::Mul(hyy, vy), vy, hn::Mul(hn::Mul(hxx, vx), vx)));
  const V off = hn::MulAdd(hn::Mul(hyz, vy), vz,
    hn::MulAdd(hn::Mul(hxz, vx), vz, hn::Mul(hn::Mul(hxy, vx), vy)));
  const V vHv = hn::MulAdd(hn::Set(d, 2.0), off, diagonal);
  const V s = hn::Neg(hn::Div(
    vHv, hn::Add(hn::Set(d, 1.0), hn::MulAdd(gz, gz, hn::MulAdd(gy, gy, hn::Mul(gx, gx))))));
  ax = hn::Mul(s, gx);
  ay = hn::Mul(s, gy);
  az = hn::Mul(s, gz);
}

/// The flow (v, a) of the state s (6 vectors) into k.
HWY_INLINE void Flow(const HandBumps& b, const V (&s)[6], V (&k)[6])
{
  k[0] = s[3];
  k[1] = s[4];
  k[2] = s[5];
  Acceleration(b, s[0], s[1], s[2], s[3], s[4], s[5], k[3], k[4], k[5]);
}

void HandPacketRungeKutta4Impl(
  const HandBumps& bumps, HandState& state, int steps, double h, double* points)
{
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  const V hv = hn::Set(d, h), half = hn::Set(d, 0.5 * h), sixth = hn::Set(d, h / 6.0);
  const V two = hn::Set(d, 2.0);
  for (int o = 0; o < HandLanes; o += n)
  {
    V y[6], k1[6], k2[6], k3[6], k4[6], t[6];
    for (int i = 0; i < 6; ++i)
    {
      y[i] = hn::Load(d, state.Y[i] + o);
    }
    for (int step = 0; step < steps; ++step)
    {
      Flow(bumps, y, k1);
      for (int i = 0; i < 6; ++i)
      {
        t[i] = hn::MulAdd(half, k1[i], y[i]);
      }
      Flow(bumps, t, k2);
      for (int i = 0; i < 6; ++i)
      {
        t[i] = hn::MulAdd(half, k2[i], y[i]);
      }
      Flow(bumps, t, k3);
      for (int i = 0; i < 6; ++i)
      {
        t[i] = hn::MulAdd(hv, k3[i], y[i]);
      }
      Flow(bumps, t, k4);
      for (int i = 0; i < 6; ++i)
      {
        const V sum = hn::Add(hn::MulAdd(two, hn::Add(k2[i], k3[i]), k1[i]), k4[i]);
        y[i] = hn::MulAdd(sixth, sum, y[i]);
      }
      for (int i = 0; i < 3; ++i)
      {
        hn::StoreU(y[i], d, points + (static_cast<size_t>(step) * 3 + i) * HandLanes + o);
      }
    }
    for (int i = 0; i < 6; ++i)
    {
      hn::Store(y[i], d, state.Y[i] + o);
    }
  }
}

void HandPacketDormandPrince45Impl(const HandBumps& bumps, HandState& state, double length,
  double h0, double tolerance, double minimumStep, double maximumStep, double* const* points,
  std::size_t capacity, long long* stepCounts)
{
  // The Butcher tableau of Dormand-Prince 5(4) (DormandPrinceTableau.h).
  using namespace riemann::dormand_prince;
  const D d;
  const int n = static_cast<int>(hn::Lanes(d));
  const V tol = hn::Set(d, tolerance);
  for (int o = 0; o < HandLanes; o += n)
  {
    V y[6], k1[6], k2[6], k3[6], k4[6], k5[6], k6[6], k7[6], t[6], next[6];
    for (int i = 0; i < 6; ++i)
    {
      y[i] = hn::Load(d, state.Y[i] + o);
    }
    Flow(bumps, y, k1);
    // Per lane: parameter reached, step, steps taken, done.
    alignas(64) double tau[HandLanes] = {}, h[HandLanes], stepLane[HandLanes];
    alignas(64) double errorLane[HandLanes], factorLane[HandLanes], rejectLane[HandLanes];
    bool done[HandLanes] = {};
    for (int l = 0; l < n; ++l)
    {
      h[l] = std::min(std::max(h0, minimumStep), maximumStep);
      stepCounts[o + l] = 0;
    }
    int running = n;
    while (running > 0)
    {
      for (int l = 0; l < n; ++l)
      {
        const double remaining = length - tau[l];
        stepLane[l] = done[l] ? 0.0 : std::min(h[l], remaining);
      }
      const V s = hn::Load(d, stepLane);
      for (int i = 0; i < 6; ++i)
      {
        t[i] = hn::MulAdd(s, hn::Mul(hn::Set(d, a21), k1[i]), y[i]);
      }
      Flow(bumps, t, k2);
      for (int i = 0; i < 6; ++i)
      {
        t[i] = hn::MulAdd(s, hn::MulAdd(hn::Set(d, a32), k2[i], hn::Mul(hn::Set(d, a31), k1[i])), y[i]);
      }
      Flow(bumps, t, k3);
      for (int i = 0; i < 6; ++i)
      {
        V sum = hn::Mul(hn::Set(d, a41), k1[i]);
        sum = hn::MulAdd(hn::Set(d, a42), k2[i], sum);
        sum = hn::MulAdd(hn::Set(d, a43), k3[i], sum);
        t[i] = hn::MulAdd(s, sum, y[i]);
      }
      Flow(bumps, t, k4);
      for (int i = 0; i < 6; ++i)
      {
        V sum = hn::Mul(hn::Set(d, a51), k1[i]);
        sum = hn::MulAdd(hn::Set(d, a52), k2[i], sum);
        sum = hn::MulAdd(hn::Set(d, a53), k3[i], sum);
        sum = hn::MulAdd(hn::Set(d, a54), k4[i], sum);
        t[i] = hn::MulAdd(s, sum, y[i]);
      }
      Flow(bumps, t, k5);
      for (int i = 0; i < 6; ++i)
      {
        V sum = hn::Mul(hn::Set(d, a61), k1[i]);
        sum = hn::MulAdd(hn::Set(d, a62), k2[i], sum);
        sum = hn::MulAdd(hn::Set(d, a63), k3[i], sum);
        sum = hn::MulAdd(hn::Set(d, a64), k4[i], sum);
        sum = hn::MulAdd(hn::Set(d, a65), k5[i], sum);
        t[i] = hn::MulAdd(s, sum, y[i]);
      }
      Flow(bumps, t, k6);
      for (int i = 0; i < 6; ++i)
      {
        V sum = hn::Mul(hn::Set(d, b1), k1[i]);
        sum = hn::MulAdd(hn::Set(d, b3), k3[i], sum);
        sum = hn::MulAdd(hn::Set(d, b4), k4[i], sum);
        sum = hn::MulAdd(hn::Set(d, b5), k5[i], sum);
        sum = hn::MulAdd(hn::Set(d, b6), k6[i], sum);
        next[i] = hn::MulAdd(s, sum, y[i]);
      }
      Flow(bumps, next, k7);
      V squares = hn::Zero(d);
      for (int i = 0; i < 6; ++i)
      {
        V sum = hn::Mul(hn::Set(d, e1), k1[i]);
        sum = hn::MulAdd(hn::Set(d, e3), k3[i], sum);
        sum = hn::MulAdd(hn::Set(d, e4), k4[i], sum);
        sum = hn::MulAdd(hn::Set(d, e5), k5[i], sum);
        sum = hn::MulAdd(hn::Set(d, e6), k6[i], sum);
        sum = hn::MulAdd(hn::Set(d, e7), k7[i], sum);
        const V scale = hn::MulAdd(tol, hn::Max(hn::Abs(y[i]), hn::Abs(next[i])), tol);
        const V ratio = hn::Div(hn::Mul(s, sum), scale);
        squares = hn::MulAdd(ratio, ratio, squares);
      }
      const V error = hn::Sqrt(hn::Div(squares, hn::Set(d, 6.0)));
      const V power =
        hn::Mul(hn::Set(d, 0.9), hn::Exp(d, hn::Mul(hn::Set(d, -0.2), hn::Log(d, error))));
      hn::Store(error, d, errorLane);
      hn::Store(hn::Min(hn::Set(d, 5.0), hn::Max(hn::Set(d, 0.2), power)), d, factorLane);
      hn::Store(hn::Max(hn::Set(d, 0.2), power), d, rejectLane);
      // The controller, per lane; accepted lanes take next and k7.
      alignas(64) double accept[HandLanes];
      for (int l = 0; l < n; ++l)
      {
        accept[l] = 0.0;
        if (done[l])
        {
          continue;
        }
        if (errorLane[l] <= 1.0)
        {
          accept[l] = 1.0;
          const bool last = h[l] >= length - tau[l];
          const double factor = errorLane[l] > 0 ? factorLane[l] : 5.0;
          if (!last || factor < 1.0)
          {
            h[l] = std::min(std::max(stepLane[l] * factor, minimumStep), maximumStep);
          }
          tau[l] += stepLane[l];
          if (last)
          {
            done[l] = true;
            --running;
          }
        }
        else
        {
          h[l] = std::max(minimumStep, stepLane[l] * rejectLane[l]);
        }
      }
      const auto take = hn::Gt(hn::Load(d, accept), hn::Zero(d));
      for (int i = 0; i < 6; ++i)
      {
        y[i] = hn::IfThenElse(take, next[i], y[i]);
        k1[i] = hn::IfThenElse(take, k7[i], k1[i]);
      }
      alignas(64) double lanes[3][HandLanes];
      for (int i = 0; i < 3; ++i)
      {
        hn::Store(y[i], d, lanes[i]);
      }
      for (int l = 0; l < n; ++l)
      {
        if (accept[l] != 0.0 && static_cast<std::size_t>(stepCounts[o + l]) < capacity)
        {
          double* point = points[o + l] + 3 * stepCounts[o + l];
          point[0] = lanes[0][l];
          point[1] = lanes[1][l];
          point[2] = lanes[2][l];
          ++stepCounts[o + l];
        }
      }
    }
    for (int i = 0; i < 6; ++i)
    {
      hn::Store(y[i], d, state.Y[i] + o);
    }
  }
}
} // namespace HWY_NAMESPACE
} // namespace riemann_bench
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace riemann_bench
{
HWY_EXPORT(HandPacketRungeKutta4Impl);
HWY_EXPORT(HandPacketDormandPrince45Impl);

void HandPacketRungeKutta4(
  const HandBumps& bumps, HandState& y, int steps, double h, double* points)
{
  HWY_DYNAMIC_DISPATCH(HandPacketRungeKutta4Impl)(bumps, y, steps, h, points);
}

void HandPacketDormandPrince45(const HandBumps& bumps, HandState& y, double length, double h0,
  double tolerance, double minimumStep, double maximumStep, double* const* points,
  std::size_t capacity, long long* stepCounts)
{
  HWY_DYNAMIC_DISPATCH(HandPacketDormandPrince45Impl)(
    bumps, y, length, h0, tolerance, minimumStep, maximumStep, points, capacity, stepCounts);
}

const char* HandPacketTargetName()
{
  return hwy::TargetName(hwy::SupportedAndGeneratedTargets()[0]);
}
} // namespace riemann_bench
#endif
