/**
 * @file PictureValues.h
 * @brief The inside view's camera and picture settings as the app shows and
 * stores them, made from the picture schema (PictureSchema.h) as
 * IntegrationValues.h makes the integration's: the form's fields (label,
 * help, range), the observer camera's values keyed by vtkCamera's property
 * names, and a project's camera object keyed by the schema's project keys.
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
/// The fields of the inside view's form (the settings the schema gives a
/// label), keyed by their VTK property, in the schema's order.
std::vector<PropertySpec> PicturePropertySpecs();

/// The camera's settings keyed by vtkCamera's property (Position,
/// FocalPoint, ViewUp, ViewAngle).
nlohmann::json CameraValues(vtkCamera* camera);

/// True when `key` is one of the camera's properties.
bool IsCameraValue(const std::string& key);

/**
 * Set the camera settings that `values` names on `camera`, if the camera
 * they make still defines a view; else leave it alone and say why ("the
 * camera is at the point it looks at", "the view up is along the view
 * direction").
 */
std::string ApplyCameraValues(const nlohmann::json& values, vtkCamera* camera);

/// Why a camera of these settings defines no view ("" when it does).
std::string CheckCameraView(
  const double position[3], const double focalPoint[3], const double viewUp[3]);
} // namespace studio
} // namespace riemann

#endif
