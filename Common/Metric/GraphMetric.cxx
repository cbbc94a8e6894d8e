#include "GraphMetric.h"

#include "PacketCurvature.h"
#include "GraphMetricPackets.h"
#include "PacketKernels.h"

#include <algorithm>
#include <cmath>

namespace riemann
{
GraphMetric::GraphMetric(std::shared_ptr<const ScalarField> f)
  : Field(std::move(f))
{
  this->Bumps = this->Field->GaussianSum(this->BumpsConstant);
}

std::string GraphMetric::Describe() const
{
  return "graph of f = " + this->Field->Describe();
}

bool GraphMetric::Tensor(const Vec3& p, Mat3& g) const
{
  ScalarJet f;
  this->Field->Evaluate(p, FirstDerivatives, f);
  g = Mat3::Identity() + f.Gradient * f.Gradient.transpose();
  return g.allFinite();
}

bool GraphMetric::TensorDerivatives(const Vec3& p, Mat3& g, Mat3Stack& dg) const
{
  // d_k g_ij = f_ik f_j + f_i f_jk.
  ScalarJet f;
  this->Field->Evaluate(p, SecondDerivatives, f);
  g = Mat3::Identity() + f.Gradient * f.Gradient.transpose();
  for (int k = 0; k < 3; ++k)
  {
    const Vec3 hk = f.Hessian.col(k);
    dg[k] = hk * f.Gradient.transpose() + f.Gradient * hk.transpose();
  }
  return g.allFinite() && dg[0].allFinite() && dg[1].allFinite() && dg[2].allFinite();
}

bool GraphMetric::TensorSecondDerivatives(
  const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const
{
  // d_k d_l g_ij = f_ikl f_j + f_ik f_jl + f_il f_jk + f_i f_jkl.
  ScalarJet f;
  this->Field->Evaluate(p, ThirdDerivatives, f);
  g = Mat3::Identity() + f.Gradient * f.Gradient.transpose();
  bool finite = g.allFinite();
  for (int k = 0; k < 3; ++k)
  {
    const Vec3 hk = f.Hessian.col(k);
    dg[k] = hk * f.Gradient.transpose() + f.Gradient * hk.transpose();
    finite = finite && dg[k].allFinite();
    for (int l = 0; l < 3; ++l)
    {
      const Vec3 hl = f.Hessian.col(l);
      const Vec3 t = f.Third[k].col(l); // t_i = f_kli
      d2g[k][l] = t * f.Gradient.transpose() + f.Gradient * t.transpose() + hk * hl.transpose() +
        hl * hk.transpose();
      finite = finite && d2g[k][l].allFinite();
    }
  }
  return finite;
}

bool GraphMetric::Christoffel(const Vec3& p, Mat3Stack& gamma) const
{
  ScalarJet f;
  this->Field->Evaluate(p, SecondDerivatives, f);
  const double scale = 1.0 / (1.0 + f.Gradient.squaredNorm());
  for (int m = 0; m < 3; ++m)
  {
    gamma[m] = (f.Gradient[m] * scale) * f.Hessian;
  }
  return std::isfinite(scale) && f.Hessian.allFinite() && f.Gradient.allFinite();
}

bool GraphMetric::Acceleration(const Vec3& p, const Vec3& v, Vec3& a) const
{
  ScalarJet f;
  this->Field->Evaluate(p, SecondDerivatives, f);
  a = (-v.dot(f.Hessian * v) / (1.0 + f.Gradient.squaredNorm())) * f.Gradient;
  return a.allFinite();
}

LaneMask GraphMetric::AccelerationPacket(
  const PacketVec3& x, const PacketVec3& v, PacketVec3& a, LaneMask lanes) const
{
  if (this->Bumps)
  {
    return GraphAccelerationOfGaussians(*this->Bumps, x, v, a) & lanes;
  }
  PacketScalarJet f;
  this->Field->EvaluatePacket(x, SecondDerivatives, f, lanes);
  return GraphAccelerationFromJet(f, v, a) & lanes;
}

void GraphMetric::VolumeFormPacket(const PacketVec3& x, double* volume, LaneMask lanes) const
{
  // VolumeForm()'s formula on the provider's packet jet.
  PacketScalarJet f;
  this->Field->EvaluatePacket(x, FirstDerivatives, f, lanes);
  for (int l = 0; l < PacketWidth; ++l)
  {
    if (HasLane(lanes, l))
    {
      const double fx = f.Gradient[0][l], fy = f.Gradient[1][l], fz = f.Gradient[2][l];
      volume[l] = std::sqrt(1.0 + fx * fx + fy * fy + fz * fz);
    }
  }
}

LaneMask GraphMetric::TensorSecondDerivativesPacket(
  const PacketVec3& x, PacketTensorJet& jet, LaneMask lanes) const
{
  PacketScalarJet f;
  this->Field->EvaluatePacket(x, ThirdDerivatives, f, lanes);
  return GraphTensorJetFromJet(f, jet) & lanes;
}

LaneMask GraphMetric::JacobiAccelerationPacket(
  const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes) const
{
  PacketScalarJet f;
  this->Field->EvaluatePacket(y.X, ThirdDerivatives, f, lanes);
  return GraphJacobiAccelerationsFromJet(f, y, dy) & lanes;
}

LaneMask GraphMetric::TensorPacket(const PacketVec3& x, PacketSym3& g, LaneMask lanes) const
{
  // g = I + grad f grad f^T.
  PacketScalarJet f;
  this->Field->EvaluatePacket(x, FirstDerivatives, f, lanes);
  LaneMask finite = 0;
  for (int l = 0; l < PacketWidth; ++l)
  {
    const double fx = f.Gradient[0][l], fy = f.Gradient[1][l], fz = f.Gradient[2][l];
    g.C[XX][l] = 1.0 + fx * fx;
    g.C[YY][l] = 1.0 + fy * fy;
    g.C[ZZ][l] = 1.0 + fz * fz;
    g.C[XY][l] = fx * fy;
    g.C[XZ][l] = fx * fz;
    g.C[YZ][l] = fy * fz;
    const bool ok = std::isfinite(g.C[XX][l]) && std::isfinite(g.C[YY][l]) &&
      std::isfinite(g.C[ZZ][l]) && std::isfinite(g.C[XY][l] + g.C[XZ][l] + g.C[YZ][l]);
    finite |= ok ? LaneMask{ 1 } << l : 0;
  }
  return finite & lanes;
}

bool GraphMetric::InverseTensor(const Vec3& p, Mat3& inverse) const
{
  ScalarJet f;
  this->Field->Evaluate(p, FirstDerivatives, f);
  inverse =
    Mat3::Identity() - (f.Gradient * f.Gradient.transpose()) / (1.0 + f.Gradient.squaredNorm());
  return inverse.allFinite();
}

double GraphMetric::VolumeForm(const Vec3& p) const
{
  ScalarJet f;
  this->Field->Evaluate(p, FirstDerivatives, f);
  return std::sqrt(1.0 + f.Gradient.squaredNorm());
}

std::string GraphMetric::Validate() const
{
  if (!this->Bumps)
  {
    return this->Metric::Validate();
  }
  // Term k's gradient: |a| e^(-Q/2) sqrt(sum_i w_i^2 d_i^2) <= |a| sqrt(w_max Q) e^(-Q/2),
  // Q = sum_i w_i d_i^2, at most |a| sqrt(w_max) e^(-1/2) (at Q = 1).
  const GaussianTerms& terms = *this->Bumps;
  double bound = 0.0;
  for (size_t k = 0; k < terms.Size(); ++k)
  {
    const double w = std::max({ terms.InverseVariance[0][k], terms.InverseVariance[1][k],
      terms.InverseVariance[2][k] });
    bound += std::abs(terms.Amplitude[k]) * std::sqrt(w) * std::exp(-0.5);
  }
  if (std::isfinite(bound) && std::isfinite(1.0 + bound * bound))
  {
    return std::string();
  }
  // The bound overflows (huge amplitudes or tiny spreads): look where.
  return this->Metric::Validate();
}

void GraphMetric::AppendSamplePoints(std::vector<Vec3>& points) const
{
  this->Field->AppendSamplePoints(points);
}

void GraphMetric::EmitGlsl(GlslBuilder& builder) const
{
  const std::string f = this->Field->EmitGlsl(builder);
  builder.AddFunction("bool rt_metric_tensor(vec3 p, out mat3 g)\n"
                      "{\n"
                      "  float f = 0.0;\n"
                      "  vec3 gf = vec3(0.0);\n"
                      "  mat3 hf = mat3(0.0);\n"
                      "  " +
    f +
    "(p, f, gf, hf);\n"
    "  g = mat3(1.0) + outerProduct(gf, gf);\n"
    "  return true;\n"
    "}\n");
  builder.AddFunction("bool rt_metric_acceleration(vec3 p, vec3 v, out vec3 a)\n"
                      "{\n"
                      "  float f = 0.0;\n"
                      "  vec3 gf = vec3(0.0);\n"
                      "  mat3 hf = mat3(0.0);\n"
                      "  " +
    f +
    "(p, f, gf, hf);\n"
    "  a = -gf * (dot(v, hf * v) / (1.0 + dot(gf, gf)));\n"
    "  return true;\n"
    "}\n");
}

} // namespace riemann
