#include "ConformalMetric.h"

#include "PacketCurvature.h"
#include "ConformalMetricPackets.h"
#include "PacketKernels.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace riemann
{
ConformalMetric::ConformalMetric(std::shared_ptr<const ScalarField> index)
  : Index(std::move(index))
{
  this->Bumps = this->Index->GaussianSum(this->BumpsConstant);
}

std::string ConformalMetric::Describe() const
{
  return "conformal with index n = " + this->Index->Describe();
}

bool ConformalMetric::Tensor(const Vec3& p, Mat3& g) const
{
  ScalarJet n;
  this->Index->Evaluate(p, ValueOnly, n);
  g = (n.Value * n.Value) * Mat3::Identity();
  return n.Value > 0 && std::isfinite(n.Value);
}

bool ConformalMetric::TensorDerivatives(const Vec3& p, Mat3& g, Mat3Stack& dg) const
{
  ScalarJet n;
  this->Index->Evaluate(p, FirstDerivatives, n);
  g = (n.Value * n.Value) * Mat3::Identity();
  for (int k = 0; k < 3; ++k)
  {
    dg[k] = (2.0 * n.Value * n.Gradient[k]) * Mat3::Identity();
  }
  return n.Value > 0 && std::isfinite(n.Value) && n.Gradient.allFinite();
}

bool ConformalMetric::TensorSecondDerivatives(
  const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const
{
  // d_k d_l g = 2 (n_k n_l + n n_kl) I.
  ScalarJet n;
  this->Index->Evaluate(p, SecondDerivatives, n);
  g = (n.Value * n.Value) * Mat3::Identity();
  for (int k = 0; k < 3; ++k)
  {
    dg[k] = (2.0 * n.Value * n.Gradient[k]) * Mat3::Identity();
    for (int l = 0; l < 3; ++l)
    {
      d2g[k][l] =
        (2.0 * (n.Gradient[k] * n.Gradient[l] + n.Value * n.Hessian(k, l))) * Mat3::Identity();
    }
  }
  return n.Value > 0 && std::isfinite(n.Value) && n.Gradient.allFinite() && n.Hessian.allFinite();
}

bool ConformalMetric::Christoffel(const Vec3& p, Mat3Stack& gamma) const
{
  ScalarJet n;
  this->Index->Evaluate(p, FirstDerivatives, n);
  if (!(n.Value > 0))
  {
    return false;
  }
  const Vec3 l = n.Gradient / n.Value;
  for (int m = 0; m < 3; ++m)
  {
    gamma[m] = -l[m] * Mat3::Identity();
    gamma[m].row(m) += l.transpose();
    gamma[m].col(m) += l;
  }
  return l.allFinite();
}

bool ConformalMetric::Acceleration(const Vec3& p, const Vec3& v, Vec3& a) const
{
  ScalarJet n;
  this->Index->Evaluate(p, FirstDerivatives, n);
  if (!(n.Value > 0))
  {
    return false;
  }
  const Vec3 l = n.Gradient / n.Value;
  a = v.squaredNorm() * l - 2.0 * l.dot(v) * v;
  return a.allFinite();
}

LaneMask ConformalMetric::AccelerationPacket(
  const PacketVec3& x, const PacketVec3& v, PacketVec3& a, LaneMask lanes) const
{
  if (this->Bumps)
  {
    return ConformalAccelerationOfGaussians(*this->Bumps, this->BumpsConstant, x, v, a) & lanes;
  }
  PacketScalarJet n;
  this->Index->EvaluatePacket(x, FirstDerivatives, n, lanes);
  return ConformalAccelerationFromJet(n, v, a) & lanes;
}

void ConformalMetric::VolumeFormPacket(const PacketVec3& x, double* volume, LaneMask lanes) const
{
  // VolumeForm()'s formula on the provider's packet jet.
  PacketScalarJet n;
  this->Index->EvaluatePacket(x, ValueOnly, n, lanes);
  for (int l = 0; l < PacketWidth; ++l)
  {
    if (HasLane(lanes, l))
    {
      const double value = n.Value[l];
      volume[l] = value > 0 ? value * value * value : std::numeric_limits<double>::quiet_NaN();
    }
  }
}

LaneMask ConformalMetric::TensorSecondDerivativesPacket(
  const PacketVec3& x, PacketTensorJet& jet, LaneMask lanes) const
{
  PacketScalarJet n;
  this->Index->EvaluatePacket(x, SecondDerivatives, n, lanes);
  return ConformalTensorJetFromJet(n, jet) & lanes;
}

LaneMask ConformalMetric::JacobiAccelerationPacket(
  const PacketJacobiState& y, PacketJacobiState& dy, LaneMask lanes) const
{
  PacketScalarJet n;
  this->Index->EvaluatePacket(y.X, SecondDerivatives, n, lanes);
  return ConformalJacobiAccelerationsFromJet(n, y, dy) & lanes;
}

LaneMask ConformalMetric::TensorPacket(const PacketVec3& x, PacketSym3& g, LaneMask lanes) const
{
  // g = n^2 I.
  PacketScalarJet n;
  this->Index->EvaluatePacket(x, ValueOnly, n, lanes);
  LaneMask defined = 0;
  for (int l = 0; l < PacketWidth; ++l)
  {
    const double n2 = n.Value[l] * n.Value[l];
    g.C[XX][l] = n2;
    g.C[YY][l] = n2;
    g.C[ZZ][l] = n2;
    g.C[XY][l] = 0.0;
    g.C[XZ][l] = 0.0;
    g.C[YZ][l] = 0.0;
    const bool ok = n.Value[l] > 0 && std::isfinite(n.Value[l]);
    defined |= ok ? LaneMask{ 1 } << l : 0;
  }
  return defined & lanes;
}

bool ConformalMetric::InverseTensor(const Vec3& p, Mat3& inverse) const
{
  ScalarJet n;
  this->Index->Evaluate(p, ValueOnly, n);
  inverse = Mat3::Identity() / (n.Value * n.Value);
  return n.Value > 0 && std::isfinite(n.Value);
}

double ConformalMetric::VolumeForm(const Vec3& p) const
{
  ScalarJet n;
  this->Index->Evaluate(p, ValueOnly, n);
  return n.Value > 0 ? n.Value * n.Value * n.Value : std::numeric_limits<double>::quiet_NaN();
}

std::string ConformalMetric::Validate() const
{
  std::vector<Vec3> points;
  this->AppendSamplePoints(points);
  points.emplace_back(Vec3::Zero());
  points.emplace_back(Vec3::Constant(1e6)); // the far field
  ScalarJet n;
  for (const Vec3& p : points)
  {
    this->Index->Evaluate(p, ValueOnly, n);
    if (!(n.Value > 0) || !std::isfinite(n.Value))
    {
      std::ostringstream s;
      s << "conformal metric: the refractive index n = " << n.Value << " at (" << p.transpose()
        << ") must be positive everywhere (g = n^2 I)";
      return s.str();
    }
  }
  return this->Metric::Validate();
}

void ConformalMetric::AppendSamplePoints(std::vector<Vec3>& points) const
{
  this->Index->AppendSamplePoints(points);
}

void ConformalMetric::EmitGlsl(GlslBuilder& builder) const
{
  const std::string n = this->Index->EmitGlsl(builder);
  builder.AddFunction("bool rt_metric_tensor(vec3 p, out mat3 g)\n"
                      "{\n"
                      "  float n = 0.0;\n"
                      "  vec3 gn = vec3(0.0);\n"
                      "  mat3 hn = mat3(0.0);\n"
                      "  " +
    n +
    "(p, n, gn, hn);\n"
    "  g = (n * n) * mat3(1.0);\n"
    "  return n > 0.0;\n"
    "}\n");
  builder.AddFunction("bool rt_metric_acceleration(vec3 p, vec3 v, out vec3 a)\n"
                      "{\n"
                      "  float n = 0.0;\n"
                      "  vec3 gn = vec3(0.0);\n"
                      "  mat3 hn = mat3(0.0);\n"
                      "  " +
    n +
    "(p, n, gn, hn);\n"
    "  if (!(n > 0.0))\n"
    "  {\n"
    "    a = vec3(0.0);\n"
    "    return false;\n"
    "  }\n"
    "  vec3 l = gn / n;\n"
    "  a = dot(v, v) * l - 2.0 * dot(l, v) * v;\n"
    "  return true;\n"
    "}\n");
}

} // namespace riemann
