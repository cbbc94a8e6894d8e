#include "SampledTensorField.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace riemann
{
namespace
{
/// The component index of g(row, column) in VTK's order XX, YY, ZZ, XY, YZ, XZ.
constexpr int ComponentOf[3][3] = { { 0, 3, 5 }, { 3, 1, 4 }, { 5, 4, 2 } };

/**
 * The four weights of the uniform cubic B-spline at fraction t in [0, 1) of
 * a cell, for the samples at offsets -1, 0, 1, 2, and their first and
 * second derivatives in t.
 */
struct SplineWeights
{
  double Value[4];
  double First[4];
  double Second[4];

  explicit SplineWeights(double t)
  {
    const double s = 1.0 - t;
    const double t2 = t * t;
    const double t3 = t2 * t;
    this->Value[0] = s * s * s / 6.0;
    this->Value[1] = (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0;
    this->Value[2] = (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;
    this->Value[3] = t3 / 6.0;
    this->First[0] = -0.5 * s * s;
    this->First[1] = 1.5 * t2 - 2.0 * t;
    this->First[2] = -1.5 * t2 + t + 0.5;
    this->First[3] = 0.5 * t2;
    this->Second[0] = s;
    this->Second[1] = 3.0 * t - 2.0;
    this->Second[2] = -3.0 * t + 1.0;
    this->Second[3] = t;
  }
};

/// The cell and fraction of grid coordinate u on an axis of n points, u in
/// the box [-1/2, n - 1/2]: cells -1 and n - 1 reach past the outer samples
/// (their missing neighbours are the edge's repeated).
void CellOf(double u, int n, int& cell, double& t)
{
  cell = std::clamp(static_cast<int>(std::floor(u)), -1, n - 1);
  t = u - cell;
}


void SetIdentity(Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>* d2g)
{
  g.setIdentity();
  for (Mat3& d : dg)
  {
    d.setZero();
  }
  if (d2g)
  {
    for (Mat3Stack& stack : *d2g)
    {
      for (Mat3& d : stack)
      {
        d.setZero();
      }
    }
  }
}

/// Symmetric 3x3 from six components XX, YY, ZZ, XY, YZ, XZ.
Mat3 FromComponents(const double c[6])
{
  Mat3 m;
  for (int r = 0; r < 3; ++r)
  {
    for (int s = 0; s < 3; ++s)
    {
      m(r, s) = c[ComponentOf[r][s]];
    }
  }
  return m;
}
} // namespace

std::string SampledTensorGrid::Check() const
{
  std::ostringstream problem;
  for (int a = 0; a < 3; ++a)
  {
    if (this->Dimensions[a] < 2)
    {
      problem << "the grid needs at least 2 points on each axis, axis " << a << " has "
              << this->Dimensions[a];
      return problem.str();
    }
    if (!std::isfinite(this->Spacing[a]) || !(this->Spacing[a] > 0.0))
    {
      problem << "the spacing must be finite and positive, axis " << a << " has "
              << this->Spacing[a];
      return problem.str();
    }
  }
  if (!this->Origin.allFinite())
  {
    return "the origin is not finite";
  }
  const Mat3 gram = this->Direction.transpose() * this->Direction;
  if (!this->Direction.allFinite() || !gram.isApprox(Mat3::Identity(), 1e-6))
  {
    return "the direction matrix is not orthonormal (a rotation, or a rotation and a "
           "reflection)";
  }
  if (static_cast<long long>(this->Components.size()) != 6 * this->NumberOfPoints())
  {
    problem << "expected 6 components per point (" << 6 * this->NumberOfPoints() << "), got "
            << this->Components.size();
    return problem.str();
  }
  return {};
}

SampledTensorField::SampledTensorField(SampledTensorGrid grid, bool stopOutside)
  : Grid(std::move(grid))
  , StopOutside(stopOutside)
{
  const std::string problem = this->Grid.Check();
  if (!problem.empty())
  {
    throw std::invalid_argument("sampled tensor field: " + problem);
  }
  // The inverse of the placement itself, not Direction^T / Spacing: a
  // direction read from a float32 s-form is orthonormal only to about 1e-7,
  // and its transpose then put the voxel centres of a mask placed by the
  // same s-form up to 1e-6 voxels off the grid (an oblique DIPY file lost
  // its seeds on the outer faces so).
  this->WorldToGrid = (this->Grid.Direction * this->Grid.Spacing.asDiagonal()).inverse();
}

Vec3 SampledTensorField::GridCoordinates(const Vec3& p) const
{
  return this->WorldToGrid * (p - this->Grid.Origin);
}


bool SampledTensorField::Inside(const Vec3& p) const
{
  const Vec3 u = this->GridCoordinates(p);
  for (int a = 0; a < 3; ++a)
  {
    if (!WithinFaces(u[a], this->Grid.Dimensions[a]))
    {
      return false;
    }
  }
  return true;
}

namespace
{
/// g and (order 1) its first derivatives in grid coordinates from the 4^3
/// samples around `cell`, with the spline weights w of each axis.
void SumSeparably(const SampledTensorGrid& grid, const int cell[3], const SplineWeights w[3],
  int order, Mat3& g, Mat3Stack& gridFirst)
{
  // The spline is a tensor product, so its sums go one axis at a time: along
  // x within each of the 16 rows of samples (contiguous in memory), then y,
  // then z. About 1,150 multiply-adds for g and its first derivatives against
  // 2,300 sample by sample, without the second derivatives' bookkeeping.
  // Geodesics, rays and Jacobi-free traces only ask for these (76% of a
  // tractography run's time was this sum).
  const std::array<int, 3>& n = grid.Dimensions;
  long long ii[4], jj[4], kk[4];
  for (int q = 0; q < 4; ++q)
  {
    ii[q] = 6LL * std::clamp(cell[0] - 1 + q, 0, n[0] - 1);
    jj[q] = std::clamp(cell[1] - 1 + q, 0, n[1] - 1);
    kk[q] = std::clamp(cell[2] - 1 + q, 0, n[2] - 1);
  }
  const double* samples = grid.Components.data();
  // Per z layer: the value, d/dy and d/dx of the x-then-y sums.
  double layerValue[4][6] = {}, layerY[4][6] = {}, layerX[4][6] = {};
  for (int c = 0; c < 4; ++c)
  {
    for (int b = 0; b < 4; ++b)
    {
      const double* row = samples + 6LL * n[0] * (jj[b] + n[1] * kk[c]);
      double rowValue[6] = {}, rowX[6] = {};
      for (int a = 0; a < 4; ++a)
      {
        const double* sample = row + ii[a];
        for (int m = 0; m < 6; ++m)
        {
          rowValue[m] += w[0].Value[a] * sample[m];
          rowX[m] += w[0].First[a] * sample[m];
        }
      }
      for (int m = 0; m < 6; ++m)
      {
        layerValue[c][m] += w[1].Value[b] * rowValue[m];
        layerY[c][m] += w[1].First[b] * rowValue[m];
        layerX[c][m] += w[1].Value[b] * rowX[m];
      }
    }
  }
  double value[6] = {}, first[3][6] = {};
  for (int c = 0; c < 4; ++c)
  {
    for (int m = 0; m < 6; ++m)
    {
      value[m] += w[2].Value[c] * layerValue[c][m];
      first[0][m] += w[2].Value[c] * layerX[c][m];
      first[1][m] += w[2].Value[c] * layerY[c][m];
      first[2][m] += w[2].First[c] * layerValue[c][m];
    }
  }
  g = FromComponents(value);
  for (int x = 0; x < 3 && order >= 1; ++x)
  {
    gridFirst[x] = FromComponents(first[x]);
  }
}

} // namespace

bool SampledTensorField::EvaluateInGrid(
  const Vec3& u, int order, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const
{
  const std::array<int, 3>& n = this->Grid.Dimensions;
  int cell[3];
  double t[3];
  bool continued[3] = { false, false, false };
  for (int a = 0; a < 3; ++a)
  {
    // On a face up to the affine map's rounding: inside (as Inside() says).
    const double low = -FaceMargin;
    const double high = n[a] - 1 + FaceMargin;
    double inBox = WithinFaces(u[a], n[a]) ? std::clamp(u[a], low, high) : u[a];
    if (!(inBox >= low && inBox <= high))
    {
      if (!this->StopOutside || std::isnan(u[a]))
      {
        return false;
      }
      // The face's value, constant along this axis.
      inBox = std::clamp(u[a], low, high);
      continued[a] = true;
    }
    CellOf(inBox, n[a], cell[a], t[a]);
  }
  SplineWeights w[3] = { SplineWeights(t[0]), SplineWeights(t[1]), SplineWeights(t[2]) };
  for (int a = 0; a < 3; ++a)
  {
    if (continued[a])
    {
      std::fill(std::begin(w[a].First), std::end(w[a].First), 0.0);
      std::fill(std::begin(w[a].Second), std::end(w[a].Second), 0.0);
    }
  }
  if (order <= 1)
  {
    SumSeparably(this->Grid, cell, w, order, g, dg);
    return true;
  }
  // Sums over the 4 x 4 x 4 samples around the cell: the value, the three
  // first derivatives and the six second ones, each of six components.
  double value[6] = {};
  double first[3][6] = {};
  double second[3][3][6] = {};
  const double* samples = this->Grid.Components.data();
  for (int c = 0; c < 4; ++c)
  {
    const long long kk = std::clamp(cell[2] - 1 + c, 0, n[2] - 1);
    for (int b = 0; b < 4; ++b)
    {
      const long long jj = std::clamp(cell[1] - 1 + b, 0, n[1] - 1);
      for (int a = 0; a < 4; ++a)
      {
        const long long ii = std::clamp(cell[0] - 1 + a, 0, n[0] - 1);
        const double* sample = samples + 6 * (ii + n[0] * (jj + n[1] * kk));
        const double v[3] = { w[0].Value[a], w[1].Value[b], w[2].Value[c] };
        const double d[3] = { w[0].First[a], w[1].First[b], w[2].First[c] };
        const double s[3] = { w[0].Second[a], w[1].Second[b], w[2].Second[c] };
        const double weight = v[0] * v[1] * v[2];
        double firstWeight[3] = { d[0] * v[1] * v[2], v[0] * d[1] * v[2], v[0] * v[1] * d[2] };
        double secondWeight[3][3] = {};
        if (order >= 2)
        {
          secondWeight[0][0] = s[0] * v[1] * v[2];
          secondWeight[1][1] = v[0] * s[1] * v[2];
          secondWeight[2][2] = v[0] * v[1] * s[2];
          secondWeight[0][1] = secondWeight[1][0] = d[0] * d[1] * v[2];
          secondWeight[1][2] = secondWeight[2][1] = v[0] * d[1] * d[2];
          secondWeight[0][2] = secondWeight[2][0] = d[0] * v[1] * d[2];
        }
        for (int m = 0; m < 6; ++m)
        {
          value[m] += weight * sample[m];
          if (order >= 1)
          {
            for (int x = 0; x < 3; ++x)
            {
              first[x][m] += firstWeight[x] * sample[m];
            }
          }
          if (order >= 2)
          {
            for (int x = 0; x < 3; ++x)
            {
              for (int y = x; y < 3; ++y)
              {
                second[x][y][m] += secondWeight[x][y] * sample[m];
              }
            }
          }
        }
      }
    }
  }
  g = FromComponents(value);
  for (int x = 0; x < 3 && order >= 1; ++x)
  {
    dg[x] = FromComponents(first[x]);
  }
  for (int x = 0; x < 3 && order >= 2; ++x)
  {
    for (int y = x; y < 3; ++y)
    {
      d2g[x][y] = FromComponents(second[x][y]);
      d2g[y][x] = d2g[x][y];
    }
  }
  return true;
}

void SampledTensorField::Evaluate(const Vec3& p, bool withDerivatives, Mat3& g, Mat3Stack& dg) const
{
  std::array<Mat3Stack, 3> unused;
  Mat3Stack gridFirst;
  if (!this->EvaluateInGrid(
        this->GridCoordinates(p), withDerivatives ? 1 : 0, g, gridFirst, unused))
  {
    SetIdentity(g, dg, nullptr);
    return;
  }
  if (!withDerivatives)
  {
    return;
  }
  // Chain rule: d/dx_k = sum_a (d u_a / d x_k) d/du_a.
  for (int k = 0; k < 3; ++k)
  {
    dg[k].setZero();
    for (int a = 0; a < 3; ++a)
    {
      dg[k] += this->WorldToGrid(a, k) * gridFirst[a];
    }
  }
}

bool SampledTensorField::EvaluateSecond(
  const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const
{
  Mat3Stack gridFirst;
  std::array<Mat3Stack, 3> gridSecond;
  if (!this->EvaluateInGrid(this->GridCoordinates(p), 2, g, gridFirst, gridSecond))
  {
    SetIdentity(g, dg, &d2g);
    return true;
  }
  const Mat3& J = this->WorldToGrid;
  for (int k = 0; k < 3; ++k)
  {
    dg[k].setZero();
    for (int a = 0; a < 3; ++a)
    {
      dg[k] += J(a, k) * gridFirst[a];
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    for (int l = k; l < 3; ++l)
    {
      Mat3 sum = Mat3::Zero();
      for (int a = 0; a < 3; ++a)
      {
        for (int b = 0; b < 3; ++b)
        {
          sum += J(a, k) * J(b, l) * gridSecond[a][b];
        }
      }
      d2g[k][l] = sum;
      d2g[l][k] = sum;
    }
  }
  return true;
}

std::string SampledTensorField::Describe() const
{
  std::ostringstream text;
  text << "samples on a " << this->Grid.Dimensions[0] << "x" << this->Grid.Dimensions[1] << "x"
       << this->Grid.Dimensions[2] << " grid (cubic B-spline"
       << (this->StopOutside ? ", rays stop outside)" : ", Euclidean outside)");
  return text.str();
}

void SampledTensorField::AppendSamplePoints(std::vector<Vec3>& points) const
{
  // Validate() checks g there: every grid point's cell centre, at most about
  // 20^3 of them (g at a cell is a convex combination of samples, so a
  // sample that is not positive definite shows at its neighbours' centres).
  const std::array<int, 3>& n = this->Grid.Dimensions;
  int stride[3];
  for (int a = 0; a < 3; ++a)
  {
    stride[a] = std::max(1, (n[a] - 1) / 20);
  }
  for (int k = 0; k + 1 < n[2]; k += stride[2])
  {
    for (int j = 0; j + 1 < n[1]; j += stride[1])
    {
      for (int i = 0; i + 1 < n[0]; i += stride[0])
      {
        const Vec3 index((i + 0.5) * this->Grid.Spacing[0], (j + 0.5) * this->Grid.Spacing[1],
          (k + 0.5) * this->Grid.Spacing[2]);
        points.push_back(this->Grid.Origin + this->Grid.Direction * index);
      }
    }
  }
}
} // namespace riemann
