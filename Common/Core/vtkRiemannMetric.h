/**
 * @class   vtkRiemannMetric
 * @brief   A Riemannian metric on R^3, defined by its JSON text.
 *
 * vtkRiemannMetric is the VTK handle on a metric of the RiemannVTK core: the
 * graph of a function, a diffeomorphism (with compositions), a conformal
 * refractive index, a constant tensor, or Euclidean space (the JSON format is
 * documented in MetricDefinition.h and ARCHITECTURE.md). Filters such as
 * vtkRiemannGeodesicTracer take it with SetMetric().
 *
 * SetDefinition() parses and validates the text; on bad input it returns
 * false, GetLastError() says where and why, and the previous definition is
 * kept (nothing is lost). The point queries (EvaluateMetricTensor, ...) are
 * thread-safe and cheap.
 *
 * @code{.py}
 * m = riemann.vtkRiemannMetric()
 * if not m.SetDefinition('{"type": "diffeo", "preset": "twist"}'):
 *     raise ValueError(m.GetLastError())
 * @endcode
 */
#ifndef vtkRiemannMetric_h
#define vtkRiemannMetric_h

#include "JsonInputError.h"         // For riemann::JsonErrorPlace
#include "RiemannCommonCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <memory> // For std::shared_ptr, std::atomic_load
#include <string> // For std::string

namespace riemann
{
class Metric;
}

class vtkImageData;

