/**
 * @file StudioDocument.h
 * @brief Everything a Riemann Studio session is: the metric (its JSON text,
 * parameter values and time), the scene, the observer (the inside view's
 * camera), the inside view's ray settings and the pipeline items; and the
 * running of the items' jobs when what they depend on changes.
 *
 * The metric on screen is always the last good one: SetMetricText() with a
 * bad text reports the error (and where it is) and changes nothing.
 */
#ifndef RiemannStudio_StudioDocument_h
#define RiemannStudio_StudioDocument_h

#include "JobRunner.h"
#include "MetricText.h"
#include "PipelineItem.h"

#include <QObject>
#include <QString>

#include "vtkNew.h"

#include <map>
#include <set>
#include <memory>
#include <string>
#include <vector>

class vtkCamera;
class vtkRiemannIntegrationSettings;
class vtkRiemannMetric;
class vtkRiemannScene;

namespace riemann
{
namespace studio
{
/// The outcome of a metric edit: empty Message when it was taken.
struct MetricStatus
{
  QString Message;
  TextLocation Location;
  bool Ok() const { return this->Message.isEmpty(); }
};

class StudioDocument : public QObject
{
  Q_OBJECT
public:
  explicit StudioDocument(QObject* parent = nullptr);
  ~StudioDocument() override;

  /// The metric of the session when it starts: the paper's Gaussian bump
  /// written with parameters a and s (so sliders show at once).
  static const char* DefaultMetricText();

  ///@{
  /// The metric: its text as the editor holds it, the slider values of its
  /// plain-number parameters (by JSON pointer) and the time t in [0, 1].
  MetricStatus SetMetricText(const std::string& text);
  const std::string& MetricText() const { return this->Text; }
  /// The folder a relative "file" of the text (a sampled metric's volume) is
  /// read from: the metric file's, the scene's metric's or the project's.
  void SetMetricDirectory(const std::string& folder) { this->MetricFolder = folder; }
  const std::string& MetricDirectory() const { return this->MetricFolder; }
  /// The definition in use: the text with the parameter values applied.
  std::string EffectiveMetricText() const;
  const std::vector<MetricParameter>& Parameters() const { return this->TextParameters; }
  double ParameterValue(const std::string& pointer) const;
  MetricStatus SetParameterValue(const std::string& pointer, double value);
  const std::map<std::string, double>& ParameterValues() const { return this->Values; }
  MetricStatus SetTime(double t);
  double Time() const;
  vtkRiemannMetric* Metric() const { return this->CurrentMetric; }
  ///@}

  ///@{
  /// The scene (a vtkRiemannScene without definition is the default grid).
  /// A scene that names a metric replaces the metric text too.
  QString SetSceneText(const std::string& text);
  QString LoadSceneFile(const QString& path);
  /// Back to the default scene (the paper's grid).
  void ResetScene();
  vtkRiemannScene* Scene() const { return this->CurrentScene; }
  ///@}

  ///@{
  /// The observer: the inside view's camera. ResetObserver puts it where
  /// the scene's camera is (or the default scene's).
  vtkCamera* Observer() const { return this->ObserverCamera; }
  void ResetObserver();
  /// Call after changing the observer (the views do): re-runs what follows it.
  void ObserverChanged();
  ///@}

  ///@{
  /// Ray settings of the inside view (pass, CPU tracer, picks, ray bundles).
  vtkRiemannIntegrationSettings* RaySettings() const { return this->Rays; }
  bool UseSceneSettings() const { return this->SceneSettings; }
  void SetUseSceneSettings(bool use);
  /// The inside view's size in pixels (ray bundles use its pixels).
  void SetViewSize(int width, int height);
  int ViewWidth() const { return this->Width; }
  int ViewHeight() const { return this->Height; }
  ///@}

  ///@{
  /// Pipeline items, in browser order.
  PipelineItem* AddItem(std::unique_ptr<PipelineItem> item);
  PipelineItem* AddItem(const std::string& kind);
  void RemoveItem(PipelineItem* item);
  void RemoveAllItems();
  const std::vector<std::unique_ptr<PipelineItem>>& Items() const { return this->ItemList; }
  int IndexOf(const PipelineItem* item) const;
  /// A name not used yet: "Geodesics1", "Geodesics2", ...
  QString UniqueName(const QString& base) const;
  ///@}

  ///@{
  /// Run an item's job now (also done on every change it depends on).
  void Run(PipelineItem* item);
  /**
   * An item coloured "over time" gets its range sampled (TimeRangeSampler)
   * when it has none for what it shows now: after it computes, and when its
   * colouring array changes. t alone never resamples (the range is over all t).
   */
  void SampleTimeRange(PipelineItem* item);
  void RunAll();
  JobRunner* Jobs() { return &this->Runner; }
  /// Why the item's last run failed ("" when it did not).
  QString ItemError(const PipelineItem* item) const;
  /**
   * Cancel every job (the window's Cancel): each cancelled item keeps its
   * last result and goes back to the settings that result was computed
   * with, so its properties say what the views show and a later change
   * does not restart the cancelled work by itself.
   */
  void CancelAll();
  /// Whether a hidden item missed a run (it computes when shown again).
  bool IsStale(const PipelineItem* item) const { return this->Stale.count(item) > 0; }
  ///@}

  JobInputs MakeJobInputs() const;

Q_SIGNALS:
  /// The metric in use changed (text, parameter value or time).
  void MetricChanged();
  /// The parameter list changed (a new text): sliders are rebuilt.
  void ParametersChanged();
  void SceneChanged();
  void ObserverMoved();
  void ItemAdded(PipelineItem* item);
  void ItemRemoved(PipelineItem* item);
  void ItemFinished(PipelineItem* item, bool ok);

private:
  MetricStatus Install(const std::string& text, const std::map<std::string, double>& values);
  void RunDependents(bool metric, bool scene, bool observer);

  vtkNew<vtkRiemannMetric> CurrentMetric;
  vtkNew<vtkRiemannScene> CurrentScene;
  vtkNew<vtkCamera> ObserverCamera;
  vtkNew<vtkRiemannIntegrationSettings> Rays;
  bool SceneSettings = true;
  int Width = 640;
  int Height = 480;
  std::string Text;
  std::string MetricFolder;
  std::vector<MetricParameter> TextParameters;
  std::map<std::string, double> Values;
  std::vector<std::unique_ptr<PipelineItem>> ItemList;
  std::map<const PipelineItem*, QString> Errors;
  /// Hidden items that missed a run.
  std::set<const PipelineItem*> Stale;
  /// The settings each item's shown result was computed with.
  std::map<const PipelineItem*, nlohmann::json> Computed;
  /// Items whose job the user cancelled (CancelAll), until its end is seen.
  std::set<const PipelineItem*> UserCancelled;
  JobRunner Runner;
};
}
}

#endif
