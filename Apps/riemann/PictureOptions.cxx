#include "PictureOptions.h"

#include "CliUtilities.h"

namespace riemann
{
namespace cli
{
namespace
{
const PictureSetting& Of(PictureSettingId id)
{
  return PictureSettingOf(id);
}

/// The help: the schema's line, and where the default comes from.
std::string Help(PictureSettingId id, const std::string& byDefault)
{
  return std::string(Of(id).Help) + " (default: " + byDefault + ")";
}

/// "640 pixels", "60 degrees".
std::string DefaultNumber(PictureSettingId id)
{
  const std::string unit = Of(id).Range.Unit;
  return FormatNumber(Of(id).Default[0]) + (unit.empty() ? "" : " " + unit);
}

std::string DefaultVector(PictureSettingId id)
{
  const auto& v = Of(id).Default;
  return FormatNumber(v[0]) + "," + FormatNumber(v[1]) + "," + FormatNumber(v[2]);
}
} // namespace

CLI::Validator InPictureSchema(const PictureSetting& setting)
{
  switch (setting.Type)
  {
    case PictureSetting::Point:
      return Point3();
    case PictureSetting::Direction:
      return Direction3();
    case PictureSetting::Choice:
      return Checked(
        [&setting](const std::string& text) -> std::string
        {
          return PictureChoiceIndex(setting, text) >= 0
            ? std::string()
            : "expected " + DescribePictureValues(setting) + ", got \"" + text + "\"";
        },
        PictureInterval(setting));
    default:
      return Checked(
        [&setting](const std::string& text) -> std::string
        {
          double value = 0.0;
          if (CLI::detail::lexical_cast(text, value) &&
            CheckPictureValue(setting, value, text).empty())
          {
            return std::string();
          }
          return "expected " + DescribePictureValues(setting) + ", got \"" + text + "\"";
        },
        "in " + PictureInterval(setting));
  }
}

void AddPictureOutputOptions(CLI::App* command, const PictureOptions& options)
{
  using Id = PictureSettingId;
  command
    ->add_option(Of(Id::Width).Flag, *options.Width, Help(Id::Width, DefaultNumber(Id::Width)))
    ->check(InPictureSchema(Of(Id::Width)));
  command
    ->add_option(Of(Id::Height).Flag, *options.Height, Help(Id::Height, DefaultNumber(Id::Height)))
    ->check(InPictureSchema(Of(Id::Height)));
  command
    ->add_option(
      Of(Id::Samples).Flag, *options.Samples, Help(Id::Samples, DefaultNumber(Id::Samples)))
    ->check(InPictureSchema(Of(Id::Samples)));
  command
    ->add_option(Of(Id::Backend).Flag, *options.Backend,
      Help(Id::Backend, PictureDefaultChoice(Of(Id::Backend))))
    ->check(InPictureSchema(Of(Id::Backend)));
  command
    ->add_option(Of(Id::GPUPath).Flag, *options.GPUPath,
      Help(Id::GPUPath, PictureDefaultChoice(Of(Id::GPUPath))))
    ->check(InPictureSchema(Of(Id::GPUPath)));
}

void AddCameraOptions(CLI::App* command, const PictureOptions& options)
{
  using Id = PictureSettingId;
  const auto sceneElse = [](const std::string& value)
  { return "the scene's camera, else " + value; };
  command
    ->add_option(Of(Id::Position).Flag, *options.Position,
      Help(Id::Position, sceneElse(DefaultVector(Id::Position))))
    ->check(InPictureSchema(Of(Id::Position)));
  command
    ->add_option(
      Of(Id::LookAt).Flag, *options.LookAt, Help(Id::LookAt, sceneElse(DefaultVector(Id::LookAt))))
    ->check(InPictureSchema(Of(Id::LookAt)));
  command
    ->add_option(
      Of(Id::ViewUp).Flag, *options.ViewUp, Help(Id::ViewUp, sceneElse(DefaultVector(Id::ViewUp))))
    ->check(InPictureSchema(Of(Id::ViewUp)));
  // VTK's camera clamps its view angle to 179 degrees: the schema refuses more.
  command
    ->add_option(Of(Id::ViewAngle).Flag, *options.ViewAngle,
      Help(Id::ViewAngle, sceneElse(DefaultNumber(Id::ViewAngle))))
    ->check(InPictureSchema(Of(Id::ViewAngle)));
  command
    ->add_option(Of(Id::Projection).Flag, *options.Projection,
      Help(Id::Projection, sceneElse(PictureDefaultChoice(Of(Id::Projection)))))
    ->check(InPictureSchema(Of(Id::Projection)));
  command->add_flag("--equirectangular", *options.Equirectangular,
    "The short form of --projection equirectangular");
}
} // namespace cli
} // namespace riemann
