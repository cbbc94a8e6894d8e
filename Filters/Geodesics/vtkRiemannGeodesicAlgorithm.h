/**
 * @class   vtkRiemannGeodesicAlgorithm
 * @brief   Base of the filters that integrate geodesics of a metric: the
 *          metric, the integration settings, and their checks, once.
 *
 * vtkRiemannGeodesicTracer, vtkRiemannExponentialMap, vtkRiemannConjugateLocus
 * and vtkRiemannRayBundle derive from it, as the field filters derive from
 * vtkRiemannFieldAlgorithm. It holds:
 *
 * - the metric: SetMetric(), or from the pipeline through the last input
 *   port (SetMetricConnection: a vtkRiemannMetricSource's output, with its
 *   parameters and time; ParaView's filters take theirs so);
 * - the integration settings (GetIntegrationSettings: integrator, steps,
 *   error, propagation and step limits in vtkStreamTracer's words; see
 *   vtkRiemannIntegrationSettings), which several filters and renderers may
 *   share (SetIntegrationSettings);
 * - GetMTime over both.
 *
 * A subclass's RequestData starts with CheckMetricAndSettings(): on a missing
 * metric or an unusable setting it reports one error through vtkErrorMacro
 * (also kept in GetLastError()) and the filter produces empty output. The
 * settings are checked only when the subclass uses them
 * (UsesIntegrationSettings(); vtkRiemannRayBundle takes the scene's unless
 * UseSceneSettings is off). Every later error that empties the output goes
 * through ReportError() too, so GetLastError() always says why.
 */
#ifndef vtkRiemannGeodesicAlgorithm_h
#define vtkRiemannGeodesicAlgorithm_h

#include "RiemannFiltersGeodesicsModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkRiemannMetricInput.h" // For the metric port
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <memory> // For std::shared_ptr
#include <string> // For std::string

class vtkRiemannIntegrationSettings;
class vtkRiemannMetric;
namespace riemann
{
class Metric;
struct GeodesicOptions;
}

class RIEMANNFILTERSGEODESICS_EXPORT vtkRiemannGeodesicAlgorithm : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkRiemannGeodesicAlgorithm, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The metric whose geodesics are integrated (required).
  virtual void SetMetric(vtkRiemannMetric* metric);
  vtkGetObjectMacro(Metric, vtkRiemannMetric);
  ///@}

  ///@{
  /**
   * The metric from the pipeline: the output of a vtkRiemannMetricSource,
   * connected to the metric port (the last input port, after the filter's
   * data inputs). When connected it is used instead of SetMetric()'s, at the
   * time the pipeline asks for (the outputs advertise the source's time
   * steps).
   */
  void SetMetricConnection(vtkAlgorithmOutput* output);
  int GetMetricPort() const { return this->MetricPort; }
  ///@}

  /// The executive's requests, with the metric input's time steps copied to the outputs.
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  ///@{
  /**
   * How geodesics are integrated. Each filter starts with its own settings
   * object (with the filter's defaults); setting another one shares it (null
   * is ignored).
   */
  virtual void SetIntegrationSettings(vtkRiemannIntegrationSettings* settings);
  vtkGetObjectMacro(IntegrationSettings, vtkRiemannIntegrationSettings);
  ///@}

  /// Why the last execution produced no output ("" after one that did).
  const char* GetLastError() const { return this->LastError.c_str(); }

  /// Include the metric's and the settings' modification times.
  vtkMTimeType GetMTime() override;

protected:
  vtkRiemannGeodesicAlgorithm();
  ~vtkRiemannGeodesicAlgorithm() override;

  /**
   * The filter's data inputs (1 here, a vtkPolyData; a subclass's
   * constructor says its own): the metric port comes after them.
   */
  void SetNumberOfDataPorts(int count);

  /// The data ports' requirements (FillInputPortInformation's, without the metric port).
  virtual int FillDataPortInformation(int port, vtkInformation* info);
  int FillInputPortInformation(int port, vtkInformation* info) final;

  /**
   * The core metric when there is one and every integration setting is
   * usable; otherwise null, after reporting the problem (ReportError).
   */
  VTK_WRAPEXCLUDE std::shared_ptr<const riemann::Metric> CheckMetricAndSettings();

  /**
   * Whether this execution integrates with GetIntegrationSettings(): true
   * here. A subclass that takes its integration from elsewhere at times
   * returns false then, and CheckMetricAndSettings() does not check settings
   * that it will not use.
   */
  virtual bool UsesIntegrationSettings() const { return true; }

  /// The core's geodesic options from the integration settings.
  VTK_WRAPEXCLUDE riemann::GeodesicOptions MakeGeodesicOptions() const;

  /// vtkErrorMacro with `message`, kept for GetLastError().
  void ReportError(const std::string& message);

  ///@{
  /**
   * The checks of the filters that shoot geodesics from an observer over a
   * cone of directions (vtkRiemannExponentialMap, vtkRiemannConjugateLocus):
   * false after ReportError ("Observer must be finite.", "ConeAxis: ...").
   */
  bool CheckObserver(const double observer[3]);
  bool BuildDirectionGrid(
    int numberOfDirections, const double coneAxis[3], double coneAngle, vtkPolyData* grid);
  ///@}

  /**
   * This execution's share of `count` items (seeds, directions, pixels) under
   * VTK's piece request (UPDATE_PIECE_NUMBER p of UPDATE_NUMBER_OF_PIECES N,
   * read from the output port the request came from; a filter's ports share
   * one piece): [count p / N, count (p + 1) / N), contiguous and in order, so
   * that the pieces appended in order are the one-piece output; [0, count)
   * without a request. Returns whether the share is a proper piece (N > 1).
   */
  static bool PieceShare(vtkInformation* request, vtkInformationVector* outputVector,
    vtkIdType count, vtkIdType& first, vtkIdType& last);

  vtkRiemannMetric* Metric = nullptr;
  vtkRiemannIntegrationSettings* IntegrationSettings = nullptr;
  std::string LastError;
  int MetricPort = 1;
  vtkRiemannMetricInput MetricInput;

private:
  vtkRiemannGeodesicAlgorithm(const vtkRiemannGeodesicAlgorithm&) = delete;
  void operator=(const vtkRiemannGeodesicAlgorithm&) = delete;
};

#endif
