/**
 * @class   vtkRiemannConjugateLocus
 * @brief   Conjugate points of an observer along a fan of geodesics.
 *
 * vtkRiemannConjugateLocus (a source: no input) shoots geodesics of a
 * vtkRiemannMetric from the Observer in NumberOfDirections directions and
 * finds, along each, the first MaximumNumberOfConjugatePoints conjugate points
 * up to MaximumPropagation (arc length) with riemann::FindConjugatePoints
 * (JacobiField.h: RK4 with IntegrationStep, roots refined to Tolerance).
 *
 * Directions are spread evenly with a Fibonacci lattice over the unit sphere
 * or, when ConeAngle < 180 degrees, over the spherical cap of that half-angle
 * around ConeAxis. They are coordinate vectors; the core normalises each to
 * unit speed in g at the observer.
 *
 * Output: one vertex per conjugate point with point data `ArcLength`
 * (double), `Multiplicity` (int, 1 or 2), `ConjugateIndex` (int, 1 for the
 * first conjugate point along its geodesic) and `DirectionId` (int, the
 * lattice index of its direction), in order of direction then arc length.
 *
 * Directions are processed in parallel with vtkSMPTools, in batches so that
 * progress is reported and AbortExecute honoured on the calling thread.
 * Without a valid metric the filter reports an error and produces empty output.
 */
#ifndef vtkRiemannConjugateLocus_h
#define vtkRiemannConjugateLocus_h

#include "RiemannFiltersGeodesicsModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkRiemannMetric;

class RIEMANNFILTERSGEODESICS_EXPORT vtkRiemannConjugateLocus : public vtkPolyDataAlgorithm
{
public:
  static vtkRiemannConjugateLocus* New();
  vtkTypeMacro(vtkRiemannConjugateLocus, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The metric (required).
  virtual void SetMetric(vtkRiemannMetric* metric);
  vtkGetObjectMacro(Metric, vtkRiemannMetric);
  ///@}

  ///@{
  /// The point whose conjugate locus is sought. Default (0, 0, 0).
  vtkSetVector3Macro(Observer, double);
  vtkGetVector3Macro(Observer, double);
  ///@}

  ///@{
  /// Number of geodesics shot from the observer. Default 100.
  vtkSetClampMacro(NumberOfDirections, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfDirections, int);
  ///@}

  ///@{
  /// Restrict the directions to the cap of half-angle ConeAngle (degrees)
  /// around ConeAxis. Defaults (0, 0, 1) and 180 (the whole sphere).
  vtkSetVector3Macro(ConeAxis, double);
  vtkGetVector3Macro(ConeAxis, double);
  vtkSetClampMacro(ConeAngle, double, 0.0, 180.0);
  vtkGetMacro(ConeAngle, double);
  ///@}

  ///@{
  /// Arc length searched along each geodesic. Default 10.
  vtkSetClampMacro(MaximumPropagation, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumPropagation, double);
  ///@}

  ///@{
  /// Fixed RK4 step in arc length. Default 0.01.
  vtkSetClampMacro(IntegrationStep, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(IntegrationStep, double);
  ///@}

  ///@{
  /// Arc-length tolerance of the root finding. Default 1e-8.
  vtkSetClampMacro(Tolerance, double, 1e-15, 1.0);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// Conjugate points kept per geodesic (<= 0: all). Default 1.
  vtkSetMacro(MaximumNumberOfConjugatePoints, int);
  vtkGetMacro(MaximumNumberOfConjugatePoints, int);
  ///@}

  /// Include the metric's modification time.
  vtkMTimeType GetMTime() override;

protected:
  vtkRiemannConjugateLocus();
  ~vtkRiemannConjugateLocus() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  vtkRiemannMetric* Metric = nullptr;
  double Observer[3] = { 0.0, 0.0, 0.0 };
  int NumberOfDirections = 100;
  double ConeAxis[3] = { 0.0, 0.0, 1.0 };
  double ConeAngle = 180.0;
  double MaximumPropagation = 10.0;
  double IntegrationStep = 0.01;
  double Tolerance = 1e-8;
  int MaximumNumberOfConjugatePoints = 1;

private:
  vtkRiemannConjugateLocus(const vtkRiemannConjugateLocus&) = delete;
  void operator=(const vtkRiemannConjugateLocus&) = delete;
};

#endif
