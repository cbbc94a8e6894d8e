#include "RiemannSceneUniforms.h"

#include <algorithm>

namespace riemann
{
namespace
{
void Store(const Vec3& v, std::vector<float>& array, int slot)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    array[3 * slot + axis] = static_cast<float>(v[axis]);
  }
}

/// Lows and highs of an axis-aligned box given as (x0, x1, y0, y1, z0, z1).
void StoreBounds(const double bounds[6], std::vector<float>& low, std::vector<float>& high, int slot)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    low[3 * slot + axis] = static_cast<float>(bounds[2 * axis]);
    high[3 * slot + axis] = static_cast<float>(bounds[2 * axis + 1]);
  }
}

void PackObject(const SceneObject& object, int slot, SceneUniforms& uniforms)
{
  uniforms.ObjectType[slot] = static_cast<int>(object.Type);
  if (object.Type == ObjectType::Grid)
  {
    StoreBounds(object.Extent, uniforms.A, uniforms.B, slot);
  }
  else
  {
    Store(object.A, uniforms.A, slot);
    Store(object.B, uniforms.B, slot);
  }
  Store(Vec3(object.Radius, object.Spacing, object.Thickness), uniforms.P, slot);

  const Material& material = object.Surface;
  uniforms.MaterialType[slot] = static_cast<int>(material.Type);
  Store(material.Color, uniforms.Color, slot);
  Store(material.Color2, uniforms.Color2, slot);
  uniforms.Size[slot] = static_cast<float>(material.Size);
  StoreBounds(material.Bounds, uniforms.Low, uniforms.High, slot);
}
} // namespace

SceneUniforms PackSceneUniforms(const Scene& scene)
{
  constexpr int slots = MaximumSceneUniformObjects;
  SceneUniforms uniforms;
  uniforms.ObjectType.assign(slots, 0);
  uniforms.MaterialType.assign(slots, 0);
  uniforms.Size.assign(slots, 1.0f);
  for (std::vector<float>* vec3 : { &uniforms.A, &uniforms.B, &uniforms.P, &uniforms.Color,
         &uniforms.Color2, &uniforms.Low, &uniforms.High })
  {
    vec3->assign(3 * slots, 0.0f);
  }
  uniforms.ObjectCount = static_cast<int>(std::min<std::size_t>(scene.Objects.size(), slots));
  uniforms.Truncated = scene.Objects.size() > static_cast<std::size_t>(slots);
  for (int i = 0; i < uniforms.ObjectCount; ++i)
  {
    PackObject(scene.Objects[i], i, uniforms);
  }
  return uniforms;
}

std::vector<float> SceneUniformBlock(const SceneUniforms& uniforms)
{
  constexpr int slots = MaximumSceneUniformObjects;
  std::vector<float> block(SceneUniformBlockFloats, 0.0f);
  auto element = [&block](SceneBlockArray array, int slot) {
    return block.data() + 4 * (static_cast<int>(array) * slots + slot);
  };
  auto store3 = [&](SceneBlockArray array, const std::vector<float>& values) {
    for (int slot = 0; slot < slots; ++slot)
    {
      std::copy_n(values.data() + 3 * slot, 3, element(array, slot));
    }
  };
  for (int slot = 0; slot < slots; ++slot)
  {
    float* kind = element(SceneBlockArray::Kind, slot);
    kind[0] = static_cast<float>(uniforms.ObjectType[slot]);
    kind[1] = static_cast<float>(uniforms.MaterialType[slot]);
    kind[2] = uniforms.Size[slot];
  }
  store3(SceneBlockArray::A, uniforms.A);
  store3(SceneBlockArray::B, uniforms.B);
  store3(SceneBlockArray::P, uniforms.P);
  store3(SceneBlockArray::Color, uniforms.Color);
  store3(SceneBlockArray::Color2, uniforms.Color2);
  store3(SceneBlockArray::Low, uniforms.Low);
  store3(SceneBlockArray::High, uniforms.High);
  return block;
}
} // namespace riemann
