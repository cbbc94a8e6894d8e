// ---------------------------------------------------------------------------
// RiemannRayTraceScene.glsl: the scene of the inside view (RiemannScene.h).
//
// A line-by-line mirror, in float, of riemann::IntersectSegment and
// riemann::SurfaceColor (RiemannScene.cxx): the same objects in the same
// order, the same closed solids, the same tie rule (the object listed first
// wins) and the same normals; triangle meshes (RiemannRayTraceMeshes.glsl,
// when RT_MESHES) after them, as riemann::IntersectSceneSegment: the nearer
// wins, the analytic object on a tie. Objects are arrays of a uniform block in scene order, up to
// RT_MAX_OBJECTS (= the sum of the per-type limits of RiemannScene.h, which
// the scene parser enforces); their values are uniforms, so editing a scene
// never recompiles the shader.
// ---------------------------------------------------------------------------

#define RT_GRID 0
#define RT_SPHERE 1
#define RT_PLANE 2
#define RT_BOX 3
#define RT_MESH 4

#define RT_POSITION 0
#define RT_SOLID 1
#define RT_CHECKER 2

#define RT_INFINITY 1e30

uniform int rt_object_count;
// One std140 block (RiemannSceneUniforms.h, SceneUniformBlock): on NVIDIA, a
// compute shader's plain uniform arrays this large fail to compile.
layout(std140) uniform rt_scene_objects
{
  // (object type, material type, checker size, 0): the types as floats.
  vec4 rt_object_kind[RT_MAX_OBJECTS];
  // Sphere: centre; plane: point; box: min; grid: extent min.
  vec4 rt_object_a[RT_MAX_OBJECTS];
  // Plane: unit normal; box: max; grid: extent max.
  vec4 rt_object_b[RT_MAX_OBJECTS];
  // (sphere radius, grid spacing, grid thickness).
  vec4 rt_object_p[RT_MAX_OBJECTS];
  vec4 rt_material_color[RT_MAX_OBJECTS];
  vec4 rt_material_color2[RT_MAX_OBJECTS];
  // Position bounds: (x0, y0, z0) and (x1, y1, z1).
  vec4 rt_material_lo[RT_MAX_OBJECTS];
  vec4 rt_material_hi[RT_MAX_OBJECTS];
};

int rt_object_type(int index)
{
  return int(rt_object_kind[index].x);
}

int rt_material_type(int index)
{
  return int(rt_object_kind[index].y);
}

// -d / |d|, or zero for d == 0: the normal of a hit at a start inside a solid.
vec3 rt_facing_normal(vec3 d)
{
  float len = length(d);
  return len > 0.0 ? -d / len : vec3(0.0);
}

// The unit vector e_axis (axis 0, 1 or 2).
vec3 rt_axis_mask(int axis)
{
  return vec3(equal(ivec3(axis), ivec3(0, 1, 2)));
}

// Slab test of the closed box [lo, hi] against the line a + t d. [enter, exit]
// is the parameter interval inside the box (enter = -inf when no slab bounds
// it from below) and axis the slab that gave enter (-1 if none). True when
// that interval meets [0, 1]. An axis with d == 0 constrains nothing if a is
// within its slab and rejects otherwise.
bool rt_slab_test(vec3 a, vec3 d, vec3 lo, vec3 hi, out float enter, out float exit, out int axis)
{
  enter = -RT_INFINITY;
  exit = RT_INFINITY;
  axis = -1;
  for (int i = 0; i < 3; ++i)
  {
    if (d[i] == 0.0)
    {
      if (a[i] < lo[i] || a[i] > hi[i])
      {
        return false;
      }
      continue;
    }
    float t0 = (lo[i] - a[i]) / d[i];
    float t1 = (hi[i] - a[i]) / d[i];
    float tNear = min(t0, t1);
    float tFar = max(t0, t1);
    if (tNear > enter)
    {
      enter = tNear;
      axis = i;
    }
    exit = min(exit, tFar);
  }
  return enter <= exit && exit >= 0.0 && enter <= 1.0;
}

// Closed box: a start inside hits at 0 with the facing normal, otherwise the
// entry face, normal -sign(d_axis) e_axis.
bool rt_intersect_box(vec3 a, vec3 d, vec3 lo, vec3 hi, out float fraction, out vec3 normal)
{
  float enter;
  float exit;
  int axis;
  fraction = 0.0;
  normal = vec3(0.0);
  if (!rt_slab_test(a, d, lo, hi, enter, exit, axis))
  {
    return false;
  }
  if (enter <= 0.0)
  {
    fraction = 0.0;
    normal = rt_facing_normal(d);
    return true;
  }
  fraction = enter;
  // Written with a mask, not normal[axis] = ...: Mesa's llvmpipe miscompiled
  // writes to dynamically indexed vector components in divergent code
  // (whole 2x2 pixel quads came out with some components unwritten).
  vec3 faceAxis = rt_axis_mask(axis);
  normal = -faceAxis * sign(dot(d, faceAxis));
  return true;
}

