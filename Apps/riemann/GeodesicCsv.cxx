#include "GeodesicCsv.h"

#include "CsvWriter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <fstream>

namespace riemann
{
namespace cli
{
bool WriteGeodesicCsv(vtkPolyData* lines, const std::string& path)
{
  std::ofstream out(path);
  if (!out)
  {
    return false;
  }
  vtkDataArray* determinant = lines->GetPointData()->GetArray("TransverseJacobian");
  vtkDataArray* singular = lines->GetPointData()->GetArray("TransverseJacobianSingularValues");
  // The transverse Jacobian's columns come after the fixed ones, when asked.
  out << "seed_id,step,t,x,y,z,vx,vy,vz"
      << (determinant ? ",TransverseJacobian,SingularValue0,SingularValue1" : "") << "\n";
  CsvWriter csv(out);
  vtkDataArray* arcLength = lines->GetPointData()->GetArray("ArcLength");
  vtkDataArray* velocity = lines->GetPointData()->GetArray("Velocity");
  vtkDataArray* seedIds = lines->GetCellData()->GetArray("SeedIds");
  if (!arcLength || !velocity)
  {
    return false; // not geodesics as the filters make them: a bug of the caller
  }
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  auto iterator = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
  vtkIdType cell = 0;
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal();
       iterator->GoToNextCell(), ++cell)
  {
    iterator->GetCurrentCell(count, ids);
    // Lines without SeedIds (vtkRiemannMinimalGeodesics') are numbered in order.
    const long long seed = seedIds ? static_cast<long long>(seedIds->GetTuple1(cell)) : cell;
    for (vtkIdType k = 0; k < count; ++k)
    {
      double p[3], v[3];
      lines->GetPoint(ids[k], p);
      velocity->GetTuple(ids[k], v);
      csv.Add(seed).Add(static_cast<long long>(k)).Add(arcLength->GetTuple1(ids[k]));
      csv.Add(p[0]).Add(p[1]).Add(p[2]).Add(v[0]).Add(v[1]).Add(v[2]);
      if (determinant && singular)
      {
        csv.Add(determinant->GetTuple1(ids[k]))
          .Add(singular->GetComponent(ids[k], 0))
          .Add(singular->GetComponent(ids[k], 1));
      }
      csv.EndRow();
    }
  }
  return csv.Finish();
}
} // namespace cli
} // namespace riemann
