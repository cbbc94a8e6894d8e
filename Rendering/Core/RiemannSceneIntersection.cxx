#include "RiemannSceneIntersection.h"

#include <Eigen/Geometry> // cross

#include <algorithm>
#include <cmath>
#include <limits>

namespace riemann
{
namespace
{
//------------------------------------------------------------------------------
// Intersection kernels. Each tests the segment p(t) = a + t d, t in [0, 1],
// and on a hit sets the fraction t and the normal. They are written to be
// mirrored line by line in GLSL: no allocation, fixed small loops (the CPU
// multiplies by 1 / d and 1 / spacing computed once per segment where the
// shader divides: the same tests, cheaper).
//------------------------------------------------------------------------------
constexpr double Infinity = std::numeric_limits<double>::infinity();

/// -d / |d|, or zero for d == 0: the normal of a hit at a start inside a solid.
Vec3 FacingNormal(const Vec3& d)
{
  const double length = d.norm();
  return length > 0 ? Vec3(-d / length) : Vec3(Vec3::Zero());
}

/**
 * Slab test of the closed box [lo, hi]. On return [enter, exit] is the
 * parameter interval of the infinite line a + t d inside the box (enter is
 * -inf when no slab bounds it from below) and `axis` the axis whose slab gave
 * `enter` (-1 if none). True when that interval meets [0, 1].
 * An axis with d == 0 constrains nothing if a is within its slab and rejects
 * otherwise (no division by zero).
 */
/// The segment p(t) = A + t D with 1 / D precomputed: every slab test of a
/// segment (the grid tests many bars) multiplies instead of dividing.
struct Segment
{
  Vec3 A;
  Vec3 D;
  Vec3 InverseD;

