// The interpreter of the tape (ExpressionTape.h): CompiledExpressions::Evaluate.
// The hot loop of every typed metric: the handlers and their helpers stay in
// this one translation unit, the helpers forced inline.
#include "Expression.h"
#include "ExpressionInternals.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#if defined(__GNUC__)
#define RIEMANN_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define RIEMANN_ALWAYS_INLINE inline
#endif

namespace riemann
{
namespace expression
{
namespace
{
/// Registers on the stack at most; larger tapes use a thread_local buffer.
constexpr int StackRegisters = 512;

/// Code::Lin's C + sum_i K[B+i] r[O[A+i]]. Four partial sums: one running
/// sum would wait for each addition (sums of 8 to 16 terms are common in
/// derivatives of sums).
RIEMANN_ALWAYS_INLINE double Lin(const Instruction* ip, const std::int32_t* __restrict operands,
  const double* __restrict k, double* __restrict r)
{
  const std::int32_t* a = operands + ip->A;
  const double* c = k + ip->B;
  const std::int32_t n = ip->N;
  double s0 = ip->C;
  double s1 = 0.0;
  double s2 = 0.0;
  double s3 = 0.0;
  std::int32_t i = 0;
  for (; i + 4 <= n; i += 4)
  {
    s0 += c[i] * r[a[i]];
    s1 += c[i + 1] * r[a[i + 1]];
    s2 += c[i + 2] * r[a[i + 2]];
    s3 += c[i + 3] * r[a[i + 3]];
  }
  for (; i < n; ++i)
  {
    s0 += c[i] * r[a[i]];
  }
  return (s0 + s1) + (s2 + s3);
}

/// c r[a[0]] r[a[1]] (r[a[2]]): a term of Code::LinP2 or Code::LinP3.
template <int Factors>
RIEMANN_ALWAYS_INLINE double Term(double c, const std::int32_t* a, const double* __restrict r)
{
  static_assert(Factors == 2 || Factors == 3, "LinP2 or LinP3");
  if constexpr (Factors == 2)
  {
    return c * r[a[0]] * r[a[1]];
  }
  else
  {
    return c * r[a[0]] * r[a[1]] * r[a[2]];
  }
}

/// Code::LinP2 (Factors = 2) and Code::LinP3 (Factors = 3): r[D] = C +
/// sum_i K[B+i] r[O[A+Factors i]] ... r[O[A+Factors i+Factors-1]]. Two partial sums.
template <int Factors>
RIEMANN_ALWAYS_INLINE void ComputeSumOfProducts(const Instruction* ip,
  const std::int32_t* __restrict operands, const double* __restrict k, double* __restrict r)
{
  const std::int32_t* a = operands + ip->A;
  const double* c = k + ip->B;
  const std::int32_t n = ip->N;
  double s0 = ip->C;
  double s1 = 0.0;
  std::int32_t i = 0;
  for (; i + 2 <= n; i += 2, a += 2 * Factors)
  {
    s0 += Term<Factors>(c[i], a, r);
    s1 += Term<Factors>(c[i + 1], a + Factors, r);
  }
  if (i < n)
  {
    s0 += Term<Factors>(c[i], a, r);
  }
  r[ip->D] = s0 + s1;
}

/// Code::Mul: r[D] = prod_i r[O[A+i]], i < N (N >= 3), two partial products.
RIEMANN_ALWAYS_INLINE void ComputeMul(
  const Instruction* ip, const std::int32_t* __restrict operands, double* __restrict r)
{
  const std::int32_t* a = operands + ip->A;
  const std::int32_t n = ip->N;
  double p0 = r[a[0]];
  double p1 = r[a[1]];
  std::int32_t i = 2;
  for (; i + 2 <= n; i += 2)
  {
    p0 *= r[a[i]];
    p1 *= r[a[i + 1]];
  }
  if (i < n)
  {
    p0 *= r[a[i]];
  }
  r[ip->D] = p0 * p1;
}

/**
 * One pass over the tape. With GCC and Clang each handler dispatches the
 * next one itself (computed goto), which the branch predictor follows far
 * better than one shared switch (about 2x faster here). One handler per
 * Code, one line each (RIEMANN_HANDLER: the statement, then the dispatch).
 */
void Run(const Instruction* ip, const Instruction* end, const std::int32_t* __restrict operands,
  const double* __restrict k, double* __restrict r, double* __restrict outputs)
{
#if defined(__GNUC__)
#define RIEMANN_OP(name) L_##name:
#define RIEMANN_NEXT                                                                               \
  if (++ip == end)                                                                                 \
  {                                                                                                \
    return;                                                                                        \
  }                                                                                                \
  goto* labels[static_cast<int>(ip->Operation)];
#define RIEMANN_LABEL(name) &&L_##name,
  static const void* const labels[] = { RIEMANN_EXPRESSION_CODES(RIEMANN_LABEL) };
#undef RIEMANN_LABEL
  if (ip == end)
  {
    return;
  }
  goto* labels[static_cast<int>(ip->Operation)];
#else
#define RIEMANN_OP(name) case Code::name:
#define RIEMANN_NEXT break;
  for (; ip != end; ++ip)
  {
    switch (ip->Operation)
    {
#endif
#define RIEMANN_HANDLER(name, statement)                                                           \
  RIEMANN_OP(name)                                                                                 \
  {                                                                                                \
    statement;                                                                                     \
    RIEMANN_NEXT                                                                                   \
  }
  RIEMANN_HANDLER(Const, r[ip->D] = ip->C)
  RIEMANN_HANDLER(Lin, r[ip->D] = Lin(ip, operands, k, r))
  RIEMANN_HANDLER(LinP2, ComputeSumOfProducts<2>(ip, operands, k, r))
  RIEMANN_HANDLER(LinP3, ComputeSumOfProducts<3>(ip, operands, k, r))
  RIEMANN_HANDLER(Lin1, r[ip->D] = ip->C + ip->K * r[ip->A])
  RIEMANN_HANDLER(AddC, r[ip->D] = ip->C + r[ip->A])
  RIEMANN_HANDLER(Add2, r[ip->D] = r[ip->A] + r[ip->B])
  RIEMANN_HANDLER(Sub2, r[ip->D] = r[ip->A] - r[ip->B])
  RIEMANN_HANDLER(Mul, ComputeMul(ip, operands, r))
  RIEMANN_HANDLER(Mul2, r[ip->D] = r[ip->A] * r[ip->B])
  RIEMANN_HANDLER(Div, r[ip->D] = r[ip->A] / r[ip->B])
  RIEMANN_HANDLER(Square, r[ip->D] = r[ip->A] * r[ip->A])
  RIEMANN_HANDLER(Recip, r[ip->D] = 1.0 / r[ip->A])
  RIEMANN_HANDLER(Sqrt, r[ip->D] = std::sqrt(r[ip->A]))
  RIEMANN_HANDLER(Pow, r[ip->D] = std::pow(r[ip->A], r[ip->B]))
  RIEMANN_HANDLER(Exp, r[ip->D] = std::exp(r[ip->A]))
  RIEMANN_HANDLER(Log, r[ip->D] = std::log(r[ip->A]))
  RIEMANN_HANDLER(Sin, r[ip->D] = std::sin(r[ip->A]))
  RIEMANN_HANDLER(Cos, r[ip->D] = std::cos(r[ip->A]))
  RIEMANN_HANDLER(Tan, r[ip->D] = std::tan(r[ip->A]))
  RIEMANN_HANDLER(Sinh, r[ip->D] = std::sinh(r[ip->A]))
  RIEMANN_HANDLER(Cosh, r[ip->D] = std::cosh(r[ip->A]))
  RIEMANN_HANDLER(Tanh, r[ip->D] = std::tanh(r[ip->A]))
  RIEMANN_HANDLER(Atan, r[ip->D] = std::atan(r[ip->A]))
  RIEMANN_HANDLER(Atan2, r[ip->D] = std::atan2(r[ip->A], r[ip->B]))
  RIEMANN_HANDLER(Abs, r[ip->D] = std::fabs(r[ip->A]))
  RIEMANN_HANDLER(Sign, r[ip->D] = Sign(r[ip->A]))
  RIEMANN_HANDLER(ExpLin, r[ip->D] = std::exp(Lin(ip, operands, k, r)))
  RIEMANN_HANDLER(Store, outputs[ip->B] = r[ip->A])
  RIEMANN_HANDLER(StoreScaled, outputs[ip->B] = ip->C * r[ip->A])
  RIEMANN_HANDLER(StoreConst, outputs[ip->B] = ip->C)
#if !defined(__GNUC__)
}
}
#endif
#undef RIEMANN_HANDLER
#undef RIEMANN_OP
#undef RIEMANN_NEXT
}
} // namespace
} // namespace expression

void CompiledExpressions::Evaluate(
  const double p[3], double t, const double* parameters, double* outputs) const
{
  this->Evaluate(p, t, parameters, outputs, this->Internal->Order);
}

void CompiledExpressions::Evaluate(
  const double p[3], double t, const double* parameters, double* outputs, int maxOrder) const
{
  using namespace expression;
  const Internals& m = *this->Internal;
  if (maxOrder < 0)
  {
    return;
  }
  maxOrder = std::min(maxOrder, m.Order);
  double stackRegisters[StackRegisters];
  double* r = stackRegisters;
  if (m.Tape.Registers > StackRegisters)
  {
    thread_local std::vector<double> heap;
    if (heap.size() < static_cast<std::size_t>(m.Tape.Registers))
    {
      heap.resize(static_cast<std::size_t>(m.Tape.Registers));
    }
    r = heap.data();
  }
  r[0] = p[0];
  r[1] = p[1];
  r[2] = p[2];
  r[3] = t;
  const int parameterCount = static_cast<int>(m.ParameterNames.size());
  for (int q = 0; q < parameterCount; ++q)
  {
    r[4 + q] = parameters[q];
  }
  r[4 + parameterCount] = 1.0;
  const ExpressionTape& tape = m.Tape;
  Run(tape.Instructions.data(), tape.Instructions.data() + tape.End[maxOrder], tape.Operands.data(),
    tape.Coefficients.data(), r, outputs);
}
} // namespace riemann
