#include "SpreadsheetView.h"

#include "DataTable.h"

#include "vtkAbstractArray.h"
#include "vtkTable.h"
#include "vtkVariant.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace riemann
{
namespace studio
{
SpreadsheetView::SpreadsheetView(QWidget* parent)
  : QWidget(parent)
  , Heading(new QLabel(this))
  , Cells(new QTableWidget(this))
{
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(this->Heading);
  layout->addWidget(this->Cells);
  this->Cells->setEditTriggers(QAbstractItemView::NoEditTriggers);
  this->Cells->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  this->Show(QString(), nullptr);
}

QString SpreadsheetView::Title() const
{
  return this->Heading->text();
}

void SpreadsheetView::Show(const QString& title, vtkDataObject* data)
{
  const vtkSmartPointer<vtkTable> table = PointTable(data);
  const vtkIdType rows = table->GetNumberOfRows();
  const int shown = static_cast<int>(std::min<vtkIdType>(rows, MaximumRows));
  this->Heading->setText(title.isEmpty()
      ? QStringLiteral("Select an item (or pick a pixel) to see its points")
      : QStringLiteral("%1: %2 points%3")
          .arg(title)
          .arg(rows)
          .arg(rows > shown ? QStringLiteral(", the first %1 shown").arg(shown) : QString()));
  this->Cells->clear();
  this->Cells->setColumnCount(static_cast<int>(table->GetNumberOfColumns()));
  this->Cells->setRowCount(shown);
  QStringList names;
  for (vtkIdType c = 0; c < table->GetNumberOfColumns(); ++c)
  {
    names << QString::fromUtf8(table->GetColumnName(c));
    for (int r = 0; r < shown; ++r)
    {
      const double value = table->GetValue(r, c).ToDouble();
      this->Cells->setItem(r, static_cast<int>(c), new QTableWidgetItem(QString::number(value, 'g', 8)));
    }
  }
  this->Cells->setHorizontalHeaderLabels(names);
}
} // namespace studio
} // namespace riemann
