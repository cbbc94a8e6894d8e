#include "ScalarFieldSum.h"

#include "GaussianField.h"

#include <sstream>

namespace riemann
{
ScalarFieldSum::ScalarFieldSum(
  double constant, std::vector<std::shared_ptr<const ScalarField>> terms)
  : Constant(constant)
  , Terms(std::move(terms))
{
  for (const auto& field : this->Terms)
  {
    if (const auto* bump = dynamic_cast<const GaussianField*>(field.get()))
    {
      this->Bumps.Add(bump->GetAmplitude(), bump->GetCenter(),
        bump->GetSigma().cwiseProduct(bump->GetSigma()).cwiseInverse());
    }
    else
    {
      this->OtherTerms.push_back(field.get());
    }
  }
}

void ScalarFieldSum::Accumulate(const Vec3& p, int order, ScalarJet& jet) const
{
  jet.Value += this->Constant;
  if (this->Bumps.Size() > 0) // a typed sum has none: skip the kernel's loads and stores
  {
    AccumulateGaussianTerms(this->Bumps, p, order, jet);
  }
  for (const ScalarField* field : this->OtherTerms)
  {
    field->Accumulate(p, order, jet);
  }
}

void ScalarFieldSum::AccumulatePacket(
  const PacketVec3& p, int order, PacketScalarJet& jet, LaneMask lanes) const
{
  for (double& value : jet.Value)
  {
    value += this->Constant;
  }
  if (this->Bumps.Size() > 0) // a typed sum has none: skip the kernel's loads and stores
  {
    AccumulateGaussianTerms(this->Bumps, p, order, jet);
  }
  for (const ScalarField* field : this->OtherTerms)
  {
    field->AccumulatePacket(p, order, jet, lanes);
  }
}

std::string ScalarFieldSum::Describe() const
{
  std::ostringstream s;
  if (this->Constant != 0.0 || this->Terms.empty())
  {
    s << this->Constant;
  }
  for (size_t i = 0; i < this->Terms.size(); ++i)
  {
    s << (i > 0 || this->Constant != 0.0 ? " + " : "") << this->Terms[i]->Describe();
  }
  return s.str();
}

void ScalarFieldSum::AppendSamplePoints(std::vector<Vec3>& points) const
{
  for (const auto& field : this->Terms)
  {
    field->AppendSamplePoints(points);
  }
}

std::string ScalarFieldSum::EmitGlsl(GlslBuilder& builder) const
{
  std::vector<std::string> terms;
  for (const auto& field : this->Terms)
  {
    terms.push_back(field->EmitGlsl(builder));
  }
  const std::string c = builder.AddUniform("constant", "float", { this->Constant });
  const std::string name = builder.NewName("sum");
  std::string code = "void " + name +
    "(vec3 p, inout float f, inout vec3 grad, inout mat3 hess)\n{\n  f += " + c + ";\n";
  for (const std::string& term : terms)
  {
    code += "  " + term + "(p, f, grad, hess);\n";
  }
  builder.AddFunction(code + "}\n");
  return name;
}

} // namespace riemann
