/**
 * @file RiemannImageIO.h
 * @brief Reading and writing pictures through OpenImageIO (PNG, EXR, and
 * whatever else OpenImageIO reads), VTK-free; the only user of OpenImageIO.
 *
 * Pixels are float RGB(A) in [0, 1] (EXR may exceed 1), row 0 at the top as
 * in image files. Files are written whole or not at all: to a temporary name
 * next to the target, then renamed.
 */
#ifndef RiemannImageIO_h
#define RiemannImageIO_h

#include "RiemannImage.h"
#include "RiemannRenderingImageIOExport.h" // For export macro
#include "RiemannShading.h"     // For EnvironmentMap

#include <string>
#include <vector>

namespace riemann
{

/**
 * Write `image` to `path` (format from the extension: .png as 8 bits per
 * channel, .exr as 32-bit float with the channel names). Returns "" on
 * success, else the reason.
 */
RIEMANNRENDERINGIMAGEIO_EXPORT std::string WriteImage(
  const std::string& path, const Image& image);

/// Read an image file as float pixels. Returns "" on success, else the reason.
RIEMANNRENDERINGIMAGEIO_EXPORT std::string ReadImage(const std::string& path, Image& image);

/// Read an image file into an environment map (EnvironmentMap::SetImage). "" or the reason.
RIEMANNRENDERINGIMAGEIO_EXPORT std::string ReadEnvironmentMap(
  const std::string& path, EnvironmentMap& map);
} // namespace riemann

#endif
