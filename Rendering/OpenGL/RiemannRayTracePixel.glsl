// ---------------------------------------------------------------------------
// RiemannRayTracePixel.glsl: one pixel of the inside view (vtkRiemannRayTracePass),
// shared by the fragment-shader path (RiemannRayTraceFS.glsl) and the
// compute-shader path (RiemannRayTraceCS.glsl), which insert it at their
// RT::Pixel::Impl tag after the metric, meshes, scene and integrators.
// ---------------------------------------------------------------------------

// ---- image and observer (riemann::ObserverCamera, computed on the CPU) ----
// Origin and size of the image in window pixels.
uniform vec4 rt_viewport;
uniform vec3 rt_eye;
// g-orthonormal frame at the eye.
uniform vec3 rt_forward;
uniform vec3 rt_up;
uniform vec3 rt_right;
// tan(vertical view angle / 2).
uniform float rt_tan_half_angle;
// 0: perspective, 1: equirectangular.
uniform int rt_projection;

// ---- integration (riemann::RaySettings) ----
uniform float rt_step;
uniform int rt_max_steps;
uniform float rt_max_length;
uniform float rt_tolerance;
uniform float rt_min_step;
uniform float rt_max_step;

// ---- shading ----
uniform vec3 rt_background;
uniform int rt_use_environment;
uniform sampler2D rt_environment;
uniform vec3 rt_fog_color;
uniform float rt_fog_density;
uniform int rt_observer_light;

// 0: colour; 1: hit capture (x, y, z, arc length), (0, 0, 0, -1) for no hit,
// (0, 0, 0, -2) where the integration failed.
uniform int rt_output;

// The camera's clipping range (near, far), for the depth of each pixel.
uniform vec2 rt_clipping_range;

#define RT_RAY_HIT 0
#define RT_RAY_ESCAPED 1
#define RT_RAY_FAILED 2

// Shown where a ray cannot go on: the metric is degenerate (not positive
// definite, not finite) or the adaptive step fell below its minimum.
const vec3 rt_failure_color = vec3(1.0, 0.0, 1.0);

const float rt_pi = 3.14159265358979;

// The unit-speed initial velocity of the ray through normalised image
// coordinates c in [-1, 1]^2: riemann::ObserverCamera::Direction.
vec3 rt_direction(vec2 c, float aspect)
{
  if (rt_projection == 1)
  {
    float longitude = c.x * rt_pi;
    float latitude = c.y * 0.5 * rt_pi;
    return cos(latitude) * (cos(longitude) * rt_forward + sin(longitude) * rt_right) +
      sin(latitude) * rt_up;
  }
  float a = c.x * rt_tan_half_angle * aspect;
  float b = c.y * rt_tan_half_angle;
  // The frame is g-orthonormal, so |d|_g^2 = 1 + a^2 + b^2.
  return (rt_forward + a * rt_right + b * rt_up) / sqrt(1.0 + a * a + b * b);
}

// Trace one ray as riemann::TraceRay does: step, intersect the chord with the
// scene, stop at the first hit, at the maximum length (the last step lands on
// it), after the maximum number of steps, or where the integration fails.
int rt_trace(vec3 x, vec3 v, out vec3 hitPosition, out vec3 hitNormal, out int hitObject,
  out float arcLength, out vec3 finalVelocity)
{
  hitPosition = x;
  hitNormal = vec3(0.0);
  hitObject = -1;
  arcLength = 0.0;
  finalVelocity = v;
  float s = 0.0;
  float h = rt_step;
  vec3 a1 = vec3(0.0);
  bool cached = false;
  float endTolerance = 1e-6 * max(1.0, rt_max_length);
  for (int n = 0; n < rt_max_steps; ++n)
  {
    float remaining = rt_max_length - s;
    if (remaining <= endTolerance)
    {
      break;
    }
    vec3 x0 = x;
    vec3 v0 = v;
    float taken = 0.0;
    int status = RT_ACCEPTED;
#if RT_INTEGRATOR == 0
    taken = min(h, remaining);
    status = rt_euler_step(x, v, taken) ? RT_ACCEPTED : RT_DEGENERATE;
#elif RT_INTEGRATOR == 1
    taken = min(h, remaining);
    status = rt_rk4_step(x, v, taken) ? RT_ACCEPTED : RT_DEGENERATE;
#else
    status =
      rt_dp45_step(x, v, a1, cached, h, remaining, rt_min_step, rt_max_step, rt_tolerance, taken);
#endif
    if (status != RT_ACCEPTED || any(isnan(x)) || any(isinf(x)) || any(isnan(v)) ||
      any(isinf(v)))
    {
      hitPosition = x0;
      arcLength = s;
      finalVelocity = v0;
      return RT_RAY_FAILED;
    }
    float fraction;
    vec3 position;
    vec3 normal;
    int object;
    if (rt_intersect_segment(x0, x, fraction, position, normal, object))
    {
      hitPosition = position;
      hitNormal = normal;
      hitObject = object;
      // Arc length and velocity at the hit, linear within the step.
      arcLength = s + fraction * taken;
      finalVelocity = v0 + fraction * (v - v0);
      return RT_RAY_HIT;
    }
    s += taken;
    if (!rt_metric_inside(x))
    {
      // Left a sampled metric's data ("outside": "stop"): escaped, as on the CPU.
      break;
    }
  }
  hitPosition = x;
  arcLength = s;
  finalVelocity = v;
  return RT_RAY_ESCAPED;
}

