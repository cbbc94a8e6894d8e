/**
 * @file RiemannMeshBVH.h
 * @brief The triangle meshes of a scene as one flat bounding-volume
 * hierarchy that the GPU pass uploads as buffer textures and traverses in
 * GLSL (RiemannRayTraceMeshes.glsl), built with Embree's BVH builder
 * (rtcBuildBVH) and then laid out in our own compact arrays (VTK-free).
 *
 * Layout (every record is a whole number of RGBA32F texels; integers are
 * stored as float values, exact up to 2^24 = MeshBVHMaximumIndex, because
 * GLSL 1.50, VTK's version, has no floatBitsToInt):
 * - Nodes, depth first, the root at 0, a node's first child right after it:
 *   (lower x, y, z, Link), (upper x, y, z, Count). An inner node has Count 0
 *   and Link = its second child; a leaf has Count > 0 triangles from
 *   triangle Link on.
 * - Triangles, in leaf order: three texels (v0, Object), (v1, Primitive),
 *   (v2, Attributes): the scene object, the triangle's index in its mesh, and
 *   whether its mesh has vertex normals (bit 0) and colours (bit 1).
 * - Corners, one texel per triangle in leaf order: the indices of its three
 *   vertices in the vertex arrays below, which hold every mesh's vertices one
 *   mesh after the other.
 * - VertexNormals, VertexColors: one texel per vertex (zeros where the
 *   mesh has none).
 *
 * IntersectMeshBVH is the CPU mirror of the GLSL traversal, line by line and
 * in float, so that the layout and the traversal are tested here against
 * Embree's own intersector (EmbreeMeshIntersector) without a GPU.
 */
#ifndef RiemannMeshBVH_h
#define RiemannMeshBVH_h

#include "RiemannRenderingMeshesExport.h" // For export macro
#include "RiemannSceneIntersection.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace riemann
{
/// Two texels: the box and what it holds.
struct MeshBVHNode
{
  float Lower[3];
  float Link;
  float Upper[3];
  float Count;
};

/// Three texels: the vertices, the scene object, the primitive and its attributes.
struct MeshBVHTriangle
{
  float V0[3];
  float Object;
  float V1[3];
  float Primitive;
  float V2[3];
  float Attributes;
};

/// One texel: the triangle's vertices in the vertex arrays.
struct MeshBVHCorners
{
  float Vertex[3];
  float Unused;
};

/// Sums of these flags are MeshBVHTriangle::Attributes.
constexpr int MeshHasNormals = 1;
constexpr int MeshHasColors = 2;

/// Indices and counts are exact in float up to here (2^24): the largest
/// number of nodes, triangles or vertices a hierarchy may have.
constexpr std::int32_t MeshBVHMaximumIndex = 1 << 24;

/// Traversal stack of the GLSL (and of its CPU mirror): the depth it allows.
constexpr int MeshBVHStackSize = 64;

struct MeshBVH
{
  std::vector<MeshBVHNode> Nodes;
  std::vector<MeshBVHTriangle> Triangles;
  std::vector<MeshBVHCorners> Corners;
  /// x, y, z, 0 per vertex.
  std::vector<float> VertexNormals;
  /// r, g, b, 0 per vertex.
  std::vector<float> VertexColors;
  /// Nodes on the longest path from the root to a leaf.
  int Depth = 0;

  bool Empty() const { return this->Triangles.empty(); }
  /// Bytes of all the arrays (what the GPU pass uploads).
  std::size_t ByteSize() const;
};

/**
 * Build the hierarchy of every mesh object of `scene` (Embree's SAH builder,
 * binary nodes, up to 4 triangles a leaf). `progress`, when given, receives
 * the fraction done and may return false to cancel (then the result is
 * empty). Throws std::runtime_error when Embree fails, a mesh object has no
 * triangles, the meshes have more than MeshBVHMaximumIndex triangles or
 * vertices, or the tree is deeper than MeshBVHStackSize. A scene without
 * meshes gives an empty MeshBVH.
 */
RIEMANNRENDERINGMESHES_EXPORT MeshBVH BuildMeshBVH(
  const Scene& scene, const std::function<bool(double)>& progress = nullptr);

/**
 * The nearest triangle hit by the segment a -> b (the GLSL traversal, in
 * float): Fraction, Position, the normal facing the segment (the interpolated
 * vertex normal where the mesh has them, else the face's), Object,
 * Primitive, U, V as EmbreeMeshIntersector gives them. False when none.
 */
RIEMANNRENDERINGMESHES_EXPORT bool IntersectMeshBVH(
  const MeshBVH& bvh, const Vec3& a, const Vec3& b, SceneHit& hit);
} // namespace riemann

#endif
