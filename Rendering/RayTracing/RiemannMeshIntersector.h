/**
 * @file RiemannMeshIntersector.h
 * @brief The triangle meshes of a scene in Embree, intersected one ray
 * segment per integration step (VTK-free).
 *
 * Each segment a -> b becomes one Embree ray: origin a, direction the unit
 * chord (b - a) / |b - a|, tnear 0, tfar |b - a|; a hit's fraction is
 * t / |b - a|, as IntersectSegment's. Segments of many rays go to Embree
 * together (rtcIntersect1M, a ray stream: the paper's future work) or one
 * by one (rtcIntersect1); the answers are the same.
 *
 * Normals: the interpolated vertex normals when the mesh has them, else
 * the triangle's geometric normal; turned to face the ray (like the
 * two-sided plane's), Euclidean-unit, a covector as the other objects'.
 *
 * Built once per render; Intersect() is thread-safe (Embree's queries are).
 */
#ifndef RiemannMeshIntersector_h
#define RiemannMeshIntersector_h

#include "RiemannRenderingRayTracingModule.h" // For export macro
#include "RiemannScene.h"

#include <memory>
#include <vector>

namespace riemann
{
class RIEMANNRENDERINGRAYTRACING_EXPORT MeshIntersector
{
public:
  /**
   * Build the Embree scene of the mesh objects of `scene` (kept by pointer:
   * it must outlive this object). Throws std::runtime_error with Embree's
   * error when the device or the scene cannot be built, or a mesh object has
   * no triangles yet.
   */
  explicit MeshIntersector(const Scene& scene);
  ~MeshIntersector();
  MeshIntersector(const MeshIntersector&) = delete;
  MeshIntersector& operator=(const MeshIntersector&) = delete;

  /// True when the scene has no meshes (Intersect then finds nothing).
  bool Empty() const;

  /// Triangles in the Embree scene.
  std::size_t NumberOfTriangles() const { return this->Triangles; }

  /**
   * The nearest mesh hit of each of the `count` segments a[i] -> b[i]:
   * found[i] tells whether hits[i] holds one (Fraction, Position, Normal,
   * Object = the mesh's index in Scene::Objects, Primitive, U, V). With
   * `stream` true all segments go to Embree in one rtcIntersect1M call.
   */
  void Intersect(const Vec3* a, const Vec3* b, std::size_t count, SceneHit* hits, bool* found,
    bool stream = true) const;

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
  std::size_t Triangles = 0;
};
/**
 * First hit of the segment a -> b with the whole scene: the analytic objects
 * (IntersectSegment) and, when `meshes` is given, its triangle meshes; the
 * nearer wins (the analytic object on a tie). False when nothing is hit.
 */
RIEMANNRENDERINGRAYTRACING_EXPORT bool IntersectSceneSegment(const Scene& scene,
  const MeshIntersector* meshes, const Vec3& a, const Vec3& b, SceneHit& hit);
} // namespace riemann

#endif
