/**
 * @file RiemannImageIO.h
 * @brief Reading, writing and comparing pictures through OpenImageIO
 * (PNG, EXR, and whatever else OpenImageIO reads), VTK-free.
 *
 * Pixels are float RGB(A) in [0, 1] (EXR may exceed 1), row 0 at the top as
 * in image files. Files are written whole or not at all: to a temporary name
 * next to the target, then renamed.
 */
#ifndef RiemannImageIO_h
#define RiemannImageIO_h

#include "RiemannRenderingRayTracingModule.h" // For export macro

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
 * Write `image` to `path` (format from the extension: .png as 8 bits per
 * channel, .exr as 32-bit float with the channel names). Returns "" on
 * success, else the reason.
 */
RIEMANNRENDERINGRAYTRACING_EXPORT std::string WriteImage(
  const std::string& path, const Image& image);

/// Read an image file as float pixels. Returns "" on success, else the reason.
RIEMANNRENDERINGRAYTRACING_EXPORT std::string ReadImage(const std::string& path, Image& image);

/**
 * Difference between two pictures of the same size: the mean over pixels of
 * the largest per-channel absolute difference, in 8-bit units (0..255) on
 * the first three channels. Returns a negative number when the sizes differ.
 */
RIEMANNRENDERINGRAYTRACING_EXPORT double ImageDifference(const Image& a, const Image& b);
} // namespace riemann

#endif