class RIEMANNCOMMONCORE_EXPORT vtkRiemannMetric : public vtkObject
{
public:
  static vtkRiemannMetric* New();
  vtkTypeMacro(vtkRiemannMetric, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Set the metric from its JSON definition (or a file holding it). Returns
   * true on success. On failure the current metric is unchanged and
   * GetLastError() explains the problem.
   */
  bool SetDefinition(const char* json);
  bool SetDefinitionFile(const char* path);
  ///@}

  /**
   * SetDefinition() with the folder that relative data files of the
   * definition (a "sampled" metric's "file") are read from: what
   * SetDefinitionFile() does with the file's folder, for a definition held
   * elsewhere (an editor's text, a project). Null or "": the working
   * directory.
   */
  bool SetDefinition(const char* json, const char* dataDirectory);
  /// The folder the current definition's relative data files were read from ("" if none).
  const char* GetDataDirectory() const { return this->BaseDirectory.c_str(); }

  /**
   * Set the metric from a tensor volume in memory, as the "sampled" family
   * does from a file (Documentation/MetricFormat.md): the point-data array
   * `arrayName` of `image` ("" or null: its active tensors, else its one
   * array of 6 or 9 components), on the image's origin, spacing and
   * direction, interpolated by the cubic B-spline of SampledTensorField;
   * `inverse` uses each tensor's inverse (diffusion tensors), `scale`
   * multiplies the metric, `repair` clamps eigenvalues that are not
   * positive to a floor instead of refusing the data, and `outside` is
   * "euclidean" (g = I beyond the volume) or "stop" (geodesics and rays stop
   * where they leave it, TerminationReason 10), and `christoffel` how
   * geodesics and rays read g and its derivatives: "voxels" (sampled at the
   * voxels, trilinear: the fast reading, on the CPU and in the shader) or
   * "spline" (the spline's own, exact). Returns false, and GetLastError()
   * says why (how many samples are bad and where), on bad data. The
   * definition text then records the options; the data are not re-read at
   * SetTime (nothing of them is animated).
   */
  bool SetTensorData(vtkImageData* image, const char* arrayName, bool inverse = false,
    double scale = 1.0, bool repair = false, const char* outside = "euclidean",
    const char* christoffel = "voxels");

  ///@{
  /**
   * The time t in [0, 1] at which animated numbers ({"from": a, "to": b})
   * of the definition are evaluated (default 0). Returns false, keeping the
   * current metric, if the definition is not valid at t (GetLastError says why).
   */
  bool SetTime(double t);
  double GetTime() const { return this->Time; }
  ///@}

  /**
   * Take a definition already parsed by the core at time 0 (a scene's metric:
   * riemann::Scene::ParsedMetric) instead of parsing `json` again; parses it
   * when the time is not 0. Same result and return value as SetDefinition.
   * `baseDirectory`: where its relative data files are (the scene's
   * riemann::Scene::MetricDirectory).
   */
  VTK_WRAPEXCLUDE bool SetParsedDefinition(const std::string& json,
    std::shared_ptr<const riemann::Metric> metricAtTimeZero,
    const std::string& baseDirectory = std::string());

  /// The JSON text of the current definition ("" when none has been set).
  /**
   * Make this metric the same as `other` (definition, time and the parsed
   * core metric, which is immutable and so shared, not parsed again). A
   * computation on another thread gets its own handle this way, so that
   * the original can be redefined meanwhile (as the desktop app does).
   */
  void ShallowCopy(vtkRiemannMetric* other);

  const char* GetDefinition() const { return this->Definition.c_str(); }

  /// Why the last SetDefinition/SetDefinitionFile failed ("" after a success).
  const char* GetLastError() const { return this->LastError.c_str(); }

  ///@{
  /**
   * Where in the definition's text the last error is, as data: the 1-based
   * line and column (in characters) and the byte offset of the offending
   * value, key, expression character or syntax error. 0 (offset -1) when
   * the error has no place in the text: the metric as a whole is not valid,
   * a file cannot be read, or after a success. An editor underlines from
   * these; it need not read the message.
   */
  int GetLastErrorLine() const;
  int GetLastErrorColumn() const;
  int GetLastErrorOffset() const;
  ///@}

  /// The JSON pointer of the failing value ("/compose/1/phi/0"; "" for the
  /// whole definition or no place).
  const char* GetLastErrorPointer() const { return this->LastErrorPlace.Pointer.c_str(); }

  /// All of the last error's place (path, key, expression column, text place).
  VTK_WRAPEXCLUDE const riemann::JsonErrorPlace& GetLastErrorPlace() const
  {
    return this->LastErrorPlace;
  }

  /// True once a valid definition is set.
  bool HasDefinition() const;

  /// "graph", "diffeo", "conformal", "tensor", "euclidean", or "" when none.
  std::string GetFamilyName() const;

  /// One line describing the metric and its providers.
  std::string GetDescription() const;

  ///@{
  /**
   * Point queries. Each returns false where no metric is set or the metric
   * is degenerate at p. g and its inverse are row-major 3x3; gamma is
   * Gamma^m_ij at gamma[9 m + 3 i + j].
   */
  bool EvaluateMetricTensor(const double p[3], double g[9]);
  bool EvaluateInverseMetricTensor(const double p[3], double inverse[9]);
  bool EvaluateChristoffelSymbols(const double p[3], double gamma[27]);
  ///@}

  /// sqrt(det g) at p; NaN where undefined.
  double EvaluateVolumeForm(const double p[3]);

  /**
   * The core metric, shared and immutable: filters hold it for the duration
   * of a computation so a concurrent SetDefinition cannot pull it away (the
   * pointer is loaded and stored atomically).
   */
  VTK_WRAPEXCLUDE std::shared_ptr<const riemann::Metric> GetMetric() const;

protected:
  vtkRiemannMetric();
  ~vtkRiemannMetric() override;

private:
  vtkRiemannMetric(const vtkRiemannMetric&) = delete;
  void operator=(const vtkRiemannMetric&) = delete;

  /// Parse `json` with relative data files read from `baseDirectory`.
  bool SetDefinitionIn(const char* json, const std::string& baseDirectory);

  std::shared_ptr<const riemann::Metric> Metric;
  std::string Definition;
  /// The folder of the definition's file (relative "sampled" files).
  std::string BaseDirectory;
  /// True when the metric came from SetTensorData (no text to parse again).
  bool FromTensorData = false;
  std::string LastError;
  riemann::JsonErrorPlace LastErrorPlace;
  double Time = 0.0;
};

#endif
