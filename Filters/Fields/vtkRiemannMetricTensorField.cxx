#include "vtkRiemannMetricTensorField.h"

#include "Metric.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <atomic>
#include <limits>

vtkStandardNewMacro(vtkRiemannMetricTensorField);

namespace
{
void StoreSymmetric(const riemann::Mat3& m, double* t)
{
  t[0] = m(0, 0);
  t[1] = m(1, 1);
  t[2] = m(2, 2);
  t[3] = m(0, 1);
  t[4] = m(1, 2);
  t[5] = m(0, 2);
}
}

bool vtkRiemannMetricTensorField::ComputeFields(const riemann::Metric& metric, vtkDataSet* output)
{
  const vtkIdType count = output->GetNumberOfPoints();
  auto tensor = NewPointArray("MetricTensor", 6, count);
  auto inverse = NewPointArray("InverseMetricTensor", 6, count);
  auto eigenvalues = NewPointArray("MetricEigenvalues", 3, count);
  double* gt = tensor->GetPointer(0);
  double* it = inverse->GetPointer(0);
  double* ev = eigenvalues->GetPointer(0);
  std::atomic<vtkIdType> undefined{ 0 };
  const bool completed = this->ForEachPointInBatches(count,
    [&](vtkIdType first, vtkIdType last)
    {
      constexpr double nan = std::numeric_limits<double>::quiet_NaN();
      vtkIdType bad = 0;
      riemann::Mat3 g;
      for (vtkIdType i = first; i < last; ++i)
      {
        double x[3];
        output->GetPoint(i, x);
        if (!metric.Tensor(riemann::Vec3(x[0], x[1], x[2]), g) || !g.allFinite())
        {
          ++bad;
          std::fill(gt + 6 * i, gt + 6 * i + 6, nan);
          std::fill(it + 6 * i, it + 6 * i + 6, nan);
          std::fill(ev + 3 * i, ev + 3 * i + 3, nan);
          continue;
        }
        // Symmetrise against rounding so that the stored tensor is what VTK reads.
        g = 0.5 * (g + g.transpose()).eval();
        StoreSymmetric(g, gt + 6 * i);
        const Eigen::SelfAdjointEigenSolver<riemann::Mat3> eigen(g, Eigen::EigenvaluesOnly);
        const riemann::Vec3 lambda = eigen.eigenvalues(); // ascending
        std::copy(lambda.data(), lambda.data() + 3, ev + 3 * i);
        const Eigen::LLT<riemann::Mat3> llt(g);
        riemann::Mat3 ginv;
        if (llt.info() == Eigen::Success &&
          (ginv = llt.solve(riemann::Mat3::Identity())).allFinite())
        {
          StoreSymmetric(0.5 * (ginv + ginv.transpose()), it + 6 * i);
        }
        else
        {
          ++bad;
          std::fill(it + 6 * i, it + 6 * i + 6, nan);
        }
      }
      undefined += bad;
    });
  if (!completed)
  {
    return false;
  }
  if (undefined > 0)
  {
    vtkWarningMacro(<< undefined << " of " << count
                    << " points have a degenerate or undefined metric: their values are NaN.");
  }
  vtkPointData* pd = output->GetPointData();
  pd->AddArray(tensor);
  pd->SetTensors(tensor);
  pd->AddArray(inverse);
  pd->AddArray(eigenvalues);
  return true;
}

void vtkRiemannMetricTensorField::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
