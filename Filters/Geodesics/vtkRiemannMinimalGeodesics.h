/**
 * @class   vtkRiemannMinimalGeodesics
 * @brief   The minimal geodesic from each target point back to its closest
 *          seed, from a distance field.
 *
 * Inputs: port 0, the image of vtkRiemannDistanceField (point data
 * Distance, ArrivalDirection, SeedId; field data Seeds); port 1 (optional),
 * a dataset whose points are targets too; the metric at GetMetricPort() (2)
 * or SetMetric(). For each target (AddTarget's, then port 1's points)
 * the filter walks back along the arrival directions to the target's
 * closest seed (riemann::DescendToSeed, DistanceDescent.h: the steepest
 * descent of the distance, within the field's first-order error), then
 * refines that path into a geodesic by Newton's method on its initial
 * direction and length at the seed (riemann::RefineConnection,
 * GeodesicConnector.h: the Jacobi fields give the exact derivative), to
 * |end - target| <= Tolerance.
 *
 * Output: one polyline per target reached, from its seed to the target,
 * with point data `ArcLength` and `Velocity` (as vtkRiemannGeodesicTracer's)
 * and cell data `TargetIds` (AddTarget's order, then port 1's), `SeedId` (its closest seed,
 * as the field's array), `Length` (the geodesic's arc length, or the field's
 * distance where no geodesic was found), `Distance` (the field's value at
 * the target: Length - Distance is the field's error there) and `Refined`
 * (1: Newton from the descent, to the tolerance; 2: found by shooting; 0:
 * no geodesic, the line is the descent path). When Newton's geodesic is
 * longer than the field's distance by more than half a grid spacing, or
 * Newton fails, the target is also joined by shooting (riemann::ConnectPoints,
 * as vtkRiemannGeodesicConnector) and the shortest geodesic kept: from a
 * point on the cut locus the descent can run along it, between the minimal
 * ways, to a longer geodesic (over a bump's top). The integration settings
 * are the connector's (adaptive, steps of at most 0.1). Targets outside the
 * grid or unreached give no line. Without a metric or a distance field it
 * reports an error (GetLastError) and produces empty output; progress and
 * AbortExecute are honoured between batches of targets.
 */
#ifndef vtkRiemannMinimalGeodesics_h
#define vtkRiemannMinimalGeodesics_h

#include "RiemannFiltersGeodesicsModule.h" // For export macro
#include "vtkRiemannGeodesicAlgorithm.h"


#include <vector> // For the targets

class RIEMANNFILTERSGEODESICS_EXPORT vtkRiemannMinimalGeodesics : public vtkRiemannGeodesicAlgorithm
{
public:
  static vtkRiemannMinimalGeodesics* New();
  vtkTypeMacro(vtkRiemannMinimalGeodesics, vtkRiemannGeodesicAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The points whose minimal geodesics are wanted (TargetIds numbers them).
  void AddTarget(double x, double y, double z);
  void AddTarget(const double point[3]) { this->AddTarget(point[0], point[1], point[2]); }
  void RemoveAllTargets();
  int GetNumberOfTargets() const { return static_cast<int>(this->Targets.size() / 3); }
  ///@}

  ///@{
  /// |end - target| each refined geodesic reaches, in [1e-13, 1e-2]. Default 1e-9
  /// (declared: vtkRiemannMinimalGeodesics.settings.json).
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  ///@}

  /// Targets whose descent Newton could not refine, in the last execution.
  vtkGetMacro(NumberOfUnrefined, int);

protected:
  vtkRiemannMinimalGeodesics();
  ~vtkRiemannMinimalGeodesics() override;

  int FillDataPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  std::vector<double> Targets;
  double Tolerance;
  int NumberOfUnrefined = 0;

private:
  vtkRiemannMinimalGeodesics(const vtkRiemannMinimalGeodesics&) = delete;
  void operator=(const vtkRiemannMinimalGeodesics&) = delete;
};

#endif
