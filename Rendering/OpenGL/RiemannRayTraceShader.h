/**
 * @file RiemannRayTraceShader.h
 * @brief The ray-tracing program's source, composed in one place: the
 * fragment or compute template (RiemannRayTraceFS.glsl,
 * RiemannRayTraceCS.glsl) with the scene's limits and the compile-time
 * choices as #defines, the metric's part (riemann::EmitMetricGlsl, written
 * through Common/Glsl's builder), the scene, meshes, integrators and pixel
 * parts, and a user's extra code. Needs no OpenGL context, so the composed
 * text is tested and printed without a GPU; vtkRiemannRayTracePass compiles
 * it and caches programs by it.
 */
#ifndef RiemannRayTraceShader_h
#define RiemannRayTraceShader_h

#include "RiemannRenderingOpenGLModule.h" // For export macro (tested without a GPU)

#include <string>

namespace riemann
{
/// The program's compile-time choices (a new camera, t or scene object changes none of them).
struct RayTraceShaderChoices
{
  /// 0: Euler, 1: RK4, 2: adaptive Dormand-Prince 5(4) (RayIntegrator).
  int Integrator = 1;
  /// The scene has triangle meshes (their traversal is compiled in).
  bool Meshes = false;
  /// The compute path (RiemannRayTraceCS.glsl), else the fragment path.
  bool Compute = false;
  /// The compute path's workgroup, in pixels (0 on the fragment path).
  int Group[2] = { 0, 0 };

  bool operator==(const RayTraceShaderChoices& other) const
  {
    return this->Integrator == other.Integrator && this->Meshes == other.Meshes &&
      this->Compute == other.Compute && this->Group[0] == other.Group[0] &&
      this->Group[1] == other.Group[1];
  }
  bool operator!=(const RayTraceShaderChoices& other) const { return !(*this == other); }
};

/**
 * The whole program for `choices`, with `metricSource` (EmitMetricGlsl's
 * Source) and `extra` (vtkRiemannRayTracePass::ExtraShaderCode, "" for none).
 * Every template's placeholder is filled.
 */
RIEMANNRENDERINGOPENGL_EXPORT std::string ComposeRayTraceShader(
  const RayTraceShaderChoices& choices, const std::string& metricSource, const std::string& extra);
}

#endif
