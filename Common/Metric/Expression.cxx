#include "Expression.h"

#include "ExpressionParser.h"

#include <ginac/ginac.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace riemann
{
namespace
{
// --- Operations of the compiled form ------------------------------------------
enum class Op : std::uint8_t
{
  Input, // x, y, z, t, parameters: registers 0 .. 3 + P
  Const,
  Lin,    // c0 + sum c_i a_i
  Mul,    // prod a_i
  Div,    // a / b
  Square, // a * a
  Recip,  // 1 / a
  Sqrt,
  Pow, // a ^ b (real power)
  Exp,
  Log,
  Sin,
  Cos,
  Tan,
  Sinh,
  Cosh,
  Tanh,
  Atan,
  Atan2, // atan2(a, b)
  Abs,
  Sign
};

/// -1, 0 or 1; NaN stays NaN (so that a non-finite input is noticed).
double Sign(double u)
{
  return u > 0.0 ? 1.0 : (u < 0.0 ? -1.0 : (u == 0.0 ? 0.0 : u));
}

double ApplyUnary(Op op, double a)
{
  switch (op)
  {
    case Op::Square:
      return a * a;
    case Op::Recip:
      return 1.0 / a;
    case Op::Sqrt:
      return std::sqrt(a);
    case Op::Exp:
      return std::exp(a);
    case Op::Log:
      return std::log(a);
    case Op::Sin:
      return std::sin(a);
    case Op::Cos:
      return std::cos(a);
    case Op::Tan:
      return std::tan(a);
    case Op::Sinh:
      return std::sinh(a);
    case Op::Cosh:
      return std::cosh(a);
    case Op::Tanh:
      return std::tanh(a);
    case Op::Atan:
      return std::atan(a);
    case Op::Abs:
      return std::fabs(a);
    case Op::Sign:
      return Sign(a);
    default:
      return std::nan("");
  }
}

/// One node of the compiled DAG (SSA: its value is computed once).
struct Node
{
  Op Operation = Op::Const;
  std::vector<int> Args;
  /// Lin: one coefficient per argument.
  std::vector<double> Coefficients;
  /// Const: the value; Lin: the constant term; Input: unused.
  double Constant = 0.0;
};

/// A value Scale * node[Id]; Id < 0: the constant Scale. Keeping constant
/// factors out of nodes lets 2 - 4x and x - 1/2 share one node.
struct Ref
{
  int Id = -1;
  double Scale = 0.0;
};

// --- The tape the CPU runs ------------------------------------------------------
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
  Store,       // out[B] = r[A]
  StoreScaled, // out[B] = C r[A]
  StoreConst   // out[B] = C
};

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

/// Instructions to compile at most (a guard against expression swell).
constexpr std::size_t MaximumNodes = 200000;
/// Distinct GiNaC subexpressions of all derivatives at most.
constexpr std::size_t MaximumDerivativeNodes = 200000;
/// Estimated work of differentiating one order (DifferentiationWork): at most
/// about a second (0.3 to 0.6 microseconds per unit measured).
constexpr double MaximumDifferentiationWork = 1.5e6;
constexpr int MaximumSources = 16;
constexpr int StackRegisters = 512;

/// (n, i, j, k) in layout order for each order.
struct DerivativeIndex
{
  int N, I, J, K;
};

/// Offset of the first derivative of order n in a source's block.
int FirstOffset(int n)
{
  static const int first[4] = { 0, 1, 4, 10 };
  return first[n];
}

const std::vector<DerivativeIndex>& Layout()
{
  static const std::vector<DerivativeIndex> layout = []
  {
    std::vector<DerivativeIndex> l;
    l.push_back({ 0, 0, 0, 0 });
    for (int i = 0; i < 3; ++i)
    {
      l.push_back({ 1, i, 0, 0 });
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int j = i; j < 3; ++j)
      {
        l.push_back({ 2, i, j, 0 });
      }
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int j = i; j < 3; ++j)
      {
        for (int k = j; k < 3; ++k)
        {
          l.push_back({ 3, i, j, k });
        }
      }
    }
    return l;
  }();
  return layout;
}

// --- GiNaC: everything below runs under this mutex -------------------------------
std::mutex& GinacMutex()
{
  static std::mutex mutex;
  return mutex;
}

unsigned SignSerial();

GiNaC::ex SignEval(const GiNaC::ex& u)
{
  if (GiNaC::is_exactly_a<GiNaC::numeric>(u) && GiNaC::ex_to<GiNaC::numeric>(u).is_real())
  {
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(u);
    return n.is_zero() ? 0 : (n.is_positive() ? 1 : -1);
  }
  return GiNaC::function(SignSerial(), u).hold();
}

GiNaC::ex SignDerivative(const GiNaC::ex&, unsigned)
{
  return 0;
}

/// sign(u) in {-1, 0, 1}; derivative 0 (what the evaluator computes away from 0).
unsigned SignSerial()
{
  static const unsigned serial =
    GiNaC::function::register_new(GiNaC::function_options("riemann_sign", 1)
                                    .eval_func(SignEval)
                                    .evalf_func(SignEval)
                                    .derivative_func(SignDerivative));
  return serial;
}

unsigned AbsSerial();

GiNaC::ex AbsEval(const GiNaC::ex& u)
{
  if (GiNaC::is_exactly_a<GiNaC::numeric>(u) && GiNaC::ex_to<GiNaC::numeric>(u).is_real())
  {
    return GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(u));
  }
  return GiNaC::function(AbsSerial(), u).hold();
}

GiNaC::ex AbsDerivative(const GiNaC::ex& u, unsigned)
{
  return GiNaC::function(SignSerial(), u);
}

/// |u| with d|u| = sign(u) du (GiNaC's abs gives u du / |u|, NaN at 0).
unsigned AbsSerial()
{
  static const unsigned serial =
    GiNaC::function::register_new(GiNaC::function_options("riemann_abs", 1)
                                    .eval_func(AbsEval)
                                    .evalf_func(AbsEval)
                                    .derivative_func(AbsDerivative));
  return serial;
}

GiNaC::ex ReadExp(const GiNaC::exvector& a)
{
  return GiNaC::exp(a[0]);
}
GiNaC::ex ReadLog(const GiNaC::exvector& a)
{
  return GiNaC::log(a[0]);
}
GiNaC::ex ReadSqrt(const GiNaC::exvector& a)
{
  return GiNaC::sqrt(a[0]);
}
GiNaC::ex ReadSin(const GiNaC::exvector& a)
{
  return GiNaC::sin(a[0]);
}
GiNaC::ex ReadCos(const GiNaC::exvector& a)
{
  return GiNaC::cos(a[0]);
}
GiNaC::ex ReadTan(const GiNaC::exvector& a)
{
  return GiNaC::tan(a[0]);
}
GiNaC::ex ReadSinh(const GiNaC::exvector& a)
{
  return GiNaC::sinh(a[0]);
}
GiNaC::ex ReadCosh(const GiNaC::exvector& a)
{
  return GiNaC::cosh(a[0]);
}
GiNaC::ex ReadTanh(const GiNaC::exvector& a)
{
  return GiNaC::tanh(a[0]);
}
GiNaC::ex ReadAtan2(const GiNaC::exvector& a)
{
  return GiNaC::atan2(a[0], a[1]);
}
GiNaC::ex ReadAbs(const GiNaC::exvector& a)
{
  return GiNaC::function(AbsSerial(), a[0]);
}
GiNaC::ex ReadPow(const GiNaC::exvector& a)
{
  return GiNaC::pow(a[0], a[1]);
}

