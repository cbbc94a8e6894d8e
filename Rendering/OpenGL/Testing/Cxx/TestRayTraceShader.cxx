// The ray-tracing program's source as RiemannRayTraceShader.h composes it,
// without a GPU: every placeholder of both templates filled, the choices
// as #defines, the metric's part and the extra code in it once, the
// meshes' traversal only where the scene has meshes.
#include "RiemannRayTraceShader.h"

#include "EuclideanMetric.h"
#include "MetricGlsl.h"

#include <gtest/gtest.h>

#include <string>

namespace
{
int Count(const std::string& text, const std::string& part)
{
  int count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1))
  {
    ++count;
  }
  return count;
}
}

TEST(RayTraceShader, EveryChoiceFillsEveryPlaceholder)
{
  const std::string metric = riemann::EmitMetricGlsl(riemann::EuclideanMetric()).Source;
  ASSERT_NE(metric.find("rt_metric_acceleration"), std::string::npos);
  const std::string extra = "vec3 user_extra_colour() { return vec3(1.0); }";
  for (int integrator = 0; integrator < 3; ++integrator)
  {
    for (bool meshes : { false, true })
    {
      for (bool compute : { false, true })
      {
        riemann::RayTraceShaderChoices choices;
        choices.Integrator = integrator;
        choices.Meshes = meshes;
        choices.Compute = compute;
        choices.Group[0] = compute ? 8 : 0;
        choices.Group[1] = compute ? 4 : 0;
        const std::string source = riemann::ComposeRayTraceShader(choices, metric, extra);
        SCOPED_TRACE("integrator " + std::to_string(integrator) + (meshes ? ", meshes" : "") +
          (compute ? ", compute" : ", fragment"));
        EXPECT_EQ(Count(source, "//RT::"), 0);
        EXPECT_EQ(Count(source, "#define RT_INTEGRATOR " + std::to_string(integrator) + "\n"), 1);
        EXPECT_EQ(Count(source, "#define RT_MESHES " + std::string(meshes ? "1" : "0") + "\n"), 1);
        EXPECT_EQ(Count(source, metric), 1);
        EXPECT_EQ(Count(source, extra), 1);
        // The meshes' traversal (RiemannRayTraceMeshes.glsl) only with meshes.
        EXPECT_EQ(Count(source, "bool rt_overlaps_box(") == 1, meshes);
        if (compute)
        {
          EXPECT_EQ(source.rfind("#version 430 core", 0), 0u);
          EXPECT_EQ(Count(source, "#define RT_GROUP_INVOCATIONS 32\n"), 1);
        }
        else
        {
          // VTK's shader program declares the fragment path's version and outputs.
          EXPECT_EQ(Count(source, "#define RT_GROUP_X"), 0);
        }
      }
    }
  }
}

TEST(RayTraceShader, NoExtraCodeAddsNothing)
{
  riemann::RayTraceShaderChoices choices;
  const std::string without = riemann::ComposeRayTraceShader(choices, "// metric\n", "");
  EXPECT_EQ(Count(without, "ExtraShaderCode"), Count(riemann::ComposeRayTraceShader(choices, "", ""), "ExtraShaderCode"));
  EXPECT_EQ(Count(without, "// metric\n"), 1);
  // The same choices and texts: the same program text (programs are cached by it).
  EXPECT_EQ(without, riemann::ComposeRayTraceShader(choices, "// metric\n", ""));
  riemann::RayTraceShaderChoices other = choices;
  other.Integrator = 2;
  EXPECT_NE(choices, other);
  EXPECT_NE(without, riemann::ComposeRayTraceShader(other, "// metric\n", ""));
}
