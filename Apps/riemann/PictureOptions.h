/**
 * @file PictureOptions.h
 * @brief `riemann render`'s camera and picture options, made from the
 * picture schema (Common/Metric/PictureSchema.h): flag, help, unit and valid
 * values are the schema's, so the options refuse what a scene's "camera"
 * block and riemann-studio's form refuse, in the same words.
 */
#ifndef RiemannCliPictureOptions_h
#define RiemannCliPictureOptions_h

#include "PictureSchema.h"

#include <CLI/CLI.hpp>

#include <string>

namespace riemann
{
namespace cli
{
/**
 * Where the options' values go. The camera's are empty (0 for the view
 * angle, "" for the projection) when not given: the scene's camera, else the
 * schema's, is used. The picture's start at the schema's defaults.
 */
struct PictureOptions
{
  std::string* Position = nullptr;
  std::string* LookAt = nullptr;
  std::string* ViewUp = nullptr;
  double* ViewAngle = nullptr;
  std::string* Projection = nullptr;
  /// --equirectangular, the short form of --projection equirectangular.
  bool* Equirectangular = nullptr;
  int* Width = nullptr;
  int* Height = nullptr;
  int* Samples = nullptr;
  std::string* Backend = nullptr;
  std::string* GPUPath = nullptr;
};

/// The options of the picture's size, samples and renderer (--width,
/// --height, --samples, --backend, --gpu-path), in the schema's order.
void AddPictureOutputOptions(CLI::App* command, const PictureOptions& options);

/// The camera's options (--camera-position, --look-at, --view-up, --fov,
/// --projection and --equirectangular), in the schema's order.
void AddCameraOptions(CLI::App* command, const PictureOptions& options);

/// The option's check: the setting's valid values in the picture schema.
CLI::Validator InPictureSchema(const PictureSetting& setting);
} // namespace cli
} // namespace riemann

#endif
