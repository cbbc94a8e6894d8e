#include "TwistMap.h"

#include <cmath>
#include <sstream>

namespace riemann
{
TwistMap::TwistMap(double rate)
  : Rate(rate)
{
}

void TwistMap::Evaluate(const Vec3& p, int order, VectorJet& jet) const
{
  // The (x, y) part is R(k z) (x, y). Every derivative of it is
  //   d_z^n R(kz) = k^n R(kz + n pi/2)
  // applied to (x, y) (no x/y derivative), e_x (one x derivative) or e_y
  // (one y derivative); two or more x/y derivatives vanish. The z part is z.
  const double k = this->Rate;
  const double angle = k * p[2];
  // rotated(n, w) = k^n R(angle + n pi/2) w, using R(a + pi/2) w = R(a) (-w_y, w_x).
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  auto rotated = [&](int n, double wx, double wy, double& ox, double& oy)
  {
    double scale = 1.0;
    for (int i = 0; i < n; ++i)
    {
      const double t = wx;
      wx = -wy;
      wy = t;
      scale *= k;
    }
    ox = scale * (c * wx - s * wy);
    oy = scale * (s * wx + c * wy);
  };
  // derivative(counts) fills the (x, y) components of the mixed partial with
  // nx x-derivatives, ny y-derivatives and nz z-derivatives.
  auto derivative = [&](int nx, int ny, int nz, double& ox, double& oy)
  {
    if (nx + ny >= 2)
    {
      ox = oy = 0.0;
    }
    else if (nx == 1)
    {
      rotated(nz, 1.0, 0.0, ox, oy);
    }
    else if (ny == 1)
    {
      rotated(nz, 0.0, 1.0, ox, oy);
    }
    else
    {
      rotated(nz, p[0], p[1], ox, oy);
    }
  };
  auto counts = [](std::initializer_list<int> indices, int& nx, int& ny, int& nz)
  {
    nx = ny = nz = 0;
    for (int i : indices)
    {
      (i == 0 ? nx : i == 1 ? ny : nz)++;
    }
  };

  int nx, ny, nz;
  derivative(0, 0, 0, jet.Value[0], jet.Value[1]);
  jet.Value[2] = p[2];
  if (order >= FirstDerivatives)
  {
    for (int i = 0; i < 3; ++i)
    {
      counts({ i }, nx, ny, nz);
      derivative(nx, ny, nz, jet.Jacobian(0, i), jet.Jacobian(1, i));
      jet.Jacobian(2, i) = (i == 2) ? 1.0 : 0.0;
    }
  }
  if (order >= SecondDerivatives)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        counts({ i, j }, nx, ny, nz);
        derivative(nx, ny, nz, jet.Hessian[0](i, j), jet.Hessian[1](i, j));
        jet.Hessian[2](i, j) = 0.0;
      }
    }
  }
  if (order >= ThirdDerivatives)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        for (int l = 0; l < 3; ++l)
        {
          counts({ i, j, l }, nx, ny, nz);
          derivative(nx, ny, nz, jet.Third[0][i](j, l), jet.Third[1][i](j, l));
          jet.Third[2][i](j, l) = 0.0;
        }
      }
    }
  }
}

std::string TwistMap::Describe() const
{
  std::ostringstream s;
  s << "twist(rate " << this->Rate << ")";
  return s.str();
}

bool TwistMap::Inverse(const Vec3& y, Vec3& p, double /*tolerance*/) const
{
  const double angle = -this->Rate * y[2];
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  p = Vec3(c * y[0] - s * y[1], s * y[0] + c * y[1], y[2]);
  return p.allFinite();
}

std::string TwistMap::EmitGlsl(GlslBuilder& builder) const
{
  // The closed form of Evaluate() to second order: with c, s = cos, sin(k z),
  // d_z Phi_x = -k Phi_y, d_z Phi_y = k Phi_x, d_xz Phi_x = -k s, d_yz Phi_x = -k c,
  // d_xz Phi_y = k c, d_yz Phi_y = -k s, d_zz Phi_{x,y} = -k^2 Phi_{x,y}.
  const std::string k = builder.AddUniform("rate", "float", { this->Rate });
  const std::string name = builder.NewName("twist");
  builder.AddFunction("void " + name +
    "(vec3 p, out vec3 y, out mat3 J, out mat3 H0, out mat3 H1, out mat3 H2)\n"
    "{\n"
    "  float k = " +
    k +
    ";\n"
    "  float c = cos(k * p.z);\n"
    "  float s = sin(k * p.z);\n"
    "  y = vec3(c * p.x - s * p.y, s * p.x + c * p.y, p.z);\n"
    "  J = mat3(c, s, 0.0, -s, c, 0.0, -k * y.y, k * y.x, 1.0);\n"
    "  H0 = mat3(0.0, 0.0, -k * s, 0.0, 0.0, -k * c, -k * s, -k * c, -k * k * y.x);\n"
    "  H1 = mat3(0.0, 0.0, k * c, 0.0, 0.0, -k * s, k * c, -k * s, -k * k * y.y);\n"
    "  H2 = mat3(0.0);\n"
    "}\n");
  return name;
}

} // namespace riemann
