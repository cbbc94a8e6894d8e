// The GLSL emitter: CompiledExpressions::EmitGlsl writes the expression
// graph (ExpressionGraph.h) as one GLSL function, a local float per live node.
#include "Expression.h"
#include "ExpressionInternals.h"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace riemann
{
namespace expression
{
namespace
{
std::string GlslNumber(double v)
{
  if (!std::isfinite(v) || std::fabs(v) > static_cast<double>(FLT_MAX))
  {
    throw GlslUnsupportedError("the constant " + std::to_string(v) + " is not a finite float");
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", std::fabs(v));
  std::string s = buffer;
  if (s.find_first_of(".e") == std::string::npos)
  {
    s += ".0";
  }
  return v < 0.0 ? "(-" + s + ")" : s;
}

/// c * v, written v for c = 1 and -v for c = -1.
std::string Scaled(double c, const std::string& v)
{
  if (c == 1.0)
  {
    return v;
  }
  if (c == -1.0)
  {
    return "-" + v;
  }
  return GlslNumber(c) + " * " + v;
}

/// The GLSL function computing a one-argument operation; null for others.
const char* UnaryFunction(Op op)
{
  switch (op)
  {
    case Op::Sqrt:
      return "sqrt";
    case Op::Exp:
      return "exp";
    case Op::Log:
      return "log";
    case Op::Sin:
      return "sin";
    case Op::Cos:
      return "cos";
    case Op::Tan:
      return "tan";
    case Op::Sinh:
      return "sinh";
    case Op::Cosh:
      return "cosh";
    case Op::Tanh:
      return "tanh";
    case Op::Atan:
      return "atan";
    case Op::Abs:
      return "abs";
    case Op::Sign:
      return "sign";
    default:
      return nullptr;
  }
}

/// Nodes the outputs of derivative order <= maxOrder need.
std::vector<char> LiveNodes(const ExpressionGraph& graph, int perSource, int maxOrder)
{
  std::vector<char> live(graph.Nodes.size(), 0);
  for (std::size_t o = 0; o < graph.Outputs.size(); ++o)
  {
    if (OutputOrder(o, perSource) <= maxOrder && graph.Outputs[o].Id >= 0)
    {
      live[graph.Outputs[o].Id] = 1;
    }
  }
  for (std::size_t i = graph.Nodes.size(); i-- > 0;)
  {
    if (live[i])
    {
      for (int a : graph.Nodes[i].Args)
      {
        live[a] = 1;
      }
    }
  }
  return live;
}

/// Writes the graph's nodes and outputs as GLSL text.
class GlslWriter
{
public:
  GlslWriter(const ExpressionGraph& graph, int inputs,
    const std::vector<std::string>& parameterUniforms, const std::string& timeUniform)
    : Graph(graph)
    , Inputs(inputs)
    , Names(graph.Nodes.size())
  {
    this->Names[0] = "p.x";
    this->Names[1] = "p.y";
    this->Names[2] = "p.z";
    this->Names[3] = timeUniform;
    for (std::size_t q = 0; q < parameterUniforms.size(); ++q)
    {
      this->Names[4 + q] = parameterUniforms[q];
    }
  }

  /// void name(vec3 p, out float o[sources * OutputsPerSource(maxOrder)]).
  std::string Function(const std::string& name, int sources, int order, int maxOrder)
  {
    const int per = CompiledExpressions::OutputsPerSource(order);
    const int glslPer = CompiledExpressions::OutputsPerSource(maxOrder);
    std::string code =
      "void " + name + "(vec3 p, out float o[" + std::to_string(sources * glslPer) + "])\n{\n";
    code += this->Temporaries(LiveNodes(this->Graph, per, maxOrder));
    for (std::size_t o = 0; o < this->Graph.Outputs.size(); ++o)
    {
      const int d = static_cast<int>(o % static_cast<std::size_t>(per));
      if (OutputOrder(o, per) > maxOrder)
      {
        continue;
      }
      const int s = static_cast<int>(o / static_cast<std::size_t>(per));
      const Ref& r = this->Graph.Outputs[o];
      const std::string value =
        r.Id < 0 ? GlslNumber(r.Scale) : Scaled(r.Scale, this->Operand(r.Id));
      code += "  o[" + std::to_string(s * glslPer + d) + "] = " + value + ";\n";
    }
    return code + "}\n";
  }

private:
  const ExpressionGraph& Graph;
  const int Inputs;
  /// GLSL name of each node (inputs and temporaries).
  std::vector<std::string> Names;

  /// One local float v0, v1, ... per live node that is not a constant.
  std::string Temporaries(const std::vector<char>& live)
  {
    std::string code;
    int counter = 0;
    for (std::size_t i = static_cast<std::size_t>(this->Inputs); i < this->Graph.Nodes.size(); ++i)
    {
      const Node& node = this->Graph.Nodes[i];
      if (!live[i] || node.Operation == Op::Const)
      {
        continue;
      }
      this->Names[i] = "v" + std::to_string(counter++);
      const std::string value = this->Value(node);
      code += "  float " + this->Names[i] + " = " + value + ";\n";
    }
    return code;
  }

  /// A constant inline, else the node's name.
  std::string Operand(int id) const
  {
    if (this->Graph.Nodes[id].Operation == Op::Const)
    {
      return GlslNumber(this->Graph.Nodes[id].Constant);
    }
    return this->Names[id];
  }

  /// c0 + c1 a1 - c2 a2 ..., without zero constant and unit factors.
  std::string Sum(const Node& node) const
  {
    std::string value;
    bool first = true;
    if (node.Constant != 0.0)
    {
      value = GlslNumber(node.Constant);
      first = false;
    }
    for (std::size_t a = 0; a < node.Args.size(); ++a)
    {
      const double c = node.Coefficients[a];
      const std::string v = this->Operand(node.Args[a]);
      if (first)
      {
        value = Scaled(c, v);
        first = false;
      }
      else
      {
        value += (c < 0.0 ? " - " : " + ") + Scaled(std::fabs(c), v);
      }
    }
    return value;
  }

  /// The GLSL expression of a node's value.
  std::string Value(const Node& node) const
  {
    switch (node.Operation)
    {
      case Op::Lin:
        return this->Sum(node);
      case Op::Mul:
      {
        std::string value;
        for (std::size_t a = 0; a < node.Args.size(); ++a)
        {
          value += (a ? " * " : "") + this->Operand(node.Args[a]);
        }
        return value;
      }
      case Op::Div:
        return this->Operand(node.Args[0]) + " / " + this->Operand(node.Args[1]);
      case Op::Square:
        return this->Operand(node.Args[0]) + " * " + this->Operand(node.Args[0]);
      case Op::Recip:
        return "1.0 / " + this->Operand(node.Args[0]);
      case Op::Pow:
        return "pow(" + this->Operand(node.Args[0]) + ", " + this->Operand(node.Args[1]) + ")";
      case Op::Atan2:
        return "atan(" + this->Operand(node.Args[0]) + ", " + this->Operand(node.Args[1]) + ")";
      default:
        break;
    }
    const char* function = UnaryFunction(node.Operation);
    if (!function)
    {
      throw GlslUnsupportedError("internal error: unexpected operation in GLSL emission");
    }
    return std::string(function) + "(" + this->Operand(node.Args[0]) + ")";
  }
};
} // namespace
} // namespace expression

std::string CompiledExpressions::EmitGlsl(GlslBuilder& builder,
  const std::vector<std::string>& parameterUniforms, const std::string& timeUniform,
  int maxOrder) const
{
  const Internals& m = *this->Internal;
  if (maxOrder < 0 || maxOrder > m.Order)
  {
    throw std::invalid_argument("EmitGlsl: maxOrder " + std::to_string(maxOrder) +
      " is not in 0.." + std::to_string(m.Order));
  }
  if (parameterUniforms.size() != m.ParameterNames.size())
  {
    throw std::invalid_argument("EmitGlsl: " + std::to_string(parameterUniforms.size()) +
      " parameter uniforms for " + std::to_string(m.ParameterNames.size()) + " parameters");
  }
  if (m.Graph.Time && timeUniform.empty())
  {
    throw std::invalid_argument(
      "EmitGlsl: the expressions depend on t but no time uniform is given");
  }
  expression::GlslWriter writer(m.Graph, m.NumberOfInputs(), parameterUniforms, timeUniform);
  const std::string name = builder.NewName("expressions");
  builder.AddFunction(writer.Function(name, m.Sources, m.Order, maxOrder));
  return name;
}
} // namespace riemann
