// The symbolic stage of the expression compiler, and the only file that
// includes GiNaC: GiNaC reads the canonical sources, differentiates them up to
// the requested order (refusing expression swell before it takes minutes),
// and the results are translated into the expression graph
// (ExpressionGraph.h), which no longer holds any GiNaC type.
//
// GiNaC is not thread-safe (reference counts, global tables): all of it runs
// under one process-wide mutex, destruction of its objects included.
#include "ExpressionGraph.h"

#include "DerivativeLayout.h"
#include "ExpressionError.h"
#include "ExpressionParser.h"

#include <ginac/ginac.h>

#include <algorithm>
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
namespace expression
{
namespace
{
/// Distinct GiNaC subexpressions of all derivatives at most.
constexpr std::size_t MaximumDerivativeNodes = 200000;
/// Estimated work of differentiating one order (DifferentiationWork): at most
/// about a second (0.3 to 0.6 microseconds per unit measured).
constexpr double MaximumDifferentiationWork = 1.5e6;

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

/// Exactly the functions of SupportedExpressionFunctions().
const GiNaC::prototype_table& Functions()
{
  static const GiNaC::prototype_table table = []
  {
    using GiNaC::ex;
    using GiNaC::exvector;
    GiNaC::prototype_table t;
    t[{ "exp", 1 }] = [](const exvector& a) -> ex { return GiNaC::exp(a[0]); };
    t[{ "log", 1 }] = [](const exvector& a) -> ex { return GiNaC::log(a[0]); };
    t[{ "sqrt", 1 }] = [](const exvector& a) -> ex { return GiNaC::sqrt(a[0]); };
    t[{ "sin", 1 }] = [](const exvector& a) -> ex { return GiNaC::sin(a[0]); };
    t[{ "cos", 1 }] = [](const exvector& a) -> ex { return GiNaC::cos(a[0]); };
    t[{ "tan", 1 }] = [](const exvector& a) -> ex { return GiNaC::tan(a[0]); };
    t[{ "sinh", 1 }] = [](const exvector& a) -> ex { return GiNaC::sinh(a[0]); };
    t[{ "cosh", 1 }] = [](const exvector& a) -> ex { return GiNaC::cosh(a[0]); };
    t[{ "tanh", 1 }] = [](const exvector& a) -> ex { return GiNaC::tanh(a[0]); };
    t[{ "atan2", 2 }] = [](const exvector& a) -> ex { return GiNaC::atan2(a[0], a[1]); };
    t[{ "abs", 1 }] = [](const exvector& a) -> ex { return GiNaC::function(AbsSerial(), a[0]); };
    t[{ "pow", 2 }] = [](const exvector& a) -> ex { return GiNaC::pow(a[0], a[1]); };
    return t;
  }();
  return table;
}

// --- Measures and keys of GiNaC expressions ----------------------------------------
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

// --- GiNaC expressions -> graph ---------------------------------------------------
/// Translates GiNaC expressions into graph nodes (hash-consed twice: by GiNaC
/// structure in Memo, by operation and operands in the GraphBuilder).
class Translator
{
public:
  GraphBuilder Graph;

  /// symbols: in register order (x, y, z, t, parameters).
  explicit Translator(const std::vector<GiNaC::ex>& symbols)
    : Graph(static_cast<int>(symbols.size()))
  {
    for (std::size_t i = 0; i < symbols.size(); ++i)
    {
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

private:
  ExMap<Ref> Memo;
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

  [[noreturn]] void Fail(const std::string& cause) const { this->Graph.Fail(cause); }

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

  static Ref Constant(double v) { return GraphBuilder::Constant(v); }

  Ref Folded(double v, const GiNaC::ex& e) const
  {
    if (!std::isfinite(v))
    {
      this->Fail("the constant part " + Printed(e) + " is not a finite real number");
    }
    return Constant(v);
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
    return this->Graph.MakeLin(c0, std::move(terms));
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
    return this->Graph.MakeProduct(coefficient, std::move(numerator), std::move(denominator));
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
      return Ref{ this->Graph.EmitUnary(Op::Square, half.Id), half.Scale * half.Scale };
    }
    const Ref even = this->Compile(GiNaC::pow(base, n - 1));
    const Ref one = this->Compile(base);
    return this->Graph.MakeProduct(even, one);
  }

  /// b^(m + 1/2) with twice = 2m + 1: sqrt(b), or b^m sqrt(b).
  Ref PowerHalfInteger(const GiNaC::ex& base, const GiNaC::numeric& twice)
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
        return Ref{ this->Graph.EmitUnary(Op::Sqrt, b.Id), std::sqrt(b.Scale) };
      }
      return Ref{ this->Graph.EmitUnary(Op::Sqrt, this->Graph.Materialize(b)), 1.0 };
    }
    const Ref whole = this->Compile(GiNaC::pow(base, (twice - 1) / 2));
    const Ref root = this->Compile(GiNaC::sqrt(base));
    return this->Graph.MakeProduct(whole, root);
  }

