// ---------------------------------------------------------------------------
// RiemannRayTraceIntegrators.glsl: one step of the geodesic flow
//   x' = v,  v' = a(x, v) = -Gamma(x)(v, v)
// in Riemannian arc length (MATH.md), a float mirror of Integrators.cxx:
// forward Euler (the paper's), classical Runge-Kutta 4, and adaptive
// Dormand-Prince 5(4) with the CPU's error norm and step control.
// rt_metric_acceleration comes from the metric part of the shader and returns
// false where the metric is degenerate.
// ---------------------------------------------------------------------------

#define RT_ACCEPTED 0
#define RT_STEP_TOO_SMALL 1
#define RT_DEGENERATE 2

// y <- y + h f(y).
bool rt_euler_step(inout vec3 x, inout vec3 v, float h)
{
  vec3 a;
  if (!rt_metric_acceleration(x, v, a))
  {
    return false;
  }
  x += h * v;
  v += h * a;
  return true;
}

// Classical RK4 on (x, v): stage k_i = (v_i, a_i).
bool rt_rk4_step(inout vec3 x, inout vec3 v, float h)
{
  vec3 a1;
  vec3 a2;
  vec3 a3;
  vec3 a4;
  if (!rt_metric_acceleration(x, v, a1))
  {
    return false;
  }
  vec3 v2 = v + (0.5 * h) * a1;
  if (!rt_metric_acceleration(x + (0.5 * h) * v, v2, a2))
  {
    return false;
  }
  vec3 v3 = v + (0.5 * h) * a2;
  if (!rt_metric_acceleration(x + (0.5 * h) * v2, v3, a3))
  {
    return false;
  }
  vec3 v4 = v + h * a3;
  if (!rt_metric_acceleration(x + h * v3, v4, a4))
  {
    return false;
  }
  x += (h / 6.0) * (v + 2.0 * v2 + 2.0 * v3 + v4);
  v += (h / 6.0) * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
  return true;
}

// Scaled RMS error of one Dormand-Prince step (Hairer's mixed tolerance).
float rt_dp45_error(vec3 ex, vec3 ev, vec3 x, vec3 v, vec3 nx, vec3 nv, float tolerance)
{
  vec3 sx = vec3(tolerance) + tolerance * max(abs(x), abs(nx));
  vec3 sv = vec3(tolerance) + tolerance * max(abs(v), abs(nv));
  vec3 qx = ex / sx;
  vec3 qv = ev / sv;
  return sqrt((dot(qx, qx) + dot(qv, qv)) / 6.0);
}

