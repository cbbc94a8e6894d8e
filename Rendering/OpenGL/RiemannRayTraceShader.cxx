#include "RiemannRayTraceShader.h"

#include "RiemannMeshBVH.h"
#include "RiemannScene.h"
#include "RiemannSceneUniforms.h"

#include "RiemannRayTraceCS.h"
#include "RiemannRayTraceFS.h"
#include "RiemannRayTraceIntegrators.h"
#include "RiemannRayTraceMeshes.h"
#include "RiemannRayTracePixel.h"
#include "RiemannRayTraceScene.h"

#include <sstream>

namespace riemann
{
namespace
{
void Fill(std::string& text, const std::string& placeholder, const std::string& value)
{
  const std::size_t at = text.find(placeholder);
  if (at != std::string::npos)
  {
    text.replace(at, placeholder.size(), value);
  }
}

/// The scene's limits and the choices, as the templates read them.
std::string Constants(const RayTraceShaderChoices& choices)
{
  std::ostringstream constants;
  constants << "// Scene limits (RiemannScene.h).\n"
            << "#define RT_MAX_SPHERES " << MaximumSpheres << "\n"
            << "#define RT_MAX_PLANES " << MaximumPlanes << "\n"
            << "#define RT_MAX_BOXES " << MaximumBoxes << "\n"
            << "#define RT_MAX_GRIDS " << MaximumGrids << "\n"
            << "#define RT_MAX_OBJECTS " << MaximumSceneUniformObjects << "\n"
            << "// 0: Euler, 1: RK4, 2: adaptive Dormand-Prince 5(4).\n"
            << "#define RT_INTEGRATOR " << choices.Integrator << "\n"
            << "// Triangle meshes (RiemannRayTraceMeshes.glsl) and their traversal stack.\n"
            << "#define RT_MESHES " << (choices.Meshes ? 1 : 0) << "\n"
            << "#define RT_MESH_STACK " << MeshBVHStackSize << "\n";
  if (choices.Compute)
  {
    constants << "// The compute path's workgroup (a tile of pixels).\n"
              << "#define RT_GROUP_X " << choices.Group[0] << "\n"
              << "#define RT_GROUP_Y " << choices.Group[1] << "\n"
              << "#define RT_GROUP_INVOCATIONS " << choices.Group[0] * choices.Group[1] << "\n";
  }
  return constants.str();
}
}

std::string ComposeRayTraceShader(
  const RayTraceShaderChoices& choices, const std::string& metricSource, const std::string& extra)
{
  std::string source = choices.Compute ? RiemannRayTraceCS : RiemannRayTraceFS;
  Fill(source, "//RT::Version::Dec", "#version 430 core");
  Fill(source, "//RT::Constants::Dec", Constants(choices));
  Fill(source, "//RT::Metric::Impl", metricSource);
  Fill(source, "//RT::Meshes::Impl", choices.Meshes ? RiemannRayTraceMeshes : "");
  Fill(source, "//RT::Scene::Impl", RiemannRayTraceScene);
  Fill(source, "//RT::Integrators::Impl", RiemannRayTraceIntegrators);
  Fill(source, "//RT::Extra::Impl", extra.empty() ? "" : "// ExtraShaderCode\n" + extra);
  Fill(source, "//RT::Pixel::Impl", RiemannRayTracePixel);
  return source;
}
}
