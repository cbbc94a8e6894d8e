/**
 * @class   vtkRiemannConjugateLocus
 * @brief   Conjugate points of an observer along a fan of geodesics, and the
 * caustic they form as sheets.
 *
 * vtkRiemannConjugateLocus (a source: no input) shoots geodesics of a
 * vtkRiemannMetric from the Observer in NumberOfDirections directions and
 * finds, along each, the first MaximumNumberOfConjugatePoints conjugate points
 * up to the settings' MaximumPropagation (arc length) with
 * riemann::FindConjugatePoints (ConjugatePoints.h). Conjugate points are
 * counted, not guessed: the Maslov phases of the Jacobi fields pass pi once
 * per conjugate point, so two simple points are never stepped over or merged
 * however close they are, as long as they are farther apart than Tolerance;
 * crossings closer than Tolerance are one point of multiplicity 2. Tolerance
 * bounds the arc-length error: the Jacobi fields are integrated (adaptive
 * integrator) to min(MaximumError, riemann::ConjugateIntegrationTolerance(
 * Tolerance)) = min(MaximumError, Tolerance / 100). This filter's default
 * settings: DORMAND_PRINCE45, MaximumError 1e-6 (a cap: Tolerance decides),
 * steps of at most 0.1 (SetMaximumIntegrationStep; the detection does not
 * depend on it), MaximumPropagation 10.
 *
 * Directions are those of vtkRiemannDirectionGrid: a Fibonacci lattice over
 * the unit sphere or, when ConeAngle < 180 degrees, over the spherical cap of
 * that half-angle around ConeAxis, triangulated. They are coordinate vectors;
 * the core normalises each to unit speed in g at the observer.
 *
 * Output port 0: one vertex per conjugate point with point data `ArcLength`
 * (double), `Multiplicity` (int, 1 or 2), `ConjugateIndex` (int, 1 for the
 * first conjugate point along its geodesic), `Sheet` (int, 1 + the number of
 * conjugate points before it counted with multiplicity: a point of
 * multiplicity 2 lies on sheets Sheet and Sheet + 1), `DirectionId` (int, the
 * lattice index of its direction) and `KernelDirection` (3 doubles: the
 * g-unit initial variation at the observer whose Jacobi field vanishes there,
 * up to sign; zero for multiplicity 2), in order of direction then arc length.
 *
 * Output port 1: the caustic as sheets (riemann::BuildCausticSheets,
 * CausticSheets.h). Sheet k holds, for each direction, its point on sheet k,
 * and the grid triangles whose three directions reach sheet k; each sheet
 * has its own points (a double point appears on two sheets). Point data as
 * port 0 (without KernelDirection) plus `KernelSlope` (|d ArcLength / d
 * angle| along the kernel direction: 0 on a cusp edge, where the sheet's
 * rank drops); cell data `Sheet` and `Singularity` (0 none, 1 a cusp edge
 * crosses the triangle, 2 a corner is a point where two sheets meet).
 * vtkThreshold on `Sheet` extracts one sheet.
 *
 * Directions are processed in parallel with vtkSMPTools, in batches so that
 * progress is reported and AbortExecute honoured on the calling thread.
 *
 * Pieces: asked for piece p of N (as an MPI job asks), the filter owns the
 * directions [n p / N, n (p + 1) / N) of the n of the grid: their conjugate
 * points on port 0, their sheet points on port 1, and the sheet triangles
 * over grid triangles whose smallest direction it owns (their other corners
 * are ghost points, vtkGhostType). It searches two rings of neighbouring
 * directions more, so that KernelSlope and the cusp edges are those of the
 * whole grid: the pieces together are the one-piece output, bitwise, with
 * the same DirectionIds.
 * Without a valid metric, or with an unusable setting, the filter reports an
 * error (GetLastError) and produces empty output.
 */
#ifndef vtkRiemannConjugateLocus_h
#define vtkRiemannConjugateLocus_h

#include "RiemannFiltersGeodesicsModule.h" // For export macro
#include "vtkRiemannGeodesicAlgorithm.h"

#include "Jets.h" // For riemann::Vec3, riemann::Mat3


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
  /// The point whose conjugate locus is sought. Defaults, ranges and help of
  /// this class's settings: vtkRiemannConjugateLocus.settings.json.
  vtkSetVector3Macro(Observer, double);
  vtkGetVector3Macro(Observer, double);
  ///@}

  ///@{
  /// Number of geodesics shot from the observer.
  vtkSetClampMacro(NumberOfDirections, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfDirections, int);
  ///@}

  ///@{
  /// Restrict the directions to the cap of half-angle ConeAngle (degrees)
  /// around ConeAxis (180: the whole sphere).
  vtkSetVector3Macro(ConeAxis, double);
  vtkGetVector3Macro(ConeAxis, double);
  vtkSetClampMacro(ConeAngle, double, 0.0, 180.0);
  vtkGetMacro(ConeAngle, double);
  ///@}

  ///@{
  /// The arc-length accuracy of the conjugate points, and the resolution:
  /// crossings closer than this are one point of multiplicity 2.
  vtkSetClampMacro(Tolerance, double, 1e-15, 1.0);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// Conjugate points kept per geodesic (<= 0: all).
  vtkSetMacro(MaximumNumberOfConjugatePoints, int);
  vtkGetMacro(MaximumNumberOfConjugatePoints, int);
  ///@}

protected:
  vtkRiemannConjugateLocus();
  ~vtkRiemannConjugateLocus() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  // The declared defaults (vtkRiemannConjugateLocus.settings.json), set in the constructor.
  double Observer[3];
  int NumberOfDirections;
  double ConeAxis[3];
  double ConeAngle;
  double Tolerance;
  int MaximumNumberOfConjugatePoints;

private:
  vtkRiemannConjugateLocus(const vtkRiemannConjugateLocus&) = delete;
  void operator=(const vtkRiemannConjugateLocus&) = delete;
};

#endif
