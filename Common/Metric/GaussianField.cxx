#include "GaussianField.h"

#include <cmath>
#include <sstream>

namespace riemann
{
GaussianField::GaussianField(double amplitude, const Vec3& center, const Vec3& sigma)
  : Amplitude(amplitude)
  , Center(center)
  , Sigma(sigma)
  , InverseVariance(sigma.cwiseProduct(sigma).cwiseInverse())
{
  this->Term.Add(amplitude, center, this->InverseVariance);
}

void AccumulateGaussianTerms(const GaussianTerms& terms, const Vec3& p, int order, ScalarJet& jet)
{
  // With w_i = 1/s_i^2 and u_i = w_i (p_i - c_i):
  //   d_i f = -u_i f
  //   d_i d_j f = (u_i u_j - delta_ij w_i) f
  //   d_i d_j d_k f = (-u_i u_j u_k + delta_ij w_i u_k + delta_ik w_i u_j + delta_jk w_j u_i) f
  for (size_t term = 0; term < terms.Size(); ++term)
  {
    const Vec3 center(terms.Center[0][term], terms.Center[1][term], terms.Center[2][term]);
    const Vec3 w(terms.InverseVariance[0][term], terms.InverseVariance[1][term],
      terms.InverseVariance[2][term]);
    const Vec3 d = p - center;
    const Vec3 u = w.cwiseProduct(d);
    const double f = terms.Amplitude[term] * std::exp(-0.5 * d.dot(u));
    jet.Value += f;
    if (order >= FirstDerivatives)
    {
      jet.Gradient.noalias() -= f * u;
    }
    if (order >= SecondDerivatives)
    {
      jet.Hessian.noalias() += (f * u) * u.transpose();
      jet.Hessian.diagonal() -= f * w;
    }
    if (order >= ThirdDerivatives)
    {
      for (int i = 0; i < 3; ++i)
      {
        for (int j = 0; j < 3; ++j)
        {
          for (int k = 0; k < 3; ++k)
          {
            double t = -u[i] * u[j] * u[k];
            if (i == j)
            {
              t += w[i] * u[k];
            }
            if (i == k)
            {
              t += w[i] * u[j];
            }
            if (j == k)
            {
              t += w[j] * u[i];
            }
            jet.Third[i](j, k) += f * t;
          }
        }
      }
    }
  }
}

void GaussianField::Accumulate(const Vec3& p, int order, ScalarJet& jet) const
{
  AccumulateGaussianTerms(this->Term, p, order, jet);
}

void GaussianField::AccumulatePacket(
  const PacketVec3& p, int order, PacketScalarJet& jet, LaneMask /*lanes*/) const
{
  AccumulateGaussianTerms(this->Term, p, order, jet);
}

std::string GaussianField::Describe() const
{
  std::ostringstream s;
  s << "gaussian(amplitude " << this->Amplitude << ", center (" << this->Center.transpose()
    << "), sigma (" << this->Sigma.transpose() << "))";
  return s.str();
}

void GaussianField::AppendSamplePoints(std::vector<Vec3>& points) const
{
  constexpr int n = 17;
  points.reserve(points.size() + n * n * n);
  // Offsets -4 sigma .. 4 sigma in steps of sigma / 2 along each axis.
  const Vec3 step = this->Sigma * (8.0 / (n - 1));
  const Vec3 corner = this->Center - 4.0 * this->Sigma;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int k = 0; k < n; ++k)
      {
        points.emplace_back(corner[0] + i * step[0], corner[1] + j * step[1], corner[2] + k * step[2]);
      }
    }
  }
}

std::string GaussianField::EmitGlsl(GlslBuilder& builder) const
{
  const std::string a = builder.AddUniform("amplitude", "float", { this->Amplitude });
  const std::string c =
    builder.AddUniform("center", "vec3", { this->Center[0], this->Center[1], this->Center[2] });
  const std::string w = builder.AddUniform("inverse_variance", "vec3",
    { this->InverseVariance[0], this->InverseVariance[1], this->InverseVariance[2] });
  const std::string name = builder.NewName("gaussian");
  builder.AddFunction("void " + name +
    "(vec3 p, inout float f, inout vec3 grad, inout mat3 hess)\n"
    "{\n"
    "  vec3 d = p - " +
    c +
    ";\n"
    "  vec3 u = " +
    w +
    " * d;\n"
    "  float e = " +
    a +
    " * exp(-0.5 * dot(d, u));\n"
    "  f += e;\n"
    "  grad -= e * u;\n"
    "  vec3 ew = e * " +
    w +
    ";\n"
    "  hess += e * outerProduct(u, u) - mat3(ew.x, 0.0, 0.0, 0.0, ew.y, 0.0, 0.0, 0.0, ew.z);\n"
    "}\n");
  return name;
}

} // namespace riemann
