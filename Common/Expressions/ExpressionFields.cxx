#include "ExpressionFields.h"

#include "Expression.h"

#include <algorithm>
#include <array>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace riemann
{
namespace
{
/// Outputs of at most 6 sources to third order (6 x 20) fit on the stack.
constexpr int MaximumOutputs = 128;
using OutputBuffer = std::array<double, MaximumOutputs>;

/**
 * Compile, or reuse a compiled tape for the same sources, parameter names and
 * order: parameter values and t are inputs of the tape, so a definition
 * re-read with new values (an animation frame, an edited amplitude) costs no
 * GiNaC work. Entries live as long as some field uses them.
 */
std::shared_ptr<const CompiledExpressions> Compile(
  const std::vector<std::string>& sources, const ExpressionInputs& inputs, int order)
{
  using Key = std::tuple<std::vector<std::string>, std::vector<std::string>, int>;
  static std::mutex mutex;
  static std::map<Key, std::weak_ptr<const CompiledExpressions>> cache;
  const Key key(sources, inputs.ParameterNames, order);
  {
    const std::lock_guard<std::mutex> lock(mutex);
    const auto found = cache.find(key);
    if (found != cache.end())
    {
      if (auto compiled = found->second.lock())
      {
        return compiled;
      }
      cache.erase(found);
    }
  }
  auto compiled =
    std::make_shared<const CompiledExpressions>(sources, inputs.ParameterNames, order);
  if (compiled->GetNumberOfOutputs() > MaximumOutputs)
  {
    throw std::logic_error("too many expression outputs for the field buffers");
  }
  const std::lock_guard<std::mutex> lock(mutex);
  for (auto it = cache.begin(); it != cache.end();)
  {
    it = it->second.expired() ? cache.erase(it) : std::next(it);
  }
  cache[key] = compiled;
  return compiled;
}

/// Evaluate the outputs up to derivative order `order` only (the tape's tail is skipped).
void Run(const CompiledExpressions& compiled, const ExpressionInputs& inputs, const Vec3& p,
  int order, OutputBuffer& out)
{
  compiled.Evaluate(p.data(), inputs.Time, inputs.ParameterValues.data(), out.data(),
    std::min(order, compiled.GetOrder()));
}

/// GLSL for a symmetric 3x3 matrix from the six second-order outputs at `base`.
std::string SymmetricFromOutputs(const std::string& o, int base)
{
  auto at = [&](int offset) { return o + "[" + std::to_string(base + offset) + "]"; };
  // Offsets xx, xy, xz, yy, yz, zz = 0..5 (Expression.h's layout).
  return "mat3(" + at(0) + ", " + at(1) + ", " + at(2) + ", " + at(1) + ", " + at(3) + ", " +
    at(4) + ", " + at(2) + ", " + at(4) + ", " + at(5) + ")";
}

/// The uniforms of the parameters and of t, declared for one expression set.
std::pair<std::vector<std::string>, std::string> DeclareInputs(
  GlslBuilder& builder, const ExpressionInputs& inputs)
{
  std::vector<std::string> parameters;
  for (size_t i = 0; i < inputs.ParameterNames.size(); ++i)
  {
    parameters.push_back(builder.AddUniform(
      "parameter_" + inputs.ParameterNames[i] + "_", "float", { inputs.ParameterValues[i] }));
  }
  const std::string time = builder.AddUniform("time", "float", { inputs.Time });
  return { parameters, time };
}

void AppendGrid(std::vector<Vec3>& points)
{
  constexpr int n = 9;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int k = 0; k < n; ++k)
      {
        points.push_back(Vec3(i, j, k) - Vec3::Constant(4.0));
      }
    }
  }
}

std::string Joined(const std::vector<std::string>& sources)
{
  std::string text;
  for (size_t i = 0; i < sources.size(); ++i)
  {
    text += (i ? ", \"" : "\"") + sources[i] + "\"";
  }
  return text;
}
} // namespace

//------------------------------------------------------------------------------
ExpressionScalarField::ExpressionScalarField(
  const std::string& source, const ExpressionInputs& inputs)
  : Source(source)
  , Inputs(inputs)
  , Compiled(Compile({ source }, inputs, ThirdDerivatives))
{
}

