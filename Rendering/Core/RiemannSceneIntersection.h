/**
 * @file RiemannSceneIntersection.h
 * @brief A ray segment against the scene: the analytic objects here (the
 * reference the GLSL of the GPU pass mirrors line by line), the triangle
 * meshes through a MeshIntersector (Embree's, in Rendering/CPU), the nearer
 * of the two (VTK-free).
 */
#ifndef RiemannSceneIntersection_h
#define RiemannSceneIntersection_h

#include "RiemannScene.h"

#include <cstddef>

namespace riemann
{
/// A ray segment's first intersection with the scene.
struct SceneHit
{
  /// Fraction of the segment [0, 1] where it hits.
  double Fraction = 0.0;
  Vec3 Position = Vec3::Zero();
  /// Outward coordinate normal (a covector: the gradient of the surface's
  /// defining function), not normalised in g.
  Vec3 Normal = Vec3::Zero();
  int Object = -1;
  /// Mesh hits: the triangle and the barycentric weights of its 2nd and 3rd vertices.
  int Primitive = -1;
  double U = 0.0;
  double V = 0.0;
};

/**
 * First hit of the segment a -> b, if any (the reference the GLSL mirrors).
 *
 * Semantics (RiemannScene.cxx documents each test):
 * - The hit is the smallest fraction t in [0, 1] at which a + t (b - a) lies
 *   in an object; ties go to the object listed first.
 * - Spheres, boxes and grid bars are closed solids: a segment that starts in
 *   one (surface included) hits it at fraction 0, with Normal = -(b - a) /
 *   |b - a| (facing the ray; zero when a == b).
 * - Otherwise Normal is the Euclidean-unit outward normal of the surface hit:
 *   (p - center) / radius for a sphere, the coordinate axis of the face
 *   entered for a box or bar, and for the two-sided plane its unit normal
 *   turned to face the ray (n . (b - a) <= 0). A segment touching or lying in
 *   the plane hits it.
 * Mesh objects are not tested here: the CPU tracer intersects them with
 * Embree (a MeshIntersector, below) and keeps the nearer of the two hits.
 * Returns false (hit unchanged) when nothing is hit.
 */
RIEMANNRENDERINGCORE_EXPORT bool IntersectSegment(
  const Scene& scene, const Vec3& a, const Vec3& b, SceneHit& hit);

/**
 * The triangle meshes of a scene, intersected one ray segment per
 * integration step. Implemented with Embree by EmbreeMeshIntersector
 * (Rendering/CPU); the core only needs this interface, so it links no
 * ray-tracing library. Intersect() must be thread-safe.
 */
class RIEMANNRENDERINGCORE_EXPORT MeshIntersector
{
public:
  virtual ~MeshIntersector();

  /// True when the scene has no meshes (Intersect then finds nothing).
  virtual bool Empty() const = 0;

  /**
   * The nearest mesh hit of each of the `count` segments a[i] -> b[i]:
   * found[i] tells whether hits[i] holds one (Fraction, Position, Normal,
   * Object = the mesh's index in Scene::Objects, Primitive, U, V). With
   * `stream` true the segments may be queried together (the answers are the
   * same).
   */
  virtual void Intersect(const Vec3* a, const Vec3* b, std::size_t count, SceneHit* hits,
    bool* found, bool stream = true) const = 0;
};

/**
 * First hit of the segment a -> b with the whole scene: the analytic objects
 * (IntersectSegment) and, when `meshes` is given, its triangle meshes; the
 * nearer wins (the analytic object on a tie). False when nothing is hit.
 */
RIEMANNRENDERINGCORE_EXPORT bool IntersectSceneSegment(const Scene& scene,
  const MeshIntersector* meshes, const Vec3& a, const Vec3& b, SceneHit& hit);
} // namespace riemann

#endif
