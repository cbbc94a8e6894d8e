/**
 * @file MetricParameters.h
 * @brief A definition's parameters given other values, without editing its text by hand.
 *
 * A user interface that shows a metric's parameters as controls of their own
 * (ParaView's panel of vtkRiemannMetricSource) keeps the definition as the
 * user wrote it and gives the values it overrides separately; this makes the
 * definition those values stand for.
 */
#ifndef MetricParameters_h
#define MetricParameters_h

#include "RiemannCommonMetricFormatExport.h"

#include <string>
#include <vector>

namespace riemann
{
/// A value given to one of a definition's top-level "parameters".
struct ParameterValue
{
  std::string Name;
  double Value = 0.0;
};

/**
 * `json` with each named top-level parameter set to its value (an animated
 * one, {"from": a, "to": b}, becomes that constant). With no values, `json`
 * itself, byte for byte. Text that is not a JSON object is returned as it
 * is, for the metric parser to say where it is wrong. Throws
 * MetricDefinitionError when a value is not finite or names a parameter the
 * definition does not have (the message lists those it has).
 */
RIEMANNCOMMONMETRICFORMAT_EXPORT std::string WithParameterValues(
  const std::string& json, const std::vector<ParameterValue>& values);

/// The names of the definition's top-level parameters, in its order ("" text: none).
RIEMANNCOMMONMETRICFORMAT_EXPORT std::vector<std::string> ParameterNames(const std::string& json);
} // namespace riemann

#endif
