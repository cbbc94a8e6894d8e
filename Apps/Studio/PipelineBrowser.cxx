#include "PipelineBrowser.h"

#include "PipelineItem.h"
#include "PipelineItems.h"
#include "StudioDocument.h"

#include "vtkRiemannMetric.h"
#include "vtkRiemannScene.h"

#include <QFileInfo>
#include <QHeaderView>
#include <QKeyEvent>
#include <QPainter>
#include <QPainterPath>

namespace riemann
{
namespace studio
{
namespace
{
/// ParaView's eye: open (shown) or closed (hidden), drawn so no image file is needed.
QIcon EyeIcon(bool open)
{
  QPixmap pixmap(20, 20);
  pixmap.fill(Qt::transparent);
  QPainter painter(&pixmap);
  painter.setRenderHint(QPainter::Antialiasing);
  const QColor ink = open ? QColor(0x20, 0x20, 0x20) : QColor(0xa0, 0xa0, 0xa0);
  painter.setPen(QPen(ink, 1.5));
  QPainterPath lid;
  lid.moveTo(2, 10);
  lid.quadTo(10, 2, 18, 10);
  if (open)
  {
    lid.quadTo(10, 18, 2, 10);
    painter.drawPath(lid);
    painter.setBrush(ink);
    painter.drawEllipse(QPointF(10, 10), 3, 3);
  }
  else
  {
    // A closed lid with lashes.
    QPainterPath closed;
    closed.moveTo(2, 9);
    closed.quadTo(10, 15, 18, 9);
    painter.drawPath(closed);
    for (int x : { 6, 10, 14 })
    {
      painter.drawLine(QPointF(x, 12.5), QPointF(x, 15.5));
    }
  }
  return QIcon(pixmap);
}
}

PipelineBrowser::PipelineBrowser(StudioDocument* document, QWidget* parent)
  : QTreeWidget(parent)
  , Document(document)
{
  this->setObjectName("PipelineBrowser");
  // Column 0: the eye (click it to show or hide); column 1: the name.
  this->setColumnCount(2);
  this->header()->hide();
  this->header()->setStretchLastSection(true);
  this->setIndentation(12);
  this->setColumnWidth(0, 60);
  this->setIconSize(QSize(20, 20));
  this->setSelectionMode(QAbstractItemView::SingleSelection);
  this->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::DoubleClicked);
  this->Metric = new QTreeWidgetItem(this);
  this->Metric->setToolTip(1, "The metric: edit it in the Metric panel");
  this->Scene = new QTreeWidgetItem(this);
  this->Scene->setToolTip(1, "The scene of the inside view; its settings are the view's");
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
        entry.first->SetName(row->text(1));
        this->UpdateRow(entry.first);
      }
    }
  });
  QObject::connect(this, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem* row, int column) {
    for (const auto& entry : this->Rows)
    {
      if (entry.second == row && column == 0)
      {
        entry.first->SetVisible(!entry.first->IsVisible());
      }
    }
  });
}

void PipelineBrowser::UpdateMetricRow()
{
  const std::string name = this->Document->Metric()->GetFamilyName();
  this->Metric->setText(1, QStringLiteral("Metric (%1)").arg(QString::fromStdString(name)));
  const QString file = QString::fromUtf8(this->Document->Scene()->GetDefinitionFile());
  this->Scene->setText(1, this->Document->Scene()->HasDefinition()
      ? QStringLiteral("Scene (%1)").arg(file.isEmpty() ? "text" : QFileInfo(file).fileName())
      : QStringLiteral("Scene (default grid)"));
}

void PipelineBrowser::AddRow(PipelineItem* item)
{
  this->Updating = true;
  auto* row = new QTreeWidgetItem(this->Metric);
  row->setFlags(row->flags() | Qt::ItemIsEditable);
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
  row->setText(1, item->Name());
  row->setIcon(0, EyeIcon(item->IsVisible()));
  row->setToolTip(0, item->IsVisible() ? "Shown: click to hide" : "Hidden: click to show");
  const QString error = this->Document->ItemError(item);
  row->setToolTip(1, QStringLiteral("%1 (%2)%3")
                       .arg(PipelineItemLabel(item->Kind()), QString::fromStdString(item->FilterClass()),
                         error.isEmpty() ? QString() : QStringLiteral("\nLast run failed: ") + error));
  row->setForeground(1, error.isEmpty() ? this->palette().text() : QBrush(QColor(0xb0, 0x00, 0x20)));
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
