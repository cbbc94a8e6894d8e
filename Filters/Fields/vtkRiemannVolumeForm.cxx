#include "vtkRiemannVolumeForm.h"

#include "Metric.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRiemannPointPackets.h"

#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkRiemannVolumeForm);

bool vtkRiemannVolumeForm::ComputeFields(const riemann::Metric& metric, vtkDataSet* output)
{
  this->VolumeIntegral = vtkMath::Nan();
  this->NumberOfExcludedPoints = 0;
  const vtkIdType count = output->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> volume;
  volume->SetName("VolumeForm");
  volume->SetNumberOfTuples(count);
  double* v = volume->GetPointer(0);
  const bool completed = this->ForEachPointInBatches(count,
    [&](vtkIdType first, vtkIdType last)
    {
      // PacketWidth points at a time (Metric::VolumeFormPacket).
      vtkRiemannForEachPointPacket(output, first, last,
        [&](vtkIdType start, int count, const riemann::PacketVec3& x, riemann::LaneMask lanes)
        {
          double packet[riemann::PacketWidth];
          metric.VolumeFormPacket(x, packet, lanes);
          for (int l = 0; l < count; ++l)
          {
            v[start + l] = std::isfinite(packet[l]) ? packet[l] : vtkMath::Nan();
          }
        });
    });
  if (!completed)
  {
    return false;
  }
  vtkPointData* pd = output->GetPointData();
  pd->AddArray(volume);
  if (!pd->GetScalars())
  {
    pd->SetScalars(volume);
  }

  vtkImageData* image = vtkImageData::SafeDownCast(output);
  if (!image)
  {
    return true;
  }
  // Composite trapezoid rule: per-axis weights, multiplied.
  int dims[3];
  image->GetDimensions(dims);
  double spacing[3];
  image->GetSpacing(spacing);
  const bool generated = this->GetNumberOfInputConnections(0) == 0;
  std::vector<double> weights[3];
  for (int a = 0; a < 3; ++a)
  {
    weights[a].assign(static_cast<size_t>(dims[a]), std::abs(spacing[a]));
    if (dims[a] == 1)
    {
      weights[a][0] = generated ? this->Bounds[2 * a + 1] - this->Bounds[2 * a] : 0.0;
    }
    else
    {
      weights[a].front() *= 0.5;
      weights[a].back() *= 0.5;
    }
  }
  const double orientation = std::abs(image->GetDirectionMatrix()->Determinant());
  // Neumaier summation, point order.
  double sum = 0.0, compensation = 0.0;
  vtkIdType excluded = 0;
  vtkIdType i = 0;
  for (int k = 0; k < dims[2]; ++k)
  {
    for (int j = 0; j < dims[1]; ++j)
    {
      const double wjk = weights[1][j] * weights[2][k];
      for (int l = 0; l < dims[0]; ++l, ++i)
      {
        if (std::isnan(v[i]))
        {
          ++excluded;
          continue;
        }
        const double term = weights[0][l] * wjk * v[i];
        const double t = sum + term;
        compensation += std::abs(sum) >= std::abs(term) ? (sum - t) + term : (term - t) + sum;
        sum = t;
      }
    }
  }
  this->VolumeIntegral = (sum + compensation) * orientation;
  this->NumberOfExcludedPoints = excluded;
  if (excluded > 0)
  {
    vtkWarningMacro(<< excluded << " of " << count
                    << " points have no volume form (degenerate metric): their NaN values "
                       "are left out of VolumeIntegral.");
  }
  vtkNew<vtkDoubleArray> integral;
  integral->SetName("VolumeIntegral");
  integral->SetNumberOfTuples(1);
  integral->SetValue(0, this->VolumeIntegral);
  output->GetFieldData()->AddArray(integral);
  return true;
}

void vtkRiemannVolumeForm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "VolumeIntegral: " << this->VolumeIntegral << "\n";
  os << indent << "NumberOfExcludedPoints: " << this->NumberOfExcludedPoints << "\n";
}
