/**
 * @class   vtkRiemannCutLocus
 * @brief   The cut locus of a distance field: where minimal geodesics from
 *          the seeds stop being unique, as a surface.
 *
 * Input: the image vtkRiemannDistanceField produces (point data `Distance`,
 * `ArrivalDirection`, `SeedId`). Output: the squares of the dual grid that
 * the cut locus pierces (riemann::ExtractCutLocus, CutLocus.h): across each,
 * the arrival direction jumps (a turn above MinimumAngle degrees and above
 * SmoothFactor times what a smooth field turns over that step) or the
 * closest seed changes. Neighbouring squares share their corners, so the
 * output is one surface. Cell data: `Angle` (the turn, degrees), `Kind` (1:
 * the direction jumps, two minimal geodesics from one seed meet; 2: the
 * seed changes, the boundary of two Voronoi regions), `Distance` (the mean
 * of the pierced edge's ends) and `CutPoint` (where on that edge the two
 * fronts meet, each extrapolated along its arrival direction): from the
 * seed to a CutPoint, `riemann connect` finds two geodesics of equal length
 * within the field's accuracy.
 *
 * The metric (optional, SetMetric) measures each grid edge in g for the
 * smooth-turn test; without it the edge's Euclidean length is used. Without
 * the arrays it reports an error (GetLastError) and produces empty output.
 */
#ifndef vtkRiemannCutLocus_h
#define vtkRiemannCutLocus_h

#include "RiemannFiltersFieldsModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkRiemannMetricInput.h" // For the metric port

#include <string> // For LastError

class vtkRiemannMetric;

class RIEMANNFILTERSFIELDS_EXPORT vtkRiemannCutLocus : public vtkPolyDataAlgorithm
{
public:
  static vtkRiemannCutLocus* New();
  vtkTypeMacro(vtkRiemannCutLocus, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The metric the distance field was computed with (optional).
  virtual void SetMetric(vtkRiemannMetric* metric);
  vtkGetObjectMacro(Metric, vtkRiemannMetric);
  ///@}

  ///@{
  /**
   * The metric from the pipeline (optional): a vtkRiemannMetricSource's
   * output at port 1 (GetMetricPort(); port 0 is the distance field). When
   * connected it is used instead of SetMetric()'s.
   */
  void SetMetricConnection(vtkAlgorithmOutput* output);
  static int GetMetricPort() { return 1; }
  ///@}

  ///@{
  /// Turns of the arrival direction below this many degrees are never
  /// jumps, in (0, 180). Default 20. Range, default and help of both
  /// settings: vtkRiemannCutLocus.settings.json.
  vtkSetMacro(MinimumAngle, double);
  vtkGetMacro(MinimumAngle, double);
  ///@}

  ///@{
  /// A jump must also turn this many times more than a smooth field would
  /// over the step, at least 1. Default 3.
  vtkSetMacro(SmoothFactor, double);
  vtkGetMacro(SmoothFactor, double);
  ///@}

  /// Why the last execution produced no output ("" after one that did).
  const char* GetLastError() const { return this->LastError.c_str(); }

  vtkMTimeType GetMTime() override;

protected:
  vtkRiemannCutLocus();
  ~vtkRiemannCutLocus() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  vtkRiemannMetric* Metric = nullptr;
  vtkRiemannMetricInput MetricInput;
  double MinimumAngle; // declared (vtkRiemannCutLocus.settings.json)
  double SmoothFactor;
  std::string LastError;

private:
  vtkRiemannCutLocus(const vtkRiemannCutLocus&) = delete;
  void operator=(const vtkRiemannCutLocus&) = delete;
};

#endif
