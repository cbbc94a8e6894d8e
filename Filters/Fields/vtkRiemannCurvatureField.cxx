#include "vtkRiemannCurvatureField.h"

#include "Curvature.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <atomic>
#include <limits>

vtkStandardNewMacro(vtkRiemannCurvatureField);

bool vtkRiemannCurvatureField::ComputeFields(const riemann::Metric& metric, vtkDataSet* output)
{
  const vtkIdType count = output->GetNumberOfPoints();
  auto scalar = NewPointArray("ScalarCurvature", 1, count);
  auto ricci = NewPointArray("Ricci", 6, count);
  auto sectionalXY = NewPointArray("SectionalXY", 1, count);
  auto sectionalXZ = NewPointArray("SectionalXZ", 1, count);
  auto sectionalYZ = NewPointArray("SectionalYZ", 1, count);
  auto sectionalMin = NewPointArray("SectionalMin", 1, count);
  auto sectionalMax = NewPointArray("SectionalMax", 1, count);
  auto norm = NewPointArray("RiemannNorm", 1, count);

  double* s = scalar->GetPointer(0);
  double* ric = ricci->GetPointer(0);
  double* kxy = sectionalXY->GetPointer(0);
  double* kxz = sectionalXZ->GetPointer(0);
  double* kyz = sectionalYZ->GetPointer(0);
  double* kmin = sectionalMin->GetPointer(0);
  double* kmax = sectionalMax->GetPointer(0);
  double* rn = norm->GetPointer(0);
  std::atomic<vtkIdType> undefined{ 0 };
  const bool completed = this->ForEachPointInBatches(count,
    [&](vtkIdType first, vtkIdType last)
    {
      constexpr double nan = std::numeric_limits<double>::quiet_NaN();
      riemann::CurvatureSample sample;
      vtkIdType bad = 0;
      for (vtkIdType i = first; i < last; ++i)
      {
        double x[3];
        output->GetPoint(i, x);
        if (!riemann::ComputeCurvature(metric, riemann::Vec3(x[0], x[1], x[2]), sample))
        {
          ++bad;
          s[i] = kxy[i] = kxz[i] = kyz[i] = kmin[i] = kmax[i] = rn[i] = nan;
          std::fill(ric + 6 * i, ric + 6 * i + 6, nan);
          continue;
        }
        const riemann::Mat3& r = sample.Ricci;
        s[i] = sample.Scalar;
        double* t = ric + 6 * i;
        t[0] = r(0, 0);
        t[1] = r(1, 1);
        t[2] = r(2, 2);
        t[3] = r(0, 1);
        t[4] = r(1, 2);
        t[5] = r(0, 2);
        kxy[i] = sample.SectionalXY;
        kxz[i] = sample.SectionalXZ;
        kyz[i] = sample.SectionalYZ;
        kmin[i] = sample.SectionalMin;
        kmax[i] = sample.SectionalMax;
        rn[i] = sample.RiemannNorm;
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
                    << " points have no curvature (degenerate metric or no second "
                       "derivatives there): their values are NaN.");
  }
  vtkPointData* pd = output->GetPointData();
  pd->AddArray(scalar);
  if (!pd->GetScalars())
  {
    pd->SetScalars(scalar);
  }
  pd->AddArray(ricci);
  pd->AddArray(sectionalXY);
  pd->AddArray(sectionalXZ);
  pd->AddArray(sectionalYZ);
  pd->AddArray(sectionalMin);
  pd->AddArray(sectionalMax);
  pd->AddArray(norm);
  return true;
}

void vtkRiemannCurvatureField::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
