#include "MapComposition.h"

namespace riemann
{
MapComposition::MapComposition(std::vector<std::shared_ptr<const SpaceMap>> maps)
  : Maps(std::move(maps))
{
}

void MapComposition::Evaluate(const Vec3& p, int order, VectorJet& jet) const
{
  // jet holds the composition of the maps applied so far (innermost first);
  // outer is the next map's jet at jet.Value. Chain rule, with J = inner
  // Jacobian, H_r / T_r inner Hessians / third derivatives, F the outer map:
  //   J'     = J_F J
  //   H'_s   = J^T H_Fs J + sum_r (J_F)_sr H_r
  //   T'_sijk = T_Fs(J_i, J_j, J_k) + H_Fs(H_.ik, J_j) + H_Fs(J_i, H_.jk) + H_Fs(H_.ij, J_k)
  //            + sum_r (J_F)_sr T_rijk
  // where J_i is column i of J and H_.ij the vector (H_1(i,j), H_2(i,j), H_3(i,j)).
  jet.SetZero(order);
  jet.Value = p;
  if (order >= FirstDerivatives)
  {
    jet.Jacobian.setIdentity();
  }
  VectorJet outer;
  VectorJet next;
  for (auto it = this->Maps.rbegin(); it != this->Maps.rend(); ++it)
  {
    (*it)->Evaluate(jet.Value, order, outer);
    next.Value = outer.Value;
    if (order >= FirstDerivatives)
    {
      next.Jacobian = outer.Jacobian * jet.Jacobian;
    }
    if (order >= SecondDerivatives)
    {
      for (int s = 0; s < 3; ++s)
      {
        next.Hessian[s] = jet.Jacobian.transpose() * outer.Hessian[s] * jet.Jacobian;
        for (int r = 0; r < 3; ++r)
        {
          next.Hessian[s] += outer.Jacobian(s, r) * jet.Hessian[r];
        }
      }
    }
    if (order >= ThirdDerivatives)
    {
      const Mat3& J = jet.Jacobian;
      for (int s = 0; s < 3; ++s)
      {
        // TJ[a](b, k) = sum_c T_Fs[a](b, c) J(c, k): contract the last index first.
        Mat3Stack tj;
        for (int a = 0; a < 3; ++a)
        {
          tj[a] = outer.Third[s][a] * J;
        }
        for (int i = 0; i < 3; ++i)
        {
          for (int j = 0; j < 3; ++j)
          {
            for (int k = 0; k < 3; ++k)
            {
              double t = 0.0;
              for (int a = 0; a < 3; ++a)
              {
                for (int b = 0; b < 3; ++b)
                {
                  t += tj[a](b, k) * J(a, i) * J(b, j);
                  const double h = outer.Hessian[s](a, b);
                  t += h *
                    (jet.Hessian[a](i, k) * J(b, j) + J(a, i) * jet.Hessian[b](j, k) +
                      jet.Hessian[a](i, j) * J(b, k));
                }
                t += outer.Jacobian(s, a) * jet.Third[a][i](j, k);
              }
              next.Third[s][i](j, k) = t;
            }
          }
        }
      }
    }
    jet.Value = next.Value;
    if (order >= FirstDerivatives)
    {
      jet.Jacobian = next.Jacobian;
    }
    if (order >= SecondDerivatives)
    {
      jet.Hessian = next.Hessian;
    }
    if (order >= ThirdDerivatives)
    {
      jet.Third = next.Third;
    }
  }
}

std::string MapComposition::Describe() const
{
  std::string s = "compose(";
  for (size_t i = 0; i < this->Maps.size(); ++i)
  {
    s += (i ? " o " : "") + this->Maps[i]->Describe();
  }
  return s + ")";
}

bool MapComposition::Inverse(const Vec3& y, Vec3& p, double tolerance) const
{
  Vec3 current = y;
  for (const auto& map : this->Maps)
  {
    if (!map->Inverse(current, p, tolerance))
    {
      return false;
    }
    current = p;
  }
  p = current;
  return true;
}

std::string MapComposition::CheckDiffeomorphism() const
{
  for (size_t i = 0; i < this->Maps.size(); ++i)
  {
    std::string why = this->Maps[i]->CheckDiffeomorphism();
    if (!why.empty())
    {
      return "map " + std::to_string(i) + " of the composition: " + why;
    }
  }
  return {};
}

void MapComposition::AppendSamplePoints(std::vector<Vec3>& points) const
{
  for (const auto& map : this->Maps)
  {
    map->AppendSamplePoints(points);
  }
}

std::string MapComposition::EmitGlsl(GlslBuilder& builder) const
{
  // Second-order forward mode, innermost map first, as in Evaluate().
  std::vector<std::string> maps;
  for (const auto& map : this->Maps)
  {
    maps.push_back(map->EmitGlsl(builder));
  }
  const std::string name = builder.NewName("compose");
  std::string code = "void " + name +
    "(vec3 p, out vec3 y, out mat3 J, out mat3 H0, out mat3 H1, out mat3 H2)\n"
    "{\n"
    "  y = p;\n"
    "  J = mat3(1.0);\n"
    "  H0 = mat3(0.0);\n"
    "  H1 = mat3(0.0);\n"
    "  H2 = mat3(0.0);\n"
    "  vec3 yo;\n"
    "  mat3 Jo, G0, G1, G2, Jt, N0, N1, N2;\n";
  for (auto it = maps.rbegin(); it != maps.rend(); ++it)
  {
    // H'_s = J^T G_s J + sum_r Jo(s, r) H_r, with Jo(s, r) = Jo[r][s] in GLSL.
    code += "  " + *it +
      "(y, yo, Jo, G0, G1, G2);\n"
      "  Jt = transpose(J);\n"
      "  N0 = Jt * G0 * J + Jo[0][0] * H0 + Jo[1][0] * H1 + Jo[2][0] * H2;\n"
      "  N1 = Jt * G1 * J + Jo[0][1] * H0 + Jo[1][1] * H1 + Jo[2][1] * H2;\n"
      "  N2 = Jt * G2 * J + Jo[0][2] * H0 + Jo[1][2] * H1 + Jo[2][2] * H2;\n"
      "  H0 = N0;\n  H1 = N1;\n  H2 = N2;\n"
      "  J = Jo * J;\n"
      "  y = yo;\n";
  }
  builder.AddFunction(code + "}\n");
  return name;
}

} // namespace riemann
