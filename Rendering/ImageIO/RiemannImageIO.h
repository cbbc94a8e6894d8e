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

#include <stdexcept>
#include <string>
#include <vector>

namespace riemann
{

/**
 * Why a picture could not be read or written, naming the file: the base
 * layer's convention (Documentation/ErrorConventions.md), as the metric and
 * scene readers' errors.
 */
class RIEMANNRENDERINGIMAGEIO_EXPORT ImageFileError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/**
 * Write `image` to `path` (format from the extension: .png as 8 bits per
 * channel, .exr as 32-bit float with the channel names). Throws
 * ImageFileError, and then nothing is left at `path`.
 */
RIEMANNRENDERINGIMAGEIO_EXPORT void WriteImage(const std::string& path, const Image& image);

/// Read an image file as float pixels; throws ImageFileError.
RIEMANNRENDERINGIMAGEIO_EXPORT Image ReadImage(const std::string& path);

/// Read an image file as an environment map (EnvironmentMap::SetImage); throws ImageFileError.
RIEMANNRENDERINGIMAGEIO_EXPORT EnvironmentMap ReadEnvironmentMap(const std::string& path);
} // namespace riemann

#endif
