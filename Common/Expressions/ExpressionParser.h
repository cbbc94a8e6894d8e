/**
 * @file ExpressionParser.h
 * @brief Syntax of user-typed expressions (metric definitions' "f", "phi",
 * "n", "g"): checked here, with the column and cause of every mistake, before
 * GiNaC sees the text (CompiledExpressions, Expression.h).
 *
 * Grammar (conventional precedence, `^` right-associative and above unary
 * signs, so -x^2 = -(x^2), 2^3^2 = 2^9, x^-2*y = (x^-2)*y):
 *
 *   sum     := product (('+' | '-') product)*
 *   product := unary (('*' | '/') unary)*
 *   unary   := ('+' | '-') unary | power
 *   power   := primary ['^' unary]
 *   primary := number | name | name '(' sum (',' sum)* ')' | '(' sum ')'
 *   number  := digits ['.' digits] [('e' | 'E') ['+' | '-'] digits] | '.' digits [exponent]
 *
 * Names are the variables x, y, z, the time t, the constant pi and the
 * parameters; functions are those of SupportedExpressionFunctions().
 *
 * GiNaC's own parser reports no positions, treats `#` as a comment, accepts
 * lists `{...}` and its constants I, Pi, Euler, Catalan, refuses `a^b^c`, and
 * reads a sign after an operator as covering the rest of the expression
 * (`x^-2*y` as x^(-2*y)). This pass therefore also rewrites the expression
 * into a fully parenthesised text (numbers as exact rationals) that GiNaC
 * reads exactly as the grammar above says.
 */
#ifndef RiemannExpressionParser_h
#define RiemannExpressionParser_h

#include "ExpressionError.h"
#include "RiemannCommonExpressionsExport.h"

#include <cstddef>
#include <string>
#include <vector>

namespace riemann
{
/// Guards against text no person types, which could exhaust GiNaC's recursion.
constexpr std::size_t MaximumExpressionLength = 10000;
/// Nesting depth: parentheses, function calls, signs and exponents together.
constexpr int MaximumExpressionNesting = 100;
constexpr std::size_t MaximumExpressionParameters = 64;

/// Function names and their numbers of arguments, as typed by users.
struct ExpressionFunction
{
  const char* Name;
  int Arguments;
};
RIEMANNCOMMONEXPRESSIONS_EXPORT const std::vector<ExpressionFunction>& SupportedExpressionFunctions();

/**
 * Throw ExpressionError (Parameter set, Column 0) unless every name is an
 * identifier ([A-Za-z][A-Za-z0-9_]*) distinct from the others, from x, y, z, t,
 * pi, from the functions and from GiNaC's reserved I, Pi, Euler, Catalan.
 */
RIEMANNCOMMONEXPRESSIONS_EXPORT void CheckExpressionParameterNames(
  const std::vector<std::string>& parameterNames);

/**
 * Check `text` against the grammar, names, numbers of arguments, nesting,
 * and constant subexpressions (division by zero, sqrt(-1), exp(1000), powers
 * too large to compute exactly); throw ExpressionError (with Column) on the
 * first problem. Returns the fully parenthesised text for GiNaC's parser, in
 * which numbers are exact rationals (0.1 -> (1/10)) and `pi` stays `pi`.
 * Parameter names are assumed checked (CheckExpressionParameterNames).
 */
RIEMANNCOMMONEXPRESSIONS_EXPORT std::string CheckExpressionSyntax(
  const std::string& text, const std::vector<std::string>& parameterNames);
} // namespace riemann

#endif