  /// b^p for a real constant p that is no small integer or half-integer.
  Ref PowerReal(const GiNaC::ex& base, const GiNaC::ex& exponent)
  {
    const double p = this->ToDouble(exponent);
    const Ref b = this->Compile(base);
    if (b.Id < 0)
    {
      return this->Folded(std::pow(b.Scale, p), base);
    }
    const int pNode = this->Graph.Materialize(Constant(p));
    if (b.Scale > 0.0)
    {
      return Ref{ this->Graph.EmitBinary(Op::Pow, b.Id, pNode), std::pow(b.Scale, p) };
    }
    return Ref{ this->Graph.EmitBinary(Op::Pow, this->Graph.Materialize(b), pNode), 1.0 };
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
        return Ref{ this->Graph.EmitUnary(Op::Recip, r.Id), 1.0 / r.Scale };
      }
      if (k.is_integer() && k <= 64)
      {
        return this->PowerInteger(base, k.to_long());
      }
      if (twice.is_integer() && twice <= 129)
      {
        return this->PowerHalfInteger(base, twice);
      }
      return this->PowerReal(base, exponent);
    }
    const Ref b = this->Compile(base);
    const Ref x = this->Compile(exponent);
    if (b.Id < 0 && x.Id < 0)
    {
      return this->Folded(std::pow(b.Scale, x.Scale), base);
    }
    const int id =
      this->Graph.EmitBinary(Op::Pow, this->Graph.Materialize(b), this->Graph.Materialize(x));
    return Ref{ id, 1.0 };
  }

  /// The operation of a function GiNaC may produce; fails for others.
  Op FunctionOperation(const GiNaC::ex& e) const
  {
    using namespace GiNaC;
    const unsigned serial = ex_to<function>(e).get_serial();
    const std::pair<unsigned, Op> operations[] = { { exp_SERIAL::serial, Op::Exp },
      { log_SERIAL::serial, Op::Log }, { sin_SERIAL::serial, Op::Sin },
      { cos_SERIAL::serial, Op::Cos }, { tan_SERIAL::serial, Op::Tan },
      { sinh_SERIAL::serial, Op::Sinh }, { cosh_SERIAL::serial, Op::Cosh },
      { tanh_SERIAL::serial, Op::Tanh },
      // GiNaC writes atan2(y, c) with c > 0 as atan(y / c).
      { atan_SERIAL::serial, Op::Atan }, { atan2_SERIAL::serial, Op::Atan2 },
      { abs_SERIAL::serial, Op::Abs }, { AbsSerial(), Op::Abs },
      // csgn is the sign for real arguments.
      { SignSerial(), Op::Sign }, { csgn_SERIAL::serial, Op::Sign } };
    for (const auto& [functionSerial, op] : operations)
    {
      if (functionSerial == serial)
      {
        return op;
      }
    }
    this->Fail("GiNaC turned the expression into " + Printed(e) +
      ", a function the evaluator does not support");
  }

  Ref CompileAtan2(const GiNaC::ex& e)
  {
    const Ref y = this->Compile(e.op(0));
    const Ref x = this->Compile(e.op(1));
    if (y.Id < 0 && x.Id < 0)
    {
      return this->Folded(std::atan2(y.Scale, x.Scale), e);
    }
    const int id =
      this->Graph.EmitBinary(Op::Atan2, this->Graph.Materialize(y), this->Graph.Materialize(x));
    return Ref{ id, 1.0 };
  }

  Ref CompileFunction(const GiNaC::ex& e)
  {
    const Op op = this->FunctionOperation(e);
    if (op == Op::Atan2)
    {
      return this->CompileAtan2(e);
    }
    const Ref a = this->Compile(e.op(0));
    if (a.Id < 0)
    {
      return this->Folded(ApplyUnary(op, a.Scale), e);
    }
    switch (op)
    {
      case Op::Abs:
        return Ref{ this->Graph.EmitUnary(Op::Abs, a.Id), std::fabs(a.Scale) };
      case Op::Sign:
        return Ref{ this->Graph.EmitUnary(Op::Sign, a.Id), Sign(a.Scale) };
      case Op::Sin:
      case Op::Tan:
      case Op::Sinh:
      case Op::Tanh:
      case Op::Atan:
        if (a.Scale == -1.0) // odd functions
        {
          return Ref{ this->Graph.EmitUnary(op, a.Id), -1.0 };
        }
        break;
      case Op::Cos:
      case Op::Cosh:
        if (a.Scale == -1.0) // even functions
        {
          return Ref{ this->Graph.EmitUnary(op, a.Id), 1.0 };
        }
        break;
      default:
        break;
    }
    return Ref{ this->Graph.EmitUnary(op, this->Graph.Materialize(a)), 1.0 };
  }
};