/// Exactly the functions of SupportedExpressionFunctions().
const GiNaC::prototype_table& Functions()
{
  static const GiNaC::prototype_table table = []
  {
    GiNaC::prototype_table t;
    t[{ "exp", 1 }] = ReadExp;
    t[{ "log", 1 }] = ReadLog;
    t[{ "sqrt", 1 }] = ReadSqrt;
    t[{ "sin", 1 }] = ReadSin;
    t[{ "cos", 1 }] = ReadCos;
    t[{ "tan", 1 }] = ReadTan;
    t[{ "sinh", 1 }] = ReadSinh;
    t[{ "cosh", 1 }] = ReadCosh;
    t[{ "tanh", 1 }] = ReadTanh;
    t[{ "atan2", 2 }] = ReadAtan2;
    t[{ "abs", 1 }] = ReadAbs;
    t[{ "pow", 2 }] = ReadPow;
    return t;
  }();
  return table;
}

struct ExHash
{
  std::size_t operator()(const GiNaC::ex& e) const { return e.gethash(); }
};
struct ExEqual
{
  bool operator()(const GiNaC::ex& a, const GiNaC::ex& b) const { return a.is_equal(b); }
};
template <typename T>
using ExMap = std::unordered_map<GiNaC::ex, T, ExHash, ExEqual>;

std::string Printed(const GiNaC::ex& e)
{
  std::ostringstream s;
  s << e;
  std::string text = s.str();
  if (text.size() > 80)
  {
    text = text.substr(0, 77) + "...";
  }
  return text;
}

/// Nodes of the tree of `e` (shared parts counted at each occurrence);
/// `memo` ends up holding the distinct subexpressions.
double TreeSize(const GiNaC::ex& e, ExMap<double>& memo)
{
  const auto it = memo.find(e);
  if (it != memo.end())
  {
    return it->second;
  }
  double size = 1.0;
  for (std::size_t i = 0; i < e.nops(); ++i)
  {
    size += TreeSize(e.op(i), memo);
  }
  memo.emplace(e, size);
  return size;
}

/**
 * Work of GiNaC's diff() on `e`, in rough units of half a microsecond: the
 * size of its tree (shared parts counted at each occurrence, as diff() visits
 * them), products counting the square of their factors (product rule).
 */
double DifferentiationWork(const GiNaC::ex& e, ExMap<double>& memo)
{
  const auto it = memo.find(e);
  if (it != memo.end())
  {
    return it->second;
  }
  const double n = static_cast<double>(e.nops());
  double work = 1.0 + (GiNaC::is_a<GiNaC::mul>(e) ? n * n : n);
  for (std::size_t i = 0; i < e.nops(); ++i)
  {
    work += DifferentiationWork(e.op(i), memo);
  }
  memo.emplace(e, work);
  return work;
}

std::uint64_t Mix(std::uint64_t h, std::uint64_t v)
{
  // splitmix64 of the combination.
  std::uint64_t z = h ^ (v + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2));
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

std::uint64_t HashText(const std::string& text)
{
  std::uint64_t h = 0xCBF29CE484222325ull; // FNV-1a
  for (unsigned char c : text)
  {
    h = (h ^ c) * 0x100000001B3ull;
  }
  return h;
}

/**
 * A hash of the structure of `e` that, unlike GiNaC's, does not depend on
 * the serial numbers of the symbols (the order in which symbols were ever
 * created in the process): symbols by name, numbers by value, sums and
 * products as multisets. GiNaC orders the terms of a sum by its own hashes,
 * so compiling them in this order instead makes the compiled form, and the
 * GLSL, depend on the expressions only.
 */
std::uint64_t StructuralKey(const GiNaC::ex& e, ExMap<std::uint64_t>& memo)
{
  using namespace GiNaC;
  const auto it = memo.find(e);
  if (it != memo.end())
  {
    return it->second;
  }
  std::uint64_t key;
  if (is_a<symbol>(e))
  {
    key = Mix(1, HashText(ex_to<symbol>(e).get_name()));
  }
  else if (is_exactly_a<numeric>(e) || is_a<constant>(e))
  {
    std::ostringstream text;
    text << e;
    key = Mix(2, HashText(text.str()));
  }
  else if (is_a<add>(e) || is_a<mul>(e))
  {
    std::vector<std::uint64_t> keys;
    for (std::size_t i = 0; i < e.nops(); ++i)
    {
      keys.push_back(StructuralKey(e.op(i), memo));
    }
    std::sort(keys.begin(), keys.end());
    key = is_a<add>(e) ? 3 : 4;
    for (std::uint64_t k : keys)
    {
      key = Mix(key, k);
    }
  }
  else
  {
    // power, functions, anything else: a tag, a name, the operands in order.
    const std::string name =
      is_a<function>(e) ? ex_to<function>(e).get_name() : ex_to<basic>(e).class_name();
    key = is_a<power>(e) ? 5 : Mix(6, HashText(name));
    for (std::size_t i = 0; i < e.nops(); ++i)
    {
      key = Mix(key, StructuralKey(e.op(i), memo));
    }
  }
  memo.emplace(e, key);
  return key;
}

/// Compiles GiNaC expressions into Nodes (hash-consed twice: by GiNaC
/// structure in Memo, by operation and operands in Keys).
class Compiler
{
public:
  std::vector<Node> Nodes;
  /// Symbols in register order: x, y, z, t, parameters.
  std::vector<GiNaC::ex> Symbols;
  int Source = -1;

  explicit Compiler(const std::vector<GiNaC::ex>& symbols)
    : Symbols(symbols)
  {
    for (std::size_t i = 0; i < symbols.size(); ++i)
    {
      Node input;
      input.Operation = Op::Input;
      input.Constant = static_cast<double>(i);
      this->Nodes.push_back(input);
      this->Memo.emplace(symbols[i], Ref{ static_cast<int>(i), 1.0 });
    }
  }

  Ref Compile(const GiNaC::ex& e)
  {
    const auto it = this->Memo.find(e);
    if (it != this->Memo.end())
    {
      return it->second;
    }
    const Ref r = this->CompileNew(e);
    this->Memo.emplace(e, r);
    return r;
  }

  /// A node holding the value of r.
  int Materialize(const Ref& r)
  {
    if (r.Id < 0)
    {
      Node c;
      c.Operation = Op::Const;
      c.Constant = r.Scale;
      return this->Emit(std::move(c));
    }
    if (r.Scale == 1.0)
    {
      return r.Id;
    }
    Node lin;
    lin.Operation = Op::Lin;
    if (this->Nodes[r.Id].Operation == Op::Lin)
    {
      lin = this->Nodes[r.Id];
      lin.Constant *= r.Scale;
      for (double& c : lin.Coefficients)
      {
        c *= r.Scale;
      }
    }
    else
    {
      lin.Args = { r.Id };
      lin.Coefficients = { r.Scale };
    }
    return this->Emit(std::move(lin));
  }

private:
  ExMap<Ref> Memo;
  std::unordered_map<std::string, int> Keys;
  ExMap<std::uint64_t> StructuralKeys;

  /// The operands of a sum or product in an order independent of GiNaC's.
  std::vector<GiNaC::ex> Operands(const GiNaC::ex& e)
  {
    std::vector<std::pair<std::uint64_t, std::size_t>> order;
    for (std::size_t i = 0; i < e.nops(); ++i)
    {
      order.emplace_back(StructuralKey(e.op(i), this->StructuralKeys), i);
    }
    std::sort(order.begin(), order.end());
    std::vector<GiNaC::ex> operands;
    for (const auto& o : order)
    {
      operands.push_back(e.op(o.second));
    }
    return operands;
  }

  [[noreturn]] void Fail(const std::string& cause) const
  {
    throw ExpressionError(0, cause, this->Source);
  }

