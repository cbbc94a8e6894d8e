/**
 * @file RiemannImage.h
 * @brief A picture in memory (float channels, row 0 at the top as in image
 * files) and the difference of two, shared by the renderers, the image files
 * (Rendering/ImageIO) and the tests (VTK-free, no image library).
 */
#ifndef RiemannImage_h
#define RiemannImage_h

#include "RiemannRenderingCoreExport.h" // For export macro

#include <string>
#include <vector>

namespace riemann
{
struct Image
{
  int Width = 0;
  int Height = 0;
  int Channels = 0;
  /// Width * Height * Channels floats, row 0 at the top.
  std::vector<float> Pixels;
  /// Names of the channels ("R", "G", "B", "A", or AOVs such as "HitX"), optional.
  std::vector<std::string> ChannelNames;
};

/**
 * Difference between two pictures of the same size: the mean over pixels of
 * the largest per-channel absolute difference, in 8-bit units (0..255) on
 * the first three channels. Returns a negative number when the sizes differ.
 */
RIEMANNRENDERINGCORE_EXPORT double ImageDifference(const Image& a, const Image& b);
} // namespace riemann

#endif
