#include "SampledTensorSamples.h"

#include "TensorMetric.h"
#include "VoxelChristoffelMetric.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>
#include <stdexcept>

namespace riemann
{
namespace
{
Mat3 SampleAt(const SampledTensorGrid& grid, long long point)
{
  const double* c = grid.Components.data() + 6 * point;
  Mat3 g;
  g << c[0], c[3], c[5], c[3], c[1], c[4], c[5], c[4], c[2];
  return g;
}

void StoreAt(SampledTensorGrid& grid, long long point, const Mat3& g)
{
  double* c = grid.Components.data() + 6 * point;
  c[0] = g(0, 0);
  c[1] = g(1, 1);
  c[2] = g(2, 2);
  c[3] = 0.5 * (g(0, 1) + g(1, 0));
  c[4] = 0.5 * (g(1, 2) + g(2, 1));
  c[5] = 0.5 * (g(0, 2) + g(2, 0));
}

std::array<int, 3> IndexOf(const SampledTensorGrid& grid, long long point)
{
  const long long nx = grid.Dimensions[0];
  const long long ny = grid.Dimensions[1];
  return { static_cast<int>(point % nx), static_cast<int>((point / nx) % ny),
    static_cast<int>(point / (nx * ny)) };
}

/// "sample (i, j, k) at (x, y, z)".
std::string Where(const SampledTensorGrid& grid, const std::array<int, 3>& index)
{
  const Vec3 x = grid.Origin +
    grid.Direction *
      Vec3(index[0] * grid.Spacing[0], index[1] * grid.Spacing[1], index[2] * grid.Spacing[2]);
  std::ostringstream text;
  text << "sample (" << index[0] << ", " << index[1] << ", " << index[2] << ") at (" << x[0] << ", "
       << x[1] << ", " << x[2] << ")";
  return text.str();
}
/// The eigenvalues of the metric `kind` makes of a tensor with eigenvalues l.
Vec3 MetricEigenvalues(TensorMetricKind kind, double sharpening, const Vec3& l)
{
  switch (kind)
  {
    case TensorMetricKind::Tensor:
      return l;
    case TensorMetricKind::Inverse:
      return l.cwiseInverse();
    case TensorMetricKind::Adjugate:
      return Vec3(l[1] * l[2], l[0] * l[2], l[0] * l[1]);
    case TensorMetricKind::Sharpened:
    {
      // Through logarithms: l_geo^(p-1) l_i^-p overflows no sooner than the result.
      const double logGeometricMean = (std::log(l[0]) + std::log(l[1]) + std::log(l[2])) / 3.0;
      Vec3 g;
      for (int i = 0; i < 3; ++i)
      {
        g[i] = std::exp((sharpening - 1.0) * logGeometricMean - sharpening * std::log(l[i]));
      }
      return g;
    }
  }
  return l;
}
} // namespace

const char* TensorMetricName(TensorMetricKind kind)
{
  switch (kind)
  {
    case TensorMetricKind::Tensor:
      return "tensor";
    case TensorMetricKind::Inverse:
      return "inverse";
    case TensorMetricKind::Adjugate:
      return "adjugate";
    case TensorMetricKind::Sharpened:
      return "sharpened";
  }
  return "tensor";
}

double DiffusionExponent(TensorMetricKind kind, double sharpening)
{
  switch (kind)
  {
    case TensorMetricKind::Tensor:
      return 1.0;
    case TensorMetricKind::Inverse:
    case TensorMetricKind::Adjugate:
      return -1.0;
    case TensorMetricKind::Sharpened:
      return -1.0 / sharpening;
  }
  return 1.0;
}

std::string SampledTensorOptions::Check() const
{
  std::ostringstream problem;
  if (!std::isfinite(this->Scale) || !(this->Scale > 0.0))
  {
    problem << "the scale must be a finite positive number, got " << this->Scale;
  }
  else if (!(this->Sharpening >= 1.0 && this->Sharpening <= 16.0))
  {
    problem << "the sharpening must be a number in [1, 16] (1: the inverse), got "
            << this->Sharpening;
  }
  else if (!(this->RelativeFloor > 0.0 && this->RelativeFloor < 1.0))
  {
    problem << "the repair floor must be between 0 and 1 (a fraction of the largest "
               "eigenvalue), got "
            << this->RelativeFloor;
  }
  return problem.str();
}

std::string PrepareTensorSamples(
  SampledTensorGrid& grid, const SampledTensorOptions& options, SampledTensorReport* report)
{
  SampledTensorReport found;
  std::string problem = grid.Check();
  if (problem.empty())
  {
    problem = options.Check();
  }
  if (!problem.empty())
  {
    if (report)
    {
      *report = found;
    }
    return problem;
  }
  const long long count = grid.NumberOfPoints();
  // Pass 1: finiteness, definiteness, and the largest eigenvalue (the floor's scale).
  double largest = 0.0;
  std::vector<double> meanDiffusivities;
  long long firstNonFinite = -1, firstIndefinite = -1;
  double indefiniteEigenvalue = 0.0;
  for (long long point = 0; point < count; ++point)
  {
    const Mat3 g = SampleAt(grid, point);
    if (!g.allFinite())
    {
      ++found.NonFinite;
      firstNonFinite = firstNonFinite < 0 ? point : firstNonFinite;
      continue;
    }
    const Vec3 eigenvalues =
      Eigen::SelfAdjointEigenSolver<Mat3>(g, Eigen::EigenvaluesOnly).eigenvalues();
    largest = std::max(largest, eigenvalues[2]);
    if (eigenvalues[0] > 0.0 && options.ScaleToMeanDiffusivity)
    {
      meanDiffusivities.push_back(eigenvalues.sum() / 3.0);
    }
    if (!(eigenvalues[0] > 0.0))
    {
      ++found.NotPositiveDefinite;
      if (firstIndefinite < 0)
      {
        firstIndefinite = point;
        indefiniteEigenvalue = eigenvalues[0];
      }
    }
  }
  const long long firstBad = firstNonFinite >= 0 ? firstNonFinite : firstIndefinite;
  if (firstBad >= 0)
  {
    found.FirstBad = IndexOf(grid, firstBad);
    found.FirstBadEigenvalue = firstNonFinite >= 0 ? std::nan("") : indefiniteEigenvalue;
  }
  std::ostringstream message;
  if (found.NonFinite > 0)
  {
    message << found.NonFinite << " of " << count
            << " samples are not finite (NaN or infinite components); the first is "
            << Where(grid, found.FirstBad);
  }
  else if (!(largest > 0.0))
  {
    message << "no sample is positive definite (" << count << " samples)";
  }
  else if (found.NotPositiveDefinite > 0 && !options.Repair)
  {
    message << found.NotPositiveDefinite << " of " << count
            << " samples are not positive definite; the first is " << Where(grid, found.FirstBad)
            << ", smallest eigenvalue " << found.FirstBadEigenvalue
            << " (\"repair\": \"clamp\" raises every eigenvalue to " << options.RelativeFloor
            << " of the largest)";
  }
  if (!message.str().empty())
  {
    if (report)
    {
      *report = found;
    }
    return message.str();
  }

  // The scale: the option's, times the median mean diffusivity's part.
  double scale = options.Scale;
  if (!meanDiffusivities.empty())
  {
    auto middle = meanDiffusivities.begin() + static_cast<std::ptrdiff_t>(meanDiffusivities.size() / 2);
    std::nth_element(meanDiffusivities.begin(), middle, meanDiffusivities.end());
    found.MedianMeanDiffusivity = *middle;
    scale /= MetricEigenvalues(options.Kind, options.Sharpening, Vec3::Constant(*middle))[0];
  }
  found.AppliedScale = scale;

  // Pass 2: clamp (with Repair), invert, scale, through each sample's eigenvectors.
  const double floor = options.RelativeFloor * largest;
  for (long long point = 0; point < count; ++point)
  {
    const Mat3 g = SampleAt(grid, point);
    const Eigen::SelfAdjointEigenSolver<Mat3> solver(g);
    Vec3 eigenvalues = solver.eigenvalues();
    bool clamped = false;
    if (options.Repair)
    {
      for (int i = 0; i < 3; ++i)
      {
        if (eigenvalues[i] < floor)
        {
          eigenvalues[i] = floor;
          clamped = true;
        }
      }
    }
    found.Repaired += clamped ? 1 : 0;
    if (!clamped && options.Kind == TensorMetricKind::Tensor && scale == 1.0)
    {
      continue; // kept exactly as given
    }
    eigenvalues = MetricEigenvalues(options.Kind, options.Sharpening, eigenvalues);
    const Mat3& v = solver.eigenvectors();
    StoreAt(grid, point, scale * (v * eigenvalues.asDiagonal() * v.transpose()));
  }
  if (report)
  {
    *report = found;
  }
  return {};
}

std::shared_ptr<const Metric> MakeSampledTensorMetric(
  SampledTensorGrid grid, const SampledTensorOptions& options)
{
  const std::string problem = PrepareTensorSamples(grid, options);
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  auto field = std::make_shared<SampledTensorField>(std::move(grid), options.StopOutside);
  field->SetDiffusionExponent(DiffusionExponent(options.Kind, options.Sharpening));
  auto exact = std::make_shared<TensorMetric>(field);
  if (options.ChristoffelAtVoxels)
  {
    return std::make_shared<VoxelChristoffelMetric>(std::move(exact), field->GetGrid());
  }
  return exact;
}

const SampledTensorField* SampledFieldOf(const Metric& metric)
{
  if (const auto* voxels = dynamic_cast<const VoxelChristoffelMetric*>(&metric))
  {
    return &voxels->GetField();
  }
  const auto* tensor = dynamic_cast<const TensorMetric*>(&metric);
  return tensor ? dynamic_cast<const SampledTensorField*>(&tensor->GetField()) : nullptr;
}
} // namespace riemann
