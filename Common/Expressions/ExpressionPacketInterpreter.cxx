// The packet interpreter of the tape (ExpressionTape.h):
// CompiledExpressions::EvaluatePacket. Every register holds PacketWidth lanes
// and every instruction runs on all of them with Highway vectors, so the
// interpreter's dispatch (one switch per instruction) is paid once per
// packet instead of once per point. Compiled for every x86 target and
// dispatched at run time, like PacketKernels.cxx.
//
// The elementary functions use Highway's vector forms inside their valid
// ranges (exp <= 706, log > 0, sin and cos within +-39000, sinh within +-709:
// at most a few ulp from the C library); a chunk with a lane outside (or
// NaN), and the functions Highway lacks (pow, tan, cosh, atan2, sign), go
// through the C library lane by lane, so results equal the scalar
// interpreter's to rounding everywhere.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "ExpressionPacketInterpreter.cxx"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include "Expression.h"
#include "ExpressionInternals.h"
#include "Packet.h"

#include <cmath>
#include <vector>

#ifndef RIEMANN_EXPRESSION_PACKET_ONCE
#define RIEMANN_EXPRESSION_PACKET_ONCE
namespace riemann
{
namespace expression
{
/// One register of the packet interpreter: a value per lane.
struct alignas(64) PacketRegister
{
  double Lane[PacketWidth];
};

/// The scalar interpreter's sign().
inline double SignOf(double x)
{
  return x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0);
}
} // namespace expression
} // namespace riemann
#endif

