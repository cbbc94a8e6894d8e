/**
 * @class   vtkRiemannMetricSource
 * @brief   A metric as pipeline data: the source the toolkit's filters take
 *          their metric from through SetMetricConnection().
 *
 * The metric is given as JSON text (SetDefinition) or a metric file
 * (SetDefinitionFile, which wins when set); SetParameter() gives a
 * top-level parameter of the definition another value without editing the
 * text (riemann::WithParameterValues), so that a user interface can show
 * each parameter as a control of its own.
 *
 * The metric's time t in [0, 1] is the pipeline's time: the source
 * advertises TIME_RANGE [0, 1] and NumberOfTimeSteps steps over it, and each
 * execution evaluates the definition at the requested UPDATE_TIME_STEP
 * (clamped to [0, 1]; 0 without a request). A filter downstream asking for
 * another time re-executes this source, as ParaView's animation does. Every
 * piece of a piece request (each rank under MPI) is the whole metric.
 *
 * The output is an empty vtkPolyData whose field data carries the metric:
 * its definition with the parameters given (string array
 * RiemannMetricDefinition), the folder its relative data files are read
 * from (RiemannMetricDataDirectory), the time (RiemannMetricTime) and a one
 * line description (RiemannMetricDescription). Text survives every
 * pipeline, process and file boundary, so the filters parse it again on
 * their side (vtkRiemannMetricInput, which does so once per definition and
 * time). On a bad definition the source reports through vtkErrorMacro
 * (GetLastError(): the message names the place in the text) and its output
 * is empty, without field data: the filters downstream then say that their
 * metric input has no metric.
 *
 * @code{.py}
 * metric = riemann.vtkRiemannMetricSource()
 * metric.SetDefinition('{"type": "conformal", "n": "1 + a*exp(-(x^2+y^2+z^2))", "parameters": {"a": 1}}')
 * metric.SetParameter("a", 0.5)
 * tracer.SetMetricConnection(metric.GetOutputPort())
 * @endcode
 */
#ifndef vtkRiemannMetricSource_h
#define vtkRiemannMetricSource_h

#include "RiemannCommonCoreModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <string>  // For std::string
#include <utility> // For std::pair
#include <vector>  // For std::vector

class vtkFieldData;
class vtkRiemannMetric;

class RIEMANNCOMMONCORE_EXPORT vtkRiemannMetricSource : public vtkPolyDataAlgorithm
{
public:
  static vtkRiemannMetricSource* New();
  vtkTypeMacro(vtkRiemannMetricSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The metric's JSON definition (Documentation/MetricFormat.md). Used when no file is set.
  vtkSetStdStringFromCharMacro(Definition);
  vtkGetCharFromStdStringMacro(Definition);
  ///@}

  ///@{
  /// A metric file; when set (not ""), it is read instead of Definition.
  vtkSetStdStringFromCharMacro(DefinitionFile);
  vtkGetCharFromStdStringMacro(DefinitionFile);
  ///@}

  ///@{
  /**
   * Give the definition's top-level parameter `name` the value `value`
   * (replacing an earlier value given to it); RemoveAllParameters() goes
   * back to the definition's own values. A name the definition does not
   * have is an error at execution.
   */
  void SetParameter(const char* name, double value);
  void RemoveAllParameters();
  int GetNumberOfParameters() const { return static_cast<int>(this->Parameters.size()); }
  ///@}

  ///@{
  /// How many time steps over [0, 1] the source advertises (at least 1; default 11: t = 0, 0.1, ..., 1).
  vtkSetClampMacro(NumberOfTimeSteps, int, 1, 100000);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

  /// Why the last execution made no metric ("" after one that did).
  const char* GetLastError() const { return this->LastError.c_str(); }

  ///@{
  /// The field-data arrays the output carries the metric in (vtkRiemannMetricInput reads them).
  static const char* DefinitionArrayName() { return "RiemannMetricDefinition"; }
  static const char* DataDirectoryArrayName() { return "RiemannMetricDataDirectory"; }
  static const char* TimeArrayName() { return "RiemannMetricTime"; }
  static const char* DescriptionArrayName() { return "RiemannMetricDescription"; }
  ///@}

  /// Write `metric` (definition, data folder, time, description) into `fieldData`.
  static void StoreMetric(vtkRiemannMetric* metric, vtkFieldData* fieldData);

protected:
  vtkRiemannMetricSource();
  ~vtkRiemannMetricSource() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkRiemannMetricSource(const vtkRiemannMetricSource&) = delete;
  void operator=(const vtkRiemannMetricSource&) = delete;

  /// The definition this execution parses, at time t, into `metric`; false after ReportError.
  bool MakeMetric(double t, vtkRiemannMetric* metric);
  void ReportError(const std::string& message);

  std::string Definition;
  std::string DefinitionFile;
  std::vector<std::pair<std::string, double>> Parameters;
  int NumberOfTimeSteps = 11;
  std::string LastError;
};

#endif
