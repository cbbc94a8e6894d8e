#include "QuadraticField.h"

#include <sstream>

namespace riemann
{
QuadraticField::QuadraticField(const Mat3& matrix, const Vec3& linear, double constant)
  : Matrix(0.5 * (matrix + matrix.transpose()))
  , Linear(linear)
  , Constant(constant)
{
}

void QuadraticField::Accumulate(const Vec3& p, int order, ScalarJet& jet) const
{
  // The third derivatives are zero: nothing to add at that order.
  const Vec3 ap = this->Matrix * p;
  jet.Value += p.dot(ap) + this->Linear.dot(p) + this->Constant;
  if (order >= FirstDerivatives)
  {
    jet.Gradient += 2.0 * ap + this->Linear;
  }
  if (order >= SecondDerivatives)
  {
    jet.Hessian += 2.0 * this->Matrix;
  }
}

std::string QuadraticField::Describe() const
{
  std::ostringstream s;
  s << "quadratic(matrix [" << this->Matrix.row(0) << "; " << this->Matrix.row(1) << "; "
    << this->Matrix.row(2) << "], linear (" << this->Linear.transpose() << "), constant "
    << this->Constant << ")";
  return s.str();
}

void QuadraticField::AppendSamplePoints(std::vector<Vec3>& points) const
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

std::string QuadraticField::EmitGlsl(GlslBuilder& builder) const
{
  const Mat3& m = this->Matrix; // symmetric: row- and column-major agree
  const std::string a =
    builder.AddUniform("matrix", "mat3", std::vector<double>(m.data(), m.data() + 9));
  const std::string b =
    builder.AddUniform("linear", "vec3", { this->Linear[0], this->Linear[1], this->Linear[2] });
  const std::string c = builder.AddUniform("constant", "float", { this->Constant });
  const std::string name = builder.NewName("quadratic");
  builder.AddFunction("void " + name +
    "(vec3 p, inout float f, inout vec3 grad, inout mat3 hess)\n"
    "{\n"
    "  vec3 ap = " +
    a +
    " * p;\n"
    "  f += dot(p, ap) + dot(" +
    b + ", p) + " + c +
    ";\n"
    "  grad += 2.0 * ap + " +
    b +
    ";\n"
    "  hess += 2.0 * " +
    a +
    ";\n"
    "}\n");
  return name;
}

} // namespace riemann
