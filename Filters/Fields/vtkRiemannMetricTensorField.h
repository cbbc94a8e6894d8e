/**
 * @class   vtkRiemannMetricTensorField
 * @brief   The metric tensor, its inverse and its eigenvalues at points.
 *
 * Point data:
 * - `MetricTensor` g_ij and `InverseMetricTensor` g^ij, each a 6-component
 *   symmetric tensor in VTK's order XX, YY, ZZ, XY, YZ, XZ
 *   (vtkMath::TensorFromSymmetricTensor). MetricTensor is the active tensor
 *   array, ready for vtkTensorGlyph: VTK 9.1's vtkTensorGlyph takes 9- or
 *   6-component tensors and expands the 6-component ones with
 *   vtkMath::TensorFromSymmetricTensor (checked in
 *   Testing/Python/TestFieldFilters.py: a 6-component tensor and its
 *   9-component expansion give the same glyphs). Note that vtkTensorGlyph
 *   scales a glyph by the eigenvalues of g, i.e. by squared lengths; glyph
 *   InverseMetricTensor to see the unit ball of g^-1 axes, or take square
 *   roots yourself for the unit ball of g.
 * - `MetricEigenvalues`: the eigenvalues of g, ascending (3 components).
 *
 * Where g is not defined every array is NaN; where g is defined but not
 * positive definite InverseMetricTensor is NaN. One warning gives the count
 * of points with any NaN. Geometry, metric, parallelism, progress and abort:
 * see vtkRiemannFieldAlgorithm.
 */
#ifndef vtkRiemannMetricTensorField_h
#define vtkRiemannMetricTensorField_h

#include "RiemannFiltersFieldsModule.h" // For export macro
#include "vtkRiemannFieldAlgorithm.h"

class RIEMANNFILTERSFIELDS_EXPORT vtkRiemannMetricTensorField : public vtkRiemannFieldAlgorithm
{
public:
  static vtkRiemannMetricTensorField* New();
  vtkTypeMacro(vtkRiemannMetricTensorField, vtkRiemannFieldAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkRiemannMetricTensorField() = default;
  ~vtkRiemannMetricTensorField() override = default;

  bool ComputeFields(const riemann::Metric& metric, vtkDataSet* output) override;

private:
  vtkRiemannMetricTensorField(const vtkRiemannMetricTensorField&) = delete;
  void operator=(const vtkRiemannMetricTensorField&) = delete;
};

#endif
