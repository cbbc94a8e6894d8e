/**
 * @class riemann::DerivativeLayout
 * @brief Where each derivative of an expression sits in a compiled
 * expression's outputs: per source, the value, then the 3 first, 6 second
 * and 10 third derivatives (symmetric: each set of indices once). Shared by
 * CompiledExpressions (Expression.h) and the compiler's stages.
 */
#ifndef RiemannDerivativeLayout_h
#define RiemannDerivativeLayout_h

#include "RiemannCommonExpressionsExport.h"

namespace riemann
{
struct RIEMANNCOMMONEXPRESSIONS_EXPORT DerivativeLayout
{
  /// 1, 4, 10, 20 for order 0..3; throws std::out_of_range otherwise.
  static int OutputsPerSource(int order);
  /**
   * Offset within a source's block of d^n / dx_i dx_j dx_k (the first n of
   * i, j, k, each 0..2, in any order; n = 0: the value). Inline and cheap
   * (callers index outputs in their inner loops); throws std::out_of_range
   * for indices out of range.
   */
  static int Offset(int n, int i = 0, int j = 0, int k = 0);
  /// Throw std::out_of_range naming the output asked for (source -1: any).
  [[noreturn]] static void FailIndex(int source, int n, int i, int j, int k);
};

inline int DerivativeLayout::Offset(int n, int i, int j, int k)
{
  // Symmetric tables: no sorting. Only the first n indices are checked.
  static constexpr signed char second[3][3] = { { 0, 1, 2 }, { 1, 3, 4 }, { 2, 4, 5 } };
  static constexpr signed char third[3][3][3] = { { { 0, 1, 2 }, { 1, 3, 4 }, { 2, 4, 5 } },
    { { 1, 3, 4 }, { 3, 6, 7 }, { 4, 7, 8 } }, { { 2, 4, 5 }, { 4, 7, 8 }, { 5, 8, 9 } } };
  const auto bad = [](int index) { return static_cast<unsigned>(index) > 2u; };
  switch (n)
  {
    case 0:
      return 0;
    case 1:
      if (bad(i))
      {
        break;
      }
      return 1 + i;
    case 2:
      if (bad(i) || bad(j))
      {
        break;
      }
      return 4 + second[i][j];
    case 3:
      if (bad(i) || bad(j) || bad(k))
      {
        break;
      }
      return 10 + third[i][j][k];
    default:
      break;
  }
  FailIndex(-1, n, i, j, k);
}
} // namespace riemann

#endif
