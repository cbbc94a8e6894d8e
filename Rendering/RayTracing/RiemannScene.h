/**
 * @file RiemannScene.h
 * @brief The scene of the inside view, shared by the GPU pass, the CPU tracer
 * and the ray-bundle filter (VTK-free: plain C++ and Eigen).
 *
 * Scene JSON (Data/scenes/<name>.json):
 * @code{.json}
 * {
 *   "metric": "../metrics/gaussian-bump.json",          // optional: a file (relative to
 *                                                        //   the scene file) or an inline object
 *   "camera": {"position": [0,0,6], "look_at": [0,0,0], "view_up": [0,1,0],
 *              "fov": 60, "projection": "perspective"}, // or "equirectangular"
 *   "integrator": {"method": "rk4", "step": 0.02, "max_steps": 1000,
 *                  "max_length": 30, "tolerance": 1e-4}, // method: euler | rk4 | adaptive
 *   "background": [0.05, 0.05, 0.08],                    // or {"environment": "sky.exr"}
 *   "fog": {"color": [0, 0, 0], "density": 0.03},        // colour -> fog by arc length s:
 *                                                        //   mix(colour, fog, 1 - exp(-density s))
 *   "lighting": "observer",                              // "none" (default) | "observer" (Lambert,
 *                                                        //   light at the eye, angle measured with
 * g) "objects": [
 *     {"type": "grid", "spacing": 1, "thickness": 0.06, "extent": [-3,3,-3,3,-3,3], "material":
 * {...}},
 *     {"type": "sphere", "center": [0,0,0], "radius": 0.5, "material": {...}},
 *     {"type": "plane", "point": [0,-2,0], "normal": [0,1,0], "material": {...}},
 *     {"type": "box", "min": [-1,-1,-1], "max": [1,1,1], "material": {...}},
 *     {"type": "mesh", "file": "bunny.ply", "material": {...},   // CPU tracer only
 *      "color_array": "Elevation", "color_map": "cool-to-warm", "color_range": [0, 1]}
 *   ]
 * }
 * @endcode
 * Materials: {"type": "position", "bounds": [x0,x1,y0,y1,z0,z1]} (the paper's
 * pseudo-colour: RGB = hit position scaled to bounds; default bounds are the
 * object's own extent: the grid's extent, a sphere's center +- radius, a box's
 * min/max, [-5,5]^3 for a plane; an axis of zero width is widened to +-1),
 * {"type": "solid", "color": [r,g,b]}, {"type": "checker", "color": [..],
 * "color2": [..], "size": s}. A material needs its "type"; the other keys
 * default to the Material struct's values. Default material (no "material"
 * key): "position". Colours are in [0, 1].
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
 * (E0 == E1 on an axis) gives a planar grid. Grid keys default to the paper's
 * grid: spacing 1, thickness 0.06, extent [-4,4]^3. Sphere (center, radius),
 * plane (point, normal; normalised by the parser, two-sided) and box (min,
 * max) keys are required. Every object accepts "name" and "description".
 *
 * Meshes (the CPU tracer, vtkRiemannCPURayTracer, only; the GPU pass refuses
 * a scene that has one): "file" names a .vtp, .ply, .obj or .stl file
 * (relative to the scene file), checked to exist here; the parser records it
 * in SceneObject::MeshFile and leaves the triangles to the VTK layer
 * (vtkRiemannScene reads the file with VTK's readers and calls SetMesh), so
 * this core stays VTK-free. Colours: an unsigned-char RGB(A) point array of
 * the file (its active scalars) colours the vertices; "color_array" names a
 * point array mapped through "color_map" ("cool-to-warm" (default),
 * "viridis", "grayscale" or "rainbow") over "color_range" (default: the
 * array's range); otherwise the material applies (default "position" over
 * the mesh's bounds). A mesh is a surface, not a solid: only its triangles
 * are hit.
 *
 * Parsing (ParseScene): unknown keys, wrong types or sizes, and values that
 * make no sense are SceneDefinitionError's whose message starts with the JSON
 * path, e.g. `scene.objects[2].radius: expected a positive number`. A metric
 * given by file or inline is read into MetricDefinition and validated with
 * ParseMetricDefinition. Keys left out keep the defaults of the structs below
 * (HasCamera is false without "camera").
 */
#ifndef RiemannScene_h
#define RiemannScene_h

#include "Integrators.h"
#include "Jets.h"
#include "ObserverCamera.h"
#include "RiemannRenderingRayTracingModule.h" // RIEMANNRENDERINGRAYTRACING_EXPORT

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace riemann
{
/// A scene that cannot be parsed or makes no sense; what() says where and why.
class RIEMANNRENDERINGRAYTRACING_EXPORT SceneDefinitionError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
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
RIEMANNRENDERINGRAYTRACING_EXPORT std::string CheckMesh(const TriangleMesh& mesh);

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

/**
 * Give mesh object `object` its triangles (checked with CheckMesh; throws
 * SceneDefinitionError naming the object and the file). Without explicit
 * material bounds, the position material spans the mesh's bounds.
 */
RIEMANNRENDERINGRAYTRACING_EXPORT void SetMesh(
  Scene& scene, std::size_t object, std::shared_ptr<const TriangleMesh> mesh);

/// Append a mesh object with `material` (its bounds: the mesh's, unless `keepBounds`); returns its index.
RIEMANNRENDERINGRAYTRACING_EXPORT std::size_t AddMesh(Scene& scene,
  std::shared_ptr<const TriangleMesh> mesh, const Material& material, bool keepBounds = false);

/// Parse a scene; relative file names resolve against `baseDirectory`. Throws SceneDefinitionError.
RIEMANNRENDERINGRAYTRACING_EXPORT Scene ParseScene(
  const std::string& json, const std::string& baseDirectory = ".");
/// Read and parse a scene file (relative names resolve against its folder);
/// messages start with the file's path.
RIEMANNRENDERINGRAYTRACING_EXPORT Scene LoadSceneFile(const std::string& path);
/// The built-in default: the paper's grid seen from outside it (no metric):
/// grid spacing 1, thickness 0.06, extent [-4,4]^3, position colours; camera
/// at (0,0,7.5) looking at the origin, up (0,1,0), fov 60; RK4, step 0.02,
/// 800 steps, length 30; dark background; black fog of density 0.02; no lighting.
RIEMANNRENDERINGRAYTRACING_EXPORT Scene DefaultScene();

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
 * Embree (RiemannMeshIntersector.h) and keeps the nearer of the two hits.
 * Returns false (hit unchanged) when nothing is hit.
 */
RIEMANNRENDERINGRAYTRACING_EXPORT bool IntersectSegment(
  const Scene& scene, const Vec3& a, const Vec3& b, SceneHit& hit);

/**
 * The material colour at a hit (before lighting and fog); black for an
 * object index out of range.
 * - Position: clamp((p - lo) / (hi - lo), 0, 1) per component (0.5 on an
 *   axis with hi <= lo).
 * - Solid: Color.
 * - Checker: Color where floor(q_x / s) + floor(q_y / s) + floor(q_z / s) is
 *   even, else Color2, at q = p - 1e-6 s n (n the unit Normal): a point just
 *   inside the surface, so that a face lying on a checker plane (a box
 *   [-1,1]^3 with size 1) gets one colour rather than rounding noise.
 * - A mesh with vertex colours: the colours of the hit triangle's vertices
 *   interpolated with the hit's barycentric weights (the material otherwise).
 */
RIEMANNRENDERINGRAYTRACING_EXPORT Vec3 SurfaceColor(const Scene& scene, const SceneHit& hit);
} // namespace riemann

#endif
