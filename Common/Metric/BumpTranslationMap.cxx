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

std::string BumpTranslationMap::EmitGlsl(GlslBuilder& builder) const
{
  // A constant direction is the affine field with A = 0: one structure, so
  // switching between them only changes uniforms.
  const std::string field = this->Field->EmitGlsl(builder);
  const Mat3& m = this->Matrix;
  const std::string a =
    builder.AddUniform("field_matrix", "mat3", std::vector<double>(m.data(), m.data() + 9));
  const std::string c = builder.AddUniform(
    "field_center", "vec3", { this->Center[0], this->Center[1], this->Center[2] });
  const std::string b = builder.AddUniform(
    "field_offset", "vec3", { this->Offset[0], this->Offset[1], this->Offset[2] });
  const std::string name = builder.NewName("bump");
  builder.AddFunction("void " + name +
    "(vec3 p, out vec3 y, out mat3 J, out mat3 H0, out mat3 H1, out mat3 H2)\n"
    "{\n"
    "  float f = 0.0;\n"
    "  vec3 gf = vec3(0.0);\n"
    "  mat3 hf = mat3(0.0);\n"
    "  " +
    field +
    "(p, f, gf, hf);\n"
    "  mat3 A = " +
    a +
    ";\n"
    "  vec3 v = A * (p - " +
    c + ") + " + b +
    ";\n"
    "  y = p + f * v;\n"
    "  J = mat3(1.0) + outerProduct(v, gf) + f * A;\n"
    "  // H_s = v_s hf + gf a_s^T + a_s gf^T with a_s the row s of A.\n"
    "  vec3 a0 = vec3(A[0][0], A[1][0], A[2][0]);\n"
    "  vec3 a1 = vec3(A[0][1], A[1][1], A[2][1]);\n"
    "  vec3 a2 = vec3(A[0][2], A[1][2], A[2][2]);\n"
    "  H0 = v.x * hf + outerProduct(gf, a0) + outerProduct(a0, gf);\n"
    "  H1 = v.y * hf + outerProduct(gf, a1) + outerProduct(a1, gf);\n"
    "  H2 = v.z * hf + outerProduct(gf, a2) + outerProduct(a2, gf);\n"
    "}\n");
  return name;
}

} // namespace riemann