// --- Sources -> derivatives -> graph -----------------------------------------------
/**
 * The symbolic stage, step by step: Read, Differentiate order by order,
 * Compile. Construct and destroy it under GinacMutex(). CurrentSource (the
 * caller's variable) names the source being worked on, for error messages.
 */
class SymbolicStage
{
public:
  SymbolicStage(const std::vector<std::string>& parameterNames, int& currentSource)
    : CurrentSource(currentSource)
    , ParameterCount(parameterNames.size())
  {
    this->DeclareSymbols(parameterNames);
    // AbsSerial/SignSerial register their functions on first use: do it here.
    AbsSerial();
    SignSerial();
  }

  /// The sources themselves: derivatives of order 0.
  void Read(const std::vector<std::string>& canonicalSources)
  {
    this->Sources = static_cast<int>(canonicalSources.size());
    this->Derivatives.assign(1, std::vector<std::vector<GiNaC::ex>>(canonicalSources.size()));
    for (int s = 0; s < this->Sources; ++s)
    {
      this->CurrentSource = s;
      GiNaC::parser reader(this->Table, true, Functions());
      this->Derivatives[0][s].push_back(reader(canonicalSources[s]));
    }
  }

  /// The derivatives of order n, each from one of order n - 1.
  void Differentiate(int n)
  {
    // GiNaC does not memoise: its work follows the trees, products by the
    // product rule. Refuse expression swell before it takes minutes.
    double estimate = 0.0;
    const std::vector<Step> steps = this->PlanDerivatives(n, estimate);
    CheckDifferentiationWork(n, estimate);
    this->Derivatives.emplace_back(static_cast<std::size_t>(this->Sources));
    for (const Step& step : steps)
    {
      this->CurrentSource = step.Source;
      const GiNaC::ex& from =
        this->Derivatives[n - 1][step.Source][static_cast<std::size_t>(step.Lower)];
      this->Derivatives[n][step.Source].push_back(
        from.diff(GiNaC::ex_to<GiNaC::symbol>(this->Symbols[step.Variable])));
    }
    this->CurrentSource = -1;
    this->CheckDistinctParts(n);
  }

  /// The graph of every derivative read or computed, with the dependencies.
  ExpressionGraph Compile()
  {
    ExpressionGraph graph;
    this->FindDependencies(graph);
    // Order by order: nodes needed by order n come after those of lower orders.
    const int order = static_cast<int>(this->Derivatives.size()) - 1;
    const int perSource = DerivativeLayout::OutputsPerSource(order);
    Translator translator(this->Symbols);
    graph.Outputs.assign(static_cast<std::size_t>(this->Sources * perSource), Ref{});
    for (int n = 0; n <= order; ++n)
    {
      for (int s = 0; s < this->Sources; ++s)
      {
        translator.Graph.Source = s;
        this->CurrentSource = s;
        const int first = FirstOffset(n);
        for (std::size_t d = 0; d < this->Derivatives[n][s].size(); ++d)
        {
          const GiNaC::ex& e = this->Derivatives[n][s][d];
          graph.TreeNodes += TreeSize(e, this->Tree);
          graph.Outputs[static_cast<std::size_t>(s * perSource + first) + d] =
            translator.Compile(e);
        }
      }
    }
    graph.Nodes = std::move(translator.Graph.Nodes);
    return graph;
  }

private:
  /// Derivative Lower of order n - 1 of Source along Variable.
  struct Step
  {
    int Source;
    int Lower;
    int Variable;
  };

