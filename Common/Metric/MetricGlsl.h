/**
 * @file MetricGlsl.h
 * @brief The metric part of the ray-tracing shader for a whole metric: its
 * EmitGlsl (GlslSource.h's builder) and the inside-data test, as one source
 * text with its uniform values. The renderers' entry point.
 */
#ifndef RiemannMetricGlsl_h
#define RiemannMetricGlsl_h

#include "GlslSource.h"
#include "Metric.h"
#include "RiemannCommonMetricExport.h"

#include <string>
#include <vector>

namespace riemann
{
/// The metric part of the shader, and its uniform values.
struct MetricGlsl
{
  std::string Source;
  std::vector<GlslUniform> Uniforms;
  std::vector<GlslTexture3D> Textures;
};

/// Emit the metric part of the shader; throws GlslUnsupportedError.
RIEMANNCOMMONMETRIC_EXPORT MetricGlsl EmitMetricGlsl(
  const Metric& metric, const GlslEmitOptions& options = GlslEmitOptions());
} // namespace riemann

#endif
