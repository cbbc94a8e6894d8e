#include "BumpTranslationMap.h"

#include "GaussianField.h"

#include <cmath>
#include <sstream>

namespace riemann
{
BumpTranslationMap::BumpTranslationMap(std::shared_ptr<const ScalarField> f, const Vec3& direction)
  : Field(std::move(f))
  , Matrix(Mat3::Zero())
  , Center(Vec3::Zero())
  , Offset(direction)
  , ConstantDirection(true)
{
}

BumpTranslationMap::BumpTranslationMap(
  std::shared_ptr<const ScalarField> f, const Mat3& matrix, const Vec3& center, const Vec3& offset)
  : Field(std::move(f))
  , Matrix(matrix)
  , Center(center)
  , Offset(offset)
  , ConstantDirection(matrix.isZero(0.0))
{
}

void BumpTranslationMap::Evaluate(const Vec3& p, int order, VectorJet& jet) const
{
  // Phi_s = p_s + f V_s with V linear (d_j V_s = A_sj), so
  //   d_i Phi_s       = delta_si + f_i V_s + f A_si
  //   d_i d_j Phi_s   = f_ij V_s + f_i A_sj + f_j A_si
  //   d_i d_j d_k Phi_s = f_ijk V_s + f_ij A_sk + f_ik A_sj + f_jk A_si
  ScalarJet f;
  this->Field->Evaluate(p, order, f);
  const Vec3 v = this->Matrix * (p - this->Center) + this->Offset;
  const Mat3& a = this->Matrix;
  jet.Value = p + f.Value * v;
  if (order >= FirstDerivatives)
  {
    jet.Jacobian = Mat3::Identity() + v * f.Gradient.transpose() + f.Value * a;
  }
  if (order >= SecondDerivatives)
  {
    for (int s = 0; s < 3; ++s)
    {
      jet.Hessian[s] = v[s] * f.Hessian;
      if (!this->ConstantDirection)
      {
        const Vec3 as = a.row(s).transpose();
        jet.Hessian[s] += f.Gradient * as.transpose() + as * f.Gradient.transpose();
      }
    }
  }
  if (order >= ThirdDerivatives)
  {
    for (int s = 0; s < 3; ++s)
    {
      for (int i = 0; i < 3; ++i)
      {
        jet.Third[s][i] = v[s] * f.Third[i];
        if (!this->ConstantDirection)
        {
          for (int j = 0; j < 3; ++j)
          {
            for (int k = 0; k < 3; ++k)
            {
              jet.Third[s][i](j, k) +=
                f.Hessian(i, j) * a(s, k) + f.Hessian(i, k) * a(s, j) + f.Hessian(j, k) * a(s, i);
            }
          }
        }
      }
    }
  }
}

std::string BumpTranslationMap::Describe() const
{
  std::ostringstream s;
  s << "bump(" << this->Field->Describe();
  if (this->ConstantDirection)
  {
    s << ", direction (" << this->Offset.transpose() << "))";
  }
  else
  {
    s << ", field A (p - (" << this->Center.transpose() << ")) + (" << this->Offset.transpose()
      << "))";
  }
  return s.str();
}

std::string BumpTranslationMap::CheckDiffeomorphism() const
{
  const auto* gaussian = dynamic_cast<const GaussianField*>(this->Field.get());
  if (!gaussian || !this->ConstantDirection)
  {
    return this->SpaceMap::CheckDiffeomorphism();
  }
  // In q_i = (p_i - c_i)/s_i: grad f . v = -a e^{-|q|^2/2} q . w, w_i = v_i/s_i,
  // whose minimum over q is -|a| |w| e^{-1/2}, reached at q = sign(a) w/|w|.
  const Vec3 w = this->Offset.cwiseQuotient(gaussian->GetSigma());
  const double a = gaussian->GetAmplitude();
  const double minimum = 1.0 - std::abs(a) * w.norm() * std::exp(-0.5);
  if (minimum > 1e-12)
  {
    return {};
  }
  const Vec3 q = (a >= 0 ? 1.0 : -1.0) * w / w.norm();
  const Vec3 where = gaussian->GetCenter() + q.cwiseProduct(gaussian->GetSigma());
  std::ostringstream s;
  s << this->Describe() << " is not a diffeomorphism: 1 + grad f . v = " << minimum << " at ("
    << where.transpose() << ") but must stay > 0; it needs |amplitude| * |direction / sigma| < "
    << std::exp(0.5) << " (now " << std::abs(a) * w.norm()
    << "): lower the amplitude or the direction, or widen sigma";
  return s.str();
}

void BumpTranslationMap::AppendSamplePoints(std::vector<Vec3>& points) const
{
  this->Field->AppendSamplePoints(points);
}
} // namespace riemann
