// ---------------------------------------------------------------------------
// RiemannRayTraceMeshes.glsl: the scene's triangle meshes (included only when
// the scene has some: RT_MESHES). A line-by-line mirror of
// riemann::IntersectMeshBVH (Rendering/CPU/RiemannMeshBVH.cxx, tested there
// against Embree): the flat hierarchy built on the CPU with Embree's BVH
// builder, read from buffer textures of RGBA32F texels whose integers are
// stored as exact float values (GLSL 1.50 has no floatBitsToInt; the layout:
// RiemannMeshBVH.h). A new mesh re-uploads
// the buffers; it never recompiles the shader.
// ---------------------------------------------------------------------------

// Two texels per node: (lower, link), (upper, count).
uniform samplerBuffer rt_mesh_nodes;
// Three texels per triangle: (v0, object), (v1, primitive), (v2, attributes).
uniform samplerBuffer rt_mesh_triangles;
// One texel per triangle: its vertices' indices in the two arrays below.
uniform samplerBuffer rt_mesh_corners;
uniform samplerBuffer rt_mesh_normals;
uniform samplerBuffer rt_mesh_colors;

#define RT_MESH_HAS_NORMALS 1
#define RT_MESH_HAS_COLORS 2

// The triangle and barycentric weights (of v1, v2) of the last mesh hit that
// rt_intersect_segment kept; -1 when its hit was an analytic object.
int rt_mesh_hit_triangle = -1;
vec2 rt_mesh_hit_uv = vec2(0.0);

// 1 / d, or 1e30 where the segment does not move (division by zero is
// undefined in GLSL).
vec3 rt_safe_inverse(vec3 d)
{
  bvec3 zero = equal(d, vec3(0.0));
  return mix(1.0 / mix(d, vec3(1.0), zero), vec3(1e30), zero);
}

// Whether the segment a + t d, t in [0, limit], meets the box [lo, hi].
bool rt_overlaps_box(vec3 lo, vec3 hi, vec3 a, vec3 inverse, float limit)
{
  vec3 t0 = (lo - a) * inverse;
  vec3 t1 = (hi - a) * inverse;
  vec3 near = min(t0, t1);
  vec3 far = max(t0, t1);
  float enter = max(max(0.0, near.x), max(near.y, near.z));
  float exit = min(min(limit, far.x), min(far.y, far.z));
  return enter <= exit;
}

// Moller-Trumbore against the segment a + t d: t in [0, best), with (u, v).
bool rt_intersect_triangle(
  vec3 v0, vec3 v1, vec3 v2, vec3 a, vec3 d, float best, out float t, out vec2 uv)
{
  const float slack = 1e-6; // a segment through a shared edge must not slip between
  t = 0.0;
  uv = vec2(0.0);
  vec3 e1 = v1 - v0;
  vec3 e2 = v2 - v0;
  vec3 p = cross(d, e2);
  float det = dot(e1, p);
  if (det == 0.0)
  {
    return false;
  }
  float inverse = 1.0 / det;
  vec3 s = a - v0;
  uv.x = dot(s, p) * inverse;
  if (uv.x < -slack || uv.x > 1.0 + slack)
  {
    return false;
  }
  vec3 q = cross(s, e1);
  uv.y = dot(d, q) * inverse;
  if (uv.y < -slack || uv.x + uv.y > 1.0 + slack)
  {
    return false;
  }
  t = dot(e2, q) * inverse;
  return t >= 0.0 && t <= 1.0 && t < best;
}

// The normal of a hit on triangle k, facing d: the vertex normals
// interpolated where the mesh has them, else the face's.
vec3 rt_mesh_normal(int k, vec2 uv, vec3 d)
{
  vec4 t0 = texelFetch(rt_mesh_triangles, 3 * k);
  vec4 t1 = texelFetch(rt_mesh_triangles, 3 * k + 1);
  vec4 t2 = texelFetch(rt_mesh_triangles, 3 * k + 2);
  vec3 normal = cross(t1.xyz - t0.xyz, t2.xyz - t0.xyz);
  if ((int(t2.w) & RT_MESH_HAS_NORMALS) != 0)
  {
    ivec4 corners = ivec4(texelFetch(rt_mesh_corners, k));
    vec3 interpolated = (1.0 - uv.x - uv.y) * texelFetch(rt_mesh_normals, corners.x).xyz +
      uv.x * texelFetch(rt_mesh_normals, corners.y).xyz +
      uv.y * texelFetch(rt_mesh_normals, corners.z).xyz;
    if (dot(interpolated, interpolated) > 0.0)
    {
      normal = interpolated;
    }
  }
  float len = length(normal);
  normal = len > 0.0 ? normal / len : vec3(0.0);
  return dot(normal, d) > 0.0 ? -normal : normal;
}

// The vertex colours of triangle k at (u, v), or false when its mesh has none.
bool rt_mesh_color(int k, vec2 uv, out vec3 color)
{
  color = vec3(0.0);
  if ((int(texelFetch(rt_mesh_triangles, 3 * k + 2).w) & RT_MESH_HAS_COLORS) == 0)
  {
    return false;
  }
  ivec4 corners = ivec4(texelFetch(rt_mesh_corners, k));
  color = (1.0 - uv.x - uv.y) * texelFetch(rt_mesh_colors, corners.x).rgb +
    uv.x * texelFetch(rt_mesh_colors, corners.y).rgb +
    uv.y * texelFetch(rt_mesh_colors, corners.z).rgb;
  color = clamp(color, 0.0, 1.0);
  return true;
}

// The nearest triangle hit by the segment a -> b at a fraction below `limit`
// (IntersectMeshBVH): fraction, normal facing the segment, scene object,
// triangle (in the buffers' order) and barycentric weights.
bool rt_intersect_meshes(vec3 a, vec3 b, float limit, out float fraction, out vec3 normal,
  out int object, out int triangle, out vec2 uv)
{
  fraction = 0.0;
  normal = vec3(0.0);
  object = -1;
  triangle = -1;
  uv = vec2(0.0);
  vec3 d = b - a;
  vec3 inverse = rt_safe_inverse(d);
  int stack[RT_MESH_STACK];
  int top = 0;
  stack[top++] = 0;
  float best = min(limit, 2.0);
  while (top > 0)
  {
    int index = stack[--top];
    vec4 lower = texelFetch(rt_mesh_nodes, 2 * index);
    vec4 upper = texelFetch(rt_mesh_nodes, 2 * index + 1);
    if (!rt_overlaps_box(lower.xyz, upper.xyz, a, inverse, min(best, 1.0)))
    {
      continue;
    }
    int link = int(lower.w);
    int count = int(upper.w);
    if (count == 0)
    {
      stack[top++] = link; // the second child, visited after the first
      stack[top++] = index + 1;
      continue;
    }
    for (int k = link; k < link + count; ++k)
    {
      float t;
      vec2 weights;
      if (rt_intersect_triangle(texelFetch(rt_mesh_triangles, 3 * k).xyz,
            texelFetch(rt_mesh_triangles, 3 * k + 1).xyz,
            texelFetch(rt_mesh_triangles, 3 * k + 2).xyz, a, d, best, t, weights))
      {
        best = t;
        triangle = k;
        uv = weights;
      }
    }
  }
  if (triangle < 0)
  {
    return false;
  }
  fraction = best;
  normal = rt_mesh_normal(triangle, uv, d);
  object = int(texelFetch(rt_mesh_triangles, 3 * triangle).w);
  return true;
}
