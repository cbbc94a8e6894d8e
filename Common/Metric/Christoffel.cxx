#include "Christoffel.h"

namespace riemann
{
void ChristoffelFromMetricDerivatives(
  const Mat3& inverseMetric, const Mat3Stack& dg, Mat3Stack& gamma)
{
  // Christoffel symbols of the first kind, lowered[k](i, j) = Gamma_kij.
  Mat3Stack lowered;
  for (int k = 0; k < 3; ++k)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        lowered[k](i, j) = 0.5 * (dg[i](j, k) + dg[j](i, k) - dg[k](i, j));
      }
    }
  }
  for (int m = 0; m < 3; ++m)
  {
    gamma[m] = inverseMetric(m, 0) * lowered[0] + inverseMetric(m, 1) * lowered[1] +
      inverseMetric(m, 2) * lowered[2];
  }
}
} // namespace riemann
