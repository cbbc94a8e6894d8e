/**
 * @file ExpressionInternals.h
 * @brief Private to Common/Metric (not installed): what a CompiledExpressions
 * (Expression.h) holds, shared by the files that implement it (Expression.cxx,
 * ExpressionInterpreter.cxx, ExpressionGlsl.cxx; the stages are listed in
 * ExpressionGraph.h).
 */
#ifndef RiemannExpressionInternals_h
#define RiemannExpressionInternals_h

#include "Expression.h"
#include "ExpressionGraph.h"
#include "ExpressionTape.h"

#include <string>
#include <vector>

namespace riemann
{
struct CompiledExpressions::Internals
{
  int Sources = 0;
  int Order = 0;
  std::vector<std::string> ParameterNames;
  /// The compiled DAG (for GLSL), its outputs and dependencies.
  expression::ExpressionGraph Graph;
  /// The CPU tape.
  expression::ExpressionTape Tape;

  int NumberOfInputs() const { return 4 + static_cast<int>(this->ParameterNames.size()); }
};
} // namespace riemann

#endif
