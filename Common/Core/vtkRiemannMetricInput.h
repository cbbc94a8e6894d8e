/**
 * @class   vtkRiemannMetricInput
 * @brief   The metric input port of the toolkit's filters: the metric read
 *          from the data of a vtkRiemannMetricSource upstream.
 *
 * vtkRiemannGeodesicAlgorithm and vtkRiemannFieldAlgorithm each keep one for
 * their last input port, so that a metric can come through the pipeline
 * (SetMetricConnection; ParaView's filters take theirs so) instead of
 * SetMetric(): then the metric follows the source's changes and its time
 * (the pipeline's UPDATE_TIME_STEP reaches the source upstream; the source's
 * TIME_STEPS are copied to the outputs, CopyTimeSteps).
 *
 * Not wrapped (NOWRAP_CLASSES): the filters hold one; scripts use SetMetricConnection.
 */
#ifndef vtkRiemannMetricInput_h
#define vtkRiemannMetricInput_h

#include "RiemannCommonCoreModule.h" // For export macro
#include "vtkNew.h"                  // For vtkNew
#include "vtkRiemannMetric.h"        // For vtkNew<vtkRiemannMetric>

#include <string> // For std::string

class vtkAlgorithm;
class vtkDataObject;
class vtkInformation;
class vtkInformationVector;

class RIEMANNCOMMONCORE_EXPORT vtkRiemannMetricInput
{
public:
  /// The port's requirements: any data object (what the source makes), optional.
  static void FillPortInformation(vtkInformation* info);

  /**
   * The metric `algorithm` integrates with: the one carried by its input at
   * `port` when that port is connected, else `own` (SetMetric's). Null with
   * `error` set when there is none or it does not parse. The pipeline's
   * metric is parsed again only when its definition, folder or time changed.
   */
  vtkRiemannMetric* Resolve(
    vtkAlgorithm* algorithm, int port, vtkRiemannMetric* own, std::string& error);

  /**
   * The metric `data` carries (a vtkRiemannMetricSource's output, or data
   * that kept its field data), parsed again only when its definition,
   * folder or time changed; null with `error` set when it carries none or
   * it does not parse. The handle is this object's: valid until the next call.
   */
  vtkRiemannMetric* FromData(vtkDataObject* data, std::string& error);

  /// Whether `data` carries a metric (the field-data array of the definition).
  static bool CarriesMetric(vtkDataObject* data);

  /// Whether `algorithm`'s input at `port` is connected.
  static bool IsConnected(vtkAlgorithm* algorithm, int port);

  /**
   * Copy TIME_STEPS and TIME_RANGE from the metric input's information to
   * every output that has none (the pipeline copies them from port 0 only).
   */
  static void CopyTimeSteps(vtkInformationVector* metricInput, vtkInformationVector* outputs);

private:
  /// Parse the definition `data` carries into Metric; false with `error`.
  bool Read(vtkDataObject* data, std::string& error);

  vtkNew<vtkRiemannMetric> Metric;
  /// Definition, folder and time of the metric last parsed ("" before).
  std::string Parsed;
};

#endif