// Lambert with the light at the eye: the cosine between the arriving
// velocity v and the surface, measured with g at the hit:
// |nu(v)| / (|nu|_{g^-1} |v|_g), nu the coordinate normal covector.
float rt_observer_cosine(vec3 p, vec3 nu, vec3 v)
{
  mat3 g;
  if (!rt_metric_tensor(p, g))
  {
    return 1.0;
  }
  float vv = dot(v, g * v);
  float nn = dot(nu, inverse(g) * nu);
  if (!(vv > 0.0) || !(nn > 0.0))
  {
    return 1.0;
  }
  return clamp(abs(dot(nu, v)) / sqrt(nn * vv), 0.0, 1.0);
}

// Equirectangular environment, +y up: longitude atan2(d.x, -d.z) (0 looking
// down -z, growing towards +x) across the width, latitude asin(d.y) from the
// top row (+90 degrees) to the bottom row (-90 degrees).
vec3 rt_environment_color(vec3 direction)
{
  float len = length(direction);
  if (!(len > 0.0))
  {
    return rt_background;
  }
  vec3 d = direction / len;
  float u = 0.5 + atan(d.x, -d.z) / (2.0 * rt_pi);
  float t = 0.5 - asin(clamp(d.y, -1.0, 1.0)) / rt_pi;
  return texture(rt_environment, vec2(u, t)).rgb;
}

// The window depth of a hit at Euclidean distance `distance` from the eye:
// what a straight perspective view gives a point that far along its axis,
// (1/near - 1/distance) / (1/near - 1/far), clamped to [0, 1].
float rt_depth(float distance)
{
  float near = rt_clipping_range.x;
  float far = rt_clipping_range.y;
  if (!(near > 0.0) || !(far > near) || !(distance > 0.0))
  {
    return distance > 0.0 ? 1.0 : 0.0;
  }
  return clamp((1.0 / near - 1.0 / distance) / (1.0 / near - 1.0 / far), 0.0, 1.0);
}

// The picture of one pixel whose centre is `fragCoord` in window pixels (as
// gl_FragCoord): with rt_output 0, its colour and window depth; with
// rt_output 1, the hit capture in `color` ((x, y, z, arc length), (0, 0, 0,
// -1) for no hit, (0, 0, 0, -2) where the integration failed) and depth 1.
// Both paths call it: the fragment shader (RiemannRayTraceFS.glsl) per
// fragment, the compute shader (RiemannRayTraceCS.glsl) per invocation.
void rt_pixel(vec2 fragCoord, out vec4 color, out float depth)
{
  vec2 pixel = fragCoord - rt_viewport.xy;
  vec2 c = 2.0 * pixel / rt_viewport.zw - 1.0;
  vec3 direction = rt_direction(c, rt_viewport.z / rt_viewport.w);

  vec3 position;
  vec3 normal;
  int object;
  float arcLength;
  vec3 velocity;
  int result = rt_trace(rt_eye, direction, position, normal, object, arcLength, velocity);

  if (rt_output == 1)
  {
    color = result == RT_RAY_HIT ? vec4(position, arcLength)
                                 : vec4(0.0, 0.0, 0.0, result == RT_RAY_FAILED ? -2.0 : -1.0);
    depth = 1.0;
    return;
  }

  // Depth, so that overlays and other passes compose: the far plane where no
  // surface was hit.
  depth = result == RT_RAY_HIT ? rt_depth(length(position - rt_eye)) : 1.0;

  vec3 shade;
  if (result == RT_RAY_HIT)
  {
    shade = rt_surface_color(object, position, normal);
    if (rt_observer_light == 1)
    {
      shade *= rt_observer_cosine(position, normal, velocity);
    }
    shade = mix(shade, rt_fog_color, 1.0 - exp(-rt_fog_density * arcLength));
  }
  else if (result == RT_RAY_FAILED)
  {
    shade = rt_failure_color;
  }
  else
  {
    shade = rt_use_environment == 1 ? rt_environment_color(velocity) : rt_background;
  }
  color = vec4(shade, 1.0);
}
