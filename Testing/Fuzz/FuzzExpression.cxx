// libFuzzer target: arbitrary text into the two parsers users type into,
// CompiledExpressions (Expression.h) and ParseMetricDefinition
// (MetricDefinition.h). Refusing the text with an exception derived from
// std::exception is the expected outcome for most inputs; crashes, hangs
// (libFuzzer's -timeout), leaks and sanitizer reports are failures.
//
// Input format for the expressions (any text is valid input):
//
//   [NAMES '|'] SOURCE [';' SOURCE [';' SOURCE]]
//
// NAMES is a comma-separated list of parameter names (the first four are
// used, whatever they are); the derivative order is the sum of the bytes
// modulo 4. The whole text is also given to ParseMetricDefinition as JSON.
#include "Expression.h"
#include "GlslSource.h"
#include "MetricDefinition.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
std::vector<std::string> Split(const std::string& text, char separator, std::size_t most)
{
  std::vector<std::string> parts;
  std::size_t begin = 0;
  while (parts.size() + 1 < most)
  {
    const std::size_t end = text.find(separator, begin);
    if (end == std::string::npos)
    {
      break;
    }
    parts.push_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  parts.push_back(text.substr(begin));
  return parts;
}

void Expressions(const std::string& text)
{
  std::vector<std::string> names;
  std::string rest = text;
  const std::size_t bar = text.find('|');
  if (bar != std::string::npos)
  {
    names = Split(text.substr(0, bar), ',', 4);
    rest = text.substr(bar + 1);
  }
  const std::vector<std::string> sources = Split(rest, ';', 3);
  unsigned sum = 0;
  for (unsigned char c : text)
  {
    sum += c;
  }
  const int order = static_cast<int>(sum % 4);
  try
  {
    const riemann::CompiledExpressions compiled(sources, names, order);
    // What the caller relies on: sizes, indices, evaluation at any point
    // (NaN and inf are legitimate values), every order prefix, GLSL.
    const int outputs = compiled.GetNumberOfOutputs();
    if (outputs !=
      compiled.GetNumberOfSources() * riemann::CompiledExpressions::OutputsPerSource(order))
    {
      __builtin_trap();
    }
    std::vector<double> out(static_cast<std::size_t>(outputs));
    const std::vector<double> parameters(names.size(), 0.5);
    const double points[4][3] = { { 0.1, -0.2, 0.3 }, { 0, 0, 0 }, { -1.5, 2.5, 1e3 },
      { 1e-300, -1e300, 7 } };
    for (const auto& p : points)
    {
      compiled.Evaluate(p, 0.25, parameters.data(), out.data());
      for (int n = 0; n <= order; ++n)
      {
        compiled.Evaluate(p, 0.25, parameters.data(), out.data(), n);
      }
    }
    for (int s = 0; s < compiled.GetNumberOfSources(); ++s)
    {
      for (int n = 0; n <= order; ++n)
      {
        const int index = compiled.OutputIndex(s, n, 2, 1, 0);
        if (index < 0 || index >= outputs)
        {
          __builtin_trap();
        }
      }
    }
    riemann::GlslBuilder builder;
    std::vector<std::string> uniforms;
    for (std::size_t q = 0; q < names.size(); ++q)
    {
      uniforms.push_back(builder.AddUniform("parameter", "float", { 0.5 }));
    }
    const std::string time = builder.AddUniform("time", "float", { 0.25 });
    try
    {
      compiled.EmitGlsl(builder, uniforms, time, order < 2 ? order : 2);
    }
    catch (const riemann::GlslUnsupportedError&)
    {
      // A constant beyond float range.
    }
  }
  catch (const riemann::ExpressionError&)
  {
  }
  catch (const std::exception&)
  {
    // Refused otherwise (GiNaC's exceptions are turned into ExpressionError;
    // this would be std::bad_alloc and the like).
  }
}

void Definition(const std::string& text)
{
  try
  {
    riemann::ParseMetricDefinition(text, 0.5);
  }
  catch (const riemann::MetricDefinitionError&)
  {
  }
  catch (const std::exception&)
  {
    // Other refusals (e.g. an ExpressionError the definition parser passes
    // on) are acceptable too; a crash is not.
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  Expressions(text);
  Definition(text);
  return 0;
}
