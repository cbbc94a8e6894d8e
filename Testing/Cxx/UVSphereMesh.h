// Shared by the rendering tests and benchmarks: a UV sphere of theta x phi
// quads, two triangles each (1000 x 500: the benchmarks' one million
// triangles), built by hand so that its size is exact.
#ifndef RiemannUVSphereMesh_h
#define RiemannUVSphereMesh_h

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cmath>

inline vtkSmartPointer<vtkPolyData> UVSphereMesh(
  double radius, int theta, int phi, double cx = 0.0, double cy = 0.0, double cz = 0.0)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  const double pi = 3.14159265358979323846;
  for (int j = 0; j <= phi; ++j)
  {
    for (int i = 0; i < theta; ++i)
    {
      const double polar = pi * j / phi;
      const double azimuth = 2 * pi * i / theta;
      points->InsertNextPoint(cx + radius * std::sin(polar) * std::cos(azimuth),
        cy + radius * std::sin(polar) * std::sin(azimuth), cz + radius * std::cos(polar));
    }
  }
  for (int j = 0; j < phi; ++j)
  {
    for (int i = 0; i < theta; ++i)
    {
      const vtkIdType a = j * theta + i;
      const vtkIdType b = j * theta + (i + 1) % theta;
      const vtkIdType c = (j + 1) * theta + (i + 1) % theta;
      const vtkIdType d = (j + 1) * theta + i;
      const vtkIdType t0[3] = { a, b, c };
      const vtkIdType t1[3] = { a, c, d };
      triangles->InsertNextCell(3, t0);
      triangles->InsertNextCell(3, t1);
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);
  return mesh;
}

#endif
