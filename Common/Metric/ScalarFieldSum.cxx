#include "ScalarFieldSum.h"

#include <sstream>

namespace riemann
{
ScalarFieldSum::ScalarFieldSum(
  double constant, std::vector<std::shared_ptr<const ScalarField>> terms)
  : Constant(constant)
  , Terms(std::move(terms))
{
}

void ScalarFieldSum::Accumulate(const Vec3& p, int order, ScalarJet& jet) const
{
  jet.Value += this->Constant;
  for (const auto& field : this->Terms)
  {
    field->Accumulate(p, order, jet);
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
} // namespace riemann