ExpressionScalarField::~ExpressionScalarField() = default;

void ExpressionScalarField::Accumulate(const Vec3& p, int order, ScalarJet& jet) const
{
  OutputBuffer out;
  Run(*this->Compiled, this->Inputs, p, order, out);
  const CompiledExpressions& c = *this->Compiled;
  jet.Value += out[c.OutputIndex(0, 0)];
  for (int i = 0; i < 3 && order >= FirstDerivatives; ++i)
  {
    jet.Gradient[i] += out[c.OutputIndex(0, 1, i)];
    for (int j = 0; j < 3 && order >= SecondDerivatives; ++j)
    {
      jet.Hessian(i, j) += out[c.OutputIndex(0, 2, i, j)];
      for (int k = 0; k < 3 && order >= ThirdDerivatives; ++k)
      {
        jet.Third[i](j, k) += out[c.OutputIndex(0, 3, i, j, k)];
      }
    }
  }
}

void ExpressionScalarField::AccumulatePacket(
  const PacketVec3& p, int order, PacketScalarJet& jet, LaneMask lanes) const
{
  const CompiledExpressions& c = *this->Compiled;
  if (order > c.GetOrder())
  {
    // Not compiled that far: the scalar path (which says what it can do).
    ScalarField::AccumulatePacket(p, order, jet, lanes);
    return;
  }
  // One source compiled to third order: 20 outputs (OutputsPerSource(3)),
  // of which those up to `order` are written.
  alignas(64) double out[20 * PacketWidth];
  c.EvaluatePacket(
    p, this->Inputs.Time, this->Inputs.ParameterValues.data(), out, std::min(order, c.GetOrder()));
  auto outputLanes = [&](int index) { return out + index * PacketWidth; };
  for (int l = 0; l < PacketWidth; ++l)
  {
    jet.Value[l] += outputLanes(c.OutputIndex(0, 0))[l];
  }
  for (int i = 0; i < 3 && order >= FirstDerivatives; ++i)
  {
    const double* gradient = outputLanes(c.OutputIndex(0, 1, i));
    for (int l = 0; l < PacketWidth; ++l)
    {
      jet.Gradient[i][l] += gradient[l];
    }
  }
  if (order >= SecondDerivatives)
  {
    const int rows[6] = { 0, 1, 2, 0, 0, 1 };
    const int columns[6] = { 0, 1, 2, 1, 2, 2 }; // XX YY ZZ XY XZ YZ
    for (int e = 0; e < 6; ++e)
    {
      const double* entry = outputLanes(c.OutputIndex(0, 2, rows[e], columns[e]));
      for (int l = 0; l < PacketWidth; ++l)
      {
        jet.Hessian.C[e][l] += entry[l];
      }
    }
  }
  if (order >= ThirdDerivatives)
  {
    for (int e = 0; e < 10; ++e)
    {
      const int(&i)[3] = ThirdEntryIndices[e];
      const double* entry = outputLanes(c.OutputIndex(0, 3, i[0], i[1], i[2]));
      for (int l = 0; l < PacketWidth; ++l)
      {
        jet.Third[e][l] += entry[l];
      }
    }
  }
}

std::string ExpressionScalarField::Describe() const
{
  return "\"" + this->Source + "\"";
}

std::string ExpressionScalarField::EmitGlsl(GlslBuilder& builder) const
{
  const auto [parameters, time] = DeclareInputs(builder, this->Inputs);
  const std::string expression =
    this->Compiled->EmitGlsl(builder, parameters, time, SecondDerivatives);
  const std::string name = builder.NewName("typed_field");
  builder.AddFunction("void " + name +
    "(vec3 p, inout float f, inout vec3 grad, inout mat3 hess)\n"
    "{\n"
    "  float o[10];\n"
    "  " +
    expression +
    "(p, o);\n"
    "  f += o[0];\n"
    "  grad += vec3(o[1], o[2], o[3]);\n"
    "  hess += " +
    SymmetricFromOutputs("o", 4) +
    ";\n"
    "}\n");
  return name;
}