// One accepted adaptive step of at most `limit`, trying h first (DormandPrince45::Step).
// `a1` caches the acceleration at (x, v) (first same as last) once `cached`.
// On return `taken` is the step used and h the suggested next one.
int rt_dp45_step(inout vec3 x, inout vec3 v, inout vec3 a1, inout bool cached, inout float h,
  float limit, float minimumStep, float maximumStep, float tolerance, out float taken)
{
  const float a21 = 1.0 / 5.0;
  const float a31 = 3.0 / 40.0;
  const float a32 = 9.0 / 40.0;
  const float a41 = 44.0 / 45.0;
  const float a42 = -56.0 / 15.0;
  const float a43 = 32.0 / 9.0;
  const float a51 = 19372.0 / 6561.0;
  const float a52 = -25360.0 / 2187.0;
  const float a53 = 64448.0 / 6561.0;
  const float a54 = -212.0 / 729.0;
  const float a61 = 9017.0 / 3168.0;
  const float a62 = -355.0 / 33.0;
  const float a63 = 46732.0 / 5247.0;
  const float a64 = 49.0 / 176.0;
  const float a65 = -5103.0 / 18656.0;
  const float b1 = 35.0 / 384.0;
  const float b3 = 500.0 / 1113.0;
  const float b4 = 125.0 / 192.0;
  const float b5 = -2187.0 / 6784.0;
  const float b6 = 11.0 / 84.0;
  const float e1 = 71.0 / 57600.0;
  const float e3 = -71.0 / 16695.0;
  const float e4 = 71.0 / 1920.0;
  const float e5 = -17253.0 / 339200.0;
  const float e6 = 22.0 / 525.0;
  const float e7 = -1.0 / 40.0;

  taken = 0.0;
  if (!cached)
  {
    if (!rt_metric_acceleration(x, v, a1))
    {
      return RT_DEGENERATE;
    }
    cached = true;
  }
  h = min(max(h, minimumStep), maximumStep);
  // A rejection multiplies the step by at most 0.9: 200 attempts cover the
  // whole range from the maximum step down to the minimum one.
  for (int attempt = 0; attempt < 200; ++attempt)
  {
    bool lastStep = h >= limit;
    float step = lastStep ? limit : h;
    // Stage k_i = (w_i, b_i): velocity and acceleration at the stage point.
    vec3 w1 = v;
    vec3 b1v = a1;
    vec3 w2 = v + step * (a21 * b1v);
    vec3 b2v;
    vec3 w3;
    vec3 b3v;
    vec3 w4;
    vec3 b4v;
    vec3 w5;
    vec3 b5v;
    vec3 w6;
    vec3 b6v;
    vec3 b7v;
    vec3 nx;
    vec3 nv;
    bool defined = rt_metric_acceleration(x + step * (a21 * w1), w2, b2v);
    if (defined)
    {
      w3 = v + step * (a31 * b1v + a32 * b2v);
      defined = rt_metric_acceleration(x + step * (a31 * w1 + a32 * w2), w3, b3v);
    }
    if (defined)
    {
      w4 = v + step * (a41 * b1v + a42 * b2v + a43 * b3v);
      defined = rt_metric_acceleration(x + step * (a41 * w1 + a42 * w2 + a43 * w3), w4, b4v);
    }
    if (defined)
    {
      w5 = v + step * (a51 * b1v + a52 * b2v + a53 * b3v + a54 * b4v);
      defined = rt_metric_acceleration(
        x + step * (a51 * w1 + a52 * w2 + a53 * w3 + a54 * w4), w5, b5v);
    }
    if (defined)
    {
      w6 = v + step * (a61 * b1v + a62 * b2v + a63 * b3v + a64 * b4v + a65 * b5v);
      defined = rt_metric_acceleration(
        x + step * (a61 * w1 + a62 * w2 + a63 * w3 + a64 * w4 + a65 * w5), w6, b6v);
    }
    bool finiteError = false;
    float error = RT_INFINITY;
    bool degenerate = !defined;
    if (defined)
    {
      nx = x + step * (b1 * w1 + b3 * w3 + b4 * w4 + b5 * w5 + b6 * w6);
      nv = v + step * (b1 * b1v + b3 * b3v + b4 * b4v + b5 * b5v + b6 * b6v);
      // k7 = f(next): its velocity part is nv itself.
      degenerate = !rt_metric_acceleration(nx, nv, b7v);
      if (!degenerate)
      {
        vec3 ex = step * (e1 * w1 + e3 * w3 + e4 * w4 + e5 * w5 + e6 * w6 + e7 * nv);
        vec3 ev = step * (e1 * b1v + e3 * b3v + e4 * b4v + e5 * b5v + e6 * b6v + e7 * b7v);
        error = rt_dp45_error(ex, ev, x, v, nx, nv, tolerance);
        finiteError = !isinf(error) && !isnan(error);
      }
    }

    if (finiteError && error <= 1.0)
    {
      x = nx;
      v = nv;
      a1 = b7v;
      taken = step;
      // Grow at most 5x, shrink at most 5x, with the usual 0.9 safety factor.
      float factor = error > 0.0 ? min(5.0, max(0.2, 0.9 * pow(error, -0.2))) : 5.0;
      if (!lastStep || factor < 1.0)
      {
        h = min(max(step * factor, minimumStep), maximumStep);
      }
      return RT_ACCEPTED;
    }
    if (step <= minimumStep)
    {
      return degenerate ? RT_DEGENERATE : RT_STEP_TOO_SMALL;
    }
    h = max(minimumStep, step * (finiteError ? max(0.2, 0.9 * pow(error, -0.2)) : 0.25));
  }
  return RT_STEP_TOO_SMALL;
}
