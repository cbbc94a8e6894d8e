// libFuzzer target: arbitrary text into the scene parser, riemann::ParseScene
// (RiemannSceneParser.h), then what a renderer does with a scene it accepted:
// camera rays marched in straight steps through IntersectSegment, and
// SurfaceColor at each hit. Refusing the text with SceneDefinitionError is
// the expected outcome for most inputs; crashes, hangs (libFuzzer's
// -timeout), leaks and sanitizer reports are failures, and so is an accepted
// scene that breaks what the headers promise (checked with __builtin_trap).
//
// Relative file names (a metric, a mesh, an environment image) resolve
// against Data/scenes, so the seeds' "../metrics/NAME.json" are read as the
// CLI reads them.
#include "EuclideanMetric.h"
#include "ObserverCamera.h"
#include "RiemannScene.h"
#include "RiemannSceneIntersection.h"
#include "RiemannSceneParser.h"
#include "RiemannShading.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#ifndef RIEMANN_FUZZ_SCENE_BASE
#define RIEMANN_FUZZ_SCENE_BASE "."
#endif

namespace
{
bool InUnit(double value)
{
  return value >= 0 && value <= 1;
}

void CheckScene(const riemann::Scene& scene)
{
  // Numbers the parser promises: finite, positive where a size.
  const riemann::RaySettings& rays = scene.Rays;
  if (!(rays.Step > 0) || !std::isfinite(rays.Step) || rays.MaximumSteps < 1 ||
    !(rays.MaximumLength > 0) || !(rays.Tolerance > 0) || !(scene.FogDensity >= 0))
  {
    __builtin_trap();
  }
  for (const riemann::SceneObject& object : scene.Objects)
  {
    if (object.Type == riemann::ObjectType::Plane && std::abs(object.B.norm() - 1) > 1e-9)
    {
      __builtin_trap();
    }
    if (object.Type == riemann::ObjectType::Grid &&
      !(object.Thickness > 0 && object.Thickness < object.Spacing))
    {
      __builtin_trap();
    }
  }
}

/// Straight rays from the camera (what a flat metric shows), a few pixels.
void MarchRays(const riemann::Scene& scene)
{
  const riemann::EuclideanMetric flat;
  riemann::ObserverCamera camera(flat, scene.HasCamera ? scene.Camera : riemann::CameraSettings());
  constexpr int Size = 3;
  constexpr int Steps = 64;
  const double step = std::fmin(scene.Rays.Step, scene.Rays.MaximumLength);
  for (int row = 0; row < Size; ++row)
  {
    for (int column = 0; column < Size; ++column)
    {
      const riemann::Vec3 direction = camera.PixelDirection(column, row, Size, Size);
      riemann::Vec3 a = camera.GetSettings().Position;
      for (int s = 0; s < Steps; ++s)
      {
        const riemann::Vec3 b = a + step * direction;
        riemann::SceneHit hit;
        if (riemann::IntersectSegment(scene, a, b, hit))
        {
          if (!InUnit(hit.Fraction) || hit.Object < 0 ||
            hit.Object >= static_cast<int>(scene.Objects.size()))
          {
            __builtin_trap();
          }
          const riemann::Vec3 color = riemann::SurfaceColor(scene, hit);
          for (int k = 0; k < 3; ++k)
          {
            if (!InUnit(color[k]))
            {
              __builtin_trap();
            }
          }
          break;
        }
        a = b;
      }
    }
  }
}

/// One long segment through each object's anchor (a sphere's centre, a
/// plane's point, a box's min corner, a grid's extent corner).
void SegmentsThroughObjects(const riemann::Scene& scene)
{
  const riemann::Vec3 from = scene.HasCamera ? scene.Camera.Position : riemann::Vec3(0, 0, 5);
  for (const riemann::SceneObject& object : scene.Objects)
  {
    const riemann::Vec3 anchor = object.Type == riemann::ObjectType::Grid
      ? riemann::Vec3(object.Extent[0], object.Extent[2], object.Extent[4])
      : object.A;
    riemann::SceneHit hit;
    if (riemann::IntersectSegment(scene, from, anchor, hit) && !InUnit(hit.Fraction))
    {
      __builtin_trap();
    }
    // And a segment that stays at the anchor (a ray that stopped moving).
    if (riemann::IntersectSegment(scene, anchor, anchor, hit) && !InUnit(hit.Fraction))
    {
      __builtin_trap();
    }
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  riemann::Scene scene;
  try
  {
    scene = riemann::ParseScene(text, RIEMANN_FUZZ_SCENE_BASE);
  }
  catch (const riemann::SceneDefinitionError&)
  {
    return 0; // refused with a message: fine
  }
  // Anything else thrown (nlohmann::json's own exceptions, std::bad_alloc)
  // escapes: libFuzzer reports it as a crash. The parser must say what is
  // wrong with a SceneDefinitionError.
  CheckScene(scene);
  try
  {
    MarchRays(scene);
  }
  catch (const std::runtime_error&)
  {
    // ObserverCamera refuses a camera it cannot frame (e.g. a position so
    // far out that the view direction overflows).
  }
  SegmentsThroughObjects(scene);
  return 0;
}