void ExpressionScalarField::AppendSamplePoints(std::vector<Vec3>& points) const
{
  AppendGrid(points);
}

//------------------------------------------------------------------------------
ExpressionMap::ExpressionMap(
  const std::vector<std::string>& sources, const ExpressionInputs& inputs)
  : Sources(sources)
  , Inputs(inputs)
  , Compiled(Compile(sources, inputs, ThirdDerivatives))
{
  if (sources.size() != 3)
  {
    throw ExpressionError("Phi needs 3 components, got " + std::to_string(sources.size()));
  }
}

ExpressionMap::~ExpressionMap() = default;

void ExpressionMap::Evaluate(const Vec3& p, int order, VectorJet& jet) const
{
  OutputBuffer out;
  Run(*this->Compiled, this->Inputs, p, order, out);
  const CompiledExpressions& c = *this->Compiled;
  for (int s = 0; s < 3; ++s)
  {
    jet.Value[s] = out[c.OutputIndex(s, 0)];
    for (int i = 0; i < 3 && order >= FirstDerivatives; ++i)
    {
      jet.Jacobian(s, i) = out[c.OutputIndex(s, 1, i)];
      for (int j = 0; j < 3 && order >= SecondDerivatives; ++j)
      {
        jet.Hessian[s](i, j) = out[c.OutputIndex(s, 2, i, j)];
        for (int k = 0; k < 3 && order >= ThirdDerivatives; ++k)
        {
          jet.Third[s][i](j, k) = out[c.OutputIndex(s, 3, i, j, k)];
        }
      }
    }
  }
}

std::string ExpressionMap::Describe() const
{
  return "phi(" + Joined(this->Sources) + ")";
}

std::string ExpressionMap::EmitGlsl(GlslBuilder& builder) const
{
  // Stride 10 per component: value, gradient (1..3), Hessian (4..9).
  const auto [parameters, time] = DeclareInputs(builder, this->Inputs);
  const std::string expression =
    this->Compiled->EmitGlsl(builder, parameters, time, SecondDerivatives);
  const std::string name = builder.NewName("typed_map");
  builder.AddFunction("void " + name +
    "(vec3 p, out vec3 y, out mat3 J, out mat3 H0, out mat3 H1, out mat3 H2)\n"
    "{\n"
    "  float o[30];\n"
    "  " +
    expression +
    "(p, o);\n"
    "  y = vec3(o[0], o[10], o[20]);\n"
    "  // Column i of J is d_i Phi.\n"
    "  J = mat3(o[1], o[11], o[21], o[2], o[12], o[22], o[3], o[13], o[23]);\n"
    "  H0 = " +
    SymmetricFromOutputs("o", 4) +
    ";\n"
    "  H1 = " +
    SymmetricFromOutputs("o", 14) +
    ";\n"
    "  H2 = " +
    SymmetricFromOutputs("o", 24) +
    ";\n"
    "}\n");
  return name;
}

void ExpressionMap::AppendSamplePoints(std::vector<Vec3>& points) const
{
  AppendGrid(points);
}

//------------------------------------------------------------------------------
namespace
{
/// The six independent components of a symmetric 3x3 array, row-major upper triangle.
std::vector<std::string> UpperTriangle(const std::vector<std::string>& components)
{
  if (components.size() != 9)
  {
    throw ExpressionError("g needs 3x3 components, got " + std::to_string(components.size()));
  }
  return { components[0], components[1], components[2], components[4], components[5],
    components[8] };
}

/// Source index of g_ij in the upper triangle.
int Upper(int i, int j)
{
  static const int index[3][3] = { { 0, 1, 2 }, { 1, 3, 4 }, { 2, 4, 5 } };
  return index[i][j];
}
}

ExpressionTensorField::ExpressionTensorField(
  const std::vector<std::string>& components, const ExpressionInputs& inputs)
  : Components(components)
  , Inputs(inputs)
  , Compiled(Compile(UpperTriangle(components), inputs, SecondDerivatives))
{
}

ExpressionTensorField::~ExpressionTensorField() = default;