  Segment(const Vec3& a, const Vec3& d)
    : A(a)
    , D(d)
    , InverseD(d.cwiseInverse())
  {
  }
};

bool SlabTest(const Segment& segment, const Vec3& lo, const Vec3& hi, double& enter, double& exit,
  int& axis)
{
  const Vec3& a = segment.A;
  const Vec3& d = segment.D;
  enter = -Infinity;
  exit = Infinity;
  axis = -1;
  for (int i = 0; i < 3; ++i)
  {
    if (d[i] == 0)
    {
      if (a[i] < lo[i] || a[i] > hi[i])
      {
        return false;
      }
      continue;
    }
    const double t0 = (lo[i] - a[i]) * segment.InverseD[i];
    const double t1 = (hi[i] - a[i]) * segment.InverseD[i];
    const double tNear = std::min(t0, t1);
    const double tFar = std::max(t0, t1);
    if (tNear > enter)
    {
      enter = tNear;
      axis = i;
    }
    exit = std::min(exit, tFar);
  }
  return enter <= exit && exit >= 0 && enter <= 1;
}

/**
 * Closed box. A start in the box (enter <= 0) hits at 0 with the facing
 * normal; otherwise the hit is the entry face, normal -sign(d_axis) e_axis.
 */
bool IntersectBox(
  const Segment& segment, const Vec3& lo, const Vec3& hi, double& fraction, Vec3& normal)
{
  const Vec3& d = segment.D;
  double enter;
  double exit;
  int axis;
  if (!SlabTest(segment, lo, hi, enter, exit, axis))
  {
    return false;
  }
  if (enter <= 0)
  {
    fraction = 0;
    normal = FacingNormal(d);
    return true;
  }
  fraction = enter;
  normal = Vec3::Zero();
  normal[axis] = d[axis] > 0 ? -1.0 : 1.0;
  return true;
}

/**
 * Closed ball |p - c| <= r: with m = a - c, solve |m + t d|^2 = r^2, i.e.
 * A t^2 + 2 B t + C = 0 with A = d.d, B = d.m, C = m.m - r^2. C <= 0 means
 * the start is in the ball (fraction 0, facing normal). Otherwise the ray
 * must approach (B < 0) with a real root; the first root
 * t = (-B - sqrt(B^2 - A C)) / A must be <= 1. Normal (p - c) / r.
 */
bool IntersectSphere(
  const Vec3& a, const Vec3& d, const Vec3& center, double radius, double& fraction, Vec3& normal)
{
  const Vec3 m = a - center;
  const double A = d.dot(d);
  const double B = d.dot(m);
  const double C = m.dot(m) - radius * radius;
  if (C <= 0)
  {
    fraction = 0;
    normal = FacingNormal(d);
    return true;
  }
  const double discriminant = B * B - A * C;
  if (B >= 0 || discriminant < 0)
  {
    return false;
  }
  const double t = (-B - std::sqrt(discriminant)) / A;
  if (t > 1)
  {
    return false;
  }
  fraction = std::max(t, 0.0);
  normal = (a + fraction * d - center) / radius;
  return true;
}

/**
 * Two-sided plane n.(p - q) = 0 (n unit). With signed distances sa, sb of
 * the ends, the segment hits when sa sb <= 0, at sa / (sa - sb) (0 when the
 * segment lies in the plane). The normal faces the ray: n if sa - sb >= 0
 * (moving towards -n), else -n.
 */
bool IntersectPlane(const Vec3& a, const Vec3& d, const Vec3& point, const Vec3& unitNormal,
  double& fraction, Vec3& normal)
{
  const double sa = unitNormal.dot(a - point);
  const double sb = unitNormal.dot(a + d - point);
  if (sa * sb > 0)
  {
    return false;
  }
  fraction = sa == sb ? 0.0 : std::clamp(sa / (sa - sb), 0.0, 1.0);
  normal = sa - sb >= 0 ? unitNormal : Vec3(-unitNormal);
  return true;
}

/**
 * False when no bar of a grid (spacing 1 / inverseS, half thickness h) can
 * meet the segment: a bar along axis k lies at lattice coordinates in the
 * two other axes, so the segment's bounding box grown by h must hold a
 * lattice coordinate in two axes at least. Most ray-marching segments
 * (much shorter than the spacing, between the bars) stop here. The test is
 * IntersectGrid's candidate enumeration over the whole segment before any
 * clipping, so it never rejects a hit.
 */
bool NearTwoLatticeLines(const Vec3& a, const Vec3& d, double h, double inverseS, double slack)
{
  int near = 0;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double lo = std::min(a[axis], a[axis] + d[axis]);
    const double hi = std::max(a[axis], a[axis] + d[axis]);
    near += std::floor((hi + h) * inverseS + slack) >= std::ceil((lo - h) * inverseS - slack) ? 1 : 0;
  }
  return near >= 2;
}

/**
 * The grid of bars (the geometry is in RiemannScene.h). The segment is first
 * clipped to the grid's bounding box (the extent grown by h = thickness / 2)
 * and cut into pieces no longer than the spacing. For each piece in order and
 * each bar axis k, the candidate bars are the lattice lines (i s, j s) whose
 * bar section overlaps the piece's bounding box in the two other axes:
 *   i in [ceil((min_u - h) / s), floor((max_u + h) / s)]  (widened by 1e-9)
 * intersected with the lattice lines inside the extent,
 *   i in [ceil(E0_u / s - 1e-9), floor(E1_u / s + 1e-9)].
 * Each candidate bar box is slab-tested against the whole segment (exact,
 * IntersectBox). A bar not yet enumerated does not meet the pieces so far, so
 * once the best fraction lies within the pieces done, it is the first hit.
 * A ray-marching shader sees segments much shorter than the spacing: one
 * piece, 0 to 2 candidates per axis and direction.
 */
bool IntersectGrid(
  const SceneObject& grid, const Segment& segment, double& fraction, Vec3& normal)
{
  const Vec3& a = segment.A;
  const Vec3& d = segment.D;
  const double s = grid.Spacing;
  // Lattice coordinates by multiplication: the 1e-9 slack below is far
  // wider than the rounding this changes.
  const double inverseS = 1.0 / s;
  const double h = 0.5 * grid.Thickness;
  constexpr double slack = 1e-9;
  if (!(s > 0) || !NearTwoLatticeLines(a, d, h, inverseS, slack))
  {
    return false;
  }
  const Vec3 extentLo(grid.Extent[0], grid.Extent[2], grid.Extent[4]);
  const Vec3 extentHi(grid.Extent[1], grid.Extent[3], grid.Extent[5]);
  const Vec3 outerLo = extentLo - Vec3::Constant(h);
  const Vec3 outerHi = extentHi + Vec3::Constant(h);
  double enter;
  double exit;
  int enterAxis;
  if (!SlabTest(segment, outerLo, outerHi, enter, exit, enterAxis))
  {
    return false;
  }
  const double t0 = std::max(enter, 0.0);
  const double t1 = std::min(exit, 1.0);

  // Lattice lines inside the extent (as doubles: no integer overflow).
  double firstLine[3];
  double lastLine[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    firstLine[axis] = std::ceil(extentLo[axis] * inverseS - slack);
    lastLine[axis] = std::floor(extentHi[axis] * inverseS + slack);
  }

  const double length = d.norm() * (t1 - t0);
  const int pieces = static_cast<int>(std::clamp(std::ceil(length * inverseS), 1.0, 65536.0));
  bool found = false;
  double best = Infinity;
  for (int piece = 0; piece < pieces; ++piece)
  {
    const double ta = t0 + (t1 - t0) * piece / pieces;
    const double tb = piece + 1 == pieces ? t1 : t0 + (t1 - t0) * (piece + 1) / pieces;
    const Vec3 pa = a + ta * d;
    const Vec3 pb = a + tb * d;
    const Vec3 boxLo = pa.cwiseMin(pb);
    const Vec3 boxHi = pa.cwiseMax(pb);
    for (int k = 0; k < 3; ++k)
    {
      const int u = (k + 1) % 3;
      const int v = (k + 2) % 3;
      const double i0 = std::max(firstLine[u], std::ceil((boxLo[u] - h) * inverseS - slack));
      const double i1 = std::min(lastLine[u], std::floor((boxHi[u] + h) * inverseS + slack));
      const double j0 = std::max(firstLine[v], std::ceil((boxLo[v] - h) * inverseS - slack));
      const double j1 = std::min(lastLine[v], std::floor((boxHi[v] + h) * inverseS + slack));
      for (double i = i0; i <= i1; ++i)
      {
        for (double j = j0; j <= j1; ++j)
        {
          Vec3 barLo;
          Vec3 barHi;
          barLo[k] = outerLo[k];
          barHi[k] = outerHi[k];
          barLo[u] = i * s - h;
          barHi[u] = i * s + h;
          barLo[v] = j * s - h;
          barHi[v] = j * s + h;
          double t;
          Vec3 n;
          if (IntersectBox(segment, barLo, barHi, t, n) && t < best)
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
} // namespace
//------------------------------------------------------------------------------
bool IntersectSegment(const Scene& scene, const Vec3& a, const Vec3& b, SceneHit& hit)
{
  const Vec3 d = b - a;
  const Segment segment(a, d);
  bool found = false;
  double best = Infinity;
  for (size_t index = 0; index < scene.Objects.size(); ++index)
  {
    const SceneObject& object = scene.Objects[index];
    double t = Infinity;
    Vec3 normal;
    bool hits = false;
    switch (object.Type)
    {
      case ObjectType::Grid:
        hits = IntersectGrid(object, segment, t, normal);
        break;
      case ObjectType::Sphere:
        hits = IntersectSphere(a, d, object.A, object.Radius, t, normal);
        break;
      case ObjectType::Plane:
        hits = IntersectPlane(a, d, object.A, object.B, t, normal);
        break;
      case ObjectType::Box:
        hits = IntersectBox(segment, object.A, object.B, t, normal);
        break;
      case ObjectType::Mesh:
        // Intersected by the CPU tracer (Embree), not here.
        break;
    }
    // Strictly smaller: a tie keeps the object listed first.
    if (hits && t < best)
    {
      found = true;
      best = t;
      hit.Fraction = t;
      hit.Normal = normal;
      hit.Object = static_cast<int>(index);
      hit.Primitive = -1;
    }
  }
  if (found)
  {
    hit.Position = a + hit.Fraction * d;
  }
  return found;
}


MeshIntersector::~MeshIntersector() = default;

bool IntersectSceneSegment(const Scene& scene, const MeshIntersector* meshes, const Vec3& a,
  const Vec3& b, SceneHit& hit)
{
  bool found = IntersectSegment(scene, a, b, hit);
  if (meshes && !meshes->Empty())
  {
    SceneHit mesh;
    bool meshFound = false;
    meshes->Intersect(&a, &b, 1, &mesh, &meshFound, false);
    if (meshFound && (!found || mesh.Fraction < hit.Fraction))
    {
      hit = mesh;
      found = true;
    }
  }
  return found;
}
} // namespace riemann
