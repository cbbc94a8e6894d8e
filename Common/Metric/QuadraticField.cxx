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
} // namespace riemann