void ExpressionTensorField::Evaluate(
  const Vec3& p, bool withDerivatives, Mat3& g, Mat3Stack& dg) const
{
  OutputBuffer out;
  Run(*this->Compiled, this->Inputs, p, withDerivatives ? 1 : 0, out);
  const CompiledExpressions& c = *this->Compiled;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      g(i, j) = out[c.OutputIndex(Upper(i, j), 0)];
      for (int k = 0; k < 3 && withDerivatives; ++k)
      {
        dg[k](i, j) = out[c.OutputIndex(Upper(i, j), 1, k)];
      }
    }
  }
}

bool ExpressionTensorField::EvaluateSecond(
  const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const
{
  OutputBuffer out;
  Run(*this->Compiled, this->Inputs, p, SecondDerivatives, out);
  const CompiledExpressions& c = *this->Compiled;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      const int source = Upper(i, j);
      g(i, j) = out[c.OutputIndex(source, 0)];
      for (int k = 0; k < 3; ++k)
      {
        dg[k](i, j) = out[c.OutputIndex(source, 1, k)];
        for (int l = 0; l < 3; ++l)
        {
          d2g[k][l](i, j) = out[c.OutputIndex(source, 2, k, l)];
        }
      }
    }
  }
  return true;
}

LaneMask ExpressionTensorField::EvaluateSecondPacket(
  const PacketVec3& x, PacketTensorJet& jet, LaneMask lanes) const
{
  const CompiledExpressions& c = *this->Compiled;
  // 6 sources compiled to second order: 6 x 10 outputs of PacketWidth lanes.
  alignas(64) double out[6 * 10 * PacketWidth];
  c.EvaluatePacket(
    x, this->Inputs.Time, this->Inputs.ParameterValues.data(), out, SecondDerivatives);
  auto outputLanes = [&](int index) { return out + index * PacketWidth; };
  for (int i = 0; i < 3; ++i)
  {
    for (int j = i; j < 3; ++j)
    {
      const int source = Upper(i, j);
      const int e = SymmetricEntryOf[i][j];
      std::copy_n(outputLanes(c.OutputIndex(source, 0)), PacketWidth, jet.G.C[e]);
      for (int k = 0; k < 3; ++k)
      {
        std::copy_n(outputLanes(c.OutputIndex(source, 1, k)), PacketWidth, jet.D[k].C[e]);
        for (int l = k; l < 3; ++l)
        {
          std::copy_n(outputLanes(c.OutputIndex(source, 2, k, l)), PacketWidth,
            jet.DD[SymmetricEntryOf[k][l]].C[e]);
        }
      }
    }
  }
  return lanes;
}

std::string ExpressionTensorField::Describe() const
{
  return "g(" + Joined(this->Components) + ")";
}

std::string ExpressionTensorField::EmitGlsl(GlslBuilder& builder) const
{
  // Stride 4 per component of the upper triangle: value, d/dx, d/dy, d/dz.
  const auto [parameters, time] = DeclareInputs(builder, this->Inputs);
  const std::string expression =
    this->Compiled->EmitGlsl(builder, parameters, time, FirstDerivatives);
  auto matrix = [](int offset)
  {
    std::string m = "mat3(";
    for (int column = 0; column < 3; ++column)
    {
      for (int row = 0; row < 3; ++row)
      {
        m +=
          (column || row ? ", o[" : "o[") + std::to_string(4 * Upper(row, column) + offset) + "]";
      }
    }
    return m + ")";
  };
  const std::string name = builder.NewName("typed_tensor");
  builder.AddFunction("void " + name +
    "(vec3 p, out mat3 g, out mat3 dg0, out mat3 dg1, out mat3 dg2)\n"
    "{\n"
    "  float o[24];\n"
    "  " +
    expression +
    "(p, o);\n"
    "  g = " +
    matrix(0) +
    ";\n"
    "  dg0 = " +
    matrix(1) +
    ";\n"
    "  dg1 = " +
    matrix(2) +
    ";\n"
    "  dg2 = " +
    matrix(3) +
    ";\n"
    "}\n");
  return name;
}

void ExpressionTensorField::AppendSamplePoints(std::vector<Vec3>& points) const
{
  AppendGrid(points);
}
} // namespace riemann
