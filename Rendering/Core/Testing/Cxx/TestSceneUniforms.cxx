// The scene as the GPU pass's uniform arrays (RiemannSceneUniforms.h): the
// layout RiemannRayTraceScene.glsl reads, checked slot by slot without OpenGL.
#include "RiemannSceneParser.h"
#include "RiemannSceneUniforms.h"

#include <gtest/gtest.h>

namespace riemann
{
namespace
{
void ExpectSlot(const std::vector<float>& array, int slot, const Vec3& expected)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    EXPECT_FLOAT_EQ(array[3 * slot + axis], static_cast<float>(expected[axis]))
      << "slot " << slot << ", axis " << axis;
  }
}

TEST(SceneUniforms, EveryObjectTypeInItsSlot)
{
  const Scene scene = ParseScene(R"({"objects": [
    {"type": "grid", "spacing": 0.5, "thickness": 0.1, "extent": [-1, 2, -3, 4, -5, 6]},
    {"type": "sphere", "center": [1, 2, 3], "radius": 0.25,
     "material": {"type": "solid", "color": [0.1, 0.2, 0.3]}},
    {"type": "plane", "point": [0, -2, 0], "normal": [0, 2, 0],
     "material": {"type": "checker", "color": [1, 1, 1], "color2": [0, 0, 0], "size": 0.75}},
    {"type": "box", "min": [-1, -1, -1], "max": [1, 2, 3],
     "material": {"type": "position", "bounds": [0, 1, 2, 3, 4, 5]}}]})");
  const SceneUniforms u = PackSceneUniforms(scene);
  ASSERT_EQ(u.ObjectCount, 4);
  EXPECT_FALSE(u.Truncated);
  const std::size_t slots = MaximumSceneUniformObjects;
  for (const std::vector<float>* vec3 : { &u.A, &u.B, &u.P, &u.Color, &u.Color2, &u.Low, &u.High })
  {
    EXPECT_EQ(vec3->size(), 3 * slots);
  }
  EXPECT_EQ(u.ObjectType.size(), slots);
  EXPECT_EQ(u.Size.size(), slots);

  EXPECT_EQ(u.ObjectType[0], static_cast<int>(ObjectType::Grid));
  EXPECT_EQ(u.ObjectType[1], static_cast<int>(ObjectType::Sphere));
  EXPECT_EQ(u.ObjectType[2], static_cast<int>(ObjectType::Plane));
  EXPECT_EQ(u.ObjectType[3], static_cast<int>(ObjectType::Box));

  // The grid: its extent's lows in a, highs in b; (radius, spacing, thickness) in p.
  ExpectSlot(u.A, 0, Vec3(-1, -3, -5));
  ExpectSlot(u.B, 0, Vec3(2, 4, 6));
  EXPECT_FLOAT_EQ(u.P[3 * 0 + 1], 0.5f);
  EXPECT_FLOAT_EQ(u.P[3 * 0 + 2], 0.1f);
  // The sphere: centre in a, radius in p.x, its solid colour.
  ExpectSlot(u.A, 1, Vec3(1, 2, 3));
  EXPECT_FLOAT_EQ(u.P[3 * 1], 0.25f);
  EXPECT_EQ(u.MaterialType[1], static_cast<int>(MaterialType::Solid));
  ExpectSlot(u.Color, 1, Vec3(0.1, 0.2, 0.3));
  // The plane: its point in a, its normal (normalised by the parser) in b; checker size.
  ExpectSlot(u.A, 2, Vec3(0, -2, 0));
  ExpectSlot(u.B, 2, Vec3(0, 1, 0));
  EXPECT_EQ(u.MaterialType[2], static_cast<int>(MaterialType::Checker));
  ExpectSlot(u.Color2, 2, Vec3(0, 0, 0));
  EXPECT_FLOAT_EQ(u.Size[2], 0.75f);
  // The box: min and max; its position material's bounds, lows and highs.
  ExpectSlot(u.A, 3, Vec3(-1, -1, -1));
  ExpectSlot(u.B, 3, Vec3(1, 2, 3));
  EXPECT_EQ(u.MaterialType[3], static_cast<int>(MaterialType::Position));
  ExpectSlot(u.Low, 3, Vec3(0, 2, 4));
  ExpectSlot(u.High, 3, Vec3(1, 3, 5));

  // Unused slots are zeros, with a checker size of 1 (never a division by 0).
  ExpectSlot(u.A, 4, Vec3::Zero());
  EXPECT_EQ(u.ObjectType[4], 0);
  EXPECT_FLOAT_EQ(u.Size[slots - 1], 1.0f);
}

