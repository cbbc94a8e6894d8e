// Shared by the rendering tests: pictures as 8-bit RGB rows (row 0 at the
// bottom, as OpenGL reads them) and the per-pixel difference statistics the
// GPU-against-CPU tests assert on.
#ifndef RiemannImageComparison_h
#define RiemannImageComparison_h

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace riemann
{
namespace testing
{
/// The CPU tracer's "Color" array, rounded as OpenGL stores colours.
inline std::vector<unsigned char> CpuPixels(vtkImageData* image)
{
  vtkDataArray* color = image->GetPointData()->GetArray("Color");
  std::vector<unsigned char> pixels(3 * static_cast<std::size_t>(color->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < color->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = std::clamp(color->GetComponent(i, c), 0.0, 1.0);
      pixels[3 * i + c] = static_cast<unsigned char>(std::lround(255.0 * v));
    }
  }
  return pixels;
}

/// What a rendered window shows (its back buffer).
inline std::vector<unsigned char> WindowPixels(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, pixels);
  return std::vector<unsigned char>(
    pixels->GetPointer(0), pixels->GetPointer(0) + 3 * static_cast<std::size_t>(size[0]) * size[1]);
}

struct DifferenceStatistics
{
  /// Over pixels, of the largest channel difference (0..255).
  double Mean = 0.0;
  double Percentile99 = 0.0;
  /// Fraction of pixels whose largest channel difference exceeds the threshold.
  double FractionAbove = 0.0;
};

inline DifferenceStatistics Compare(
  const std::vector<unsigned char>& a, const std::vector<unsigned char>& b, int threshold)
{
  DifferenceStatistics s;
  const std::size_t n = a.size() / 3;
  std::vector<int> d(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    int m = 0;
    for (int c = 0; c < 3; ++c)
    {
      m = std::max(m, std::abs(int(a[3 * i + c]) - int(b[3 * i + c])));
    }
    d[i] = m;
    s.Mean += m;
    s.FractionAbove += m > threshold ? 1 : 0;
  }
  s.Mean /= n;
  s.FractionAbove /= n;
  std::sort(d.begin(), d.end());
  s.Percentile99 = d[std::min(n - 1, static_cast<std::size_t>(0.99 * n))];
  return s;
}
} // namespace testing
} // namespace riemann

#endif
