#include "EuclideanMetric.h"

namespace riemann
{
bool EuclideanMetric::Tensor(const Vec3& p, Mat3& g) const
{
  g.setIdentity();
  return p.allFinite();
}

bool EuclideanMetric::TensorDerivatives(const Vec3& p, Mat3& g, Mat3Stack& dg) const
{
  g.setIdentity();
  for (Mat3& m : dg)
  {
    m.setZero();
  }
  return p.allFinite();
}

bool EuclideanMetric::TensorSecondDerivatives(
  const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const
{
  g.setIdentity();
  for (int k = 0; k < 3; ++k)
  {
    dg[k].setZero();
    for (Mat3& m : d2g[k])
    {
      m.setZero();
    }
  }
  return p.allFinite();
}

bool EuclideanMetric::Christoffel(const Vec3& p, Mat3Stack& gamma) const
{
  for (Mat3& m : gamma)
  {
    m.setZero();
  }
  return p.allFinite();
}

bool EuclideanMetric::Acceleration(const Vec3& p, const Vec3& v, Vec3& a) const
{
  a.setZero();
  return p.allFinite() && v.allFinite();
}

bool EuclideanMetric::InverseTensor(const Vec3& p, Mat3& inverse) const
{
  inverse.setIdentity();
  return p.allFinite();
}

double EuclideanMetric::VolumeForm(const Vec3& /*p*/) const
{
  return 1.0;
}

void EuclideanMetric::EmitGlsl(GlslBuilder& builder) const
{
  builder.AddFunction("bool rt_metric_tensor(vec3 p, out mat3 g)\n"
                      "{\n"
                      "  g = mat3(1.0);\n"
                      "  return true;\n"
                      "}\n");
  builder.AddFunction("bool rt_metric_acceleration(vec3 p, vec3 v, out vec3 a)\n"
                      "{\n"
                      "  a = vec3(0.0);\n"
                      "  return true;\n"
                      "}\n");
}

} // namespace riemann