  double ToDouble(const GiNaC::ex& e) const
  {
    GiNaC::ex value = e;
    if (!GiNaC::is_exactly_a<GiNaC::numeric>(value))
    {
      value = value.evalf();
    }
    if (!GiNaC::is_exactly_a<GiNaC::numeric>(value) ||
      !GiNaC::ex_to<GiNaC::numeric>(value).is_real())
    {
      this->Fail("the expression takes complex values (it simplifies partly to " + Printed(e) +
        "; e.g. log or a fractional power of a negative number)");
    }
    const double d = GiNaC::ex_to<GiNaC::numeric>(value).to_double();
    if (!std::isfinite(d))
    {
      this->Fail("the constant " + Printed(e) + " is out of double precision's range");
    }
    return d;
  }

  static Ref Constant(double v) { return Ref{ -1, v }; }

  Ref Folded(double v, const GiNaC::ex& e) const
  {
    if (!std::isfinite(v))
    {
      this->Fail("the constant part " + Printed(e) + " is not a finite real number");
    }
    return Constant(v);
  }

  int Emit(Node node)
  {
    if (node.Operation == Op::Lin)
    {
      std::vector<std::pair<int, double>> terms;
      for (std::size_t i = 0; i < node.Args.size(); ++i)
      {
        terms.emplace_back(node.Args[i], node.Coefficients[i]);
      }
      std::sort(terms.begin(), terms.end());
      for (std::size_t i = 0; i < terms.size(); ++i)
      {
        node.Args[i] = terms[i].first;
        node.Coefficients[i] = terms[i].second;
      }
    }
    else if (node.Operation == Op::Mul)
    {
      std::sort(node.Args.begin(), node.Args.end());
    }
    std::string key(1, static_cast<char>(node.Operation));
    auto append = [&key](const void* data, std::size_t size)
    { key.append(static_cast<const char*>(data), size); };
    for (int a : node.Args)
    {
      append(&a, sizeof a);
    }
    key += '|';
    for (double c : node.Coefficients)
    {
      append(&c, sizeof c);
    }
    append(&node.Constant, sizeof node.Constant);
    const auto it = this->Keys.find(key);
    if (it != this->Keys.end())
    {
      return it->second;
    }
    if (this->Nodes.size() >= MaximumNodes)
    {
      this->Fail("the expressions are too complex: their derivatives need more than " +
        std::to_string(MaximumNodes) + " operations");
    }
    this->Nodes.push_back(std::move(node));
    const int id = static_cast<int>(this->Nodes.size()) - 1;
    this->Keys.emplace(std::move(key), id);
    return id;
  }

  int EmitUnary(Op op, int a)
  {
    Node n;
    n.Operation = op;
    n.Args = { a };
    return this->Emit(std::move(n));
  }

  int EmitBinary(Op op, int a, int b)
  {
    Node n;
    n.Operation = op;
    n.Args = { a, b };
    return this->Emit(std::move(n));
  }

  /// c0 + sum c_i node[i], normalised so that the first coefficient is 1.
  Ref MakeLin(double c0, std::vector<std::pair<int, double>> terms)
  {
    std::sort(terms.begin(), terms.end());
    std::vector<std::pair<int, double>> merged;
    for (const auto& t : terms)
    {
      if (!merged.empty() && merged.back().first == t.first)
      {
        merged.back().second += t.second;
      }
      else
      {
        merged.push_back(t);
      }
    }
    merged.erase(std::remove_if(merged.begin(), merged.end(),
                   [](const std::pair<int, double>& t) { return t.second == 0.0; }),
      merged.end());
    if (merged.empty())
    {
      return Constant(c0);
    }
    const double k = merged.front().second;
    if (merged.size() == 1 && c0 == 0.0)
    {
      return Ref{ merged.front().first, k };
    }
    Node lin;
    lin.Operation = Op::Lin;
    lin.Constant = c0 / k;
    for (const auto& t : merged)
    {
      lin.Args.push_back(t.first);
      lin.Coefficients.push_back(t.second / k);
    }
    return Ref{ this->Emit(std::move(lin)), k };
  }

  /// coefficient * prod numerator / prod denominator.
  Ref MakeProduct(double coefficient, std::vector<int> numerator, std::vector<int> denominator)
  {
    if (coefficient == 0.0)
    {
      return Constant(0.0);
    }
    auto product = [this](std::vector<int>& ids)
    {
      if (ids.size() == 1)
      {
        return ids.front();
      }
      Node mul;
      mul.Operation = Op::Mul;
      mul.Args = ids;
      return this->Emit(std::move(mul));
    };
    if (denominator.empty())
    {
      if (numerator.empty())
      {
        return Constant(coefficient);
      }
      return Ref{ product(numerator), coefficient };
    }
    const int d = product(denominator);
    if (numerator.empty())
    {
      return Ref{ this->EmitUnary(Op::Recip, d), coefficient };
    }
    return Ref{ this->EmitBinary(Op::Div, product(numerator), d), coefficient };
  }

  Ref CompileNew(const GiNaC::ex& e)
  {
    using namespace GiNaC;
    if (is_exactly_a<numeric>(e) || is_a<constant>(e))
    {
      return Constant(this->ToDouble(e));
    }
    if (is_a<symbol>(e))
    {
      // Every symbol the parser can produce is in Memo already.
      this->Fail("internal error: unknown symbol " + Printed(e));
    }
    if (is_a<add>(e))
    {
      return this->CompileAdd(e);
    }
    if (is_a<mul>(e))
    {
      return this->CompileMul(e);
    }
    if (is_a<power>(e))
    {
      return this->CompilePower(e.op(0), e.op(1));
    }
    if (is_a<function>(e))
    {
      return this->CompileFunction(e);
    }
    this->Fail("the expression contains " + Printed(e) + ", which the evaluator does not support");
  }

  Ref CompileAdd(const GiNaC::ex& e)
  {
    using namespace GiNaC;
    double c0 = 0.0;
    std::vector<std::pair<int, double>> terms;
    for (const ex& term : this->Operands(e))
    {
      double coefficient = 1.0;
      ex rest = term;
      if (is_a<mul>(term) && is_exactly_a<numeric>(term.op(term.nops() - 1)))
      {
        const ex factor = term.op(term.nops() - 1);
        coefficient = this->ToDouble(factor);
        rest = term / factor;
      }
      const Ref r = this->Compile(rest);
      if (r.Id < 0)
      {
        c0 += coefficient * r.Scale;
      }
      else
      {
        terms.emplace_back(r.Id, coefficient * r.Scale);
      }
    }
    return this->MakeLin(c0, std::move(terms));
  }

  Ref CompileMul(const GiNaC::ex& e)
  {
    using namespace GiNaC;
    double coefficient = 1.0;
    std::vector<int> numerator;
    std::vector<int> denominator;
    for (const ex& factor : this->Operands(e))
    {
      if (is_exactly_a<numeric>(factor))
      {
        coefficient *= this->ToDouble(factor);
        continue;
      }
      if (is_a<power>(factor) && is_exactly_a<numeric>(factor.op(1)) &&
        ex_to<numeric>(factor.op(1)).is_real() && ex_to<numeric>(factor.op(1)).is_negative())
      {
        const Ref r = this->Compile(pow(factor.op(0), -factor.op(1)));
        coefficient /= r.Scale;
        if (r.Id >= 0)
        {
          denominator.push_back(r.Id);
        }
        continue;
      }
      const Ref r = this->Compile(factor);
      coefficient *= r.Scale;
      if (r.Id >= 0)
      {
        numerator.push_back(r.Id);
      }
    }
    if (!std::isfinite(coefficient))
    {
      this->Fail("the constant factor of " + Printed(e) + " is not finite");
    }
    return this->MakeProduct(coefficient, std::move(numerator), std::move(denominator));
  }

