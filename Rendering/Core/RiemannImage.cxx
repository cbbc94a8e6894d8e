#include "RiemannImage.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace riemann
{
double ImageDifference(const Image& a, const Image& b)
{
  if (a.Width != b.Width || a.Height != b.Height || a.Channels < 3 || b.Channels < 3)
  {
    return -1.0;
  }
  double total = 0.0;
  const std::size_t pixels = static_cast<std::size_t>(a.Width) * a.Height;
  for (std::size_t i = 0; i < pixels; ++i)
  {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst,
        std::abs(double(a.Pixels[i * a.Channels + c]) - double(b.Pixels[i * b.Channels + c])));
    }
    total += worst;
  }
  return pixels ? 255.0 * total / pixels : 0.0;
}
} // namespace riemann
