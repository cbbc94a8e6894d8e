#include "TensorMetric.h"

#include "PacketCurvature.h"

#include "Christoffel.h"

#include <Eigen/Cholesky>

#include <cmath>
#include <sstream>

namespace riemann
{
ConstantTensorField::ConstantTensorField(const Mat3& value)
  : Value(0.5 * (value + value.transpose()))
{
}

void ConstantTensorField::Evaluate(
  const Vec3& /*p*/, bool withDerivatives, Mat3& g, Mat3Stack& dg) const
{
  g = this->Value;
  if (withDerivatives)
  {
    for (Mat3& m : dg)
    {
      m.setZero();
    }
  }
}

bool ConstantTensorField::EvaluateSecond(
  const Vec3& /*p*/, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const
{
  g = this->Value;
  for (int k = 0; k < 3; ++k)
  {
    dg[k].setZero();
    for (Mat3& m : d2g[k])
    {
      m.setZero();
    }
  }
  return true;
}

std::string ConstantTensorField::Describe() const
{
  std::ostringstream s;
  s << "constant [" << this->Value.row(0) << "; " << this->Value.row(1) << "; "
    << this->Value.row(2) << "]";
  return s.str();
}

TensorMetric::TensorMetric(std::shared_ptr<const TensorField> field)
  : Field(std::move(field))
{
}

std::string TensorMetric::Describe() const
{
  return "tensor g = " + this->Field->Describe();
}

bool TensorMetric::Tensor(const Vec3& p, Mat3& g) const
{
  Mat3Stack unused;
  this->Field->Evaluate(p, false, g, unused);
  return g.allFinite() && Eigen::LLT<Mat3>(g).info() == Eigen::Success;
}

bool TensorMetric::TensorDerivatives(const Vec3& p, Mat3& g, Mat3Stack& dg) const
{
  this->Field->Evaluate(p, true, g, dg);
  return g.allFinite() && Eigen::LLT<Mat3>(g).info() == Eigen::Success;
}

bool TensorMetric::TensorSecondDerivatives(
  const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const
{
  if (!this->Field->EvaluateSecond(p, g, dg, d2g))
  {
    return false;
  }
  bool finite = g.allFinite();
  for (int k = 0; k < 3; ++k)
  {
    finite = finite && dg[k].allFinite();
    for (const Mat3& m : d2g[k])
    {
      finite = finite && m.allFinite();
    }
  }
  return finite && Eigen::LLT<Mat3>(g).info() == Eigen::Success;
}

LaneMask TensorField::EvaluateSecondPacket(
  const PacketVec3& x, PacketTensorJet& jet, LaneMask lanes) const
{
  LaneMask done = 0;
  Mat3 g;
  Mat3Stack dg;
  std::array<Mat3Stack, 3> d2g;
  for (int l = 0; l < PacketWidth; ++l)
  {
    if (HasLane(lanes, l) && this->EvaluateSecond(x.Lane(l), g, dg, d2g))
    {
      done |= LaneMask{ 1 } << l;
      jet.SetLane(l, g, dg, d2g);
    }
    else
    {
      jet.SetFlatLane(l);
    }
  }
  return done;
}

LaneMask TensorMetric::TensorSecondDerivativesPacket(
  const PacketVec3& x, PacketTensorJet& jet, LaneMask lanes) const
{
  // As TensorSecondDerivatives: every entry finite and g positive definite
  // (the Cholesky of InverseTensor).
  LaneMask defined = this->Field->EvaluateSecondPacket(x, jet, lanes);
  PacketSym3 inverse;
  defined &= riemann::InverseTensor(jet.G, inverse);
  const auto finite = [&defined](const PacketSym3& m)
  {
    for (int e = 0; e < 6; ++e)
    {
      for (int l = 0; l < PacketWidth; ++l)
      {
        if (!std::isfinite(m.C[e][l]))
        {
          defined &= ~(LaneMask{ 1 } << l);
        }
      }
    }
  };
  finite(jet.G);
  for (int k = 0; k < 3; ++k)
  {
    finite(jet.D[k]);
  }
  for (const PacketSym3& m : jet.DD)
  {
    finite(m);
  }
  return defined;
}

bool TensorMetric::Christoffel(const Vec3& p, Mat3Stack& gamma) const
{
  Mat3 g;
  Mat3Stack dg;
  this->Field->Evaluate(p, true, g, dg);
  const Eigen::LLT<Mat3> llt(g);
  if (!g.allFinite() || llt.info() != Eigen::Success)
  {
    return false;
  }
  ChristoffelFromMetricDerivatives(llt.solve(Mat3::Identity()), dg, gamma);
  return gamma[0].allFinite() && gamma[1].allFinite() && gamma[2].allFinite();
}

void TensorMetric::AppendSamplePoints(std::vector<Vec3>& points) const
{
  this->Field->AppendSamplePoints(points);
}

std::string ConstantTensorField::EmitGlsl(GlslBuilder& builder) const
{
  const std::string value = builder.AddUniform(
    "tensor", "mat3", std::vector<double>(this->Value.data(), this->Value.data() + 9));
  const std::string name = builder.NewName("constant_tensor");
  builder.AddFunction("void " + name +
    "(vec3 p, out mat3 g, out mat3 dg0, out mat3 dg1, out mat3 dg2)\n"
    "{\n"
    "  g = " +
    value +
    ";\n"
    "  dg0 = mat3(0.0);\n"
    "  dg1 = mat3(0.0);\n"
    "  dg2 = mat3(0.0);\n"
    "}\n");
  return name;
}

void EmitTensorMetricGlsl(GlslBuilder& builder, const std::string& field)
{
  // The general formula contracted with v twice:
  //   Gamma_kij v^i v^j = ((sum_i v^i d_i g) v)_k - 1/2 v^T (d_k g) v,
  //   a = -g^-1 of that. Positive definiteness by Sylvester's criterion.
  const std::string positive =
    "  return g[0][0] > 0.0 && g[0][0] * g[1][1] - g[0][1] * g[1][0] > 0.0 &&\n"
    "    determinant(g) > 0.0;\n";
  builder.AddFunction("bool rt_metric_tensor(vec3 p, out mat3 g)\n"
                      "{\n"
                      "  mat3 dg0, dg1, dg2;\n"
                      "  " +
    field + "(p, g, dg0, dg1, dg2);\n" + positive + "}\n");
  builder.AddFunction("bool rt_metric_acceleration(vec3 p, vec3 v, out vec3 a)\n"
                      "{\n"
                      "  mat3 g, dg0, dg1, dg2;\n"
                      "  " +
    field +
    "(p, g, dg0, dg1, dg2);\n"
    "  vec3 w = ((v.x * dg0 + v.y * dg1 + v.z * dg2) * v) -\n"
    "    0.5 * vec3(dot(v, dg0 * v), dot(v, dg1 * v), dot(v, dg2 * v));\n"
    "  a = -(inverse(g) * w);\n" +
    positive + "}\n");
}

void TensorMetric::EmitGlsl(GlslBuilder& builder) const
{
  EmitTensorMetricGlsl(builder, this->Field->EmitGlsl(builder));
}
} // namespace riemann
