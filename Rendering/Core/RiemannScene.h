/**
 * @file RiemannScene.h
 * @brief The scene model of the inside view, shared by the GPU pass, the CPU
 * tracer and the ray-bundle filter (VTK-free: plain C++ and Eigen): objects
 * (the paper's grid of bars, spheres, planes, boxes, triangle meshes), their
 * materials, the camera, how rays are integrated, background, fog, lighting.
 *
 * The JSON text of a scene is read by RiemannSceneParser.h (the format:
 * Documentation/SceneFormat.md); segments are intersected with it by
 * RiemannSceneIntersection.h; surfaces are coloured by RiemannShading.h.
 *
 * The grid is the paper's regular grid of thin bars: bars parallel to each
 * axis through every lattice line (multiples of `spacing`), square cross
 * section `thickness`, clipped to `extent`. Precisely, with h = thickness / 2
 * and E = extent: the bar along axis k through the lattice line (i s, j s) in
 * the two other axes (u, v) = (k+1, k+2) mod 3 exists when i s lies in
 * [E0_u, E1_u] and j s in [E0_v, E1_v] (lattice lines inside the extent), and
 * is the box |p_u - i s| <= h, |p_v - j s| <= h, E0_k - h <= p_k <= E1_k + h.
 * So every bar keeps its full square section and the bars meet flush at the
 * extent's corners; the grid lies in the extent grown by h. A flat extent
 * (E0 == E1 on an axis) gives a planar grid.
 *
 * Meshes: the scene holds their triangles (SetMesh, AddMesh) once the VTK
 * layer has read them (vtkRiemannScene with VTK's readers), so this core stays
 * VTK-free. A mesh is a surface, not a solid: only its triangles are hit.
 */
#ifndef RiemannScene_h
#define RiemannScene_h

