#include "ExpressionError.h"

namespace riemann
{
ExpressionError::ExpressionError(const std::string& cause)
  : ExpressionError(0, cause)
{
}

ExpressionError::ExpressionError(int column, const std::string& cause, int source, int parameter)
  : std::runtime_error(column > 0 ? "column " + std::to_string(column) + ": " + cause : cause)
  , Column(column)
  , Source(source)
  , Parameter(parameter)
  , Cause(cause)
{
}
} // namespace riemann
