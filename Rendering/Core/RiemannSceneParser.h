/**
 * @file RiemannSceneParser.h
 * @brief The scene JSON format (Documentation/SceneFormat.md is its
 * reference) read into the model of RiemannScene.h (VTK-free).
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
#ifndef RiemannSceneParser_h
#define RiemannSceneParser_h

#include "RiemannScene.h"

#include <string>

namespace riemann
{
/// Parse a scene; relative file names resolve against `baseDirectory`. Throws SceneDefinitionError.
RIEMANNRENDERINGCORE_EXPORT Scene ParseScene(
  const std::string& json, const std::string& baseDirectory = ".");
/// Read and parse a scene file (relative names resolve against its folder);
/// messages start with the file's path.
RIEMANNRENDERINGCORE_EXPORT Scene LoadSceneFile(const std::string& path);
} // namespace riemann

#endif
