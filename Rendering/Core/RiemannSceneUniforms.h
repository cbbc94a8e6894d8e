/**
 * @file RiemannSceneUniforms.h
 * @brief The scene's objects as the GPU pass's uniform arrays
 * (RiemannRayTraceScene.glsl reads them): packed here, without OpenGL, so
 * that the layout is one testable function.
 *
 * Object i of the scene is slot i of every array (up to
 * MaximumSceneUniformObjects; the rest are dropped and Truncated is set):
 *
 * | uniform              | per slot | holds                                          |
 * |----------------------|----------|------------------------------------------------|
 * | rt_object_type       | int      | ObjectType                                     |
 * | rt_object_a, _b      | vec3     | A, B; for a grid the extent's lows and highs   |
 * | rt_object_p          | vec3     | (Radius, Spacing, Thickness)                   |
 * | rt_material_type     | int      | MaterialType                                   |
 * | rt_material_color(2) | vec3     | Color, Color2                                  |
 * | rt_material_size     | float    | checker Size                                   |
 * | rt_material_lo, _hi  | vec3     | the material's bounds, lows and highs          |
 *
 * The shader reads them from one uniform block (SceneUniformBlock), not from
 * plain uniform arrays: NVIDIA's compiler puts a compute shader's plain
 * uniforms in program parameters, which ten arrays of 60 overran ("invalid
 * local parameter number", measured on an H200); a block is a buffer on both
 * paths and on every driver with OpenGL 3.1.
 */
#ifndef RiemannSceneUniforms_h
#define RiemannSceneUniforms_h

#include "RiemannRenderingCoreExport.h" // For export macro
#include "RiemannScene.h"

#include <vector>

namespace riemann
{
/// Mesh objects the GPU pass draws (their triangles are in buffer textures;
/// their slots hold the type and the material).
constexpr int MaximumUniformMeshes = 16;

/// Slots of the uniform arrays: every analytic object type's limit and the meshes' together.
constexpr int MaximumSceneUniformObjects =
  MaximumSpheres + MaximumPlanes + MaximumBoxes + MaximumGrids + MaximumUniformMeshes;

struct SceneUniforms
{
  /// Objects packed (the slots in use).
  int ObjectCount = 0;
  /// The scene had more objects than slots: the first ones were packed.
  bool Truncated = false;
  /// Each array has MaximumSceneUniformObjects slots (times 3 for vec3).
  std::vector<int> ObjectType;
  std::vector<float> A;
  std::vector<float> B;
  std::vector<float> P;
  std::vector<int> MaterialType;
  std::vector<float> Color;
  std::vector<float> Color2;
  std::vector<float> Size;
  std::vector<float> Low;
  std::vector<float> High;
};

/// Pack the scene's objects into the uniform arrays (unused slots are zeros, Size 1).
RIEMANNRENDERINGCORE_EXPORT SceneUniforms PackSceneUniforms(const Scene& scene);

/// The arrays of the scene's uniform block, in the block's order: each holds
/// MaximumSceneUniformObjects vec4s.
enum class SceneBlockArray
{
  Kind = 0, ///< (ObjectType, MaterialType, Size, 0): the types as floats (small integers, exact)
  A,        ///< (A, 0)
  B,        ///< (B, 0)
  P,        ///< (P, 0)
  Color,    ///< (Color, 0)
  Color2,   ///< (Color2, 0)
  Low,      ///< (Low, 0)
  High,     ///< (High, 0)
  Count
};

/// Floats in the block: std140 gives every vec4 array element 16 bytes.
constexpr int SceneUniformBlockFloats =
  4 * MaximumSceneUniformObjects * static_cast<int>(SceneBlockArray::Count);

/**
 * The uniform block `rt_scene_objects` of RiemannRayTraceScene.glsl in
 * std140 layout: the arrays of SceneBlockArray one after the other, element
 * `slot` of array `a` at floats 4 * (a * MaximumSceneUniformObjects + slot).
 */
RIEMANNRENDERINGCORE_EXPORT std::vector<float> SceneUniformBlock(const SceneUniforms& uniforms);
} // namespace riemann

#endif