  int& CurrentSource;
  std::size_t ParameterCount;
  int Sources = 0;
  /// In register order: x, y, z, t, parameters.
  std::vector<GiNaC::ex> Symbols;
  GiNaC::symtab Table;
  /// Derivatives[n][s][d]: the d-th derivative of order n of source s.
  std::vector<std::vector<std::vector<GiNaC::ex>>> Derivatives;
  /// Memos of TreeSize and DifferentiationWork over all orders.
  ExMap<double> Tree;
  ExMap<double> Work;

  /// Strict symbol table: x, y, z, t, pi and the parameters.
  void DeclareSymbols(const std::vector<std::string>& parameterNames)
  {
    using namespace GiNaC;
    this->Symbols = { realsymbol("x"), realsymbol("y"), realsymbol("z"), realsymbol("t") };
    this->Table["x"] = this->Symbols[0];
    this->Table["y"] = this->Symbols[1];
    this->Table["z"] = this->Symbols[2];
    this->Table["t"] = this->Symbols[3];
    this->Table["pi"] = Pi;
    for (const std::string& name : parameterNames)
    {
      this->Symbols.push_back(realsymbol(name));
      this->Table[name] = this->Symbols.back();
    }
  }

  /// The steps computing the derivatives of order n, and their estimated work.
  std::vector<Step> PlanDerivatives(int n, double& estimate)
  {
    const std::vector<DerivativeIndex>& layout = Layout();
    std::vector<Step> steps;
    for (int s = 0; s < this->Sources; ++s)
    {
      this->CurrentSource = s;
      for (int d = FirstOffset(n); d < DerivativeLayout::OutputsPerSource(n); ++d)
      {
        const DerivativeIndex& index = layout[static_cast<std::size_t>(d)];
        // d_i f, d_j (d_i f), d_k (d_i d_j f): the lower derivative (the
        // first n - 1 indices) along the last index.
        const int last = n == 1 ? index.I : (n == 2 ? index.J : index.K);
        const int lower = DerivativeLayout::Offset(n - 1, index.I, index.J, index.K) -
          FirstOffset(n - 1);
        steps.push_back({ s, lower, last });
        estimate += DifferentiationWork(
          this->Derivatives[n - 1][s][static_cast<std::size_t>(lower)], this->Work);
      }
    }
    return steps;
  }

  static void CheckDifferentiationWork(int n, double estimate)
  {
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
  }

  /// Refuses derivatives of orders 1..n with too many distinct parts.
  void CheckDistinctParts(int n)
  {
    for (int s = 0; s < this->Sources; ++s)
    {
      for (const GiNaC::ex& e : this->Derivatives[n][s])
      {
        TreeSize(e, this->Tree);
      }
    }
    if (this->Tree.size() > MaximumDerivativeNodes)
    {
      throw ExpressionError(0,
        "the expressions are too complex: their derivatives of order " + std::to_string(n) +
          " have more than " + std::to_string(MaximumDerivativeNodes) +
          " distinct parts; simplify them or use a built-in provider");
    }
  }

  /// Which sources depend on t and on each parameter.
  void FindDependencies(ExpressionGraph& graph) const
  {
    graph.Time = false;
    graph.Parameters.assign(this->ParameterCount, false);
    for (int s = 0; s < this->Sources; ++s)
    {
      const GiNaC::ex& f = this->Derivatives[0][s][0];
      graph.Time = graph.Time || f.has(this->Symbols[3]);
      for (std::size_t q = 0; q < this->ParameterCount; ++q)
      {
        graph.Parameters[q] = graph.Parameters[q] || f.has(this->Symbols[4 + q]);
      }
    }
  }
};
} // namespace

ExpressionGraph BuildExpressionGraph(const std::vector<std::string>& canonicalSources,
  const std::vector<std::string>& parameterNames, int order)
{
  const std::lock_guard<std::mutex> lock(GinacMutex());
  int currentSource = -1;
  try
  {
    SymbolicStage stage(parameterNames, currentSource);
    stage.Read(canonicalSources);
    for (int n = 1; n <= order; ++n)
    {
      stage.Differentiate(n);
    }
    return stage.Compile();
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
}
} // namespace expression
} // namespace riemann
