/**
 * @class riemann::CompiledExpressions
 * @brief User-typed expressions (f, the components of Phi, n, g_ij) in x, y,
 * z, the time t and named parameters, differentiated symbolically and
 * compiled into one fast evaluator.
 *
 * Construction (the only place GiNaC is used):
 *  1. each source is checked and rewritten by CheckExpressionSyntax
 *     (ExpressionParser.h: columns and causes of mistakes), then read by
 *     GiNaC's parser (strict symbol table: x, y, z, t, pi, the parameters;
 *     a function table holding exactly SupportedExpressionFunctions());
 *  2. GiNaC differentiates every source up to `order` (0..3) in x, y, z;
 *  3. the GiNaC expression DAGs of all outputs are compiled into one
 *     instruction tape. Identical subexpressions (GiNaC structure, and again
 *     after compilation) are computed once; constant factors are kept out of
 *     the tape (2 - 4x and x - 1/2 share one instruction); integer powers
 *     become multiplications, half-integer ones square roots.
 *
 * Evaluation runs the tape: no allocation (registers on the stack, or a
 * thread_local buffer for very large tapes), no GiNaC, no shared mutable
 * state, so one object may be evaluated from many threads at once.
 *
 * GiNaC itself is not thread-safe (reference counts, global tables):
 * constructions are serialised by a process-wide mutex.
 *
 * `abs` is differentiated as d|u| = sign(u) du (sign(0) = 0), not as GiNaC's
 * u du / |u| (NaN at u = 0); sign has derivative 0.
 *
 * Output layout (CPU and GLSL alike), source-major: source s owns the block
 * [s * OutputsPerSource(order), (s + 1) * OutputsPerSource(order)) holding
 *
 *   offset 0        value
 *   offsets 1..3    d/dx, d/dy, d/dz                       (order >= 1)
 *   offsets 4..9    xx, xy, xz, yy, yz, zz                  (order >= 2)
 *   offsets 10..19  xxx, xxy, xxz, xyy, xyz, xzz, yyy, yyz, yzz, zzz (order 3)
 *
 * i.e. DerivativeOffset(n, i, j, k) with sorted indices. OutputsPerSource is
 * 1, 4, 10, 20 for orders 0..3. The block of a lower order is a prefix of the
 * block of a higher one; EmitGlsl(.., maxOrder) uses the stride
 * OutputsPerSource(maxOrder).
 */
#ifndef RiemannExpression_h
#define RiemannExpression_h

