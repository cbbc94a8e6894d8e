/**
 * @class   vtkRiemannFieldAlgorithm
 * @brief   Base of the filters that sample a field of a metric at points.
 *
 * The grid's settings are declared in vtkRiemannFieldAlgorithm.settings.json
 * (Documentation/Settings.md), which the subclasses' declarations take.
 * The points are either a regular grid, produced as vtkImageData over Bounds
 * (x0,x1,y0,y1,z0,z1; default [-2,2]^3) with Dimensions (nx,ny,nz; default
 * 33^3) points — the corners of the box are grid points — or, when an input
 * dataset is connected to port 0, the points of that input: the output is
 * then a shallow copy of the input with the arrays added. An axis with one
 * point puts it at the middle of the bounds (and min may equal max there).
 *
 * Subclasses implement ComputeFields(); this class checks the metric, builds
 * the output and offers ForEachPointInBatches(), which runs a functor over
 * the points in parallel (vtkSMPTools) in batches, reporting progress and
 * honouring AbortExecute between batches on the calling thread.
 *
 * Without a valid metric, or with invalid Bounds/Dimensions, the filter
 * reports an error (vtkErrorMacro) and produces an empty output.
 *
 * Pieces: the grid honours VTK's piece requests (UPDATE_PIECE_NUMBER,
 * UPDATE_NUMBER_OF_PIECES, ghost levels), as an MPI job or a streaming
 * pipeline makes them: it declares CAN_PRODUCE_SUB_EXTENT, computes only the
 * requested extent (vtkExtentTranslator's split of the whole grid), and
 * marks the ghost points it adds as duplicated (vtkGhostType). Each point's
 * values depend on its coordinates only, so the pieces are bitwise the whole
 * grid's. With an input dataset the input's pieces apply.
 */
#ifndef vtkRiemannFieldAlgorithm_h
#define vtkRiemannFieldAlgorithm_h

#include "RiemannFiltersFieldsModule.h" // For export macro
#include "vtkDataSetAlgorithm.h"
#include "vtkDoubleArray.h"   // For NewPointArray
#include "vtkRiemannMetricInput.h" // For the metric port
#include "vtkSmartPointer.h"  // For NewPointArray
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <functional> // For std::function
#include <string>     // For std::string

class vtkRiemannMetric;

namespace riemann
{
class Metric;
}

class RIEMANNFILTERSFIELDS_EXPORT vtkRiemannFieldAlgorithm : public vtkDataSetAlgorithm
{
public:
  vtkTypeMacro(vtkRiemannFieldAlgorithm, vtkDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The metric whose field is sampled (required).
  virtual void SetMetric(vtkRiemannMetric* metric);
  vtkGetObjectMacro(Metric, vtkRiemannMetric);
  ///@}

  ///@{
  /**
   * The metric from the pipeline: the output of a vtkRiemannMetricSource,
   * connected to port 1 (GetMetricPort(); port 0 is the optional dataset
   * whose points are sampled). When connected it is used instead of
   * SetMetric()'s, at the time the pipeline asks for.
   */
  void SetMetricConnection(vtkAlgorithmOutput* output);
  static int GetMetricPort() { return 1; }
  ///@}

  /// The executive's requests, with the metric input's time steps copied to the outputs.
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  ///@{
  /// The grid's box x0,x1,y0,y1,z0,z1 (used without an input). Default [-2,2]^3.
  vtkSetVector6Macro(Bounds, double);
  vtkGetVector6Macro(Bounds, double);
  ///@}

  ///@{
  /// The grid's number of points per axis (used without an input). Default 33^3.
  vtkSetVector3Macro(Dimensions, int);
  vtkGetVector3Macro(Dimensions, int);
  ///@}

  /// Include the metric's modification time.
  vtkMTimeType GetMTime() override;

  /**
   * The last error this filter reported (also raised through vtkErrorMacro),
   * or "" when its last update succeeded (ErrorConventions.md).
   */
  const char* GetLastError() const { return this->LastError.c_str(); }

protected:
  vtkRiemannFieldAlgorithm();
  ~vtkRiemannFieldAlgorithm() override;

  /// A named double array of `count` tuples of `components`, for a subclass's point data.
  static vtkSmartPointer<vtkDoubleArray> NewPointArray(
    const char* name, int components, vtkIdType count);

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /**
   * Add the subclass's arrays to `output` (the grid or the copy of the
   * input). Called with a valid metric; return false after vtkErrorMacro to
   * make the output empty.
   */
  VTK_WRAPEXCLUDE virtual bool ComputeFields(const riemann::Metric& metric, vtkDataSet* output) = 0;

  /**
   * Run `work(first, last)` over the point ids [0, count) in parallel, in
   * batches; progress and abort are handled between batches on this thread.
   * Returns false when aborted.
   */
  VTK_WRAPEXCLUDE bool ForEachPointInBatches(
    vtkIdType count, const std::function<void(vtkIdType, vtkIdType)>& work);

  /**
   * Whether port 0's dataset is the one whose points are sampled (the
   * default). A subclass that takes port 0 for something else (the distance
   * field's seeds) answers false: its output is then always the grid.
   */
  virtual bool SamplesInputPoints() const { return true; }

  /// The dataset whose points are sampled: port 0's, when connected and SamplesInputPoints().
  vtkDataSet* SampledInput(vtkInformationVector** inputVector);

  /// Empty string when Bounds and Dimensions make a valid grid, else why not.
  VTK_WRAPEXCLUDE std::string CheckGrid() const;

  vtkRiemannMetric* Metric = nullptr;
  vtkRiemannMetricInput MetricInput;
  // The declared defaults (vtkRiemannFieldAlgorithm.settings.json), set by the constructor.
  double Bounds[6];
  int Dimensions[3];

  /// GetLastError(): set by vtkRiemannReportErrorMacro, cleared where RequestData starts.
  std::string LastError;

private:
  vtkRiemannFieldAlgorithm(const vtkRiemannFieldAlgorithm&) = delete;
  void operator=(const vtkRiemannFieldAlgorithm&) = delete;
  void GridGeometry(double origin[3], double spacing[3]) const;
};

#endif
