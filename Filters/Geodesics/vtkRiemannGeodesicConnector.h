/**
 * @class   vtkRiemannGeodesicConnector
 * @brief   Every geodesic from one point to another, up to an arc length:
 *          the two-point problem of a metric.
 *
 * Given StartPosition p and EndPosition q, the filter finds the geodesics
 * from p that reach q within MaximumPropagation (the integration settings'
 * arc-length limit), each to |end - q| <= Tolerance: geodesics are shot from
 * a grid of NumberOfDirections directions at p, each close pass of q starts
 * Newton's method on the initial direction and the length, whose derivative
 * the Jacobi fields give exactly (riemann::ConnectPoints,
 * GeodesicConnector.h; Documentation/Mathematics.md, "Between two points").
 * Each geodesic comes with its length, its Morse index (the conjugate points
 * of p before q, counted with multiplicity as vtkRiemannConjugateLocus
 * counts them) and whether it is the shortest found. Where q is conjugate to
 * p along a geodesic, the Newton system is singular; the geodesic is still
 * found and says so (ConjugateMultiplicity), and a whole family of them (the
 * antipode of p on a round sphere) comes out as one geodesic per grid
 * direction.
 *
 * Output, as vtkRiemannGeodesicTracer's: one polyline per geodesic, sorted
 * by length, from p to q, with point data `ArcLength` and `Velocity`; cell
 * data `SeedIds` (0, 1, ...: the geodesic's number), `Length`, `MorseIndex`,
 * `ConjugateMultiplicity` (0, or 1 or 2 where q is conjugate to p),
 * `Shortest` (1 for the shortest), `Miss` (|end - q| reached), `Iterations`
 * (Newton's) and `InitialDirection` (the g-unit velocity at p).
 *
 * The integration defaults are the adaptive integrator with steps of at most
 * 0.1 (Newton then integrates at a per-step tolerance of Tolerance / 1000,
 * so that the integration error stays well under the connection's
 * tolerance). The shooting and the refinements run on all cores, with
 * progress (shooting 0-60%, Newton 60-90%, Morse indices 90-100%) and
 * AbortExecute honoured between batches. Without a metric, with a setting
 * out of range, p = q, or g not positive definite at p, the filter reports
 * an error (GetLastError) and produces empty output.
 */
#ifndef vtkRiemannGeodesicConnector_h
#define vtkRiemannGeodesicConnector_h

#include "RiemannFiltersGeodesicsModule.h" // For export macro
#include "vtkRiemannGeodesicAlgorithm.h"

#include <string> // For CheckTolerance

class RIEMANNFILTERSGEODESICS_EXPORT vtkRiemannGeodesicConnector
  : public vtkRiemannGeodesicAlgorithm
{
public:
  static vtkRiemannGeodesicConnector* New();
  vtkTypeMacro(vtkRiemannGeodesicConnector, vtkRiemannGeodesicAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The points to join: the geodesics start at StartPosition and end at
  /// EndPosition. Defaults (0, 0, 0) and (1, 0, 0).
  vtkSetVector3Macro(StartPosition, double);
  vtkGetVector3Macro(StartPosition, double);
  vtkSetVector3Macro(EndPosition, double);
  vtkGetVector3Macro(EndPosition, double);
  ///@}

  ///@{
  /// |end - EndPosition| (coordinate distance) each geodesic reaches, in
  /// [MinimumTolerance, MaximumTolerance] (below 1e-13 the integration's own
  /// rounding would keep Newton from it). Defaults, ranges and help of this
  /// class's settings: vtkRiemannGeodesicConnector.settings.json.
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  static constexpr double MinimumTolerance = 1e-13;
  static constexpr double MaximumTolerance = 1e-2;
  /// "" when `tolerance` is in that range, else why not ("Tolerance is ...").
  static std::string CheckTolerance(double tolerance);
  ///@}

  /**
   * The integration defaults of a connection (dp45, steps of at most 0.1,
   * MaximumError 1e-8, 10^7 steps), which this filter starts with and
   * vtkRiemannMinimalGeodesics, whose Newton step is this one's, too.
   */
  static void ApplyConnectionDefaults(vtkRiemannIntegrationSettings* settings);

  ///@{
  /// Directions of the shooting grid, in [1, 1000000]. More finds geodesics
  /// that only a narrow pencil of directions sends past q.
  vtkSetMacro(NumberOfDirections, int);
  vtkGetMacro(NumberOfDirections, int);
  ///@}

  ///@{
  /// Newton iterations per candidate at most, in [1, 1000].
  vtkSetMacro(MaximumNumberOfIterations, int);
  vtkGetMacro(MaximumNumberOfIterations, int);
  ///@}

  /// How many geodesics the last execution found.
  vtkGetMacro(NumberOfGeodesics, int);

protected:
  vtkRiemannGeodesicConnector();
  ~vtkRiemannGeodesicConnector() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  // The declared defaults (vtkRiemannGeodesicConnector.settings.json), set in the constructor.
  double StartPosition[3];
  double EndPosition[3];
  double Tolerance;
  int NumberOfDirections;
  int MaximumNumberOfIterations;
  int NumberOfGeodesics = 0;

private:
  vtkRiemannGeodesicConnector(const vtkRiemannGeodesicConnector&) = delete;
  void operator=(const vtkRiemannGeodesicConnector&) = delete;
};

#endif
