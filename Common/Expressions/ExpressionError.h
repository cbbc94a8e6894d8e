/**
 * @class riemann::ExpressionError
 * @brief The error of every stage of the expression compiler (parser,
 * GiNaC, tape): what cannot be used, and where.
 */
#ifndef RiemannExpressionError_h
#define RiemannExpressionError_h

#include "RiemannCommonExpressionsExport.h"

#include <stdexcept>
#include <string>

namespace riemann
{
/**
 * An expression (or a parameter name) that cannot be used. what() is
 * "column C: cause" (C the 1-based column, in characters, in the expression's
 * own string) or the cause alone; callers prefix the JSON path, e.g.
 * `metric.phi[1]: column 7: unknown symbol "w"; ...`.
 */
class RIEMANNCOMMONEXPRESSIONS_EXPORT ExpressionError : public std::runtime_error
{
public:
  /// A cause without position.
  explicit ExpressionError(const std::string& cause);
  ExpressionError(int column, const std::string& cause, int source = -1, int parameter = -1);

  /// 1-based column of the offending text in its source string; 0: no position.
  int Column = 0;
  /// Index of the offending source (CompiledExpressions' `sources`), or -1.
  int Source = -1;
  /// Index of the offending parameter name, or -1.
  int Parameter = -1;
  /// The cause alone, without "column C: ".
  std::string Cause;
};
} // namespace riemann

#endif
