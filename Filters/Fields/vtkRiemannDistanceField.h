/**
 * @class   vtkRiemannDistanceField
 * @brief   The geodesic distance from one or several seeds on a grid, with
 *          the direction each point is reached from and its closest seed.
 *
 * The distance u solves the eikonal equation |grad u|_{g^-1} = 1 with u = 0
 * at the seeds (riemann::ComputeDistanceField, DistanceField.h: a
 * semi-Lagrangian scheme on the 26-point stencil, iterated to its fixed
 * point over blocks of the grid in parallel; first order up to the
 * logarithm of a point source; Documentation/Mathematics.md, "Between two
 * points"). The grid is the field filters' (Bounds, Dimensions); every seed
 * must lie inside Bounds. Point data:
 * - `Distance`: u, the length of the shortest geodesic to the closest seed
 *   (NaN where the metric fails, so no geodesic gets there);
 * - `ArrivalDirection`: the g-unit velocity at the point of that geodesic
 *   (pointing away from the seed): the direction the wavefront moves;
 * - `SeedId`: which seed is closest (0, 1, ... in AddSeed's order, then
 *   the seeds input's points in theirs; -1 where unreached): the seeds'
 *   Voronoi regions in g.
 * Field data `Seeds` holds the seeds (3 components, in SeedId's order). Its
 * level sets are the true wavefronts of the metric; vtkRiemannCutLocus
 * extracts where ArrivalDirection jumps (the cut locus of the seeds), and
 * vtkRiemannMinimalGeodesics walks back from any point to its seed.
 *
 * Seeds: AddSeed's, then the points of the dataset at port 0 (optional; any
 * dataset: ParaView's Input, a Point Source, a probe). Unlike the other
 * field filters, port 0 is not sampled, and the field is computed on the
 * whole grid at once (a point's distance depends on the whole grid between
 * it and its seed): it does not split into pieces (every piece request gets
 * the whole grid, from all of the seeds input), and `riemann distance`
 * refuses to run under mpirun. Progress is reported between rounds of the
 * solver (a rough fraction of the grid settled) and AbortExecute honoured.
 * Without a metric, without seeds, with a seed outside Bounds or a bad grid,
 * it reports an error (GetLastError) and produces an empty output.
 */
#ifndef vtkRiemannDistanceField_h
#define vtkRiemannDistanceField_h

#include "RiemannFiltersFieldsModule.h" // For export macro
#include "vtkRiemannFieldAlgorithm.h"

#include <vector> // For the seeds

class RIEMANNFILTERSFIELDS_EXPORT vtkRiemannDistanceField : public vtkRiemannFieldAlgorithm
{
public:
  static vtkRiemannDistanceField* New();
  vtkTypeMacro(vtkRiemannDistanceField, vtkRiemannFieldAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The points the distance is measured from (SeedId numbers them).
  void AddSeed(double x, double y, double z);
  void AddSeed(const double point[3]) { this->AddSeed(point[0], point[1], point[2]); }
  void RemoveAllSeeds();
  int GetNumberOfSeeds() const { return static_cast<int>(this->Seeds.size() / 3); }
  void GetSeed(int index, double point[3]) const;
  ///@}

  ///@{
  /// Points within this many grid spacings of a seed take the local
  /// distance (|x - p| in g at their midpoint), in [1, 20]. Default 2.5.
  vtkSetMacro(SeedRadius, double);
  vtkGetMacro(SeedRadius, double);
  ///@}

  /// The solver's point updates and rounds in the last execution.
  vtkGetMacro(NumberOfUpdates, vtkIdType);
  vtkGetMacro(NumberOfRounds, int);

protected:
  vtkRiemannDistanceField();
  ~vtkRiemannDistanceField() override;

  /// Port 0 holds seeds, not points to sample.
  bool SamplesInputPoints() const override { return false; }
  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  /// All of the seeds input, whatever piece is asked for.
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  VTK_WRAPEXCLUDE bool ComputeFields(const riemann::Metric& metric, vtkDataSet* output) override;

  std::vector<double> Seeds;
  /// The seeds input's points of the execution under way (RequestData to ComputeFields).
  vtkDataSet* SeedsInput = nullptr;
  double SeedRadius; // declared (vtkRiemannDistanceField.settings.json)
  vtkIdType NumberOfUpdates = 0;
  int NumberOfRounds = 0;

private:
  vtkRiemannDistanceField(const vtkRiemannDistanceField&) = delete;
  void operator=(const vtkRiemannDistanceField&) = delete;
};

#endif