  /// b^n for an integer n >= 1, by squaring and multiplying (x^2 is shared by x^3 and x^4).
  Ref PowerInteger(const GiNaC::ex& base, long n)
  {
    if (n == 1)
    {
      return this->Compile(base);
    }
    if (n % 2 == 0)
    {
      const Ref half = n == 2 ? this->Compile(base) : this->Compile(GiNaC::pow(base, n / 2));
      if (half.Id < 0)
      {
        return this->Folded(half.Scale * half.Scale, base);
      }
      return Ref{ this->EmitUnary(Op::Square, half.Id), half.Scale * half.Scale };
    }
    const Ref even = this->Compile(GiNaC::pow(base, n - 1));
    const Ref one = this->Compile(base);
    std::vector<int> numerator;
    for (const Ref& r : { even, one })
    {
      if (r.Id >= 0)
      {
        numerator.push_back(r.Id);
      }
    }
    return this->MakeProduct(even.Scale * one.Scale, std::move(numerator), {});
  }

  Ref CompilePower(const GiNaC::ex& base, const GiNaC::ex& exponent)
  {
    using namespace GiNaC;
    if (is_exactly_a<numeric>(exponent) && ex_to<numeric>(exponent).is_real())
    {
      const numeric k = ex_to<numeric>(exponent);
      const numeric twice = k * 2;
      if (k.is_zero())
      {
        return Constant(1.0);
      }
      if (k.is_negative())
      {
        const Ref r = this->Compile(pow(base, -exponent));
        if (r.Id < 0)
        {
          return this->Folded(1.0 / r.Scale, base);
        }
        return Ref{ this->EmitUnary(Op::Recip, r.Id), 1.0 / r.Scale };
      }
      if (k.is_integer() && k <= 64)
      {
        return this->PowerInteger(base, k.to_long());
      }
      if (twice.is_integer() && twice <= 129)
      {
        if (twice == 1)
        {
          const Ref b = this->Compile(base);
          if (b.Id < 0)
          {
            return this->Folded(std::sqrt(b.Scale), base);
          }
          if (b.Scale > 0.0)
          {
            return Ref{ this->EmitUnary(Op::Sqrt, b.Id), std::sqrt(b.Scale) };
          }
          return Ref{ this->EmitUnary(Op::Sqrt, this->Materialize(b)), 1.0 };
        }
        // b^(m + 1/2) = b^m sqrt(b)
        const Ref whole = this->Compile(pow(base, (twice - 1) / 2));
        const Ref root = this->Compile(sqrt(base));
        std::vector<int> numerator;
        for (const Ref& r : { whole, root })
        {
          if (r.Id >= 0)
          {
            numerator.push_back(r.Id);
          }
        }
        return this->MakeProduct(whole.Scale * root.Scale, std::move(numerator), {});
      }
      // A real constant exponent.
      const double p = this->ToDouble(exponent);
      const Ref b = this->Compile(base);
      if (b.Id < 0)
      {
        return this->Folded(std::pow(b.Scale, p), base);
      }
      const int pNode = this->Materialize(Constant(p));
      if (b.Scale > 0.0)
      {
        return Ref{ this->EmitBinary(Op::Pow, b.Id, pNode), std::pow(b.Scale, p) };
      }
      return Ref{ this->EmitBinary(Op::Pow, this->Materialize(b), pNode), 1.0 };
    }
    const Ref b = this->Compile(base);
    const Ref x = this->Compile(exponent);
    if (b.Id < 0 && x.Id < 0)
    {
      return this->Folded(std::pow(b.Scale, x.Scale), base);
    }
    return Ref{ this->EmitBinary(Op::Pow, this->Materialize(b), this->Materialize(x)), 1.0 };
  }

  Ref CompileFunction(const GiNaC::ex& e)
  {
    using namespace GiNaC;
    const unsigned serial = ex_to<function>(e).get_serial();
    Op op;
    if (serial == exp_SERIAL::serial)
    {
      op = Op::Exp;
    }
    else if (serial == log_SERIAL::serial)
    {
      op = Op::Log;
    }
    else if (serial == sin_SERIAL::serial)
    {
      op = Op::Sin;
    }
    else if (serial == cos_SERIAL::serial)
    {
      op = Op::Cos;
    }
    else if (serial == tan_SERIAL::serial)
    {
      op = Op::Tan;
    }
    else if (serial == sinh_SERIAL::serial)
    {
      op = Op::Sinh;
    }
    else if (serial == cosh_SERIAL::serial)
    {
      op = Op::Cosh;
    }
    else if (serial == tanh_SERIAL::serial)
    {
      op = Op::Tanh;
    }
    else if (serial == atan_SERIAL::serial)
    {
      op = Op::Atan; // GiNaC writes atan2(y, c) with c > 0 as atan(y / c)
    }
    else if (serial == atan2_SERIAL::serial)
    {
      op = Op::Atan2;
    }
    else if (serial == abs_SERIAL::serial || serial == AbsSerial())
    {
      op = Op::Abs;
    }
    else if (serial == SignSerial() || serial == csgn_SERIAL::serial)
    {
      op = Op::Sign; // csgn is the sign for real arguments
    }
    else
    {
      this->Fail("GiNaC turned the expression into " + Printed(e) +
        ", a function the evaluator does not support");
    }
    if (op == Op::Atan2)
    {
      const Ref y = this->Compile(e.op(0));
      const Ref x = this->Compile(e.op(1));
      if (y.Id < 0 && x.Id < 0)
      {
        return this->Folded(std::atan2(y.Scale, x.Scale), e);
      }
      return Ref{ this->EmitBinary(Op::Atan2, this->Materialize(y), this->Materialize(x)), 1.0 };
    }
    const Ref a = this->Compile(e.op(0));
    if (a.Id < 0)
    {
      return this->Folded(ApplyUnary(op, a.Scale), e);
    }
    switch (op)
    {
      case Op::Abs:
        return Ref{ this->EmitUnary(Op::Abs, a.Id), std::fabs(a.Scale) };
      case Op::Sign:
        return Ref{ this->EmitUnary(Op::Sign, a.Id), Sign(a.Scale) };
      case Op::Sin:
      case Op::Tan:
      case Op::Sinh:
      case Op::Tanh:
      case Op::Atan:
        if (a.Scale == -1.0) // odd functions
        {
          return Ref{ this->EmitUnary(op, a.Id), -1.0 };
        }
        break;
      case Op::Cos:
      case Op::Cosh:
        if (a.Scale == -1.0) // even functions
        {
          return Ref{ this->EmitUnary(op, a.Id), 1.0 };
        }
        break;
      default:
        break;
    }
    return Ref{ this->EmitUnary(op, this->Materialize(a)), 1.0 };
  }
};

