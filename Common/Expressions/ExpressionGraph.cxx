// The expression graph (ExpressionGraph.h): the output layout, constant
// folding of one-argument operations, and GraphBuilder, which adds each
// distinct node once.
#include "ExpressionGraph.h"

#include "ExpressionError.h"

#include <algorithm>
#include <cmath>

namespace riemann
{
namespace expression
{
namespace
{
/// Instructions to compile at most (a guard against expression swell).
constexpr std::size_t MaximumNodes = 200000;

/// The key under which Emit finds an existing node equal to `node`.
std::string NodeKey(const Node& node)
{
  std::string key(1, static_cast<char>(node.Operation));
  auto append = [&key](const void* data, std::size_t size)
  { key.append(static_cast<const char*>(data), size); };
  for (int a : node.Args)
  {
    append(&a, sizeof a);
  }
  key += '|';
  for (double c : node.Coefficients)
  {
    append(&c, sizeof c);
  }
  append(&node.Constant, sizeof node.Constant);
  return key;
}

/// Sorts the operands of a sum (with their coefficients) or of a product.
void SortOperands(Node& node)
{
  if (node.Operation == Op::Lin)
  {
    std::vector<std::pair<int, double>> terms;
    for (std::size_t i = 0; i < node.Args.size(); ++i)
    {
      terms.emplace_back(node.Args[i], node.Coefficients[i]);
    }
    std::sort(terms.begin(), terms.end());
    for (std::size_t i = 0; i < terms.size(); ++i)
    {
      node.Args[i] = terms[i].first;
      node.Coefficients[i] = terms[i].second;
    }
  }
  else if (node.Operation == Op::Mul)
  {
    std::sort(node.Args.begin(), node.Args.end());
  }
}

/// Terms sorted by node, those of the same node added, zero ones dropped.
std::vector<std::pair<int, double>> MergedTerms(std::vector<std::pair<int, double>> terms)
{
  std::sort(terms.begin(), terms.end());
  std::vector<std::pair<int, double>> merged;
  for (const auto& t : terms)
  {
    if (!merged.empty() && merged.back().first == t.first)
    {
      merged.back().second += t.second;
    }
    else
    {
      merged.push_back(t);
    }
  }
  merged.erase(std::remove_if(merged.begin(), merged.end(),
                 [](const std::pair<int, double>& t) { return t.second == 0.0; }),
    merged.end());
  return merged;
}
} // namespace

double ApplyUnary(Op op, double a)
{
  switch (op)
  {
    case Op::Square:
      return a * a;
    case Op::Recip:
      return 1.0 / a;
    case Op::Sqrt:
      return std::sqrt(a);
    case Op::Exp:
      return std::exp(a);
    case Op::Log:
      return std::log(a);
    case Op::Sin:
      return std::sin(a);
    case Op::Cos:
      return std::cos(a);
    case Op::Tan:
      return std::tan(a);
    case Op::Sinh:
      return std::sinh(a);
    case Op::Cosh:
      return std::cosh(a);
    case Op::Tanh:
      return std::tanh(a);
    case Op::Atan:
      return std::atan(a);
    case Op::Abs:
      return std::fabs(a);
    case Op::Sign:
      return Sign(a);
    default:
      return std::nan("");
  }
}

int FirstOffset(int n)
{
  static const int first[4] = { 0, 1, 4, 10 };
  return first[n];
}

const std::vector<DerivativeIndex>& Layout()
{
  static const std::vector<DerivativeIndex> layout = []
  {
    std::vector<DerivativeIndex> l;
    l.push_back({ 0, 0, 0, 0 });
    for (int i = 0; i < 3; ++i)
    {
      l.push_back({ 1, i, 0, 0 });
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int j = i; j < 3; ++j)
      {
        l.push_back({ 2, i, j, 0 });
      }
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int j = i; j < 3; ++j)
      {
        for (int k = j; k < 3; ++k)
        {
          l.push_back({ 3, i, j, k });
        }
      }
    }
    return l;
  }();
  return layout;
}

