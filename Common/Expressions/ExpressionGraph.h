/**
 * @file ExpressionGraph.h
 * @brief Private to Common/Metric (not installed): the expression graph, the
 * form every stage of the expression compiler (CompiledExpressions,
 * Expression.h) shares. The stages, one file each:
 *
 *   ExpressionParser.cxx       syntax check, canonical text (no GiNaC)
 *   ExpressionGinac.cxx        GiNaC: read, differentiate, translate into the
 *                              graph (the only file that includes GiNaC)
 *   ExpressionGraph.cxx        the graph: hash-consed nodes, sums, products
 *   ExpressionTape.cxx         graph -> CPU tape (schedule, fusion, registers)
 *   ExpressionInterpreter.cxx  runs the tape (CompiledExpressions::Evaluate)
 *   ExpressionGlsl.cxx         graph -> GLSL (CompiledExpressions::EmitGlsl)
 *   Expression.cxx             CompiledExpressions: the stages in order
 *
 * No GiNaC type appears here: the graph is plain data.
 */
#ifndef RiemannExpressionGraph_h
#define RiemannExpressionGraph_h

#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace riemann
{
namespace expression
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
inline double Sign(double u)
{
  return u > 0.0 ? 1.0 : (u < 0.0 ? -1.0 : (u == 0.0 ? 0.0 : u));
}

/// The value of a one-argument operation (constant folding); NaN for others.
double ApplyUnary(Op op, double a);

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

// --- Output layout (Expression.h) ---------------------------------------------
/// (n, i, j, k) in layout order for each order.
struct DerivativeIndex
{
  int N, I, J, K;
};

/// Offset of the first derivative of order n in a source's block.
int FirstOffset(int n);

/// The 20 derivatives of order 0..3 in layout order.
const std::vector<DerivativeIndex>& Layout();

/// Derivative order of output o when each source owns `perSource` outputs.
inline int OutputOrder(std::size_t o, int perSource)
{
  return Layout()[o % static_cast<std::size_t>(perSource)].N;
}

// --- The graph and how it is built --------------------------------------------
/// What the symbolic stage hands on: the graph, its outputs and what the
/// sources depend on.
struct ExpressionGraph
{
  /// Inputs first (x, y, z, t, parameters), operands before their users.
  std::vector<Node> Nodes;
  /// Output o (CPU layout) = Outputs[o].
  std::vector<Ref> Outputs;
  /// A source depends on t.
  bool Time = false;
  /// A source depends on parameter q.
  std::vector<bool> Parameters;
  /// Nodes of the outputs' expression trees (Statistics::TreeNodes).
  double TreeNodes = 0.0;
};

/**
 * Parse the canonical sources (CheckExpressionSyntax's output), differentiate
 * them up to `order` and compile them into a graph (ExpressionGinac.cxx, the
 * GiNaC stage). Throws ExpressionError.
 */
ExpressionGraph BuildExpressionGraph(const std::vector<std::string>& canonicalSources,
  const std::vector<std::string>& parameterNames, int order);

/**
 * Adds nodes to a graph, each distinct node once (hash-consed by operation,
 * operands and coefficients), with constant factors kept out of the nodes
 * (Ref). Throws ExpressionError naming Source when the graph grows too large.
 */
class GraphBuilder
{
public:
  /// Starts the graph with `inputs` Input nodes.
  explicit GraphBuilder(int inputs);

  std::vector<Node> Nodes;
  /// The source being compiled, for error messages.
  int Source = -1;

  static Ref Constant(double v) { return Ref{ -1, v }; }

  /// A node holding the value of r.
  int Materialize(const Ref& r);
  /// The node `node` (operands of sums and products sorted), added if new.
  int Emit(Node node);
  int EmitUnary(Op op, int a);
  int EmitBinary(Op op, int a, int b);
  /// c0 + sum c_i node[i], normalised so that the first coefficient is 1.
  Ref MakeLin(double c0, std::vector<std::pair<int, double>> terms);
  /// coefficient * prod numerator / prod denominator.
  Ref MakeProduct(double coefficient, std::vector<int> numerator, std::vector<int> denominator);
  /// a * b.
  Ref MakeProduct(const Ref& a, const Ref& b);

  [[noreturn]] void Fail(const std::string& cause) const;

private:
  std::unordered_map<std::string, int> Keys;
};
} // namespace expression
} // namespace riemann

#endif
