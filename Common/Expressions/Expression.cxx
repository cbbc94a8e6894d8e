// CompiledExpressions (Expression.h): the expression compiler's stages in
// order (syntax, GiNaC, tape; see ExpressionGraph.h for the files), the
// output layout and the accessors. Evaluate is in ExpressionInterpreter.cxx,
// EmitGlsl in ExpressionGlsl.cxx.
#include "Expression.h"

#include "ExpressionInternals.h"
#include "ExpressionParser.h"

#include <stdexcept>

namespace riemann
{
namespace
{
constexpr int MaximumSources = 16;

/// Checks every source's syntax (no GiNaC, no lock): columns and causes.
/// Returns the canonical texts GiNaC reads.
std::vector<std::string> CheckSyntax(
  const std::vector<std::string>& sources, const std::vector<std::string>& parameterNames)
{
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
  return canonical;
}
} // namespace

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
  const std::vector<std::string> canonical = CheckSyntax(sources, parameterNames);
  m.Graph = expression::BuildExpressionGraph(canonical, parameterNames, order);
  m.Tape = expression::BuildExpressionTape(m.Graph, order, m.NumberOfInputs());
}

CompiledExpressions::~CompiledExpressions() = default;

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
  return this->Internal->Graph.Time;
}

bool CompiledExpressions::DependsOnParameter(int q) const
{
  const std::vector<bool>& parameters = this->Internal->Graph.Parameters;
  return q >= 0 && q < static_cast<int>(parameters.size()) &&
    parameters[static_cast<std::size_t>(q)];
}

CompiledExpressions::Statistics CompiledExpressions::GetStatistics() const
{
  const Internals& m = *this->Internal;
  Statistics s;
  s.Instructions = static_cast<int>(m.Tape.Instructions.size());
  s.Operations = m.Tape.Operations;
  s.Operands = expression::CountOperands(m.Tape);
  s.Registers = m.Tape.Registers;
  s.TreeNodes = m.Graph.TreeNodes;
  return s;
}
} // namespace riemann
