/**
 * @file PictureSchema.h
 * @brief Every setting of the inside view's camera and of the picture made
 * from it, described once: its name on each surface, its type, its
 * default, its valid values, its unit and its help. The integration of the
 * rays is declared with vtkRiemannIntegrationSettings
 * (vtkRiemannIntegrationSettings.settings.json); together they are the
 * settings of a picture.
 *
 * What is made from this table, and nowhere else decided:
 * - the defaults of CameraSettings (ObserverCamera.h);
 * - the keys, checks and error words of a scene's "camera" block
 *   (RiemannSceneParser.cxx, SceneFormat.md);
 * - the camera and picture options of `riemann render` (flag, help, range);
 * - riemann-studio's inside-view form (label, help, range), the keys of a
 *   project's "observer" and "inside" objects, and the Python it exports
 *   (vtkCamera's and the renderers' property names).
 *
 * One range per setting on every surface: a view angle is in (0, 179]
 * degrees because vtkCamera clamps larger ones silently (a scene said
 * (0, 180) and the CLI (0, 179] before this table).
 */
#ifndef RiemannPictureSchema_h
#define RiemannPictureSchema_h

#include "RiemannCommonObserverExport.h"
#include "SettingRange.h"

#include <array>
#include <string>
#include <vector>

namespace riemann
{
/// One camera or picture setting.
struct PictureSetting
{
  enum Kind
  {
    Point,     ///< three finite numbers X,Y,Z
    Direction, ///< three finite numbers X,Y,Z, not all zero
    Number,    ///< a real number in Range
    Count,     ///< a whole number in Range
    Choice     ///< one of Choices, by name
  };
  /// Member of CameraSettings ("" for a setting of the picture, not the camera).
  const char* Core;
  /// The VTK property: vtkCamera's for the camera (Set<Property>), the
  /// renderers' (vtkRiemannRayTracePass, vtkRiemannCPURayTracer) for the
  /// rest; Backend is riemann-studio's inside view's (which renderer).
  const char* Property;
  /// Key in a scene's "camera" block ("" where a scene does not set it).
  const char* SceneKey;
  /// Key in a project's "observer" (camera) or "inside" (picture) object ("" where none).
  const char* ProjectKey;
  /// Option of `riemann render` ("" where none).
  const char* Flag;
  /// riemann-studio's label ("" where the app's inside-view form has no field for it).
  const char* Label;
  Kind Type;
  /// The default: a point or direction; a number in [0]; a choice's index in [0].
  std::array<double, 3> Default;
  /// The valid values of a Number or a Count.
  SettingRange Range;
  /// A Choice's names, separated by '|' (the default is Default[0]'s).
  const char* Choices;
  /// One line, without the unit or range (every surface shows those from the fields above).
  const char* Help;
};

/// The settings, in the order every surface lists them.
enum class PictureSettingId
{
  Position,
  LookAt,
  ViewUp,
  ViewAngle,
  Projection,
  Width,
  Height,
  Samples,
  Backend,
  GPUPath
};

namespace detail
{
constexpr SettingRange NoRange{ 0.0, false, 0.0, false, "" };
}

constexpr std::array<PictureSetting, 10> PictureSchema{ {
  { "Position", "Position", "position", "position", "--camera-position", "Position",
    PictureSetting::Point, { 0, 0, 5 }, detail::NoRange, "", "Where the observer stands" },
  { "LookAt", "FocalPoint", "look_at", "focal-point", "--look-at", "Looks at",
    PictureSetting::Point, { 0, 0, 0 }, detail::NoRange, "",
    "The point the observer looks at" },
  { "ViewUp", "ViewUp", "view_up", "view-up", "--view-up", "View up", PictureSetting::Direction,
    { 0, 1, 0 }, detail::NoRange, "", "Up in the picture (not along the view)" },
  { "ViewAngle", "ViewAngle", "fov", "view-angle", "--fov", "View angle", PictureSetting::Number,
    { 60, 0, 0 }, { 0.0, true, 179.0, false, "degrees" }, "",
    "Vertical field of view of a perspective picture" },
  { "Mode", "Projection", "projection", "", "--projection", "", PictureSetting::Choice,
    { 0, 0, 0 }, detail::NoRange, "perspective|equirectangular",
    "perspective, or equirectangular (360 x 180 degrees about the view up)" },
  { "", "Width", "", "", "--width", "", PictureSetting::Count, { 640, 0, 0 },
    { 1.0, false, 16384.0, true, "pixels" }, "", "Picture width" },
  { "", "Height", "", "", "--height", "", PictureSetting::Count, { 480, 0, 0 },
    { 1.0, false, 16384.0, true, "pixels" }, "", "Picture height" },
  { "", "SamplesPerPixel", "", "samples", "--samples", "Samples (CPU)", PictureSetting::Count,
    { 1, 0, 0 }, { 1.0, false, 4096.0, true, "" }, "",
    "Rays per pixel, stratified (anti-aliasing; the CPU renderer)" },
  { "", "Backend", "", "backend", "--backend", "Renderer", PictureSetting::Choice, { 0, 0, 0 },
    detail::NoRange, "gpu|cpu",
    "gpu: the GLSL pass (vtkRiemannRayTracePass; every scene object, meshes included); cpu: "
    "Embree (vtkRiemannCPURayTracer: double precision, samples, EXR with AOVs)" },
  { "", "GPUPath", "", "", "--gpu-path", "", PictureSetting::Choice, { 0, 0, 0 },
    detail::NoRange, "auto|fragment|compute",
    "The GPU pass's shader path: auto (compute where the OpenGL context has 4.3 compute "
    "shaders, else fragment); the same picture either way" },
} };

constexpr const PictureSetting& PictureSettingOf(PictureSettingId id)
{
  return PictureSchema[static_cast<std::size_t>(id)];
}

/// A Choice's names, in order ({"perspective", "equirectangular"}).
RIEMANNCOMMONOBSERVER_EXPORT std::vector<std::string> PictureChoices(const PictureSetting& setting);

/// The index of `name` among a Choice's names; -1 when it is none of them.
RIEMANNCOMMONOBSERVER_EXPORT int PictureChoiceIndex(
  const PictureSetting& setting, const std::string& name);

/// The name of a Choice's default ("perspective").
RIEMANNCOMMONOBSERVER_EXPORT std::string PictureDefaultChoice(const PictureSetting& setting);

/// The valid values as words: "a number above 0 and at most 179 (degrees)",
/// "perspective or equirectangular", "three numbers X,Y,Z, not all 0".
RIEMANNCOMMONOBSERVER_EXPORT std::string DescribePictureValues(const PictureSetting& setting);

/// The valid values in brief: "(0, 179]", "perspective|equirectangular", "X,Y,Z".
RIEMANNCOMMONOBSERVER_EXPORT std::string PictureInterval(const PictureSetting& setting);

/**
 * "" when `value` is valid for a Number or Count `setting`; else why not,
 * naming it `name` ("scene.camera.fov is 180: expected a number above 0 and
 * at most 179 (degrees)").
 */
RIEMANNCOMMONOBSERVER_EXPORT std::string CheckPictureValue(
  const PictureSetting& setting, double value, const std::string& name);

/**
 * "" when `value` is valid for a Point or Direction `setting` (finite; a
 * direction not zero); else why not, naming it `name`.
 */
RIEMANNCOMMONOBSERVER_EXPORT std::string CheckPictureVector(
  const PictureSetting& setting, const double value[3], const std::string& name);
} // namespace riemann

#endif