GraphBuilder::GraphBuilder(int inputs)
{
  for (int i = 0; i < inputs; ++i)
  {
    Node input;
    input.Operation = Op::Input;
    input.Constant = static_cast<double>(i);
    this->Nodes.push_back(input);
  }
}

void GraphBuilder::Fail(const std::string& cause) const
{
  throw ExpressionError(0, cause, this->Source);
}

int GraphBuilder::Materialize(const Ref& r)
{
  if (r.Id < 0)
  {
    Node c;
    c.Operation = Op::Const;
    c.Constant = r.Scale;
    return this->Emit(std::move(c));
  }
  if (r.Scale == 1.0)
  {
    return r.Id;
  }
  Node lin;
  lin.Operation = Op::Lin;
  if (this->Nodes[r.Id].Operation == Op::Lin)
  {
    lin = this->Nodes[r.Id];
    lin.Constant *= r.Scale;
    for (double& c : lin.Coefficients)
    {
      c *= r.Scale;
    }
  }
  else
  {
    lin.Args = { r.Id };
    lin.Coefficients = { r.Scale };
  }
  return this->Emit(std::move(lin));
}

int GraphBuilder::Emit(Node node)
{
  SortOperands(node);
  std::string key = NodeKey(node);
  const auto it = this->Keys.find(key);
  if (it != this->Keys.end())
  {
    return it->second;
  }
  if (this->Nodes.size() >= MaximumNodes)
  {
    this->Fail("the expressions are too complex: their derivatives need more than " +
      std::to_string(MaximumNodes) + " operations");
  }
  this->Nodes.push_back(std::move(node));
  const int id = static_cast<int>(this->Nodes.size()) - 1;
  this->Keys.emplace(std::move(key), id);
  return id;
}

int GraphBuilder::EmitUnary(Op op, int a)
{
  Node n;
  n.Operation = op;
  n.Args = { a };
  return this->Emit(std::move(n));
}

int GraphBuilder::EmitBinary(Op op, int a, int b)
{
  Node n;
  n.Operation = op;
  n.Args = { a, b };
  return this->Emit(std::move(n));
}

Ref GraphBuilder::MakeLin(double c0, std::vector<std::pair<int, double>> terms)
{
  const std::vector<std::pair<int, double>> merged = MergedTerms(std::move(terms));
  if (merged.empty())
  {
    return Constant(c0);
  }
  const double k = merged.front().second;
  if (merged.size() == 1 && c0 == 0.0)
  {
    return Ref{ merged.front().first, k };
  }
  Node lin;
  lin.Operation = Op::Lin;
  lin.Constant = c0 / k;
  for (const auto& t : merged)
  {
    lin.Args.push_back(t.first);
    lin.Coefficients.push_back(t.second / k);
  }
  return Ref{ this->Emit(std::move(lin)), k };
}

Ref GraphBuilder::MakeProduct(
  double coefficient, std::vector<int> numerator, std::vector<int> denominator)
{
  if (coefficient == 0.0)
  {
    return Constant(0.0);
  }
  auto product = [this](std::vector<int>& ids)
  {
    if (ids.size() == 1)
    {
      return ids.front();
    }
    Node mul;
    mul.Operation = Op::Mul;
    mul.Args = ids;
    return this->Emit(std::move(mul));
  };
  if (denominator.empty())
  {
    if (numerator.empty())
    {
      return Constant(coefficient);
    }
    return Ref{ product(numerator), coefficient };
  }
  const int d = product(denominator);
  if (numerator.empty())
  {
    return Ref{ this->EmitUnary(Op::Recip, d), coefficient };
  }
  return Ref{ this->EmitBinary(Op::Div, product(numerator), d), coefficient };
}

Ref GraphBuilder::MakeProduct(const Ref& a, const Ref& b)
{
  std::vector<int> numerator;
  for (const Ref& r : { a, b })
  {
    if (r.Id >= 0)
    {
      numerator.push_back(r.Id);
    }
  }
  return this->MakeProduct(a.Scale * b.Scale, std::move(numerator), {});
}
} // namespace expression
} // namespace riemann