// Closed ball |p - c| <= r (see IntersectSphere in RiemannScene.cxx).
bool rt_intersect_sphere(
  vec3 a, vec3 d, vec3 center, float radius, out float fraction, out vec3 normal)
{
  fraction = 0.0;
  normal = vec3(0.0);
  vec3 m = a - center;
  float A = dot(d, d);
  float B = dot(d, m);
  float C = dot(m, m) - radius * radius;
  if (C <= 0.0)
  {
    fraction = 0.0;
    normal = rt_facing_normal(d);
    return true;
  }
  float discriminant = B * B - A * C;
  if (B >= 0.0 || discriminant < 0.0)
  {
    return false;
  }
  float t = (-B - sqrt(discriminant)) / A;
  if (t > 1.0)
  {
    return false;
  }
  fraction = max(t, 0.0);
  normal = (a + fraction * d - center) / radius;
  return true;
}

// Two-sided plane n.(p - q) = 0, n unit; the normal faces the ray.
bool rt_intersect_plane(
  vec3 a, vec3 d, vec3 point, vec3 unitNormal, out float fraction, out vec3 normal)
{
  fraction = 0.0;
  normal = vec3(0.0);
  float sa = dot(unitNormal, a - point);
  float sb = dot(unitNormal, a + d - point);
  if (sa * sb > 0.0)
  {
    return false;
  }
  fraction = sa == sb ? 0.0 : clamp(sa / (sa - sb), 0.0, 1.0);
  normal = sa - sb >= 0.0 ? unitNormal : -unitNormal;
  return true;
}

// The paper's grid of bars (IntersectGrid in RiemannScene.cxx): clip to the
// grid's bounding box, cut into pieces no longer than the spacing, slab-test
// the candidate bars of each piece against the whole segment.
bool rt_intersect_grid(vec3 a, vec3 d, vec3 extentLo, vec3 extentHi, float s, float thickness,
  out float fraction, out vec3 normal)
{
  fraction = 0.0;
  normal = vec3(0.0);
  float h = 0.5 * thickness;
  vec3 outerLo = extentLo - vec3(h);
  vec3 outerHi = extentHi + vec3(h);
  float enter;
  float exit;
  int enterAxis;
  if (!(s > 0.0) || !rt_slab_test(a, d, outerLo, outerHi, enter, exit, enterAxis))
  {
    return false;
  }
  float t0 = max(enter, 0.0);
  float t1 = min(exit, 1.0);

  // The CPU widens the lattice-line ranges by 1e-9; float needs 1e-6 (the
  // ranges only choose candidate bars, each then tested exactly).
  const float slack = 1e-6;
  vec3 firstLine = ceil(extentLo / s - slack);
  vec3 lastLine = floor(extentHi / s + slack);

  float len = length(d) * (t1 - t0);
  int pieces = int(clamp(ceil(len / s), 1.0, 65536.0));
  bool found = false;
  float best = RT_INFINITY;
  for (int piece = 0; piece < pieces; ++piece)
  {
    float ta = t0 + (t1 - t0) * float(piece) / float(pieces);
    float tb = piece + 1 == pieces ? t1 : t0 + (t1 - t0) * float(piece + 1) / float(pieces);
    vec3 pa = a + ta * d;
    vec3 pb = a + tb * d;
    vec3 boxLo = min(pa, pb);
    vec3 boxHi = max(pa, pb);
    for (int k = 0; k < 3; ++k)
    {
      int u = k == 2 ? 0 : k + 1;
      int v = k == 0 ? 2 : k - 1;
      float i0 = max(firstLine[u], ceil((boxLo[u] - h) / s - slack));
      float i1 = min(lastLine[u], floor((boxHi[u] + h) / s + slack));
      float j0 = max(firstLine[v], ceil((boxLo[v] - h) / s - slack));
      float j1 = min(lastLine[v], floor((boxHi[v] + h) / s + slack));
      for (float i = i0; i <= i1; i += 1.0)
      {
        for (float j = j0; j <= j1; j += 1.0)
        {
          // Masks instead of dynamic component writes (see rt_intersect_box).
          vec3 ek = rt_axis_mask(k);
          vec3 eu = rt_axis_mask(u);
          vec3 ev = rt_axis_mask(v);
          vec3 barLo = ek * outerLo + eu * (i * s - h) + ev * (j * s - h);
          vec3 barHi = ek * outerHi + eu * (i * s + h) + ev * (j * s + h);
          float t;
          vec3 n;
          if (rt_intersect_box(a, d, barLo, barHi, t, n) && t < best)
          {
            found = true;
            best = t;
            fraction = t;
            normal = n;
          }
        }
      }
    }
    if (found && best <= tb)
    {
      break;
    }
  }
  return found;
}

