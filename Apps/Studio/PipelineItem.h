/**
 * @file PipelineItem.h
 * @brief One entry of the pipeline browser: a toolkit filter run on the
 * document's metric (geodesics, ray bundle, exponential map, conjugate
 * locus, a field), its settings and how its result is shown in the outside
 * view.
 *
 * An item never computes geometry itself. MakeJob() returns the toolkit's
 * own filter, configured from the item's settings with private copies of
 * the metric, scene and camera (vtkRiemannMetric::ShallowCopy), so the job
 * may run on a worker thread while the user goes on editing. TakeResult()
 * keeps the job's output. An item draws nothing either: it says what it
 * shows (ShownData(), one OutputLook each) and the outside view draws it
 * with the display its data type has (ItemDisplay.h, OutputDisplay.h),
 * whose settings the item's form and project carry.
 *
 * Settings are one JSON object keyed by the toolkit's property names
 * (StartPosition, ConeAngle, IntegratorType, ...): the properties panel
 * edits them, the project file stores them and the Python trace writes
 * them back as the same Set calls.
 */
#ifndef RiemannStudio_PipelineItem_h
#define RiemannStudio_PipelineItem_h

#include <nlohmann/json.hpp>

#include <QObject>
#include <QString>
#include <QStringList>

#include "ColorMaps.h"   // For ColorScale
#include "ShownOutput.h" // For OutputLook
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkCamera;
class vtkDataObject;
class vtkRiemannIntegrationSettings;
class vtkRiemannMetric;
class vtkRiemannScene;

namespace riemann
{
namespace studio
{
/// One setting of an item, as the properties panel shows and checks it.
struct PropertySpec
{
  enum Kind
  {
    Number,   ///< a real number in [Minimum, Maximum]
    Integer,  ///< a whole number in [Minimum, Maximum]
    Vector3,  ///< three real numbers
    Numbers6, ///< six real numbers (bounds x0 x1 y0 y1 z0 z1)
    Integers3,///< three whole numbers (grid dimensions)
    Choice,   ///< one of Choices (stored as the string)
    Boolean,
    NumberList, ///< one or more real numbers in [Minimum, Maximum] (radii), typed "1, 2.5, 4"
    PointList  ///< zero or more points [x, y, z] (key positions), typed "x, y, z; x, y, z"
  };
  std::string Key;
  QString Label;
  Kind Type = Number;
  double Minimum = -1e300;
  double Maximum = 1e300;
  /// A Number must be strictly greater than Minimum (a step, a tolerance).
  bool MinimumExclusive = false;
  /// A Number must be strictly less than Maximum (an angle below 180 degrees).
  bool MaximumExclusive = false;
  /// A Vector3 may not be (0, 0, 0) (a direction).
  bool NonZero = false;
  QStringList Choices;
  /// A Choice that also takes any other non-empty name (a colouring array
  /// the next result will have): an editable combo box.
  bool OpenChoice = false;
  QString Help;
  /// Old keys a project or script may still use for it ("ConeAxis"): taken as Key.
  QStringList Aliases;
  /// Display-only (colouring, opacity): changing it does not re-run the job.
  bool Display = false;
  /// A new item's value, where the field's declaration gives one (the displays').
  nlohmann::json Default;
};

/**
 * Why `value` is not acceptable for `spec` (empty when it is): the panel
 * shows this next to the field and never applies such a value.
 */
QString CheckPropertyValue(const PropertySpec& spec, const nlohmann::json& value);

/**
 * The integration settings (vtkRiemannIntegrationSettings's names:
 * IntegratorType spelled euler|rk4|dp45, InitialIntegrationStep,
 * MaximumError, MaximumPropagation, MaximumNumberOfSteps), as every item and
 * the inside view's properties show them.
 */
std::vector<PropertySpec> IntegrationPropertySpecs();

/**
 * An item's defaults with the integration settings added: the toolkit's own
 * (a new vtkRiemannIntegrationSettings, that is the core's GeodesicOptions,
 * as `riemann trace` has them: one default per setting), except the
 * integrator and the arc length, which are the item's choice.
 */
nlohmann::json WithIntegrationDefaults(nlohmann::json own, const char* integrator, double length);

/// What a job needs from the document, copied on the GUI thread.
struct JobInputs
{
  vtkRiemannMetric* Metric = nullptr;
  vtkRiemannScene* Scene = nullptr;
  /// The inside view's camera (the observer).
  vtkCamera* Observer = nullptr;
  /// The inside view's size in pixels (the ray bundle's image).
  int Width = 640;
  int Height = 480;
  /// The inside view's ray settings (shared with the pass) and whether the
  /// scene's "integrator" block overrides them.
  vtkRiemannIntegrationSettings* RaySettings = nullptr;
  bool UseSceneSettings = true;
};

class PipelineItem : public QObject
{
  Q_OBJECT
public:
  ~PipelineItem() override;

  /// The kind as the project file and the Add menu spell it ("geodesics", ...).
  virtual std::string Kind() const = 0;
  /// The toolkit class this item runs (for tooltips and the Python trace).
  virtual std::string FilterClass() const = 0;
  /// The preset of the class's declaration a new item starts from ("Fan"), or "".
  virtual std::string Preset() const { return std::string(); }

  QString Name() const { return this->ItemName; }
  void SetName(const QString& name);
  bool IsVisible() const { return this->Visible; }
  void SetVisible(bool visible);

