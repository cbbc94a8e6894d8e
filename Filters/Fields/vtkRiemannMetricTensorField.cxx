#include "vtkRiemannMetricTensorField.h"

#include "Metric.h"
#include "PacketCurvature.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRiemannPointPackets.h"

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
      // PacketWidth points at a time: g (TensorPacket), its eigenvalues and
      // inverse on the packet (PacketCurvature.h).
      constexpr double nan = std::numeric_limits<double>::quiet_NaN();
      vtkIdType bad = 0;
      vtkRiemannForEachPointPacket(output, first, last,
        [&](vtkIdType start, int count, const riemann::PacketVec3& x, riemann::LaneMask lanes)
        {
          riemann::PacketSym3 g;
          const riemann::LaneMask defined = metric.TensorPacket(x, g, lanes);
          double lambda[3][riemann::PacketWidth];
          riemann::SymmetricEigenvalues(g, lambda); // ascending
          riemann::PacketSym3 ginv;
          const riemann::LaneMask invertible = riemann::InverseTensor(g, ginv);
          for (int l = 0; l < count; ++l)
          {
            const vtkIdType i = start + l;
            if (!riemann::HasLane(defined, l))
            {
              ++bad;
              std::fill(gt + 6 * i, gt + 6 * i + 6, nan);
              std::fill(it + 6 * i, it + 6 * i + 6, nan);
              std::fill(ev + 3 * i, ev + 3 * i + 3, nan);
              continue;
            }
            StoreSymmetric(g.Lane(l), gt + 6 * i);
            for (int k = 0; k < 3; ++k)
            {
              ev[3 * i + k] = lambda[k][l];
            }
            if (riemann::HasLane(invertible, l))
            {
              StoreSymmetric(ginv.Lane(l), it + 6 * i);
            }
            else
            {
              ++bad;
              std::fill(it + 6 * i, it + 6 * i + 6, nan);
            }
          }
        });
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
