#include "CausticSheets.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace riemann
{
namespace
{
/// The conjugate point of `points` on sheet k, or nullptr.
const ConjugatePoint* PointOnSheet(const std::vector<ConjugatePoint>& points, int k)
{
  for (const ConjugatePoint& point : points)
  {
    if (point.Sheet <= k && k <= point.Sheet + point.Multiplicity - 1)
    {
      return &point;
    }
  }
  return nullptr;
}

/// Two unit vectors spanning the plane orthogonal to the unit vector d.
void TangentBasis(const Vec3& d, Vec3& a, Vec3& b)
{
  const Vec3 helper = std::abs(d[0]) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  a = d.cross(helper).normalized();
  b = d.cross(a);
}

/**
 * dt / d(angle) at vertex v along its kernel direction: the gradient of the
 * arc length over the unit sphere of grid directions by least squares over
 * the neighbours, dotted with the unit grid-direction change that the
 * kernel variation u makes (d = xi / |xi| for the g-unit xi = d / |d|_g:
 * delta d = |d|_g (u - (d.u) d)). False where it cannot be estimated.
 */
bool KernelSlope(const CausticSheets& sheets, const std::vector<Vec3>& directions, int v,
  const std::vector<int>& neighbours, const Vec3& kernel, const Mat3& g, double& slope)
{
  const Vec3& d = directions[sheets.Direction[v]];
  Vec3 a, b;
  TangentBasis(d, a, b);
  Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
  Eigen::Vector2d right = Eigen::Vector2d::Zero();
  for (int w : neighbours)
  {
    const Vec3 step = directions[sheets.Direction[w]] - d;
    const Eigen::Vector2d x(step.dot(a), step.dot(b));
    normal += x * x.transpose();
    right += x * (sheets.ArcLength[w] - sheets.ArcLength[v]);
  }
  // Well conditioned: neighbours around the vertex, not along one line.
  const double trace = normal.trace();
  if (neighbours.size() < 2 || !(normal.determinant() > 1e-6 * trace * trace))
  {
    return false;
  }
  const Eigen::Vector2d gradient = normal.ldlt().solve(right);
  const Vec3 change = std::sqrt(d.dot(g * d)) * (kernel - d.dot(kernel) * d);
  const double norm = change.norm();
  if (!(norm > 0.0))
  {
    return false;
  }
  slope = (gradient[0] * change.dot(a) + gradient[1] * change.dot(b)) / norm;
  return std::isfinite(slope);
}
} // namespace

CausticSheets BuildCausticSheets(const std::vector<Vec3>& directions,
  const std::vector<std::array<int, 3>>& triangles,
  const std::vector<std::vector<ConjugatePoint>>& found, const Mat3& g)
{
  CausticSheets sheets;
  int deepest = 0;
  for (const auto& points : found)
  {
    if (!points.empty())
    {
      deepest = std::max(deepest, points.back().Sheet + points.back().Multiplicity - 1);
    }
  }
  std::vector<int> local(found.size());
  std::vector<Vec3> kernels;
  std::vector<char> hasSlope;
  // KernelSlope with the sign of each point's (arbitrary) kernel direction.
  std::vector<double> signedSlopes;
  for (int k = 1; k <= deepest; ++k)
  {
    // The sheet's vertices: each direction's point on it.
    const int firstVertex = static_cast<int>(sheets.Points.size());
    for (size_t i = 0; i < found.size(); ++i)
    {
      local[i] = -1;
      const ConjugatePoint* point = PointOnSheet(found[i], k);
      if (point)
      {
        local[i] = static_cast<int>(sheets.Points.size());
        sheets.Points.push_back(point->Point);
        sheets.Direction.push_back(static_cast<int>(i));
        sheets.Sheet.push_back(k);
        sheets.ArcLength.push_back(point->ArcLength);
        sheets.Multiplicity.push_back(point->Multiplicity);
        sheets.Index.push_back(point->Index);
        kernels.push_back(point->KernelDirection);
      }
    }
    // Its triangles and each vertex's neighbours on it.
    const size_t firstTriangle = sheets.Triangles.size();
    std::vector<std::vector<int>> neighbours(sheets.Points.size() - firstVertex);
    for (const std::array<int, 3>& triangle : triangles)
    {
      const std::array<int, 3> t = { local[triangle[0]], local[triangle[1]], local[triangle[2]] };
      if (t[0] < 0 || t[1] < 0 || t[2] < 0)
      {
        continue;
      }
      sheets.Triangles.push_back(t);
      sheets.TriangleSheet.push_back(k);
      for (int c = 0; c < 3; ++c)
      {
        auto& list = neighbours[t[c] - firstVertex];
        for (int o : { t[(c + 1) % 3], t[(c + 2) % 3] })
        {
          if (std::find(list.begin(), list.end(), o) == list.end())
          {
            list.push_back(o);
          }
        }
      }
    }
    // KernelSlope at the simple points.
    for (int v = firstVertex; v < static_cast<int>(sheets.Points.size()); ++v)
    {
      double slope = 0.0;
      const bool ok = sheets.Multiplicity[v] == 1 &&
        KernelSlope(sheets, directions, v, neighbours[v - firstVertex], kernels[v], g, slope);
      signedSlopes.push_back(ok ? slope : 0.0);
      sheets.KernelSlope.push_back(std::abs(signedSlopes.back()));
      hasSlope.push_back(ok ? 1 : 0);
    }
    // Singularities: sheets meeting at a double point, or a cusp edge where
    // the slope changes sign with the kernel directions oriented alike.
    for (size_t t = firstTriangle; t < sheets.Triangles.size(); ++t)
    {
      const std::array<int, 3>& c = sheets.Triangles[t];
      auto singularity = CausticSingularity::None;
      if (sheets.Multiplicity[c[0]] > 1 || sheets.Multiplicity[c[1]] > 1 ||
        sheets.Multiplicity[c[2]] > 1)
      {
        singularity = CausticSingularity::SheetsMeet;
      }
      else if (hasSlope[c[0]] && hasSlope[c[1]] && hasSlope[c[2]])
      {
        double low = HUGE_VAL;
        double high = -HUGE_VAL;
        for (int v : c)
        {
          const double orientation = kernels[v].dot(g * kernels[c[0]]) < 0.0 ? -1.0 : 1.0;
          low = std::min(low, orientation * signedSlopes[v]);
          high = std::max(high, orientation * signedSlopes[v]);
        }
        if (low < 0.0 && high > 0.0)
        {
          singularity = CausticSingularity::Cusp;
        }
      }
      sheets.TriangleSingularity.push_back(static_cast<int>(singularity));
    }
  }
  return sheets;
}
} // namespace riemann
