/**
 * @file Jets.h
 * @brief Value and exact derivatives (up to third order) of scalar fields and
 * of maps R^3 -> R^3, the currency between field providers and metric families.
 *
 * Index conventions (used everywhere in the metric core):
 * - ScalarJet::Gradient(i)      = d_i f
 * - ScalarJet::Hessian(i, j)    = d_i d_j f
 * - ScalarJet::Third[i](j, k)   = d_i d_j d_k f
 * - VectorJet::Jacobian(s, i)   = d_i Phi_s          (row = component)
 * - VectorJet::Hessian[s](i, j) = d_i d_j Phi_s
 * - VectorJet::Third[s][i](j,k) = d_i d_j d_k Phi_s
 *
 * Lower orders are always filled when a higher order is requested; orders
 * above the requested one are left untouched (callers must not read them).
 */
#ifndef RiemannJets_h
#define RiemannJets_h

#include <Eigen/Core>

#include <array>

namespace riemann
{
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
/// Three 3x3 matrices: a rank-3 array indexed [a](b, c).
using Mat3Stack = std::array<Mat3, 3>;

/// How many derivatives a provider must compute (0 = value only).
enum DerivativeOrder : int
{
  ValueOnly = 0,
  FirstDerivatives = 1,
  SecondDerivatives = 2,
  ThirdDerivatives = 3
};

struct ScalarJet
{
  double Value = 0.0;
  Vec3 Gradient = Vec3::Zero();
  Mat3 Hessian = Mat3::Zero();
  Mat3Stack Third = { Mat3::Zero(), Mat3::Zero(), Mat3::Zero() };

  /// Zero every entry up to and including `order`.
  void SetZero(int order)
  {
    this->Value = 0.0;
    if (order >= FirstDerivatives)
    {
      this->Gradient.setZero();
    }
    if (order >= SecondDerivatives)
    {
      this->Hessian.setZero();
    }
    if (order >= ThirdDerivatives)
    {
      for (Mat3& m : this->Third)
      {
        m.setZero();
      }
    }
  }
};

struct VectorJet
{
  Vec3 Value = Vec3::Zero();
  Mat3 Jacobian = Mat3::Identity();
  Mat3Stack Hessian = { Mat3::Zero(), Mat3::Zero(), Mat3::Zero() };
  std::array<Mat3Stack, 3> Third = { Mat3Stack{ Mat3::Zero(), Mat3::Zero(), Mat3::Zero() },
    Mat3Stack{ Mat3::Zero(), Mat3::Zero(), Mat3::Zero() },
    Mat3Stack{ Mat3::Zero(), Mat3::Zero(), Mat3::Zero() } };

  /// Zero every entry up to and including `order`.
  void SetZero(int order)
  {
    this->Value.setZero();
    if (order >= FirstDerivatives)
    {
      this->Jacobian.setZero();
    }
    if (order >= SecondDerivatives)
    {
      for (Mat3& m : this->Hessian)
      {
        m.setZero();
      }
    }
    if (order >= ThirdDerivatives)
    {
      for (Mat3Stack& s : this->Third)
      {
        for (Mat3& m : s)
        {
          m.setZero();
        }
      }
    }
  }
};

/// Axis-aligned box, used to say where a provider varies (for validation sampling).
struct Box
{
  Vec3 Lower = Vec3::Zero();
  Vec3 Upper = Vec3::Zero();
};
} // namespace riemann

#endif
