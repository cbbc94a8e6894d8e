/**
 * @file ExpressionTape.h
 * @brief Private to Common/Metric (not installed): the instruction tape the
 * CPU runs for CompiledExpressions (Expression.h), built from the expression
 * graph (ExpressionGraph.h) by ExpressionTape.cxx and run by
 * ExpressionInterpreter.cxx.
 */
#ifndef RiemannExpressionTape_h
#define RiemannExpressionTape_h

#include "ExpressionGraph.h"

#include <cstdint>
#include <vector>

namespace riemann
{
namespace expression
{
enum class Code : std::uint8_t
{
  Const,       // r[D] = C
  Lin,         // r[D] = C + sum_i K[B+i] r[O[A+i]], i < N
  LinP2,       // r[D] = C + sum_i K[B+i] r[O[A+2i]] r[O[A+2i+1]], i < N
  LinP3,       // r[D] = C + sum_i K[B+i] r[O[A+3i]] r[O[A+3i+1]] r[O[A+3i+2]], i < N
  Lin1,        // r[D] = C + K r[A]
  AddC,        // r[D] = C + r[A]
  Add2,        // r[D] = r[A] + r[B]
  Sub2,        // r[D] = r[A] - r[B]
  Mul,         // r[D] = prod_i r[O[A+i]], i < N
  Mul2,        // r[D] = r[A] r[B]
  Div,         // r[D] = r[A] / r[B]
  Square,      // r[D] = r[A]^2
  Recip,       // r[D] = 1 / r[A]
  Sqrt,        // r[D] = sqrt(r[A])
  Pow,         // r[D] = pow(r[A], r[B])
  Exp,         // r[D] = exp(r[A])
  Log,         // r[D] = log(r[A])
  Sin,         // r[D] = sin(r[A])
  Cos,         // r[D] = cos(r[A])
  Tan,         // r[D] = tan(r[A])
  Sinh,        // r[D] = sinh(r[A])
  Cosh,        // r[D] = cosh(r[A])
  Tanh,        // r[D] = tanh(r[A])
  Atan,        // r[D] = atan(r[A])
  Atan2,       // r[D] = atan2(r[A], r[B])
  Abs,         // r[D] = abs(r[A])
  Sign,        // r[D] = sign(r[A])
  ExpLin,      // r[D] = exp(C + sum_i K[B+i] r[O[A+i]]), i < N: a Lin read only by an Exp
  Store,       // out[B] = r[A]
  StoreScaled, // out[B] = C r[A]
  StoreConst   // out[B] = C
};

/// Every Code in the enum's order, for the tables indexed by code (the
/// interpreters' dispatch): X(name) once per code.
#define RIEMANN_EXPRESSION_CODES(X)                                                                \
  X(Const) X(Lin) X(LinP2) X(LinP3) X(Lin1) X(AddC) X(Add2) X(Sub2) X(Mul) X(Mul2) X(Div)          \
    X(Square) X(Recip) X(Sqrt) X(Pow) X(Exp) X(Log) X(Sin) X(Cos) X(Tan) X(Sinh) X(Cosh) X(Tanh)   \
      X(Atan) X(Atan2) X(Abs) X(Sign) X(ExpLin) X(Store) X(StoreScaled) X(StoreConst)

/// True when RIEMANN_EXPRESSION_CODES lists every Code once, in order.
constexpr bool ExpressionCodesListedInOrder()
{
#define RIEMANN_CODE_ENTRY(name) Code::name,
  constexpr Code listed[] = { RIEMANN_EXPRESSION_CODES(RIEMANN_CODE_ENTRY) };
#undef RIEMANN_CODE_ENTRY
  constexpr int count = static_cast<int>(sizeof(listed) / sizeof(listed[0]));
  for (int i = 0; i < count; ++i)
  {
    if (static_cast<int>(listed[i]) != i)
    {
      return false;
    }
  }
  return count == static_cast<int>(Code::StoreConst) + 1;
}
static_assert(ExpressionCodesListedInOrder(), "RIEMANN_EXPRESSION_CODES must follow Code");

struct Instruction
{
  Code Operation;
  std::int32_t N;
  std::int32_t D;
  std::int32_t A;
  std::int32_t B;
  double C;
  double K;
};

/**
 * The CPU form. Registers 0 .. inputs - 1 hold x, y, z, t and the
 * parameters, register `inputs` holds 1.0 (padding of product terms); the
 * others are reused after their last use.
 */
struct ExpressionTape
{
  std::vector<Instruction> Instructions;
  /// Operand registers of the n-ary instructions (O above).
  std::vector<std::int32_t> Operands;
  /// Coefficients of the sums (K above).
  std::vector<double> Coefficients;
  /// Instructions to run for outputs up to order n: Instructions[0, End[n]).
  int End[4] = { 0, 0, 0, 0 };
  int Registers = 0;
  /// Instructions that compute (not constant loads nor stores).
  int Operations = 0;
};

/// The tape computing the outputs of `graph` (derivatives up to `order`),
/// whose first `inputs` nodes are the inputs.
ExpressionTape BuildExpressionTape(const ExpressionGraph& graph, int order, int inputs);

/// Operands over all instructions (an n-ary sum of 8 terms counts 8).
int CountOperands(const ExpressionTape& tape);
} // namespace expression
} // namespace riemann

#endif
