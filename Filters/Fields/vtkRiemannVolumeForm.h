/**
 * @class   vtkRiemannVolumeForm
 * @brief   The Riemannian volume form sqrt(det g) and its integral.
 *
 * Point data `VolumeForm` = sqrt(det g) (NaN where g is degenerate or not
 * defined). When the output is vtkImageData (the grid over Bounds, or an
 * image input) field data `VolumeIntegral` (one value) holds the integral of
 * the volume form over the image's box by the composite trapezoid rule: the
 * tensor product of per-axis weights h/2, h, ..., h, h/2 (h the spacing; an
 * axis with one point has weight max - min of Bounds for the generated grid,
 * 0 for an input image, which then spans no volume). Its error for a smooth
 * integrand is O(h^2): -(1/12) sum_a h_a^2 int (d_a^2 f) over the box, up to
 * the boundary terms. Points with NaN are left out of the sum (their weight
 * is dropped) and one warning gives their count. Other inputs (point sets)
 * get no VolumeIntegral.
 *
 * Geometry, metric, parallelism, progress and abort: see
 * vtkRiemannFieldAlgorithm.
 */
#ifndef vtkRiemannVolumeForm_h
#define vtkRiemannVolumeForm_h

#include "RiemannFiltersFieldsModule.h" // For export macro
#include "vtkMath.h"                    // For vtkMath::Nan
#include "vtkRiemannFieldAlgorithm.h"

class RIEMANNFILTERSFIELDS_EXPORT vtkRiemannVolumeForm : public vtkRiemannFieldAlgorithm
{
public:
  static vtkRiemannVolumeForm* New();
  vtkTypeMacro(vtkRiemannVolumeForm, vtkRiemannFieldAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The last computed VolumeIntegral (NaN before, or without an image output).
  vtkGetMacro(VolumeIntegral, double);

  /// How many points were left out of the last VolumeIntegral (NaN volume form).
  vtkGetMacro(NumberOfExcludedPoints, vtkIdType);

protected:
  vtkRiemannVolumeForm() = default;
  ~vtkRiemannVolumeForm() override = default;

  bool ComputeFields(const riemann::Metric& metric, vtkDataSet* output) override;

  double VolumeIntegral = vtkMath::Nan();
  vtkIdType NumberOfExcludedPoints = 0;

private:
  vtkRiemannVolumeForm(const vtkRiemannVolumeForm&) = delete;
  void operator=(const vtkRiemannVolumeForm&) = delete;
};

#endif
