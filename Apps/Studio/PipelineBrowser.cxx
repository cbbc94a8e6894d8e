#include "PipelineBrowser.h"

#include "PipelineItem.h"
#include "PipelineItems.h"
#include "StudioDocument.h"

#include "vtkRiemannMetric.h"
#include "vtkRiemannScene.h"

#include <QFileInfo>
#include <QHeaderView>
#include <QKeyEvent>

namespace riemann
{
namespace studio
{
PipelineBrowser::PipelineBrowser(StudioDocument* document, QWidget* parent)
  : QTreeWidget(parent)
  , Document(document)
{
  this->setObjectName("PipelineBrowser");
  this->setColumnCount(1);
  this->header()->hide();
  this->setSelectionMode(QAbstractItemView::SingleSelection);
  this->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::DoubleClicked);
  this->Metric = new QTreeWidgetItem(this);
  this->Metric->setToolTip(0, "The metric: edit it in the Metric panel");
  this->Scene = new QTreeWidgetItem(this);
  this->Scene->setToolTip(0, "The scene of the inside view; its settings are the view's");
  this->Metric->setExpanded(true);
  this->UpdateMetricRow();

  for (const auto& item : document->Items())
  {
    this->AddRow(item.get());
  }
  QObject::connect(document, &StudioDocument::ItemAdded, this, [this](PipelineItem* item) {
    this->AddRow(item);
    this->Select(item);
  });
  QObject::connect(document, &StudioDocument::ItemRemoved, this, &PipelineBrowser::RemoveRow);
  QObject::connect(document, &StudioDocument::MetricChanged, this, &PipelineBrowser::UpdateMetricRow);
  QObject::connect(document, &StudioDocument::SceneChanged, this, &PipelineBrowser::UpdateMetricRow);
  QObject::connect(document, &StudioDocument::ItemFinished, this,
    [this](PipelineItem* item, bool) { this->UpdateRow(item); });
  QObject::connect(this, &QTreeWidget::itemSelectionChanged, this, &PipelineBrowser::SelectionChanged);
  QObject::connect(this, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* row, int) {
    if (this->Updating)
    {
      return;
    }
    for (const auto& entry : this->Rows)
    {
      if (entry.second == row)
      {
        entry.first->SetVisible(row->checkState(0) == Qt::Checked);
        entry.first->SetName(row->text(0));
        this->UpdateRow(entry.first);
      }
    }
  });
}

void PipelineBrowser::UpdateMetricRow()
{
  const std::string name = this->Document->Metric()->GetFamilyName();
  this->Metric->setText(0, QStringLiteral("Metric (%1)").arg(QString::fromStdString(name)));
  const QString file = QString::fromUtf8(this->Document->Scene()->GetDefinitionFile());
  this->Scene->setText(0, this->Document->Scene()->HasDefinition()
      ? QStringLiteral("Scene (%1)").arg(file.isEmpty() ? "text" : QFileInfo(file).fileName())
      : QStringLiteral("Scene (default grid)"));
}

void PipelineBrowser::AddRow(PipelineItem* item)
{
  this->Updating = true;
  auto* row = new QTreeWidgetItem(this->Metric);
  row->setFlags(row->flags() | Qt::ItemIsEditable | Qt::ItemIsUserCheckable);
  this->Rows[item] = row;
  this->Metric->setExpanded(true);
  this->Updating = false;
  this->UpdateRow(item);
  QObject::connect(item, &PipelineItem::NameChanged, this, [this, item]() { this->UpdateRow(item); });
  QObject::connect(
    item, &PipelineItem::VisibilityChanged, this, [this, item]() { this->UpdateRow(item); });
}

void PipelineBrowser::UpdateRow(PipelineItem* item)
{
  QTreeWidgetItem* row = this->Row(item);
  if (!row)
  {
    return;
  }
  this->Updating = true;
  row->setText(0, item->Name());
  row->setCheckState(0, item->IsVisible() ? Qt::Checked : Qt::Unchecked);
  const QString error = this->Document->ItemError(item);
  row->setToolTip(0, QStringLiteral("%1 (%2)%3")
                       .arg(PipelineItemLabel(item->Kind()), QString::fromStdString(item->FilterClass()),
                         error.isEmpty() ? QString() : QStringLiteral("\nLast run failed: ") + error));
  row->setForeground(0, error.isEmpty() ? this->palette().text() : QBrush(QColor(0xb0, 0x00, 0x20)));
  this->Updating = false;
}

void PipelineBrowser::RemoveRow(PipelineItem* item)
{
  auto row = this->Rows.find(item);
  if (row != this->Rows.end())
  {
    delete row->second;
    this->Rows.erase(row);
  }
}

QTreeWidgetItem* PipelineBrowser::Row(PipelineItem* item) const
{
  auto row = this->Rows.find(item);
  return row == this->Rows.end() ? nullptr : row->second;
}

PipelineItem* PipelineBrowser::SelectedItem() const
{
  const QList<QTreeWidgetItem*> selected = this->selectedItems();
  for (const auto& entry : this->Rows)
  {
    if (!selected.isEmpty() && entry.second == selected.first())
    {
      return entry.first;
    }
  }
  return nullptr;
}

bool PipelineBrowser::IsMetricSelected() const
{
  return !this->selectedItems().isEmpty() && this->selectedItems().first() == this->Metric;
}

bool PipelineBrowser::IsSceneSelected() const
{
  return !this->selectedItems().isEmpty() && this->selectedItems().first() == this->Scene;
}

void PipelineBrowser::Select(PipelineItem* item)
{
  if (QTreeWidgetItem* row = this->Row(item))
  {
    this->setCurrentItem(row);
  }
}

void PipelineBrowser::SelectMetric()
{
  this->setCurrentItem(this->Metric);
}

void PipelineBrowser::SelectScene()
{
  this->setCurrentItem(this->Scene);
}

void PipelineBrowser::keyPressEvent(QKeyEvent* event)
{
  if (event->key() == Qt::Key_Delete && this->SelectedItem() && this->state() != EditingState)
  {
    Q_EMIT this->DeleteRequested(this->SelectedItem());
    return;
  }
  QTreeWidget::keyPressEvent(event);
}
}
}
