#include "SpaceMap.h"

#include <Eigen/LU>

#include <cmath>
#include <sstream>

namespace riemann
{
bool SpaceMap::Inverse(const Vec3& y, Vec3& p, double tolerance) const
{
  p = y;
  VectorJet jet;
  this->Evaluate(p, FirstDerivatives, jet);
  Vec3 residual = jet.Value - y;
  double norm = residual.norm();
  const double scale = 1.0 + y.norm();
  for (int iteration = 0; iteration < 100 && norm > tolerance * scale; ++iteration)
  {
    const Eigen::FullPivLU<Mat3> lu(jet.Jacobian);
    if (!lu.isInvertible())
    {
      return false;
    }
    const Vec3 step = lu.solve(residual);
    // Backtrack so that the residual decreases: far from the root a bump's
    // Jacobian can point Newton well past it.
    double damping = 1.0;
    for (int halving = 0; halving < 30; ++halving, damping *= 0.5)
    {
      const Vec3 candidate = p - damping * step;
      this->Evaluate(candidate, FirstDerivatives, jet);
      const Vec3 candidateResidual = jet.Value - y;
      if (candidateResidual.norm() < norm || halving == 29)
      {
        p = candidate;
        residual = candidateResidual;
        break;
      }
    }
    norm = residual.norm();
  }
  return std::isfinite(norm) && norm <= tolerance * scale;
}

std::string SpaceMap::CheckDiffeomorphism() const
{
  std::vector<Vec3> points;
  this->AppendSamplePoints(points);
  VectorJet jet;
  double worst = 1e300;
  Vec3 worstPoint = Vec3::Zero();
  for (const Vec3& p : points)
  {
    this->Evaluate(p, FirstDerivatives, jet);
    const double det = jet.Jacobian.determinant();
    if (!std::isfinite(det) || det < worst)
    {
      worst = det;
      worstPoint = p;
      if (!std::isfinite(det))
      {
        break;
      }
    }
  }
  if (std::isfinite(worst) && worst > 1e-12)
  {
    return {};
  }
  std::ostringstream s;
  s << this->Describe() << " is not a diffeomorphism: det J = " << worst << " at ("
    << worstPoint.transpose() << "); it must stay > 0 everywhere";
  return s.str();
}
} // namespace riemann
