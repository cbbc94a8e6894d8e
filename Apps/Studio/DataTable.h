/**
 * @file DataTable.h
 * @brief An item's data as a table, as ParaView's spreadsheet shows it: one
 * row per point, the point's coordinates (Points_X, Points_Y, Points_Z) and
 * its point arrays (a vector array's components as name_0, name_1, ...),
 * for the spreadsheet view and the .csv export.
 */
#ifndef RiemannStudioDataTable_h
#define RiemannStudioDataTable_h

#include "vtkSmartPointer.h"

#include <QByteArray>
#include <QString>

class vtkDataObject;
class vtkTable;

namespace riemann
{
namespace studio
{
/// The points of `data` (a vtkDataSet) as a table; empty for other data.
vtkSmartPointer<vtkTable> PointTable(vtkDataObject* data);

/// The table as CSV (a header of column names, then one line per row), by
/// vtkDelimitedTextWriter.
QByteArray TableCsv(vtkTable* table);
} // namespace studio
} // namespace riemann

#endif