/**
 * The interpreter: one pass over the tape. With GCC and Clang each handler
 * dispatches the next one itself (computed goto), which the branch predictor
 * follows far better than one shared switch (about 2x faster here).
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
  // In the order of Code.
  static const void* const labels[] = { &&L_Const, &&L_Lin, &&L_LinP2, &&L_LinP3, &&L_Lin1,
    &&L_AddC, &&L_Add2, &&L_Sub2, &&L_Mul, &&L_Mul2, &&L_Div, &&L_Square, &&L_Recip, &&L_Sqrt,
    &&L_Pow, &&L_Exp, &&L_Log, &&L_Sin, &&L_Cos, &&L_Tan, &&L_Sinh, &&L_Cosh, &&L_Tanh, &&L_Atan,
    &&L_Atan2, &&L_Abs, &&L_Sign, &&L_Store, &&L_StoreScaled, &&L_StoreConst };
  static_assert(sizeof(labels) / sizeof(labels[0]) == static_cast<int>(Code::StoreConst) + 1,
    "one label per Code");
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
  RIEMANN_OP(Const)
  {
    r[ip->D] = ip->C;
    RIEMANN_NEXT
  }
  RIEMANN_OP(Lin)
  {
    // Four partial sums: one running sum would wait for each addition
    // (sums of 8 to 16 terms are common in derivatives of sums).
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
    r[ip->D] = (s0 + s1) + (s2 + s3);
    RIEMANN_NEXT
  }
  RIEMANN_OP(LinP2)
  {
    const std::int32_t* a = operands + ip->A;
    const double* c = k + ip->B;
    const std::int32_t n = ip->N;
    double s0 = ip->C;
    double s1 = 0.0;
    std::int32_t i = 0;
    for (; i + 2 <= n; i += 2, a += 4)
    {
      s0 += c[i] * r[a[0]] * r[a[1]];
      s1 += c[i + 1] * r[a[2]] * r[a[3]];
    }
    if (i < n)
    {
      s0 += c[i] * r[a[0]] * r[a[1]];
    }
    r[ip->D] = s0 + s1;
    RIEMANN_NEXT
  }
  RIEMANN_OP(LinP3)
  {
    const std::int32_t* a = operands + ip->A;
    const double* c = k + ip->B;
    const std::int32_t n = ip->N;
    double s0 = ip->C;
    double s1 = 0.0;
    std::int32_t i = 0;
    for (; i + 2 <= n; i += 2, a += 6)
    {
      s0 += c[i] * r[a[0]] * r[a[1]] * r[a[2]];
      s1 += c[i + 1] * r[a[3]] * r[a[4]] * r[a[5]];
    }
    if (i < n)
    {
      s0 += c[i] * r[a[0]] * r[a[1]] * r[a[2]];
    }
    r[ip->D] = s0 + s1;
    RIEMANN_NEXT
  }
  RIEMANN_OP(Lin1)
  {
    r[ip->D] = ip->C + ip->K * r[ip->A];
    RIEMANN_NEXT
  }
  RIEMANN_OP(AddC)
  {
    r[ip->D] = ip->C + r[ip->A];
    RIEMANN_NEXT
  }
  RIEMANN_OP(Add2)
  {
    r[ip->D] = r[ip->A] + r[ip->B];
    RIEMANN_NEXT
  }
  RIEMANN_OP(Sub2)
  {
    r[ip->D] = r[ip->A] - r[ip->B];
    RIEMANN_NEXT
  }
  RIEMANN_OP(Mul)
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
    RIEMANN_NEXT
  }
  RIEMANN_OP(Mul2)
  {
    r[ip->D] = r[ip->A] * r[ip->B];
    RIEMANN_NEXT
  }
  RIEMANN_OP(Div)
  {
    r[ip->D] = r[ip->A] / r[ip->B];
    RIEMANN_NEXT
  }
  RIEMANN_OP(Square)
  {
    r[ip->D] = r[ip->A] * r[ip->A];
    RIEMANN_NEXT
  }
  RIEMANN_OP(Recip)
  {
    r[ip->D] = 1.0 / r[ip->A];
    RIEMANN_NEXT
  }
  RIEMANN_OP(Sqrt)
  {
    r[ip->D] = std::sqrt(r[ip->A]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Pow)
  {
    r[ip->D] = std::pow(r[ip->A], r[ip->B]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Exp)
  {
    r[ip->D] = std::exp(r[ip->A]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Log)
  {
    r[ip->D] = std::log(r[ip->A]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Sin)
  {
    r[ip->D] = std::sin(r[ip->A]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Cos)
  {
    r[ip->D] = std::cos(r[ip->A]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Tan)
  {
    r[ip->D] = std::tan(r[ip->A]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Sinh)
  {
    r[ip->D] = std::sinh(r[ip->A]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Cosh)
  {
    r[ip->D] = std::cosh(r[ip->A]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Tanh)
  {
    r[ip->D] = std::tanh(r[ip->A]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Atan)
  {
    r[ip->D] = std::atan(r[ip->A]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Atan2)
  {
    r[ip->D] = std::atan2(r[ip->A], r[ip->B]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Abs)
  {
    r[ip->D] = std::fabs(r[ip->A]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Sign)
  {
    r[ip->D] = Sign(r[ip->A]);
    RIEMANN_NEXT
  }
  RIEMANN_OP(Store)
  {
    outputs[ip->B] = r[ip->A];
    RIEMANN_NEXT
  }
  RIEMANN_OP(StoreScaled)
  {
    outputs[ip->B] = ip->C * r[ip->A];
    RIEMANN_NEXT
  }
  RIEMANN_OP(StoreConst)
  {
    outputs[ip->B] = ip->C;
    RIEMANN_NEXT
  }
#if !defined(__GNUC__)
}
}
#endif
#undef RIEMANN_OP
#undef RIEMANN_NEXT
}

// --- GLSL ----------------------------------------------------------------------------
std::string GlslNumber(double v)
{
  if (!std::isfinite(v) || std::fabs(v) > static_cast<double>(FLT_MAX))
  {
    throw GlslUnsupportedError("the constant " + std::to_string(v) + " is not a finite float");
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", std::fabs(v));
  std::string s = buffer;
  if (s.find_first_of(".e") == std::string::npos)
  {
    s += ".0";
  }
  return v < 0.0 ? "(-" + s + ")" : s;
}
} // namespace

// --- CompiledExpressions ----------------------------------------------------------------
struct CompiledExpressions::Internals
{
  int Sources = 0;
  int Order = 0;
  std::vector<std::string> ParameterNames;
  bool Time = false;
  std::vector<bool> Parameters;
  double TreeNodes = 0.0;

  // The compiled DAG (for GLSL) and its outputs.
  std::vector<Node> Nodes;
  /// Output o (CPU layout) = Outputs[o].
  std::vector<Ref> Outputs;

  // The CPU tape.
  std::vector<Instruction> Tape;
  std::vector<std::int32_t> Operands;
  std::vector<double> Coefficients;
  /// Instructions to run for outputs up to order n: Tape[0, End[n]).
  int End[4] = { 0, 0, 0, 0 };
  int Registers = 0;
  int Operations = 0;

  int NumberOfInputs() const { return 4 + static_cast<int>(this->ParameterNames.size()); }
  void BuildTape();
};

int CompiledExpressions::OutputsPerSource(int order)
{
  static const int counts[4] = { 1, 4, 10, 20 };
  if (order < 0 || order > 3)
  {
    throw std::out_of_range("derivative order " + std::to_string(order) + " is not in 0..3");
  }
  return counts[order];
}

void CompiledExpressions::FailIndex(int source, int n, int i, int j, int k)
{
  throw std::out_of_range("no output for source " + std::to_string(source) + ", derivative order " +
    std::to_string(n) + ", indices " + std::to_string(i) + " " + std::to_string(j) + " " +
    std::to_string(k));
}

CompiledExpressions::CompiledExpressions(const std::vector<std::string>& sources,
  const std::vector<std::string>& parameterNames, int order)
  : Internal(new Internals)
{
  Internals& m = *this->Internal;
  if (order < 0 || order > 3)
  {
    throw std::invalid_argument("derivative order " + std::to_string(order) + " is not in 0..3");
  }
  if (sources.empty() || sources.size() > static_cast<std::size_t>(MaximumSources))
  {
    throw ExpressionError(0,
      std::to_string(sources.size()) + " expressions given; 1 to " +
        std::to_string(MaximumSources) + " are accepted");
  }
  m.Sources = static_cast<int>(sources.size());
  m.Order = order;
  this->Sources = m.Sources;
  this->Order = order;
  this->Stride = OutputsPerSource(order);
  m.ParameterNames = parameterNames;
  CheckExpressionParameterNames(parameterNames);

  // Syntax first (no GiNaC, no lock): columns and causes.
  std::vector<std::string> canonical;
  for (std::size_t s = 0; s < sources.size(); ++s)
  {
    try
    {
      canonical.push_back(CheckExpressionSyntax(sources[s], parameterNames));
    }
    catch (const ExpressionError& e)
    {
      throw ExpressionError(e.Column, e.Cause, static_cast<int>(s));
    }
  }

  const std::lock_guard<std::mutex> lock(GinacMutex());
  int currentSource = -1;
  try
  {
    using namespace GiNaC;
    std::vector<ex> symbols = { realsymbol("x"), realsymbol("y"), realsymbol("z"),
      realsymbol("t") };
    symtab table;
    table["x"] = symbols[0];
    table["y"] = symbols[1];
    table["z"] = symbols[2];
    table["t"] = symbols[3];
    table["pi"] = Pi;
    for (const std::string& name : parameterNames)
    {
      symbols.push_back(realsymbol(name));
      table[name] = symbols.back();
    }
    // AbsSerial/SignSerial register their functions on first use: do it here.
    AbsSerial();
    SignSerial();

    // derivatives[n][s][d]: the d-th derivative of order n of source s.
    std::vector<std::vector<std::vector<ex>>> derivatives(
      order + 1, std::vector<std::vector<ex>>(m.Sources));
    for (int s = 0; s < m.Sources; ++s)
    {
      currentSource = s;
      parser reader(table, true, Functions());
      derivatives[0][s].push_back(reader(canonical[s]));
    }
    const std::vector<DerivativeIndex>& layout = Layout();
    ExMap<double> tree;
    ExMap<double> work;
    for (int n = 1; n <= order; ++n)
    {
      // Each derivative differentiates one of order n - 1. GiNaC does not
      // memoise: its work follows the trees, products by the product rule.
      // Refuse expression swell before it takes minutes.
      struct Step
      {
        int Source;
        int Lower;
        int Variable;
      };
      std::vector<Step> steps;
      double estimate = 0.0;
      for (int s = 0; s < m.Sources; ++s)
      {
        currentSource = s;
        for (int d = FirstOffset(n); d < OutputsPerSource(n); ++d)
        {
          const DerivativeIndex& index = layout[static_cast<std::size_t>(d)];
          // d_i f, d_j (d_i f), d_k (d_i d_j f): the lower derivative (the
          // first n - 1 indices) along the last index.
          const int last = n == 1 ? index.I : (n == 2 ? index.J : index.K);
          const int lower = DerivativeOffset(n - 1, index.I, index.J, index.K) - FirstOffset(n - 1);
          steps.push_back({ s, lower, last });
          estimate +=
            DifferentiationWork(derivatives[n - 1][s][static_cast<std::size_t>(lower)], work);
        }
      }
      if (estimate > MaximumDifferentiationWork)
      {
        char text[32];
        std::snprintf(text, sizeof text, "%.2g", estimate);
        throw ExpressionError(0,
          "the expressions are too complex to differentiate to order " + std::to_string(n) +
            " (about " + text + " steps, at most " +
            std::to_string(static_cast<long>(MaximumDifferentiationWork)) +
            "); simplify them or use a built-in provider");
      }
      for (const Step& step : steps)
      {
        currentSource = step.Source;
        const ex& from = derivatives[n - 1][step.Source][static_cast<std::size_t>(step.Lower)];
        derivatives[n][step.Source].push_back(from.diff(ex_to<symbol>(symbols[step.Variable])));
      }
      currentSource = -1;
      for (int s = 0; s < m.Sources; ++s)
      {
        for (const ex& e : derivatives[n][s])
        {
          TreeSize(e, tree);
        }
      }
      if (tree.size() > MaximumDerivativeNodes)
      {
        throw ExpressionError(0,
          "the expressions are too complex: their derivatives of order " + std::to_string(n) +
            " have more than " + std::to_string(MaximumDerivativeNodes) +
            " distinct parts; simplify them or use a built-in provider");
      }
    }

    m.Time = false;
    m.Parameters.assign(parameterNames.size(), false);
    for (int s = 0; s < m.Sources; ++s)
    {
      const ex& f = derivatives[0][s][0];
      m.Time = m.Time || f.has(symbols[3]);
      for (std::size_t q = 0; q < parameterNames.size(); ++q)
      {
        m.Parameters[q] = m.Parameters[q] || f.has(symbols[4 + q]);
      }
    }

    // Compile order by order: nodes needed by order n come after those of lower orders.
    Compiler compiler(symbols);
    m.Outputs.assign(static_cast<std::size_t>(m.Sources * OutputsPerSource(order)), Ref{});
    m.TreeNodes = 0.0;
    for (int n = 0; n <= order; ++n)
    {
      for (int s = 0; s < m.Sources; ++s)
      {
        compiler.Source = s;
        currentSource = s;
        const int first = FirstOffset(n);
        for (std::size_t d = 0; d < derivatives[n][s].size(); ++d)
        {
          const ex& e = derivatives[n][s][d];
          m.TreeNodes += TreeSize(e, tree);
          m.Outputs[static_cast<std::size_t>(s * OutputsPerSource(order) + first) + d] =
            compiler.Compile(e);
        }
      }
    }
    m.Nodes = std::move(compiler.Nodes);
  }
  catch (const ExpressionError& e)
  {
    throw ExpressionError(e.Column, e.Cause, e.Source >= 0 ? e.Source : currentSource, e.Parameter);
  }
  catch (const GiNaC::pole_error& e)
  {
    throw ExpressionError(0,
      std::string("the expression is infinite where it simplifies to a constant (division by "
                  "zero, log(0), tan(pi/2), ...): ") +
        e.what(),
      currentSource);
  }
  catch (const std::exception& e)
  {
    throw ExpressionError(
      0, std::string("the expression cannot be used: ") + e.what(), currentSource);
  }
  m.BuildTape();
}

CompiledExpressions::~CompiledExpressions() = default;

void CompiledExpressions::Internals::BuildTape()
{
  const int inputs = this->NumberOfInputs();
  // Register `inputs` holds 1.0 (padding of product terms, see below).
  const int one = inputs;
  const int per = OutputsPerSource(this->Order);
  const std::vector<DerivativeIndex>& layout = Layout();
  auto orderOf = [&](std::size_t o) { return layout[o % static_cast<std::size_t>(per)].N; };
  const std::size_t count = this->Nodes.size();

  // Level of a node: the lowest derivative order of an output needing it
  // (4: dead). Operands have a level at most their users'.
  std::vector<int> level(count, 4);
  std::vector<int> uses(count, 0);
  for (std::size_t o = 0; o < this->Outputs.size(); ++o)
  {
    const int id = this->Outputs[o].Id;
    if (id >= 0)
    {
      level[id] = std::min(level[id], orderOf(o));
      ++uses[id];
    }
  }
  for (std::size_t i = count; i-- > 0;)
  {
    if (level[i] > this->Order)
    {
      continue;
    }
    for (int a : this->Nodes[i].Args)
    {
      level[a] = std::min(level[a], level[i]);
      ++uses[a];
    }
  }

  // Fusion: a product (of at most 3 factors, or a square) used only by one
  // sum becomes a term of that sum, c * r[a] * r[b] (* r[c]): derivatives of
  // sums are sums of products, and this halves the instructions dispatched.
  std::vector<char> fused(count, 0);
  auto factors = [&](int id) -> std::vector<int>
  {
    const Node& n = this->Nodes[id];
    if (id >= inputs && uses[id] == 1 && n.Operation == Op::Mul && n.Args.size() <= 3)
    {
      return n.Args;
    }
    if (id >= inputs && uses[id] == 1 && n.Operation == Op::Square)
    {
      return { n.Args[0], n.Args[0] };
    }
    return { id };
  };
  // Per live node: its operand groups (Lin: one group per term; others: one
  // group per argument).
  std::vector<std::vector<std::vector<int>>> groups(count);
  for (std::size_t i = static_cast<std::size_t>(inputs); i < count; ++i)
  {
    if (level[i] > this->Order)
    {
      continue;
    }
    const Node& node = this->Nodes[i];
    for (int a : node.Args)
    {
      if (node.Operation == Op::Lin)
      {
        groups[i].push_back(factors(a));
        if (groups[i].back().size() > 1)
        {
          fused[a] = 1;
        }
      }
      else
      {
        groups[i].push_back({ a });
      }
    }
  }

  // Instruction sequence: nodes of level n, then the stores of order n.
  struct Item
  {
    int Node;   // >= 0: compute this node
    int Output; // else: store this output
  };
  std::vector<Item> items;
  std::vector<int> ends;
  for (int n = 0; n <= this->Order; ++n)
  {
    for (std::size_t i = static_cast<std::size_t>(inputs); i < count; ++i)
    {
      if (level[i] == n && !fused[i])
      {
        items.push_back({ static_cast<int>(i), -1 });
      }
    }
    for (std::size_t o = 0; o < this->Outputs.size(); ++o)
    {
      if (orderOf(o) == n)
      {
        items.push_back({ -1, static_cast<int>(o) });
      }
    }
    ends.push_back(static_cast<int>(items.size()));
  }
  // Last use of each node.
  std::vector<int> lastUse(count, -1);
  for (std::size_t p = 0; p < items.size(); ++p)
  {
    if (items[p].Node >= 0)
    {
      for (const std::vector<int>& g : groups[items[p].Node])
      {
        for (int a : g)
        {
          lastUse[a] = static_cast<int>(p);
        }
      }
    }
    else if (this->Outputs[items[p].Output].Id >= 0)
    {
      lastUse[this->Outputs[items[p].Output].Id] = static_cast<int>(p);
    }
  }
  // Registers: inputs and `one` fixed, the rest reused after their last use.
  std::vector<int> reg(count, -1);
  for (int i = 0; i < inputs; ++i)
  {
    reg[i] = i;
  }
  std::vector<int> freeRegisters;
  int registers = inputs + 1;
  std::vector<int> released;
  auto release = [&](int node, int p)
  {
    if (node >= inputs && lastUse[node] == p &&
      std::find(released.begin(), released.end(), node) == released.end())
    {
      released.push_back(node);
      freeRegisters.push_back(reg[node]);
    }
  };
  for (std::size_t p = 0; p < items.size(); ++p)
  {
    const int position = static_cast<int>(p);
    released.clear();
    Instruction in{};
    if (items[p].Output >= 0)
    {
      const Ref& r = this->Outputs[items[p].Output];
      in.B = items[p].Output;
      if (r.Id < 0)
      {
        in.Operation = Code::StoreConst;
        in.C = r.Scale;
      }
      else
      {
        in.Operation = r.Scale == 1.0 ? Code::Store : Code::StoreScaled;
        in.A = reg[r.Id];
        in.C = r.Scale;
        release(r.Id, position);
      }
      this->Tape.push_back(in);
      continue;
    }
    const Node& node = this->Nodes[items[p].Node];
    const std::vector<std::vector<int>>& operandGroups = groups[items[p].Node];
    // Operands are read before the result is written: the result may reuse
    // an operand's register.
    std::vector<int> args;
    std::size_t width = 1;
    for (const std::vector<int>& g : operandGroups)
    {
      width = std::max(width, g.size());
    }
    for (const std::vector<int>& g : operandGroups)
    {
      for (std::size_t f = 0; f < width; ++f)
      {
        args.push_back(f < g.size() ? reg[g[f]] : one);
      }
    }
    for (const std::vector<int>& g : operandGroups)
    {
      for (int a : g)
      {
        release(a, position);
      }
    }
    int dst;
    if (!freeRegisters.empty())
    {
      dst = freeRegisters.back();
      freeRegisters.pop_back();
    }
    else
    {
      dst = registers++;
    }
    reg[items[p].Node] = dst;
    in.D = dst;
    ++this->Operations;
    switch (node.Operation)
    {
      case Op::Const:
        in.Operation = Code::Const;
        in.C = node.Constant;
        --this->Operations;
        break;
      case Op::Lin:
        in.C = node.Constant;
        if (width == 1 && args.size() == 1)
        {
          in.Operation = node.Coefficients[0] == 1.0 ? Code::AddC : Code::Lin1;
          in.A = args[0];
          in.K = node.Coefficients[0];
        }
        else if (width == 1 && args.size() == 2 && node.Constant == 0.0 &&
          node.Coefficients[0] == 1.0 &&
          (node.Coefficients[1] == 1.0 || node.Coefficients[1] == -1.0))
        {
          in.Operation = node.Coefficients[1] == 1.0 ? Code::Add2 : Code::Sub2;
          in.A = args[0];
          in.B = args[1];
        }
        else
        {
          in.Operation = width == 1 ? Code::Lin : (width == 2 ? Code::LinP2 : Code::LinP3);
          in.N = static_cast<std::int32_t>(node.Args.size());
          in.A = static_cast<std::int32_t>(this->Operands.size());
          in.B = static_cast<std::int32_t>(this->Coefficients.size());
          this->Operands.insert(this->Operands.end(), args.begin(), args.end());
          this->Coefficients.insert(
            this->Coefficients.end(), node.Coefficients.begin(), node.Coefficients.end());
        }
        break;
      case Op::Mul:
        if (args.size() == 2)
        {
          in.Operation = Code::Mul2;
          in.A = args[0];
          in.B = args[1];
        }
        else
        {
          in.Operation = Code::Mul;
          in.N = static_cast<std::int32_t>(args.size());
          in.A = static_cast<std::int32_t>(this->Operands.size());
          this->Operands.insert(this->Operands.end(), args.begin(), args.end());
        }
        break;
      default:
      {
        static const std::pair<Op, Code> simple[] = { { Op::Div, Code::Div },
          { Op::Square, Code::Square }, { Op::Recip, Code::Recip }, { Op::Sqrt, Code::Sqrt },
          { Op::Pow, Code::Pow }, { Op::Exp, Code::Exp }, { Op::Log, Code::Log },
          { Op::Sin, Code::Sin }, { Op::Cos, Code::Cos }, { Op::Tan, Code::Tan },
          { Op::Sinh, Code::Sinh }, { Op::Cosh, Code::Cosh }, { Op::Tanh, Code::Tanh },
          { Op::Atan, Code::Atan }, { Op::Atan2, Code::Atan2 }, { Op::Abs, Code::Abs },
          { Op::Sign, Code::Sign } };
        for (const auto& [op, code] : simple)
        {
          if (op == node.Operation)
          {
            in.Operation = code;
          }
        }
        in.A = args.at(0);
        in.B = args.size() > 1 ? args[1] : 0;
        break;
      }
    }
    this->Tape.push_back(in);
  }
  for (int n = 0; n <= this->Order; ++n)
  {
    this->End[n] = ends[static_cast<std::size_t>(n)];
  }
  this->Registers = registers;
}

int CompiledExpressions::GetNumberOfParameters() const
{
  return static_cast<int>(this->Internal->ParameterNames.size());
}

const std::vector<std::string>& CompiledExpressions::GetParameterNames() const
{
  return this->Internal->ParameterNames;
}

bool CompiledExpressions::DependsOnTime() const
{
  return this->Internal->Time;
}

bool CompiledExpressions::DependsOnParameter(int q) const
{
  return q >= 0 && q < static_cast<int>(this->Internal->Parameters.size()) &&
    this->Internal->Parameters[static_cast<std::size_t>(q)];
}

CompiledExpressions::Statistics CompiledExpressions::GetStatistics() const
{
  const Internals& m = *this->Internal;
  Statistics s;
  s.Instructions = static_cast<int>(m.Tape.size());
  s.Operations = m.Operations;
  for (const Instruction& in : m.Tape)
  {
    switch (in.Operation)
    {
      case Code::Lin:
      case Code::Mul:
        s.Operands += in.N;
        break;
      case Code::LinP2:
        s.Operands += 2 * in.N;
        break;
      case Code::LinP3:
        s.Operands += 3 * in.N;
        break;
      case Code::Add2:
      case Code::Sub2:
      case Code::Mul2:
      case Code::Div:
      case Code::Pow:
      case Code::Atan2:
        s.Operands += 2;
        break;
      case Code::Const:
      case Code::StoreConst:
        break;
      default:
        s.Operands += 1;
        break;
    }
  }
  s.Registers = m.Registers;
  s.TreeNodes = m.TreeNodes;
  return s;
}

void CompiledExpressions::Evaluate(
  const double p[3], double t, const double* parameters, double* outputs) const
{
  this->Evaluate(p, t, parameters, outputs, this->Internal->Order);
}

void CompiledExpressions::Evaluate(
  const double p[3], double t, const double* parameters, double* outputs, int maxOrder) const
{
  const Internals& m = *this->Internal;
  if (maxOrder < 0)
  {
    return;
  }
  maxOrder = std::min(maxOrder, m.Order);
  double stackRegisters[StackRegisters];
  double* r = stackRegisters;
  if (m.Registers > StackRegisters)
  {
    thread_local std::vector<double> heap;
    if (heap.size() < static_cast<std::size_t>(m.Registers))
    {
      heap.resize(static_cast<std::size_t>(m.Registers));
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
  Run(m.Tape.data(), m.Tape.data() + m.End[maxOrder], m.Operands.data(), m.Coefficients.data(), r,
    outputs);
}

std::string CompiledExpressions::EmitGlsl(GlslBuilder& builder,
  const std::vector<std::string>& parameterUniforms, const std::string& timeUniform,
  int maxOrder) const
{
  const Internals& m = *this->Internal;
  if (maxOrder < 0 || maxOrder > m.Order)
  {
    throw std::invalid_argument("EmitGlsl: maxOrder " + std::to_string(maxOrder) +
      " is not in 0.." + std::to_string(m.Order));
  }
  if (parameterUniforms.size() != m.ParameterNames.size())
  {
    throw std::invalid_argument("EmitGlsl: " + std::to_string(parameterUniforms.size()) +
      " parameter uniforms for " + std::to_string(m.ParameterNames.size()) + " parameters");
  }
  if (m.Time && timeUniform.empty())
  {
    throw std::invalid_argument(
      "EmitGlsl: the expressions depend on t but no time uniform is given");
  }
  const int per = OutputsPerSource(m.Order);
  const int glslPer = OutputsPerSource(maxOrder);
  const std::vector<DerivativeIndex>& layout = Layout();

  // Nodes the outputs up to maxOrder need.
  std::vector<char> live(m.Nodes.size(), 0);
  for (std::size_t o = 0; o < m.Outputs.size(); ++o)
  {
    if (layout[o % static_cast<std::size_t>(per)].N <= maxOrder && m.Outputs[o].Id >= 0)
    {
      live[m.Outputs[o].Id] = 1;
    }
  }
  for (std::size_t i = m.Nodes.size(); i-- > 0;)
  {
    if (live[i])
    {
      for (int a : m.Nodes[i].Args)
      {
        live[a] = 1;
      }
    }
  }
  const int inputs = m.NumberOfInputs();
  std::vector<std::string> names(m.Nodes.size());
  names[0] = "p.x";
  names[1] = "p.y";
  names[2] = "p.z";
  names[3] = timeUniform;
  for (std::size_t q = 0; q < parameterUniforms.size(); ++q)
  {
    names[4 + q] = parameterUniforms[q];
  }
  auto operand = [&](int id) -> std::string
  {
    if (m.Nodes[id].Operation == Op::Const)
    {
      return GlslNumber(m.Nodes[id].Constant);
    }
    return names[id];
  };
  auto scaled = [&](double c, const std::string& v) -> std::string
  {
    if (c == 1.0)
    {
      return v;
    }
    if (c == -1.0)
    {
      return "-" + v;
    }
    return GlslNumber(c) + " * " + v;
  };

  const std::string name = builder.NewName("expressions");
  std::string code =
    "void " + name + "(vec3 p, out float o[" + std::to_string(m.Sources * glslPer) + "])\n{\n";
  int counter = 0;
  for (std::size_t i = static_cast<std::size_t>(inputs); i < m.Nodes.size(); ++i)
  {
    const Node& node = m.Nodes[i];
    if (!live[i] || node.Operation == Op::Const)
    {
      continue;
    }
    names[i] = "v" + std::to_string(counter++);
    std::string value;
    auto unary = [&](const char* f) { return std::string(f) + "(" + operand(node.Args[0]) + ")"; };
    switch (node.Operation)
    {
      case Op::Lin:
      {
        bool first = true;
        if (node.Constant != 0.0)
        {
          value = GlslNumber(node.Constant);
          first = false;
        }
        for (std::size_t a = 0; a < node.Args.size(); ++a)
        {
          const double c = node.Coefficients[a];
          const std::string v = operand(node.Args[a]);
          if (first)
          {
            value = scaled(c, v);
            first = false;
          }
          else
          {
            value += (c < 0.0 ? " - " : " + ") + scaled(std::fabs(c), v);
          }
        }
        break;
      }
      case Op::Mul:
        for (std::size_t a = 0; a < node.Args.size(); ++a)
        {
          value += (a ? " * " : "") + operand(node.Args[a]);
        }
        break;
      case Op::Div:
        value = operand(node.Args[0]) + " / " + operand(node.Args[1]);
        break;
      case Op::Square:
        value = operand(node.Args[0]) + " * " + operand(node.Args[0]);
        break;
      case Op::Recip:
        value = "1.0 / " + operand(node.Args[0]);
        break;
      case Op::Pow:
        value = "pow(" + operand(node.Args[0]) + ", " + operand(node.Args[1]) + ")";
        break;
      case Op::Atan2:
        value = "atan(" + operand(node.Args[0]) + ", " + operand(node.Args[1]) + ")";
        break;
      case Op::Sqrt:
        value = unary("sqrt");
        break;
      case Op::Exp:
        value = unary("exp");
        break;
      case Op::Log:
        value = unary("log");
        break;
      case Op::Sin:
        value = unary("sin");
        break;
      case Op::Cos:
        value = unary("cos");
        break;
      case Op::Tan:
        value = unary("tan");
        break;
      case Op::Sinh:
        value = unary("sinh");
        break;
      case Op::Cosh:
        value = unary("cosh");
        break;
      case Op::Tanh:
        value = unary("tanh");
        break;
      case Op::Atan:
        value = unary("atan");
        break;
      case Op::Abs:
        value = unary("abs");
        break;
      case Op::Sign:
        value = unary("sign");
        break;
      default:
        throw GlslUnsupportedError("internal error: unexpected operation in GLSL emission");
    }
    code += "  float " + names[i] + " = " + value + ";\n";
  }
  for (std::size_t o = 0; o < m.Outputs.size(); ++o)
  {
    const int d = static_cast<int>(o % static_cast<std::size_t>(per));
    if (layout[static_cast<std::size_t>(d)].N > maxOrder)
    {
      continue;
    }
    const int s = static_cast<int>(o / static_cast<std::size_t>(per));
    const Ref& r = m.Outputs[o];
    const std::string value = r.Id < 0 ? GlslNumber(r.Scale) : scaled(r.Scale, operand(r.Id));
    code += "  o[" + std::to_string(s * glslPer + d) + "] = " + value + ";\n";
  }
  code += "}\n";
  builder.AddFunction(code);
  return name;
}
} // namespace riemann
