/**
 * @class riemann::studio::SpreadsheetView
 * @brief The spreadsheet dock of riemann-studio: the selected item's points
 * (or, with no item selected, the picked ray's) as a table, ParaView's
 * spreadsheet view for one item (DataTable.h: coordinates and point arrays).
 * At most MaximumRows rows are shown; the title says how many there are.
 */
#ifndef RiemannStudioSpreadsheetView_h
#define RiemannStudioSpreadsheetView_h

#include <QWidget>

class QLabel;
class QTableWidget;
class vtkDataObject;

namespace riemann
{
namespace studio
{
class SpreadsheetView : public QWidget
{
  Q_OBJECT
public:
  static constexpr int MaximumRows = 10000;

  explicit SpreadsheetView(QWidget* parent = nullptr);
  /// Show `data`'s points under `title` (nothing: an empty table).
  void Show(const QString& title, vtkDataObject* data);
  QTableWidget* Table() const { return this->Cells; }
  QString Title() const;

private:
  QLabel* Heading;
  QTableWidget* Cells;
};
} // namespace studio
} // namespace riemann

#endif