#include "DerivativeLayout.h"
#include "ExpressionError.h"
#include "GlslSource.h"
#include "RiemannCommonExpressionsExport.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace riemann
{
struct PacketVec3;

class RIEMANNCOMMONEXPRESSIONS_EXPORT CompiledExpressions
{
public:
  /**
   * Parse, differentiate up to `order` (0..3) and compile. Throws
   * ExpressionError: Column and Source for a mistake in one source,
   * Parameter for a bad parameter name, neither for problems of the whole
   * (an expression too large to differentiate, a complex constant, ...).
   */
  CompiledExpressions(const std::vector<std::string>& sources,
    const std::vector<std::string>& parameterNames, int order);
  ~CompiledExpressions();
  CompiledExpressions(const CompiledExpressions&) = delete;
  CompiledExpressions& operator=(const CompiledExpressions&) = delete;

  int GetNumberOfSources() const { return this->Sources; }
  int GetOrder() const { return this->Order; }
  int GetNumberOfParameters() const;
  const std::vector<std::string>& GetParameterNames() const;
  /// NumberOfSources * OutputsPerSource(order).
  int GetNumberOfOutputs() const { return this->Sources * this->Stride; }

  /// 1, 4, 10, 20 for order 0..3; throws std::out_of_range otherwise.
  static int OutputsPerSource(int order);
  /**
   * Offset within a source's block of d^n / dx_i dx_j dx_k (the first n of
   * i, j, k, each 0..2, in any order; n = 0: the value). Inline and cheap
   * (callers index outputs in their inner loops); throws std::out_of_range
   * for indices out of range.
   */
  static int DerivativeOffset(int n, int i = 0, int j = 0, int k = 0);
  /// source * OutputsPerSource(order) + DerivativeOffset(n, i, j, k); n <= order.
  int OutputIndex(int source, int n, int i = 0, int j = 0, int k = 0) const;

  /**
   * Evaluate every output at p, time t, with the parameter values (in the
   * order of parameterNames; may be null without parameters).
   */
  void Evaluate(const double p[3], double t, const double* parameters, double* outputs) const;
  /**
   * Evaluate only the outputs of derivative order <= maxOrder (others are
   * left untouched), running only the part of the tape they need.
   */
  void Evaluate(
    const double p[3], double t, const double* parameters, double* outputs, int maxOrder) const;
  /**
   * Evaluate at the PacketWidth points of a packet at once (Packet.h): output
   * o of lane l goes to outputs[o * PacketWidth + l] (any alignment). The tape runs once,
   * each instruction on every lane with SIMD (ExpressionPacketInterpreter.cxx);
   * results equal Evaluate()'s to rounding.
   */
  void EvaluatePacket(const PacketVec3& p, double t, const double* parameters, double* outputs,
    int maxOrder) const;

  /// True if a source depends on t (after GiNaC's simplification: t - t does not).
  bool DependsOnTime() const;
  /// True if a source depends on parameter q.
  bool DependsOnParameter(int q) const;

  /**
   * Emit into `builder` the GLSL function
   *
   *   void NAME(vec3 p, out float o[M])
   *
   * with M = NumberOfSources * OutputsPerSource(maxOrder) (maxOrder <=
   * GetOrder()), filling o in the layout above with stride
   * OutputsPerSource(maxOrder); returns NAME. Every temporary is a local
   * float, numbers are inline literals; parameter q is read from the uniform
   * named parameterUniforms[q] and t from timeUniform (the caller declares
   * them, e.g. with GlslBuilder::AddUniform; timeUniform may be empty when
   * !DependsOnTime()). The text depends only on the expressions, the names
   * and maxOrder: the same expressions with other parameter values give
   * byte-identical source. Throws std::invalid_argument on wrong names or
   * maxOrder, GlslUnsupportedError if a constant is not a finite float.
   */
  std::string EmitGlsl(GlslBuilder& builder, const std::vector<std::string>& parameterUniforms,
    const std::string& timeUniform, int maxOrder) const;

  /// Sizes of the compiled form (for tests, benchmarks and `riemann info`).
  struct Statistics
  {
    /// Instructions of the tape (computations, constant loads and stores).
    int Instructions = 0;
    /// Computations among them (the rest loads constants or stores outputs).
    int Operations = 0;
    /// Operands over all instructions (an n-ary sum of 8 terms counts 8).
    int Operands = 0;
    /// Size of the register file.
    int Registers = 0;
    /// Nodes of the outputs' expression trees, shared parts counted each
    /// time they occur: what evaluating each output separately would cost.
    double TreeNodes = 0.0;
  };
  Statistics GetStatistics() const;

private:

  struct Internals;
  std::unique_ptr<Internals> Internal;
  // Copies of the sizes for the inline index functions.
  int Sources = 0;
  int Order = 0;
  int Stride = 1;
};

inline int CompiledExpressions::OutputsPerSource(int order)
{
  return DerivativeLayout::OutputsPerSource(order);
}

inline int CompiledExpressions::DerivativeOffset(int n, int i, int j, int k)
{
  return DerivativeLayout::Offset(n, i, j, k);
}

inline int CompiledExpressions::OutputIndex(int source, int n, int i, int j, int k) const
{
  if (static_cast<unsigned>(source) >= static_cast<unsigned>(this->Sources) ||
    static_cast<unsigned>(n) > static_cast<unsigned>(this->Order))
  {
    DerivativeLayout::FailIndex(source, n, i, j, k);
  }
  return source * this->Stride + DerivativeOffset(n, i, j, k);
}
} // namespace riemann

#endif
