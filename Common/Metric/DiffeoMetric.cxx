#include "DiffeoMetric.h"

#include <Eigen/LU>

#include <cmath>

namespace riemann
{
namespace
{
/// Below this |det J| the pull-back is treated as degenerate (the map folds).
constexpr double DegenerateDeterminant = 1e-12;
}

DiffeoMetric::DiffeoMetric(std::shared_ptr<const SpaceMap> map)
  : Map(std::move(map))
{
}

std::string DiffeoMetric::Describe() const
{
  return "pull-back of Euclidean space through " + this->Map->Describe();
}

bool DiffeoMetric::Tensor(const Vec3& p, Mat3& g) const
{
  VectorJet jet;
  this->Map->Evaluate(p, FirstDerivatives, jet);
  g = jet.Jacobian.transpose() * jet.Jacobian;
  return g.allFinite() && std::abs(jet.Jacobian.determinant()) > DegenerateDeterminant;
}

bool DiffeoMetric::TensorDerivatives(const Vec3& p, Mat3& g, Mat3Stack& dg) const
{
  // d_k g_ij = sum_s H_s(i, k) J(s, j) + J(s, i) H_s(j, k).
  VectorJet jet;
  this->Map->Evaluate(p, SecondDerivatives, jet);
  const Mat3& J = jet.Jacobian;
  g = J.transpose() * J;
  for (int k = 0; k < 3; ++k)
  {
    // B(s, i) = H_s(i, k) = d_k J(s, i).
    Mat3 b;
    for (int s = 0; s < 3; ++s)
    {
      b.row(s) = jet.Hessian[s].col(k).transpose();
    }
    dg[k] = b.transpose() * J + J.transpose() * b;
  }
  return g.allFinite() && std::abs(J.determinant()) > DegenerateDeterminant;
}

bool DiffeoMetric::TensorSecondDerivatives(
  const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const
{
  // With B_k(s, i) = H_s(i, k) = d_k J(s, i) and C_kl(s, i) = T_s(i, k, l):
  // d_k g = B_k^T J + J^T B_k, d_l d_k g = C_kl^T J + B_k^T B_l + B_l^T B_k + J^T C_kl.
  VectorJet jet;
  this->Map->Evaluate(p, ThirdDerivatives, jet);
  const Mat3& J = jet.Jacobian;
  g = J.transpose() * J;
  Mat3Stack b;
  for (int k = 0; k < 3; ++k)
  {
    for (int s = 0; s < 3; ++s)
    {
      b[k].row(s) = jet.Hessian[s].col(k).transpose();
    }
    dg[k] = b[k].transpose() * J + J.transpose() * b[k];
  }
  bool finite = g.allFinite();
  for (int k = 0; k < 3; ++k)
  {
    finite = finite && dg[k].allFinite();
    for (int l = 0; l < 3; ++l)
    {
      Mat3 c;
      for (int s = 0; s < 3; ++s)
      {
        for (int i = 0; i < 3; ++i)
        {
          c(s, i) = jet.Third[s][i](k, l);
        }
      }
      d2g[k][l] =
        c.transpose() * J + b[k].transpose() * b[l] + b[l].transpose() * b[k] + J.transpose() * c;
      finite = finite && d2g[k][l].allFinite();
    }
  }
  return finite && std::abs(J.determinant()) > DegenerateDeterminant;
}

bool DiffeoMetric::Christoffel(const Vec3& p, Mat3Stack& gamma) const
{
  VectorJet jet;
  this->Map->Evaluate(p, SecondDerivatives, jet);
  if (!(std::abs(jet.Jacobian.determinant()) > DegenerateDeterminant))
  {
    return false;
  }
  const Mat3 inverse = jet.Jacobian.inverse();
  for (int m = 0; m < 3; ++m)
  {
    gamma[m] = inverse(m, 0) * jet.Hessian[0] + inverse(m, 1) * jet.Hessian[1] +
      inverse(m, 2) * jet.Hessian[2];
  }
  return gamma[0].allFinite() && gamma[1].allFinite() && gamma[2].allFinite();
}

bool DiffeoMetric::Acceleration(const Vec3& p, const Vec3& v, Vec3& a) const
{
  VectorJet jet;
  this->Map->Evaluate(p, SecondDerivatives, jet);
  const double det = jet.Jacobian.determinant();
  if (!(std::abs(det) > DegenerateDeterminant))
  {
    return false;
  }
  const Vec3 w(v.dot(jet.Hessian[0] * v), v.dot(jet.Hessian[1] * v), v.dot(jet.Hessian[2] * v));
  // A 3x3 inverse by cofactors (Eigen's fixed-size inverse) is cheaper than a
  // pivoted solve and exact enough away from det J = 0, which is refused above.
  a = -(jet.Jacobian.inverse() * w);
  return a.allFinite();
}

double DiffeoMetric::VolumeForm(const Vec3& p) const
{
  VectorJet jet;
  this->Map->Evaluate(p, FirstDerivatives, jet);
  return std::abs(jet.Jacobian.determinant());
}

std::string DiffeoMetric::Validate() const
{
  std::string why = this->Map->CheckDiffeomorphism();
  return why.empty() ? this->Metric::Validate() : why;
}

bool DiffeoMetric::ExactGeodesic(const Vec3& p, const Vec3& v, double t, Vec3& point) const
{
  VectorJet jet;
  this->Map->Evaluate(p, FirstDerivatives, jet);
  return this->Map->Inverse(jet.Value + t * (jet.Jacobian * v), point);
}

void DiffeoMetric::AppendSamplePoints(std::vector<Vec3>& points) const
{
  this->Map->AppendSamplePoints(points);
}

void DiffeoMetric::EmitGlsl(GlslBuilder& builder) const
{
  // Single precision: |det J| below 1e-6 counts as degenerate on the GPU.
  const std::string phi = this->Map->EmitGlsl(builder);
  builder.AddFunction("bool rt_metric_tensor(vec3 p, out mat3 g)\n"
                      "{\n"
                      "  vec3 y;\n"
                      "  mat3 J, H0, H1, H2;\n"
                      "  " +
    phi +
    "(p, y, J, H0, H1, H2);\n"
    "  g = transpose(J) * J;\n"
    "  return abs(determinant(J)) > 1e-6;\n"
    "}\n");
  builder.AddFunction("bool rt_metric_acceleration(vec3 p, vec3 v, out vec3 a)\n"
                      "{\n"
                      "  vec3 y;\n"
                      "  mat3 J, H0, H1, H2;\n"
                      "  " +
    phi +
    "(p, y, J, H0, H1, H2);\n"
    "  if (!(abs(determinant(J)) > 1e-6))\n"
    "  {\n"
    "    a = vec3(0.0);\n"
    "    return false;\n"
    "  }\n"
    "  vec3 w = vec3(dot(v, H0 * v), dot(v, H1 * v), dot(v, H2 * v));\n"
    "  a = -(inverse(J) * w);\n"
    "  return true;\n"
    "}\n");
}

} // namespace riemann
