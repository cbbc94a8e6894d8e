/**
 * @class   vtkRiemannExponentialMap
 * @brief   The exponential map at an observer: a bundle of geodesics over a
 * grid of directions, and its geodesic spheres (wavefronts) as surfaces.
 *
 * vtkRiemannExponentialMap (a source: no input) shoots the geodesics of a
 * vtkRiemannMetric from Observer over the triangulated direction grid of
 * vtkRiemannDirectionGrid (NumberOfDirections over the unit sphere, or over
 * the cap of half-angle ConeAngle around ConeAxis), each integrated with its
 * two Jacobi fields (riemann::TraceJacobiFields) as GetIntegrationSettings()
 * says, up to its MaximumPropagation (this filter's defaults: RUNGE_KUTTA4,
 * step 0.01, adaptive steps of at most 0.1, MaximumPropagation 5).
 *
 * Output port 0, the ray bundle: one polyline per direction, with point data
 * `ArcLength`, `SpeedDrift`, `TransverseJacobian` (signed determinant of
 * the differential of exp transverse to the ray: zero at conjugate points,
 * negative past a simple one) and `TransverseJacobianSingularValues`, and cell
 * data `DirectionId` and `ReasonForTermination`.
 *
 * Output port 1, the wavefronts: for each radius r of the Radii list (up to
 * MaximumPropagation), the geodesic sphere exp(r S), S the direction grid, as a
 * triangulated surface: point i is where the geodesic of direction i is at arc
 * length r (the integration lands there exactly; no interpolation), the
 * triangles are the grid's, kept where all three geodesics got that far.
 * Point data `TransverseJacobian`, `TransverseJacobianSingularValues`,
 * `DirectionId`, and `Radius` (also as cell data, to threshold one sphere).
 * Past the first conjugate points a geodesic sphere folds over itself: the
 * sign of TransverseJacobian shows which sheet is which, and its zeros the
 * cusps and folds (the caustic, vtkRiemannConjugateLocus).
 *
 * Directions are traced in parallel with vtkSMPTools, in batches so that
 * progress is reported and AbortExecute honoured on the calling thread.
 *
 * Pieces: asked for piece p of N (as an MPI job asks), the filter owns the
 * directions [n p / N, n (p + 1) / N) of the n of the grid: their rays on
 * port 0, their wavefront points on port 1, and the grid's triangles whose
 * smallest direction it owns, for which it also traces their other corners
 * (marked as ghost points, vtkGhostType). The pieces together are the
 * one-piece output: the same rays, points and triangles, bitwise, with the
 * same DirectionIds.
 * Without a valid metric, or with a bad axis or observer, the filter reports
 * an error and produces empty outputs.
 */
#ifndef vtkRiemannExponentialMap_h
#define vtkRiemannExponentialMap_h

#include "RiemannFiltersGeodesicsModule.h" // For export macro
#include "vtkRiemannGeodesicAlgorithm.h"

#include <vector> // For Radii


class RIEMANNFILTERSGEODESICS_EXPORT vtkRiemannExponentialMap : public vtkRiemannGeodesicAlgorithm
{
public:
  static vtkRiemannExponentialMap* New();
  vtkTypeMacro(vtkRiemannExponentialMap, vtkRiemannGeodesicAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The point where the exponential map is taken. Defaults, ranges and help
  /// of this class's settings: vtkRiemannExponentialMap.settings.json.
  vtkSetVector3Macro(Observer, double);
  vtkGetVector3Macro(Observer, double);
  ///@}

  ///@{
  /// Number of directions of the grid (at most the direction grid's maximum).
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
  /// Radii (arc lengths) of the wavefronts on output port 1. None by default.
  void AddRadius(double radius);
  void RemoveAllRadii();
  int GetNumberOfRadii() const { return static_cast<int>(this->Radii.size()); }
  double GetRadius(int i) const;
  ///@}

  /// Largest NumberOfDirections x MaximumPropagation / InitialIntegrationStep
  /// accepted (each sample holds the Jacobi fields, about 280 bytes with its
  /// output: 3e7 samples are about 8 GiB); beyond, an error.
  static constexpr double MaximumNumberOfSamples = 3e7;

protected:
  vtkRiemannExponentialMap();
  ~vtkRiemannExponentialMap() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  // The declared defaults (vtkRiemannExponentialMap.settings.json), set in the constructor.
  double Observer[3];
  int NumberOfDirections;
  double ConeAxis[3];
  double ConeAngle;
  std::vector<double> Radii;

private:
  /// Step 1 of RequestData: Observer, Radii and the sample budget, each
  /// refused by name (ReportError); the other steps are in the .cxx.
  bool CheckRequest();

  vtkRiemannExponentialMap(const vtkRiemannExponentialMap&) = delete;
  void operator=(const vtkRiemannExponentialMap&) = delete;
};

#endif
