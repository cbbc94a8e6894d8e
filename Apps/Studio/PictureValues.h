/**
 * @file PictureValues.h
 * @brief The inside view's camera and picture settings as the app shows and
 * stores them, made from their declaration
 * (vtkRiemannPictureSettings.settings.json) as IntegrationValues.h makes the
 * integration's: the form's fields (label, help, range), the observer
 * camera's values and a project's "observer" and "inside" objects, all keyed
 * by vtkRiemannPictureSettings's property names (a project of an older
 * version keyed them "focal-point", "view-angle", "samples": those are the
 * declared project aliases, still read).
 */
#ifndef RiemannStudioPictureValues_h
#define RiemannStudioPictureValues_h

#include "PipelineItem.h" // For PropertySpec

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

class vtkCamera;

namespace riemann
{
namespace studio
{
/// The fields of the inside view's form: the observer's camera, the
/// samples and the renderer (the declared settings the app lets one set
/// there), in the declaration's order.
std::vector<PropertySpec> PicturePropertySpecs();

/// The camera's settings (Position, LookAt, ViewUp, ViewAngle).
nlohmann::json CameraValues(vtkCamera* camera);

/**
 * Set the camera settings that `values` names on `camera`, if the camera
 * they make still defines a view; else leave it alone and say why ("the
 * camera is at the point it looks at", "the view up is along the view
 * direction").
 */
std::string ApplyCameraValues(const nlohmann::json& values, vtkCamera* camera);

/**
 * The picture settings `names` of a project's object (`where`: "observer",
 * "inside"), each under its name or a declared project alias, those it does
 * not give at their defaults. Sets `error` to the first bad value
 * ("observer.view-angle is 180: expected a number above 0 and at most 179
 * (degrees)") and returns null then.
 */
nlohmann::json ReadPictureValues(const nlohmann::json& object,
  const std::vector<std::string>& names, const std::string& where, std::string& error);

/// Why a camera of these settings (CameraValues' keys) defines no view ("" when it does).
std::string CheckCameraValues(const nlohmann::json& values);
} // namespace studio
} // namespace riemann

#endif
