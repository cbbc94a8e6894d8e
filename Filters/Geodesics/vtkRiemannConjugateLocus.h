/**
 * @class   vtkRiemannConjugateLocus
 * @brief   Conjugate points of an observer along a fan of geodesics.
 *
 * vtkRiemannConjugateLocus (a source: no input) shoots geodesics of a
 * vtkRiemannMetric from the Observer in NumberOfDirections directions and
 * finds, along each, the first MaximumNumberOfConjugatePoints conjugate points
 * up to the settings' MaximumPropagation (arc length) with
 * riemann::FindConjugatePoints (JacobiField.h: the Jacobi fields integrated as
 * GetIntegrationSettings() says, roots refined to Tolerance). This filter's
 * default settings: DORMAND_PRINCE45 with MaximumError 1e-9, steps of at most
 * 0.1 (no step jumps over two conjugate points), MaximumPropagation 10.
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
 * Without a valid metric, or with an unusable setting, the filter reports an
 * error (GetLastError) and produces empty output.
 */
#ifndef vtkRiemannConjugateLocus_h
#define vtkRiemannConjugateLocus_h

#include "RiemannFiltersGeodesicsModule.h" // For export macro
#include "vtkRiemannGeodesicAlgorithm.h"

#include <vector> // For BuildLocusSurfaces

namespace riemann
{
struct ConjugatePoint;
}

class RIEMANNFILTERSGEODESICS_EXPORT vtkRiemannConjugateLocus : public vtkRiemannGeodesicAlgorithm
{
public:
  static vtkRiemannConjugateLocus* New();
  vtkTypeMacro(vtkRiemannConjugateLocus, vtkRiemannGeodesicAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

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
  /// Arc-length tolerance of the root finding. Default 1e-8.
  vtkSetClampMacro(Tolerance, double, 1e-15, 1.0);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// Conjugate points kept per geodesic (<= 0: all). Default 1.
  vtkSetMacro(MaximumNumberOfConjugatePoints, int);
  vtkGetMacro(MaximumNumberOfConjugatePoints, int);
  ///@}

protected:
  vtkRiemannConjugateLocus();
  ~vtkRiemannConjugateLocus() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /// Port 1: the k-th conjugate points as surfaces over the grid's triangles.
  void BuildLocusSurfaces(vtkPolyData* grid,
    const std::vector<std::vector<riemann::ConjugatePoint>>& found, vtkPolyData* locus);

  double Observer[3] = { 0.0, 0.0, 0.0 };
  int NumberOfDirections = 100;
  double ConeAxis[3] = { 0.0, 0.0, 1.0 };
  double ConeAngle = 180.0;
  double Tolerance = 1e-8;
  int MaximumNumberOfConjugatePoints = 1;

private:
  vtkRiemannConjugateLocus(const vtkRiemannConjugateLocus&) = delete;
  void operator=(const vtkRiemannConjugateLocus&) = delete;
};

#endif
