/**
 * @file PipelineBrowser.h
 * @brief The pipeline browser (ParaView's): the metric and the scene at the
 * top, the items derived from them below the metric. The check box is the
 * eye (show/hide in the outside view); names are edited in place (F2 or a
 * double click); Delete removes the selected item.
 */
#ifndef RiemannStudio_PipelineBrowser_h
#define RiemannStudio_PipelineBrowser_h

#include <QTreeWidget>

#include <map>

namespace riemann
{
namespace studio
{
class PipelineItem;
class StudioDocument;

class PipelineBrowser : public QTreeWidget
{
  Q_OBJECT
public:
  explicit PipelineBrowser(StudioDocument* document, QWidget* parent = nullptr);

  /// The selected item (null when the metric or the scene is selected).
  PipelineItem* SelectedItem() const;
  bool IsMetricSelected() const;
  bool IsSceneSelected() const;
  void Select(PipelineItem* item);
  void SelectMetric();
  void SelectScene();
  QTreeWidgetItem* Row(PipelineItem* item) const;
  QTreeWidgetItem* MetricRow() const { return this->Metric; }
  QTreeWidgetItem* SceneRow() const { return this->Scene; }

Q_SIGNALS:
  void SelectionChanged();
  void DeleteRequested(PipelineItem* item);

protected:
  void keyPressEvent(QKeyEvent* event) override;

private:
  void AddRow(PipelineItem* item);
  void RemoveRow(PipelineItem* item);
  void UpdateRow(PipelineItem* item);
  void UpdateMetricRow();

  StudioDocument* Document;
  QTreeWidgetItem* Metric;
  QTreeWidgetItem* Scene;
  std::map<PipelineItem*, QTreeWidgetItem*> Rows;
  bool Updating = false;
};
}
}

#endif
