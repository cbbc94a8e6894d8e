#include "TractStops.h"

#include "Metric.h"
#include "SampledTensorSamples.h"

#include <Eigen/LU>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace riemann
{
int VoxelOnAxis(double u, int n)
{
  if (!SampledTensorField::WithinFaces(u, n))
  {
    return -1;
  }
  return std::clamp(static_cast<int>(std::floor(u + 0.5)), 0, n - 1);
}

bool VoxelMask::Contains(const Vec3& x) const
{
  if (this->Set.empty())
  {
    return false;
  }
  // Grid coordinates: Direction is orthonormal, so its transpose inverts it.
  const Vec3 u = (this->Direction.transpose() * (x - this->Origin)).cwiseQuotient(this->Spacing);
  long long index = 0;
  long long stride = 1;
  for (int a = 0; a < 3; ++a)
  {
    const int nearest = VoxelOnAxis(u[a], this->Dimensions[a]);
    if (nearest < 0)
    {
      return false; // beyond the outer voxels' faces, or NaN
    }
    index += stride * nearest;
    stride *= this->Dimensions[a];
  }
  return this->Set[static_cast<std::size_t>(index)] != 0;
}

double FractionalAnisotropy(const Vec3& eigenvalues)
{
  const double norm = eigenvalues.norm();
  if (!(norm > 0.0))
  {
    return 0.0;
  }
  const Vec3 deviation = eigenvalues.array() - eigenvalues.mean();
  return std::sqrt(1.5) * deviation.norm() / norm;
}

double DiffusionExponentOf(const Metric& metric)
{
  // A sampled metric's (read either way), else -1.
  const SampledTensorField* sampled = SampledFieldOf(metric);
  return sampled ? sampled->GetDiffusionExponent() : -1.0;
}

namespace
{
/// FA of a symmetric positive definite m from its invariants (no eigensolver):
/// sqrt(3/2) |m - tr(m)/3 I| / |m|, Frobenius norms.
double FractionalAnisotropyOfMatrix(const Mat3& m)
{
  const double squared = m.squaredNorm();
  const double trace = m.trace();
  if (!(squared > 0.0))
  {
    return 0.0;
  }
  return std::sqrt(std::max(0.0, 1.5 * (squared - trace * trace / 3.0) / squared));
}
} // namespace

bool FractionalAnisotropyOfMetric(const Metric& metric, const Vec3& x, double& anisotropy)
{
  return FractionalAnisotropyOfMetric(metric, DiffusionExponentOf(metric), x, anisotropy);
}

bool FractionalAnisotropyOfMetric(
  const Metric& metric, double exponent, const Vec3& x, double& anisotropy)
{
  Mat3 g;
  if (!metric.Tensor(x, g) || !g.allFinite() || !(g.determinant() > 0.0) || !(g(0, 0) > 0.0))
  {
    return false;
  }
  // Every step of a tract asks this (--stop-fa): the inverse and the tensor
  // itself, the usual metrics, need no eigenvalues.
  if (exponent == -1.0 || exponent == 1.0)
  {
    anisotropy = FractionalAnisotropyOfMatrix(exponent == 1.0 ? g : Mat3(g.inverse()));
    return std::isfinite(anisotropy);
  }
  const Vec3 eigenvalues =
    Eigen::SelfAdjointEigenSolver<Mat3>(g, Eigen::EigenvaluesOnly).eigenvalues();
  if (!(eigenvalues[0] > 0.0))
  {
    return false;
  }
  anisotropy = FractionalAnisotropy(eigenvalues.array().pow(exponent).matrix());
  return std::isfinite(anisotropy);
}

int TractStopRules::ReasonToStop(const Vec3& x) const
{
  if (!this->StopMask.Empty() && !this->StopMask.Contains(x))
  {
    return StoppedByMask;
  }
  if (this->MinimumAnisotropy > 0.0)
  {
    double anisotropy = 0.0;
    if (!FractionalAnisotropyOfMetric(this->TheMetric, this->Exponent, x, anisotropy) ||
      anisotropy < this->MinimumAnisotropy)
    {
      return LowAnisotropy;
    }
  }
  return 0;
}

bool CutAtSharpTurn(GeodesicPath& path, double degreesPerMillimetre)
{
  const double limit = degreesPerMillimetre * std::acos(-1.0) / 180.0;
  const std::size_t n = path.Points.size();
  for (std::size_t k = 0; k + 1 < n && k + 1 < path.Velocities.size(); ++k)
  {
    const double chord = (path.Points[k + 1] - path.Points[k]).norm();
    const Vec3& a = path.Velocities[k];
    const Vec3& b = path.Velocities[k + 1];
    // atan2 of |a x b| and a.b: accurate for the small angles of small steps.
    const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
    if (chord > 0.0 && angle > limit * chord)
    {
      const std::size_t keep = k + 1;
      path.Points.resize(keep);
      path.Velocities.resize(keep);
      path.ArcLength.resize(std::min(keep, path.ArcLength.size()));
      path.SpeedDrift.resize(std::min(keep, path.SpeedDrift.size()));
      path.Reason = SharpTurn;
      return true;
    }
  }
  return false;
}

double EuclideanLength(const GeodesicPath& path)
{
  double length = 0.0;
  for (std::size_t k = 1; k < path.Points.size(); ++k)
  {
    length += (path.Points[k] - path.Points[k - 1]).norm();
  }
  return length;
}

const char* TractRejectionName(int rejection)
{
  switch (rejection)
  {
    case TractKept:
      return "kept";
    case TractTooShort:
      return "shorter than the minimum length";
    case TractMissedInclude:
      return "missed the include region";
    case TractCrossedExclude:
      return "entered the exclude region";
    default:
      return "unknown";
  }
}

int SelectTract(const GeodesicPath* const* paths, int count, const TractSelection& selection)
{
  bool included = selection.Include.Empty();
  double length = 0.0;
  for (int p = 0; p < count; ++p)
  {
    for (const Vec3& x : paths[p]->Points)
    {
      if (!selection.Exclude.Empty() && selection.Exclude.Contains(x))
      {
        return TractCrossedExclude;
      }
      included = included || selection.Include.Contains(x);
    }
    length += EuclideanLength(*paths[p]);
  }
  if (!included)
  {
    return TractMissedInclude;
  }
  return length < selection.MinimumLength ? TractTooShort : TractKept;
}
} // namespace riemann