#include "Integrators.h"
#include "Jets.h"
#include "JsonInputError.h"
#include "ObserverCamera.h"
#include "RiemannRenderingCoreExport.h" // RIEMANNRENDERINGCORE_EXPORT

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace riemann
{
/// A scene that cannot be parsed or makes no sense; what() says where and why.
class RIEMANNRENDERINGCORE_EXPORT SceneDefinitionError : public JsonInputError
{
public:
  using JsonInputError::JsonInputError;
};

enum class MaterialType : int
{
  Position = 0,
  Solid = 1,
  Checker = 2
};

struct Material
{
  MaterialType Type = MaterialType::Position;
  Vec3 Color = Vec3(0.8, 0.8, 0.8);
  Vec3 Color2 = Vec3(0.2, 0.2, 0.2);
  double Size = 1.0;
  /// Bounds of the pseudo-colour (Position): x0,x1,y0,y1,z0,z1.
  double Bounds[6] = { -1, 1, -1, 1, -1, 1 };
};

enum class ObjectType : int
{
  Grid = 0,
  Sphere = 1,
  Plane = 2,
  Box = 3,
  /// A triangle mesh (CPU tracer only): Scene::Meshes[SceneObject::Mesh].
  Mesh = 4
};

/**
 * The triangles of a mesh object, VTK-free (filled by the VTK layer from any
 * vtkPolyData). Float coordinates: what Embree intersects.
 */
struct TriangleMesh
{
  /// x, y, z per vertex.
  std::vector<float> Points;
  /// Three vertex indices per triangle.
  std::vector<unsigned int> Triangles;
  /// Optional unit normals per vertex (smooth shading); empty for face normals.
  std::vector<float> Normals;
  /// Optional RGB in [0, 1] per vertex; empty to use the object's material.
  std::vector<float> Colors;

  std::size_t NumberOfPoints() const { return this->Points.size() / 3; }
  std::size_t NumberOfTriangles() const { return this->Triangles.size() / 3; }
};

/**
 * Why `mesh` cannot be traced ("" when it can): no triangles, a coordinate
 * that is not finite, an index out of range, arrays of the wrong size.
 */
RIEMANNRENDERINGCORE_EXPORT std::string CheckMesh(const TriangleMesh& mesh);

struct SceneObject
{
  ObjectType Type = ObjectType::Sphere;
  /// Sphere: Center; Plane: Point; Box: Min.
  Vec3 A = Vec3::Zero();
  /// Plane: unit Normal; Box: Max.
  Vec3 B = Vec3::Zero();
  /// Sphere: radius.
  double Radius = 1.0;
  /// Grid: lattice spacing and bar thickness.
  double Spacing = 1.0;
  double Thickness = 0.05;
  /// Grid: clipping box x0,x1,y0,y1,z0,z1.
  double Extent[6] = { -1, 1, -1, 1, -1, 1 };
  Material Surface;
  /// Mesh: index into Scene::Meshes (-1 until the triangles are set).
  int Mesh = -1;
  /// Mesh: the file named by the scene (absolute path), "" for a mesh given as data.
  std::string MeshFile;
  /// Mesh: point array mapped through ColorMap ("" for none).
  std::string ColorArray;
  std::string ColorMap = "cool-to-warm";
  /// Mesh: scalar range of the colour map; the array's own range when unset.
  double ColorRange[2] = { 0, 1 };
  bool HasColorRange = false;
  /// Mesh: whether the material's "bounds" were given (else the mesh's bounds).
  bool HasMaterialBounds = false;
};

/// How rays are integrated (in Riemannian arc length).
/**
 * How the rays of a picture are integrated (a scene's "integrator" block).
 * Plain defaults: the "Rays" preset of vtkRiemannIntegrationSettings's
 * declaration (vtkRiemannIntegrationSettings.settings.json), which
 * RenderingCore.Scene.RayDefaultsAreTheDeclaredPreset checks.
 */
struct RaySettings
{
  /// Euler, RungeKutta4 or DormandPrince45 ("adaptive").
  IntegratorType Integrator = IntegratorType::RungeKutta4;
  double Step = 0.02;
  int MaximumSteps = 1000;
  double MaximumLength = 30.0;
  /// Per-step tolerance of the adaptive integrator.
  double Tolerance = 1e-4;
};

/**
 * Bounds of the adaptive ray step relative to RaySettings::Step, shared by
 * the GPU pass and the CPU rays. The upper bound is small on purpose: hits
 * are found on each step's straight chord, which strays from the curve by
 * about h^2 kappa / 8, so long accurate steps would still cut corners.
 */
constexpr double AdaptiveMinimumStepFactor = 1e-6;
constexpr double AdaptiveMaximumStepFactor = 4.0;

/// Limits of the GPU pass's uniform arrays (the parser enforces them).
constexpr int MaximumSpheres = 16;
constexpr int MaximumPlanes = 8;
constexpr int MaximumBoxes = 16;
constexpr int MaximumGrids = 4;
/// Mesh objects per scene (the CPU tracer's; one Embree geometry each).
constexpr int MaximumMeshes = 256;

struct Scene
{
  std::vector<SceneObject> Objects;
  Vec3 Background = Vec3(0.05, 0.05, 0.08);
  /// Equirectangular environment image (absolute path), looked up by the
  /// escaping ray's final direction; empty for a plain background colour.
  std::string EnvironmentImage;
  Vec3 FogColor = Vec3::Zero();
  double FogDensity = 0.0;
  bool ObserverLight = false;
  CameraSettings Camera;
  bool HasCamera = false;
  RaySettings Rays;
  /// The metric definition named by the scene (JSON text), empty if none.
  std::string MetricDefinition;
  /// That metric at t = 0, parsed while the scene was checked (null if none),
  /// so that a user of the scene need not parse it again.
  std::shared_ptr<const Metric> ParsedMetric;
  /// The folder that metric's relative data files ("sampled") are read from:
  /// its file's, or the scene's for a metric written in the scene.
  std::string MetricDirectory;
  /// Triangles of the mesh objects (shared: scenes are copied, meshes are big).
  std::vector<std::shared_ptr<const TriangleMesh>> Meshes;

  /// True when an object is a mesh (the GPU pass cannot draw the scene).
  bool HasMeshes() const
  {
    for (const SceneObject& object : this->Objects)
    {
      if (object.Type == ObjectType::Mesh)
      {
        return true;
      }
    }
    return false;
  }
};

/// The default bounds of the position material: [lo, hi] with flat axes widened to +-1.
RIEMANNRENDERINGCORE_EXPORT void SetDefaultMaterialBounds(
  Material& material, const Vec3& lo, const Vec3& hi);

/**
 * Give mesh object `object` its triangles (checked with CheckMesh; throws
 * SceneDefinitionError naming the object and the file). Without explicit
 * material bounds, the position material spans the mesh's bounds.
 */
RIEMANNRENDERINGCORE_EXPORT void SetMesh(
  Scene& scene, std::size_t object, std::shared_ptr<const TriangleMesh> mesh);

/**
 * The triangles of mesh object `object` (an index into scene.Objects).
 * Throws SceneDefinitionError naming the object when it has none yet (its
 * file not read, or no data given).
 */
RIEMANNRENDERINGCORE_EXPORT const std::shared_ptr<const TriangleMesh>& ObjectMesh(
  const Scene& scene, std::size_t object);

/// Append a mesh object with `material` (its bounds: the mesh's, unless `keepBounds`); returns its
/// index.
RIEMANNRENDERINGCORE_EXPORT std::size_t AddMesh(Scene& scene,
  std::shared_ptr<const TriangleMesh> mesh, const Material& material, bool keepBounds = false);

/// The built-in default: the paper's grid seen from outside it (no metric):
/// grid spacing 1, thickness 0.06, extent [-4,4]^3, position colours; camera
/// at (0,0,7.5) looking at the origin, up (0,1,0), fov 60; RK4, step 0.02,
/// 800 steps, length 30; dark background; black fog of density 0.02; no lighting.
RIEMANNRENDERINGCORE_EXPORT Scene DefaultScene();

} // namespace riemann

#endif
