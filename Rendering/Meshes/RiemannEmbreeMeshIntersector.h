/**
 * @file RiemannEmbreeMeshIntersector.h
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
#ifndef RiemannEmbreeMeshIntersector_h
#define RiemannEmbreeMeshIntersector_h

#include "RiemannRenderingMeshesExport.h" // For export macro
#include "RiemannSceneIntersection.h" // For MeshIntersector

#include <memory>
#include <vector>

namespace riemann
{
class RIEMANNRENDERINGMESHES_EXPORT EmbreeMeshIntersector : public MeshIntersector
{
public:
  /**
   * Build the Embree scene of the mesh objects of `scene` (kept by pointer:
   * it must outlive this object). Throws std::runtime_error with Embree's
   * error when the device or the scene cannot be built, or a mesh object has
   * no triangles yet.
   */
  explicit EmbreeMeshIntersector(const Scene& scene);
  ~EmbreeMeshIntersector() override;
  EmbreeMeshIntersector(const EmbreeMeshIntersector&) = delete;
  EmbreeMeshIntersector& operator=(const EmbreeMeshIntersector&) = delete;

  /// True when the scene has no meshes (Intersect then finds nothing).
  bool Empty() const override;

  /// Triangles in the Embree scene.
  std::size_t NumberOfTriangles() const { return this->Triangles; }

  /**
   * The nearest mesh hit of each of the `count` segments a[i] -> b[i]:
   * found[i] tells whether hits[i] holds one (Fraction, Position, Normal,
   * Object = the mesh's index in Scene::Objects, Primitive, U, V). With
   * `stream` true all segments go to Embree in one rtcIntersect1M call.
   */
  void Intersect(const Vec3* a, const Vec3* b, std::size_t count, SceneHit* hits, bool* found,
    bool stream = true) const override;

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
  std::size_t Triangles = 0;
};
} // namespace riemann

#endif