  /**
   * The settings the panel shows: the item's own (ItemProperties()), then
   * the display settings of its outputs' data types (DisplayPropertySpecs,
   * with the current colouring choices).
   */
  std::vector<PropertySpec> Properties() const;
  const nlohmann::json& Settings() const { return this->Values; }
  /**
   * Check and take new settings (keys not given keep their value). Returns
   * the first problem ("Seed: ..."), keeping every setting, or "" when all
   * were taken. Emits SettingsChanged(needsRun) on success.
   */
  QString ApplySettings(const nlohmann::json& settings);
  /**
   * Put back `settings` (the ones the shown result was computed with, after
   * a cancelled job) without asking for a run: the properties say what the
   * view shows, and nothing restarts by itself.
   */
  void RevertSettings(const nlohmann::json& settings);

  /// The toolkit filter for these settings, ready to Update() on any thread.
  virtual vtkSmartPointer<vtkAlgorithm> MakeJob(const JobInputs& inputs) const = 0;
  /// Keep a finished job's output and show it.
  void TakeResult(vtkAlgorithm* job);
  /// The last result (output port `port`), null before the first run.
  vtkDataObject* Result(int port = 0) const;
  int NumberOfResults() const { return static_cast<int>(this->Results.size()); }

  /// Re-run when the observer (inside camera) moves (the ray bundle).
  virtual bool FollowsObserver() const { return false; }
  /// Re-run when the scene changes.
  virtual bool UsesScene() const { return false; }
  /// Noticeable work: run with the progress bar (all jobs run off the GUI thread).
  virtual bool IsLongJob() const { return false; }

  /// How each output the item shows looks (its data type picks the view's display).
  const std::vector<OutputLook>& Looks() const { return this->OutputLooks; }
  /**
   * What the item shows, one per look: its results (the default), or what
   * it derives from them for the view (a distance field's cut locus, a
   * marker at its seed). Null entries are not shown.
   */
  virtual std::vector<vtkSmartPointer<vtkDataObject>> ShownData() const;

  /// Python lines that build this item with `import riemann` (trace export):
  /// `var` is the filter's variable; `metric`, `scene`, `camera` exist.
  virtual std::vector<std::string> PythonLines(const std::string& var) const = 0;

  /// Names of the result's arrays that colouring may use.
  QStringList ColorArrays() const;
  /// The colouring as the display applies it now.
  ColorScale CurrentColoring() const
  {
    return this->Coloring(this->Text("ColorArray"), this->Number("Opacity"));
  }

  ///@{
  /**
   * Colour range "over time": `source` names what the range was sampled
   * for (the item's job settings, its colouring array and the metric:
   * StudioDocument's TimeRangeSource). ColoursOverTime: an array colours the
   * item over time. NeedsTimeRange: it does, and has no range for `source`. SetTimeRange keeps it and redraws.
   */
  bool ColoursOverTime() const;
  bool NeedsTimeRange(const std::string& source) const;
  void SetTimeRange(const double range[2], const std::string& source);
  /// The JobRunner key of the item's range sampling (distinct from its own job).
  const void* TimeRangeKey() const { return &this->TimeRange; }
  ///@}

  /**
   * A point Ctrl+clicked in the outside view while this item is selected.
   * An item that places points takes it (the connector's ends, the distance
   * field's seed) and returns true; the others return false.
   */
  virtual bool TakePickedPoint(const double point[3])
  {
    (void)point;
    return false;
  }

Q_SIGNALS:
  /// needsRun: the job's settings changed (not only the display).
  void SettingsChanged(bool needsRun);
  void ResultChanged();
  /// Only how it is drawn changed (a colour range sampled over time).
  void DisplayChanged();
  void NameChanged();
  void VisibilityChanged();

protected:
  /// `defaults`: the item's settings (and any display default it overrides);
  /// `looks`: what it shows, whose displays' defaults complete the settings.
  PipelineItem(const QString& name, nlohmann::json defaults, std::vector<OutputLook> looks);

  /// The item's own settings: its filter's, and any the item derives its shown data with.
  virtual std::vector<PropertySpec> ItemProperties() const = 0;
  /// How `array` colours the item at `opacity`: the colour-map settings
  /// (ColorMap, ColorRange and its minimum and maximum, ColorSteps, ScalarBar).
  ColorScale Coloring(const std::string& array, double opacity) const;
  /// Shared helpers for the concrete items.
  double Number(const char* key) const;
  int Integer(const char* key) const;
  void Vector(const char* key, double* out, int count) const;
  std::string Text(const char* key) const;
  /// Copy integration settings keys (IntegratorType, InitialIntegrationStep,
  /// MaximumError, MaximumPropagation, MaximumNumberOfSteps) into `settings`.
  void ApplyIntegration(vtkRiemannIntegrationSettings* settings) const;
  /// The Python lines of ApplyIntegration.
  std::vector<std::string> IntegrationPythonLines(const std::string& var) const;
  /// `specs` followed by the integration settings.
  static std::vector<PropertySpec> WithIntegration(std::vector<PropertySpec> specs);

  std::vector<vtkSmartPointer<vtkDataObject>> Results;

private:
  double TimeRange[2] = { 0.0, 1.0 };
  std::string TimeRangeFor;
  std::vector<OutputLook> OutputLooks;
  QString ItemName;
  bool Visible = true;
  nlohmann::json Values;
};

/// Python source for a number list: "(1, 2, 3)" (round-trip precision).
std::string PythonTuple(const nlohmann::json& values);
/// Round-trip text of a double.
std::string PythonNumber(double value);
/// A Python string literal for any text (JSON included): json.dumps-style.
std::string PythonString(const std::string& text);
}
}

#endif
