#include "vtkRiemannCurvatureField.h"

#include "Curvature.h"
#include "PacketCurvature.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRiemannPointPackets.h"

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
      // PacketWidth points at a time (the packet curvature, PacketCurvature.h).
      constexpr double nan = std::numeric_limits<double>::quiet_NaN();
      vtkIdType bad = 0;
      vtkRiemannForEachPointPacket(output, first, last,
        [&](vtkIdType start, int count, const riemann::PacketVec3& x, riemann::LaneMask lanes)
        {
          riemann::PacketCurvature c;
          const riemann::LaneMask defined = riemann::ComputeCurvature(metric, x, lanes, c);
          for (int l = 0; l < count; ++l)
          {
            const vtkIdType i = start + l;
            if (!riemann::HasLane(defined, l))
            {
              ++bad;
              s[i] = kxy[i] = kxz[i] = kyz[i] = kmin[i] = kmax[i] = rn[i] = nan;
              std::fill(ric + 6 * i, ric + 6 * i + 6, nan);
              continue;
            }
            s[i] = c.Scalar[l];
            // VTK's symmetric tensor order: XX YY ZZ XY YZ XZ.
            double* t = ric + 6 * i;
            t[0] = c.Ricci.C[riemann::XX][l];
            t[1] = c.Ricci.C[riemann::YY][l];
            t[2] = c.Ricci.C[riemann::ZZ][l];
            t[3] = c.Ricci.C[riemann::XY][l];
            t[4] = c.Ricci.C[riemann::YZ][l];
            t[5] = c.Ricci.C[riemann::XZ][l];
            kxy[i] = c.SectionalXY[l];
            kxz[i] = c.SectionalXZ[l];
            kyz[i] = c.SectionalYZ[l];
            kmin[i] = c.SectionalMin[l];
            kmax[i] = c.SectionalMax[l];
            rn[i] = c.RiemannNorm[l];
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
