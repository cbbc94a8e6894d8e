/**
 * @class   vtkRiemannCurvatureField
 * @brief   Curvature of a metric sampled on a grid or on an input's points.
 *
 * Point data (see Common/Metric/Curvature.h for the conventions; the round
 * unit 3-sphere has K = +1, Ric = 2 g, S = 6):
 * - `ScalarCurvature` S = g^ik Ric_ik
 * - `Ricci` Ric_ik as a 6-component symmetric tensor in VTK's order
 *   XX, YY, ZZ, XY, YZ, XZ (vtkMath::TensorFromSymmetricTensor)
 * - `SectionalXY`, `SectionalXZ`, `SectionalYZ`: sectional curvature of the
 *   coordinate planes
 * - `SectionalMin`, `SectionalMax`: extremes over all planes at the point
 * - `RiemannNorm` sqrt(R_abcd R^abcd)
 *
 * Points where the metric is degenerate or has no second derivatives get NaN
 * in every array, with one warning giving their count. Geometry, metric,
 * parallelism, progress and abort: see vtkRiemannFieldAlgorithm.
 */
#ifndef vtkRiemannCurvatureField_h
#define vtkRiemannCurvatureField_h

#include "RiemannFiltersFieldsModule.h" // For export macro
#include "vtkRiemannFieldAlgorithm.h"

class RIEMANNFILTERSFIELDS_EXPORT vtkRiemannCurvatureField : public vtkRiemannFieldAlgorithm
{
public:
  static vtkRiemannCurvatureField* New();
  vtkTypeMacro(vtkRiemannCurvatureField, vtkRiemannFieldAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkRiemannCurvatureField() = default;
  ~vtkRiemannCurvatureField() override = default;

  bool ComputeFields(const riemann::Metric& metric, vtkDataSet* output) override;

private:
  vtkRiemannCurvatureField(const vtkRiemannCurvatureField&) = delete;
  void operator=(const vtkRiemannCurvatureField&) = delete;
};

#endif
