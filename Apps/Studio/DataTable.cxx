#include "DataTable.h"

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDelimitedTextWriter.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTable.h"

namespace riemann
{
namespace studio
{
vtkSmartPointer<vtkTable> PointTable(vtkDataObject* data)
{
  auto table = vtkSmartPointer<vtkTable>::New();
  auto* dataSet = vtkDataSet::SafeDownCast(data);
  if (!dataSet)
  {
    return table;
  }
  const vtkIdType n = dataSet->GetNumberOfPoints();
  // The coordinates first, as ParaView's spreadsheet names them.
  for (int axis = 0; axis < 3; ++axis)
  {
    vtkNew<vtkDoubleArray> column;
    column->SetName(axis == 0 ? "Points_X" : axis == 1 ? "Points_Y" : "Points_Z");
    column->SetNumberOfValues(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      column->SetValue(i, dataSet->GetPoint(i)[axis]);
    }
    table->AddColumn(column);
  }
  vtkPointData* points = dataSet->GetPointData();
  for (int a = 0; a < points->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = points->GetArray(a);
    if (!array || !array->GetName())
    {
      continue;
    }
    const int components = array->GetNumberOfComponents();
    for (int c = 0; c < components; ++c)
    {
      vtkNew<vtkDoubleArray> column;
      const std::string name = components == 1
        ? std::string(array->GetName())
        : std::string(array->GetName()) + "_" + std::to_string(c);
      column->SetName(name.c_str());
      column->SetNumberOfValues(n);
      for (vtkIdType i = 0; i < n; ++i)
      {
        column->SetValue(i, array->GetComponent(i, c));
      }
      table->AddColumn(column);
    }
  }
  return table;
}

QByteArray TableCsv(vtkTable* table)
{
  vtkNew<vtkDelimitedTextWriter> writer;
  writer->SetInputData(table);
  writer->SetFieldDelimiter(",");
  writer->SetUseStringDelimiter(false);
  writer->WriteToOutputStringOn();
  writer->Write();
  // The caller owns the string RegisterAndGetOutputString hands over.
  char* text = writer->RegisterAndGetOutputString();
  const QByteArray bytes(text ? text : "");
  delete[] text;
  return bytes;
}
} // namespace studio
} // namespace riemann