TEST(SceneUniforms, MoreObjectsThanSlotsAreTruncated)
{
  Scene scene;
  SceneObject sphere;
  sphere.Type = ObjectType::Sphere;
  for (int i = 0; i < MaximumSceneUniformObjects + 3; ++i)
  {
    sphere.A = Vec3(i, 0, 0);
    scene.Objects.push_back(sphere);
  }
  const SceneUniforms u = PackSceneUniforms(scene);
  EXPECT_TRUE(u.Truncated);
  EXPECT_EQ(u.ObjectCount, MaximumSceneUniformObjects);
  ExpectSlot(u.A, MaximumSceneUniformObjects - 1, Vec3(MaximumSceneUniformObjects - 1, 0, 0));
  EXPECT_EQ(u.A.size(), 3u * MaximumSceneUniformObjects);
}

TEST(SceneUniforms, EmptySceneHasNoObjects)
{
  const SceneUniforms u = PackSceneUniforms(Scene());
  EXPECT_EQ(u.ObjectCount, 0);
  EXPECT_FALSE(u.Truncated);
  EXPECT_EQ(u.ObjectType.size(), static_cast<std::size_t>(MaximumSceneUniformObjects));
}
TEST(SceneUniforms, TheBlockIsStd140ArraysOfVec4InTheShadersOrder)
{
  const Scene scene = ParseScene(R"({"objects": [
    {"type": "sphere", "center": [1, 2, 3], "radius": 0.25,
     "material": {"type": "checker", "color": [0.1, 0.2, 0.3], "color2": [0.4, 0.5, 0.6],
                  "size": 0.75}},
    {"type": "box", "min": [-1, -2, -3], "max": [4, 5, 6],
     "material": {"type": "position", "bounds": [0, 1, 2, 3, 4, 5]}}]})");
  const std::vector<float> block = SceneUniformBlock(PackSceneUniforms(scene));
  // 8 arrays x 60 slots x 16 bytes: what the program reports as
  // GL_UNIFORM_BLOCK_DATA_SIZE (SceneUniformBuffer checks it at every bind).
  ASSERT_EQ(block.size(), static_cast<std::size_t>(SceneUniformBlockFloats));
  EXPECT_EQ(block.size() * sizeof(float), 8u * MaximumSceneUniformObjects * 16u);
  auto at = [&block](SceneBlockArray array, int slot, int component) {
    return block[4 * (static_cast<int>(array) * MaximumSceneUniformObjects + slot) + component];
  };
  EXPECT_EQ(at(SceneBlockArray::Kind, 0, 0), static_cast<float>(ObjectType::Sphere));
  EXPECT_EQ(at(SceneBlockArray::Kind, 0, 1), static_cast<float>(MaterialType::Checker));
  EXPECT_FLOAT_EQ(at(SceneBlockArray::Kind, 0, 2), 0.75f);
  EXPECT_EQ(at(SceneBlockArray::Kind, 1, 0), static_cast<float>(ObjectType::Box));
  EXPECT_EQ(at(SceneBlockArray::Kind, 1, 1), static_cast<float>(MaterialType::Position));
  EXPECT_FLOAT_EQ(at(SceneBlockArray::Kind, 5, 2), 1.0f) << "unused slots: size 1";
  EXPECT_FLOAT_EQ(at(SceneBlockArray::A, 0, 2), 3.0f);
  EXPECT_FLOAT_EQ(at(SceneBlockArray::P, 0, 0), 0.25f);
  EXPECT_FLOAT_EQ(at(SceneBlockArray::Color, 0, 1), 0.2f);
  EXPECT_FLOAT_EQ(at(SceneBlockArray::Color2, 0, 2), 0.6f);
  EXPECT_FLOAT_EQ(at(SceneBlockArray::A, 1, 1), -2.0f);
  EXPECT_FLOAT_EQ(at(SceneBlockArray::B, 1, 0), 4.0f);
  EXPECT_FLOAT_EQ(at(SceneBlockArray::Low, 1, 1), 2.0f);
  EXPECT_FLOAT_EQ(at(SceneBlockArray::High, 1, 2), 5.0f);
  for (int array = 0; array < static_cast<int>(SceneBlockArray::Count); ++array)
  {
    EXPECT_EQ(at(static_cast<SceneBlockArray>(array), 0, 3), 0.0f) << "w is padding, array " << array;
  }
}
} // namespace
} // namespace riemann