// First hit of the segment a -> b: fraction in [0, 1], position, outward
// coordinate normal (a covector) and object index. False when nothing is hit.
bool rt_intersect_segment(
  vec3 a, vec3 b, out float hitFraction, out vec3 hitPosition, out vec3 hitNormal, out int hitObject)
{
  vec3 d = b - a;
  bool found = false;
  float best = RT_INFINITY;
  hitFraction = 0.0;
  hitPosition = a;
  hitNormal = vec3(0.0);
  hitObject = -1;
  for (int index = 0; index < rt_object_count; ++index)
  {
    int type = rt_object_type(index);
    float t = RT_INFINITY;
    vec3 normal = vec3(0.0);
    bool hits = false;
    if (type == RT_GRID)
    {
      hits = rt_intersect_grid(a, d, rt_object_a[index].xyz, rt_object_b[index].xyz,
        rt_object_p[index].y, rt_object_p[index].z, t, normal);
    }
    else if (type == RT_SPHERE)
    {
      hits = rt_intersect_sphere(a, d, rt_object_a[index].xyz, rt_object_p[index].x, t, normal);
    }
    else if (type == RT_PLANE)
    {
      hits = rt_intersect_plane(a, d, rt_object_a[index].xyz, rt_object_b[index].xyz, t, normal);
    }
    else if (type == RT_BOX)
    {
      hits = rt_intersect_box(a, d, rt_object_a[index].xyz, rt_object_b[index].xyz, t, normal);
    }
    // Strictly smaller: a tie keeps the object listed first.
    if (hits && t < best)
    {
      found = true;
      best = t;
      hitFraction = t;
      hitNormal = normal;
      hitObject = index;
    }
  }
#if RT_MESHES
  rt_mesh_hit_triangle = -1;
  float meshFraction;
  vec3 meshNormal;
  int meshObject;
  int meshTriangle;
  vec2 meshWeights;
  if (rt_intersect_meshes(
        a, b, best, meshFraction, meshNormal, meshObject, meshTriangle, meshWeights))
  {
    found = true;
    hitFraction = meshFraction;
    hitNormal = meshNormal;
    hitObject = meshObject;
    rt_mesh_hit_triangle = meshTriangle;
    rt_mesh_hit_uv = meshWeights;
  }
#endif
  if (found)
  {
    hitPosition = a + hitFraction * d;
  }
  return found;
}

// The material colour at a hit, before lighting and fog (SurfaceColor).
vec3 rt_surface_color(int object, vec3 position, vec3 normal)
{
  if (object < 0 || object >= rt_object_count)
  {
    return vec3(0.0);
  }
#if RT_MESHES
  vec3 vertexColor;
  if (rt_object_type(object) == RT_MESH && rt_mesh_hit_triangle >= 0 &&
    rt_mesh_color(rt_mesh_hit_triangle, rt_mesh_hit_uv, vertexColor))
  {
    return vertexColor;
  }
#endif
  int type = rt_material_type(object);
  if (type == RT_POSITION)
  {
    // Component-wise without dynamic indexing (see rt_intersect_box).
    vec3 lo = rt_material_lo[object].xyz;
    vec3 width = rt_material_hi[object].xyz - lo;
    vec3 thin = vec3(lessThanEqual(width, vec3(0.0)));
    vec3 scaled = clamp((position - lo) / mix(width, vec3(1.0), thin), 0.0, 1.0);
    return mix(scaled, vec3(0.5), thin);
  }
  if (type == RT_SOLID)
  {
    return rt_material_color[object].xyz;
  }
  // Checker, sampled just inside the surface. The CPU steps 1e-6 size inwards;
  // float positions need a larger step (1e-4 size) to leave the rounding noise
  // of a face that lies on a checker plane.
  float size = rt_object_kind[object].z > 0.0 ? rt_object_kind[object].z : 1.0;
  float normalLength = length(normal);
  vec3 inward = normalLength > 0.0 ? -normal / normalLength : vec3(0.0);
  vec3 q = position + (1e-4 * size) * inward;
  vec3 cells3 = floor(q / size);
  float cells = cells3.x + cells3.y + cells3.z;
  return mod(abs(cells), 2.0) == 0.0 ? rt_material_color[object].xyz : rt_material_color2[object].xyz;
}
