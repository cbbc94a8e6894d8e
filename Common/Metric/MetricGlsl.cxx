#include "MetricGlsl.h"

namespace riemann
{
MetricGlsl EmitMetricGlsl(const Metric& metric, const GlslEmitOptions& options)
{
  GlslBuilder builder(options);
  metric.EmitGlsl(builder);
  const std::string& inside = builder.GetInsideDataFunction();
  builder.AddFunction("bool rt_metric_inside(vec3 p)\n"
                      "{\n"
                      "  return " +
    (inside.empty() ? std::string("true") : inside + "(p)") + ";\n}\n");
  return { builder.Source(), builder.GetUniforms(), builder.GetTextures() };
}
} // namespace riemann
