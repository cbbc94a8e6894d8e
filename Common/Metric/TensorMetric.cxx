#include "TensorMetric.h"

#include "Christoffel.h"

#include <Eigen/Cholesky>

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

std::string ConstantTensorField::EmitConstantGlsl(GlslBuilder& builder) const
{
  return builder.AddUniform(
    "tensor", "mat3", std::vector<double>(this->Value.data(), this->Value.data() + 9));
}

void TensorMetric::EmitGlsl(GlslBuilder& builder) const
{
  // A constant g is flat: straight rays, only the camera frame feels g.
  const std::string g = this->Field->EmitConstantGlsl(builder);
  builder.AddFunction("bool rt_metric_tensor(vec3 p, out mat3 g)\n"
                      "{\n"
                      "  g = " + g + ";\n"
                      "  return true;\n"
                      "}\n");
  builder.AddFunction("bool rt_metric_acceleration(vec3 p, vec3 v, out vec3 a)\n"
                      "{\n"
                      "  a = vec3(0.0);\n"
                      "  return true;\n"
                      "}\n");
}

} // namespace riemann