HWY_BEFORE_NAMESPACE();
namespace riemann
{
namespace expression
{
namespace HWY_NAMESPACE
{
namespace hn = hwy::HWY_NAMESPACE;
using D = hn::CappedTag<double, PacketWidth>;
using V = hn::Vec<D>;

/// f on the lanes [o, o + N) of register a, lane by lane through the C library.
template <class Function>
HWY_INLINE V Scalar(D d, const PacketRegister& a, int o, Function f)
{
  alignas(64) double lanes[PacketWidth];
  const int n = static_cast<int>(hn::Lanes(d));
  for (int l = 0; l < n; ++l)
  {
    lanes[l] = f(a.Lane[o + l]);
  }
  return hn::Load(d, lanes);
}

/// True when every lane of x is in [low, high] (false for a NaN lane).
HWY_INLINE bool AllWithin(D d, V x, double low, double high)
{
  return hn::AllTrue(d, hn::And(hn::Ge(x, hn::Set(d, low)), hn::Le(x, hn::Set(d, high))));
}

/// Code::Lin's C + sum_i K[B+i] r[O[A+i]] on the lanes [o, o + N).
HWY_INLINE V Lin(D d, const Instruction& in, const std::int32_t* operands, const double* k,
  const PacketRegister* r, int o)
{
  auto load = [&](std::int32_t reg) { return hn::Load(d, r[reg].Lane + o); };
  // Four partial sums, as the scalar interpreter: one running sum would
  // wait for each fused multiply-add (sums of 8 to 16 terms are common).
  const std::int32_t* f = operands + in.A;
  const double* c = k + in.B;
  V s0 = hn::Set(d, in.C), s1 = hn::Zero(d), s2 = hn::Zero(d), s3 = hn::Zero(d);
  std::int32_t i = 0;
  for (; i + 4 <= in.N; i += 4)
  {
    s0 = hn::MulAdd(hn::Set(d, c[i]), load(f[i]), s0);
    s1 = hn::MulAdd(hn::Set(d, c[i + 1]), load(f[i + 1]), s1);
    s2 = hn::MulAdd(hn::Set(d, c[i + 2]), load(f[i + 2]), s2);
    s3 = hn::MulAdd(hn::Set(d, c[i + 3]), load(f[i + 3]), s3);
  }
  for (; i < in.N; ++i)
  {
    s0 = hn::MulAdd(hn::Set(d, c[i]), load(f[i]), s0);
  }
  return hn::Add(hn::Add(s0, s1), hn::Add(s2, s3));
}

/// exp(x), with the C library on the lanes of chunks that have one outside
/// Highway's valid range (or a NaN).
HWY_INLINE V ExpOf(D d, V x)
{
  if (AllWithin(d, x, -HUGE_VAL, 706.0))
  {
    return hn::Exp(d, x);
  }
  alignas(64) double lanes[PacketWidth];
  hn::Store(x, d, lanes);
  for (int l = 0; l < static_cast<int>(hn::Lanes(d)); ++l)
  {
    lanes[l] = std::exp(lanes[l]);
  }
  return hn::Load(d, lanes);
}

/// One instruction of code Op on the lanes [o, o + N) (the switch on the
/// template argument folds away: each handler of RunPacketImpl gets its code).
template <Code Op>
HWY_INLINE void Execute(const Instruction& in, const std::int32_t* operands, const double* k,
  PacketRegister* r, double* outputs, int o)
{
  const D d;
  auto load = [&](std::int32_t reg) { return hn::Load(d, r[reg].Lane + o); };
  auto store = [&](V x) { hn::Store(x, d, r[in.D].Lane + o); };
  const PacketRegister& a = r[in.A];
  switch (Op)
  {
    case Code::Const:
      store(hn::Set(d, in.C));
      break;
    case Code::Lin:
      store(Lin(d, in, operands, k, r, o));
      break;
    case Code::LinP2:
    {
      const std::int32_t* f = operands + in.A;
      const double* c = k + in.B;
      V s0 = hn::Set(d, in.C), s1 = hn::Zero(d);
      std::int32_t i = 0;
      for (; i + 2 <= in.N; i += 2, f += 4)
      {
        s0 = hn::MulAdd(hn::Mul(hn::Set(d, c[i]), load(f[0])), load(f[1]), s0);
        s1 = hn::MulAdd(hn::Mul(hn::Set(d, c[i + 1]), load(f[2])), load(f[3]), s1);
      }
      if (i < in.N)
      {
        s0 = hn::MulAdd(hn::Mul(hn::Set(d, c[i]), load(f[0])), load(f[1]), s0);
      }
      store(hn::Add(s0, s1));
      break;
    }
    case Code::LinP3:
    {
      const std::int32_t* f = operands + in.A;
      const double* c = k + in.B;
      V s0 = hn::Set(d, in.C), s1 = hn::Zero(d);
      std::int32_t i = 0;
      for (; i + 2 <= in.N; i += 2, f += 6)
      {
        s0 = hn::MulAdd(hn::Mul(hn::Mul(hn::Set(d, c[i]), load(f[0])), load(f[1])), load(f[2]), s0);
        s1 = hn::MulAdd(
          hn::Mul(hn::Mul(hn::Set(d, c[i + 1]), load(f[3])), load(f[4])), load(f[5]), s1);
      }
      if (i < in.N)
      {
        s0 = hn::MulAdd(hn::Mul(hn::Mul(hn::Set(d, c[i]), load(f[0])), load(f[1])), load(f[2]), s0);
      }
      store(hn::Add(s0, s1));
      break;
    }
    case Code::Lin1:
      store(hn::MulAdd(hn::Set(d, in.K), load(in.A), hn::Set(d, in.C)));
      break;
    case Code::AddC:
      store(hn::Add(hn::Set(d, in.C), load(in.A)));
      break;
    case Code::Add2:
      store(hn::Add(load(in.A), load(in.B)));
      break;
    case Code::Sub2:
      store(hn::Sub(load(in.A), load(in.B)));
      break;
    case Code::Mul:
    {
      V p = load(operands[in.A]);
      for (std::int32_t i = 1; i < in.N; ++i)
      {
        p = hn::Mul(p, load(operands[in.A + i]));
      }
      store(p);
      break;
    }
    case Code::Mul2:
      store(hn::Mul(load(in.A), load(in.B)));
      break;
    case Code::Div:
      store(hn::Div(load(in.A), load(in.B)));
      break;
    case Code::Square:
    {
      const V x = load(in.A);
      store(hn::Mul(x, x));
      break;
    }
    case Code::Recip:
      store(hn::Div(hn::Set(d, 1.0), load(in.A)));
      break;
    case Code::Sqrt:
      store(hn::Sqrt(load(in.A)));
      break;
    case Code::Pow:
    {
      alignas(64) double lanes[PacketWidth];
      for (int l = 0; l < static_cast<int>(hn::Lanes(d)); ++l)
      {
        lanes[l] = std::pow(a.Lane[o + l], r[in.B].Lane[o + l]);
      }
      store(hn::Load(d, lanes));
      break;
    }
    case Code::Exp:
      store(ExpOf(d, load(in.A)));
      break;
    case Code::Log:
    {
      const V x = load(in.A);
      store(AllWithin(d, x, 1e-300, 1.7e308)
          ? hn::Log(d, x)
          : Scalar(d, a, o, [](double v) { return std::log(v); }));
      break;
    }
    case Code::Sin:
    {
      const V x = load(in.A);
      store(AllWithin(d, x, -39000.0, 39000.0)
          ? hn::Sin(d, x)
          : Scalar(d, a, o, [](double v) { return std::sin(v); }));
      break;
    }
    case Code::Cos:
    {
      const V x = load(in.A);
      store(AllWithin(d, x, -39000.0, 39000.0)
          ? hn::Cos(d, x)
          : Scalar(d, a, o, [](double v) { return std::cos(v); }));
      break;
    }
    case Code::Tan:
      store(Scalar(d, a, o, [](double v) { return std::tan(v); }));
      break;
    case Code::Sinh:
    {
      const V x = load(in.A);
      store(AllWithin(d, x, -709.0, 709.0)
          ? hn::Sinh(d, x)
          : Scalar(d, a, o, [](double v) { return std::sinh(v); }));
      break;
    }
    case Code::Cosh:
      store(Scalar(d, a, o, [](double v) { return std::cosh(v); }));
      break;
    case Code::Tanh:
    {
      const V x = load(in.A);
      store(AllWithin(d, x, -HUGE_VAL, HUGE_VAL)
          ? hn::Tanh(d, x)
          : Scalar(d, a, o, [](double v) { return std::tanh(v); }));
      break;
    }
    case Code::Atan:
    {
      const V x = load(in.A);
      store(AllWithin(d, x, -HUGE_VAL, HUGE_VAL)
          ? hn::Atan(d, x)
          : Scalar(d, a, o, [](double v) { return std::atan(v); }));
      break;
    }
    case Code::Atan2:
    {
      alignas(64) double lanes[PacketWidth];
      for (int l = 0; l < static_cast<int>(hn::Lanes(d)); ++l)
      {
        lanes[l] = std::atan2(a.Lane[o + l], r[in.B].Lane[o + l]);
      }
      store(hn::Load(d, lanes));
      break;
    }
    case Code::Abs:
      store(hn::Abs(load(in.A)));
      break;
    case Code::Sign:
      store(Scalar(d, a, o, SignOf));
      break;
    case Code::ExpLin:
      store(ExpOf(d, Lin(d, in, operands, k, r, o)));
      break;
    case Code::Store:
      hn::StoreU(load(in.A), d, outputs + in.B * PacketWidth + o);
      break;
    case Code::StoreScaled:
      hn::StoreU(hn::Mul(hn::Set(d, in.C), load(in.A)), d, outputs + in.B * PacketWidth + o);
      break;
    case Code::StoreConst:
      hn::StoreU(hn::Set(d, in.C), d, outputs + in.B * PacketWidth + o);
      break;
  }
}

/// Every lane chunk of one instruction of code Op.
template <Code Op>
HWY_INLINE void ExecuteAllLanes(const Instruction& in, const std::int32_t* operands,
  const double* k, PacketRegister* r, double* outputs)
{
  const D d;
  for (int o = 0; o < PacketWidth; o += static_cast<int>(hn::Lanes(d)))
  {
    Execute<Op>(in, operands, k, r, outputs, o);
  }
}

/**
 * One pass over the tape. As in the scalar interpreter
 * (ExpressionInterpreter.cxx), each handler dispatches the next one itself
 * with GCC and Clang (computed goto), which the branch predictor follows
 * better than one shared switch (the 8-bump typed metric's geodesic steps:
 * Testing/Benchmarks/README.md).
 */
void RunPacketImpl(const ExpressionTape& tape, int end, PacketRegister* r, double* outputs)
{
  const Instruction* ip = tape.Instructions.data();
  const Instruction* const last = ip + end;
  const std::int32_t* operands = tape.Operands.data();
  const double* k = tape.Coefficients.data();
  if (ip == last)
  {
    return;
  }
#if defined(__GNUC__)
#define RIEMANN_OP(name) L_##name:
#define RIEMANN_NEXT                                                                               \
  if (++ip == last)                                                                                \
  {                                                                                                \
    return;                                                                                        \
  }                                                                                                \
  goto* labels[static_cast<int>(ip->Operation)];
#define RIEMANN_LABEL(name) &&L_##name,
  static const void* const labels[] = { RIEMANN_EXPRESSION_CODES(RIEMANN_LABEL) };
#undef RIEMANN_LABEL
  goto* labels[static_cast<int>(ip->Operation)];
#else
#define RIEMANN_OP(name) case Code::name:
#define RIEMANN_NEXT break;
  for (; ip != last; ++ip)
  {
    switch (ip->Operation)
    {
#endif
#define RIEMANN_HANDLER(name)                                                                      \
  RIEMANN_OP(name)                                                                                 \
  {                                                                                                \
    ExecuteAllLanes<Code::name>(*ip, operands, k, r, outputs);                                     \
    RIEMANN_NEXT                                                                                   \
  }
  RIEMANN_EXPRESSION_CODES(RIEMANN_HANDLER)
#if !defined(__GNUC__)
}
}
#endif
#undef RIEMANN_HANDLER
#undef RIEMANN_OP
#undef RIEMANN_NEXT
}
} // namespace HWY_NAMESPACE
} // namespace expression
} // namespace riemann
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace riemann
{
namespace expression
{
HWY_EXPORT(RunPacketImpl);
} // namespace expression

void CompiledExpressions::EvaluatePacket(
  const PacketVec3& p, double t, const double* parameters, double* outputs, int maxOrder) const
{
  using namespace expression;
  const Internals& m = *this->Internal;
  if (maxOrder < 0)
  {
    return;
  }
  maxOrder = std::min(maxOrder, m.Order);
  // Registers on the stack up to 128 (8 KiB); larger tapes use a
  // thread_local buffer.
  constexpr int StackRegisters = 128;
  PacketRegister stackRegisters[StackRegisters];
  PacketRegister* r = stackRegisters;
  if (m.Tape.Registers > StackRegisters)
  {
    thread_local std::vector<PacketRegister> heap;
    if (heap.size() < static_cast<std::size_t>(m.Tape.Registers))
    {
      heap.resize(static_cast<std::size_t>(m.Tape.Registers));
    }
    r = heap.data();
  }
  const int parameterCount = static_cast<int>(m.ParameterNames.size());
  for (int l = 0; l < PacketWidth; ++l)
  {
    r[0].Lane[l] = p.C[0][l];
    r[1].Lane[l] = p.C[1][l];
    r[2].Lane[l] = p.C[2][l];
    r[3].Lane[l] = t;
    for (int q = 0; q < parameterCount; ++q)
    {
      r[4 + q].Lane[l] = parameters[q];
    }
    r[4 + parameterCount].Lane[l] = 1.0;
  }
  HWY_DYNAMIC_DISPATCH(RunPacketImpl)(m.Tape, m.Tape.End[maxOrder], r, outputs);
}
} // namespace riemann
#endif
