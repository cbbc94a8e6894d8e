/**
 * @class riemann::SampledTensorField
 * @brief A metric tensor field given by samples on a regular grid (issue 17:
 * diffusion tensors, anisotropic media, another code's output), smooth
 * between them, with exact derivatives: the TensorField of TensorMetric for
 * data.
 *
 * Each of the six components of g is interpolated by the uniform cubic
 * B-spline of its samples, g(x) = sum_abc B(u - a) B(v - b) B(w - c) g_abc,
 * (u, v, w) the grid coordinates of x. Why this interpolant:
 * - the B-spline's weights are non-negative and sum to one, so g(x) is a
 *   convex combination of the 64 nearest samples: symmetric positive
 *   definite wherever they are, with its smallest eigenvalue at least
 *   theirs. Interpolating splines (the B-spline after a prefilter,
 *   Catmull-Rom) take negative weights and can leave the cone of metrics
 *   between positive samples; the log-Euclidean mean stays inside it too,
 *   but its derivatives need the Frechet derivatives of exp, three times
 *   the work of every Christoffel symbol;
 * - it is C2: g, its first and second derivatives are continuous, so the
 *   Christoffel symbols are C1 and the curvature continuous;
 * - its derivatives are those of the cubic pieces, exact.
 * The cost is that it approximates rather than interpolates: it reproduces
 * fields affine in x exactly, and smooth ones to O(h^2) (h the spacing), as
 * are their first and second derivatives. Samples beyond the grid's edge
 * repeat the edge's.
 *
 * The grid is VTK's image geometry: point (i, j, k) is at
 * Origin + Direction * (i Spacing_x, j Spacing_y, k Spacing_z). The samples
 * are g in world coordinates, six per point in VTK's order for symmetric
 * tensors (XX, YY, ZZ, XY, YZ, XZ), point index i + nx (j + ny k).
 *
 * The data reach the outer faces of the outer voxels, half a spacing beyond
 * the outer samples (grid coordinates [-1/2, n - 1/2] on an axis), as a
 * scan's voxels fill their boxes and as MRtrix and DIPY read them: there the
 * spline runs on with the edge samples repeated. Outside that box the field
 * is Euclidean (g = I): Inside() says where the data holds. With
 * `stopOutside` ("outside": "stop") the field is instead continued by its
 * value on the box's faces (constant along the outward axes), and
 * InsideData() is false there, so geodesics and rays stop at the first point
 * beyond the faces (OutOfData); the step that crosses a face sees no jump.
 */
#ifndef RiemannSampledTensorField_h
#define RiemannSampledTensorField_h

#include "TensorMetric.h"
#include "RiemannCommonMetricExport.h"

#include <array>
#include <memory>
#include <mutex>
#include <vector>

namespace riemann
{
/// A regular grid of symmetric tensors (see SampledTensorField).
struct RIEMANNCOMMONMETRIC_EXPORT SampledTensorGrid
{
  Vec3 Origin = Vec3::Zero();
  Vec3 Spacing = Vec3::Ones();
  /// Index to world axes (orthonormal; VTK's direction matrix, NIfTI's q-form rotation).
  Mat3 Direction = Mat3::Identity();
  std::array<int, 3> Dimensions = { 0, 0, 0 };
  /// Six per point: XX, YY, ZZ, XY, YZ, XZ.
  std::vector<double> Components;

  /// Number of grid points.
  long long NumberOfPoints() const
  {
    return static_cast<long long>(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2];
  }
  /**
   * What is wrong with the grid, or "": dimensions below 2 on an axis,
   * spacings not finite and positive, a direction that is not a rotation or
   * reflection, a component count that is not six per point.
   */
  std::string Check() const;
};

class RIEMANNCOMMONMETRIC_EXPORT SampledTensorField : public TensorField
{
public:
  /// Throws std::invalid_argument with SampledTensorGrid::Check()'s message.
  explicit SampledTensorField(SampledTensorGrid grid, bool stopOutside = false);

  void Evaluate(const Vec3& p, bool withDerivatives, Mat3& g, Mat3Stack& dg) const override;
  bool EvaluateSecond(
    const Vec3& p, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const override;
  std::string Describe() const override;
  /**
   * The same spline in GLSL (SampledTensorFieldGlsl.cxx): the samples as two
   * RGB float 3D textures (XX, YY, ZZ and XY, YZ, XZ). By default the 64
   * texels around the cell are read with texelFetch and weighted in the
   * shader, so the GPU's g is the CPU's up to float rounding; with the
   * builder's FilteredTextureReads, the same sums come from 8 trilinear reads
   * each (the texture unit's weights). With StopOutside, also the InsideData
   * test.
   */
  std::string EmitGlsl(GlslBuilder& builder) const override;

  /// Whether p is in the grid's box (to the outer voxels' faces), where the samples define g.
  bool Inside(const Vec3& p) const;
  /// How far beyond the outer samples the box reaches, in voxels: their faces.
  static constexpr double FaceMargin = 0.5;
  /**
   * The box's extent, faces included: a face maps to grid coordinate -1/2
   * or n - 1/2 only up to the rounding of the affine maps (a mask's placement
   * and the tensors' are each read from float32 numbers), so this much (in
   * voxels) beyond a face is on it.
   */
  static constexpr double FaceTolerance = 1e-6;

  /// Whether grid coordinate u is in the box on an axis of n samples, its
  /// faces included (to FaceTolerance): the one test of the box, which
  /// Inside(), the voxels' symbols and tractography's masks share.
  static bool WithinFaces(double u, int n)
  {
    return u >= -FaceMargin - FaceTolerance && u <= n - 1 + FaceMargin + FaceTolerance;
  }

  /// Inside() when rays stop outside the box, else true (g = I is data too).
  bool InsideData(const Vec3& p) const override { return !this->StopOutside || this->Inside(p); }
  bool GetStopOutside() const { return this->StopOutside; }
  /// The grid coordinates (i, j, k as reals) of world point p.
  Vec3 GridCoordinates(const Vec3& p) const;
  const SampledTensorGrid& GetGrid() const { return this->Grid; }
  /**
   * The diffusion tensor these metric samples stand for is g^q up to a scale
   * (q = DiffusionExponent() of the "tensor_metric" that made them: -1 for
   * D^-1). Tractography's anisotropy (FractionalAnisotropyOfMetric) reads it.
   */
  void SetDiffusionExponent(double q) { this->DiffusionExponent = q; }
  double GetDiffusionExponent() const { return this->DiffusionExponent; }

protected:
  void AppendSamplePoints(std::vector<Vec3>& points) const override;

private:
  /// g and its derivatives in grid coordinates up to `order` (0, 1 or 2) at
  /// grid point u; false outside the box, unless StopOutside continues it.
  bool EvaluateInGrid(
    const Vec3& u, int order, Mat3& g, Mat3Stack& dg, std::array<Mat3Stack, 3>& d2g) const;

  SampledTensorGrid Grid;
  bool StopOutside = false;
  double DiffusionExponent = -1.0;
  /// The samples in float for the GPU, made on the first EmitGlsl().
  mutable std::once_flag TexelsMade;
  mutable std::shared_ptr<const std::vector<float>> DiagonalTexels;
  mutable std::shared_ptr<const std::vector<float>> OffDiagonalTexels;
  /// d(grid coordinate a)/d(world k) = Direction(k, a) / Spacing(a): row a.
  Mat3 WorldToGrid;
};
} // namespace riemann

#endif
