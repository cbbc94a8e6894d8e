/**
 * @class   vtkRiemannConjugateLocus
 * @brief   Conjugate points of an observer along a fan of geodesics.
 *
 * vtkRiemannConjugateLocus (a source: no input) shoots geodesics of a
 * vtkRiemannMetric from the Observer in NumberOfDirections directions and
 * finds, along each, the first MaximumNumberOfConjugatePoints conjugate points
 * up to MaximumPropagation (arc length) with riemann::FindConjugatePoints
 * (JacobiField.h: the Jacobi fields integrated with IntegratorType and
 * IntegrationStep, roots refined to Tolerance).
 *
 * Directions are those of vtkRiemannDirectionGrid: a Fibonacci lattice over
 * the unit sphere or, when ConeAngle < 180 degrees, over the spherical cap of
 * that half-angle around ConeAxis, triangulated. They are coordinate vectors;
 * the core normalises each to unit speed in g at the observer.
 *
 * Output port 0: one vertex per conjugate point with point data `ArcLength`
 * (double), `Multiplicity` (int, 1 or 2), `ConjugateIndex` (int, 1 for the
 * first conjugate point along its geodesic) and `DirectionId` (int, the
 * lattice index of its direction), in order of direction then arc length.
 *
 * Output port 1: the conjugate locus (caustic) as surfaces over the direction
 * grid: for each index k, point i is the k-th conjugate point along direction
 * i, and a triangle of the grid is kept where its three directions all have a
 * k-th conjugate point. Same point data as port 0, and `ConjugateIndex` as
 * cell data too. Where the locus degenerates (a round sphere's conjugate
 * points all coincide at the antipode) the surface collapses accordingly.
 *
 * Directions are processed in parallel with vtkSMPTools, in batches so that
 * progress is reported and AbortExecute honoured on the calling thread.
 * Without a valid metric the filter reports an error and produces empty output.
 */
#ifndef vtkRiemannConjugateLocus_h
#define vtkRiemannConjugateLocus_h

#include "RiemannFiltersGeodesicsModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <vector> // For BuildLocusSurfaces

class vtkRiemannMetric;
namespace riemann
{
struct ConjugatePoint;
}

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

  /// Integrators (vtkRiemannGeodesicTracer's numbering).
  enum Integrators
  {
    EULER = 0,
    RUNGE_KUTTA4 = 1,
    DORMAND_PRINCE45 = 2
  };

  ///@{
  /// Integrator of the Jacobi fields. Default DORMAND_PRINCE45: on the round
  /// sphere it finds all of 10,000 double conjugate points to 1e-8 and is
  /// faster than RK4 at step 0.01, which gives up on 16 of them: they pass near
  /// the chart's point at infinity, where the fixed step drifts g(v, v) past
  /// the search's trust limit (Testing/Benchmarks/README.md).
  vtkSetClampMacro(IntegratorType, int, EULER, DORMAND_PRINCE45);
  vtkGetMacro(IntegratorType, int);
  void SetIntegratorTypeToEuler() { this->SetIntegratorType(EULER); }
  void SetIntegratorTypeToRungeKutta4() { this->SetIntegratorType(RUNGE_KUTTA4); }
  void SetIntegratorTypeToDormandPrince45() { this->SetIntegratorType(DORMAND_PRINCE45); }
  ///@}

  ///@{
  /// Step in arc length (fixed, or initial for DP45). Default 0.01.
  vtkSetClampMacro(IntegrationStep, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(IntegrationStep, double);
  ///@}

  ///@{
  /// Largest adaptive step (DP45): short enough that no step jumps over two
  /// conjugate points. Default 0.1.
  vtkSetClampMacro(MaximumIntegrationStep, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumIntegrationStep, double);
  ///@}

  ///@{
  /// Per-step error tolerance of DP45. Default 1e-9.
  vtkSetClampMacro(MaximumError, double, 1e-15, 1.0);
  vtkGetMacro(MaximumError, double);
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

  /// Port 1: the k-th conjugate points as surfaces over the grid's triangles.
  void BuildLocusSurfaces(vtkPolyData* grid,
    const std::vector<std::vector<riemann::ConjugatePoint>>& found, vtkPolyData* locus);

  vtkRiemannMetric* Metric = nullptr;
  double Observer[3] = { 0.0, 0.0, 0.0 };
  int NumberOfDirections = 100;
  double ConeAxis[3] = { 0.0, 0.0, 1.0 };
  double ConeAngle = 180.0;
  double MaximumPropagation = 10.0;
  int IntegratorType = DORMAND_PRINCE45;
  double IntegrationStep = 0.01;
  double MaximumIntegrationStep = 0.1;
  double MaximumError = 1e-9;
  double Tolerance = 1e-8;
  int MaximumNumberOfConjugatePoints = 1;

private:
  vtkRiemannConjugateLocus(const vtkRiemannConjugateLocus&) = delete;
  void operator=(const vtkRiemannConjugateLocus&) = delete;
};

#endif
