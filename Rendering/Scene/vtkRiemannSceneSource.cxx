#include "vtkRiemannSceneSource.h"

#include "RiemannScene.h"
#include "RiemannSceneIntersection.h"
#include "RiemannShading.h"
#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRiemannScene.h"
#include "vtkSphereSource.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkRiemannSceneSource);
vtkCxxSetObjectMacro(vtkRiemannSceneSource, Scene, vtkRiemannScene);

vtkRiemannSceneSource::vtkRiemannSceneSource()
{
  this->SetNumberOfInputPorts(0);
}

vtkRiemannSceneSource::~vtkRiemannSceneSource()
{
  this->SetScene(nullptr);
}

vtkMTimeType vtkRiemannSceneSource::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  return this->Scene ? std::max(time, this->Scene->GetMTime()) : time;
}

namespace
{
/// Cell data `ObjectIndex`: which scene object (index in "objects") a cell belongs to.
void AddObjectIndex(vtkPolyData* piece, int object)
{
  vtkNew<vtkIntArray> index;
  index->SetName("ObjectIndex");
  index->SetNumberOfTuples(piece->GetNumberOfCells());
  index->FillValue(object);
  piece->GetCellData()->AddArray(index);
}

/// Triangulate `piece`, colour its vertices by the object's material, append.
void AddPiece(
  vtkAppendPolyData* append, vtkPolyDataAlgorithm* source, const riemann::Scene& scene, int object)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  triangles->Update();
  vtkNew<vtkPolyData> piece;
  piece->ShallowCopy(triangles->GetOutput());
  piece->GetPointData()->Initialize(); // normals/texture coordinates differ between sources
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(piece->GetNumberOfPoints());
  riemann::SceneHit hit;
  hit.Object = object;
  for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
  {
    double p[3];
    piece->GetPoint(i, p);
    hit.Position = riemann::Vec3(p[0], p[1], p[2]);
    const riemann::Vec3 color = riemann::SurfaceColor(scene, hit);
    for (int c = 0; c < 3; ++c)
    {
      colors->SetTypedComponent(
        i, c, static_cast<unsigned char>(std::lround(255.0 * std::clamp(color[c], 0.0, 1.0))));
    }
  }
  piece->GetPointData()->SetScalars(colors);
  AddObjectIndex(piece, object);
  append->AddInputData(piece);
}
}

namespace
{
/// A grid object as one box per bar: bars parallel to axis a through the
/// lattice lines of the other two axes, clipped to the extent.
void AddGridBars(
  vtkAppendPolyData* append, const riemann::SceneObject& o, const riemann::Scene& scene, int object)
{
  const double* e = o.Extent;
  for (int a = 0; a < 3; ++a)
  {
    const int b = (a + 1) % 3;
    const int c = (a + 2) % 3;
    // The lattice lines inside the extent, with the ray tracers' 1e-9
    // slack so that rounding (-0.3 / 0.1 = -2.9999999999999996) keeps
    // the boundary lines.
    const auto first = [&](int axis) { return std::ceil(e[2 * axis] / o.Spacing - 1e-9); };
    const auto last = [&](int axis) { return std::floor(e[2 * axis + 1] / o.Spacing + 1e-9); };
    for (double i = first(b); i <= last(b); ++i)
    {
      for (double j = first(c); j <= last(c); ++j)
      {
        double bounds[6];
        // Bars run the extent plus half the thickness (RiemannScene.h).
        bounds[2 * a] = e[2 * a] - 0.5 * o.Thickness;
        bounds[2 * a + 1] = e[2 * a + 1] + 0.5 * o.Thickness;
        bounds[2 * b] = i * o.Spacing - 0.5 * o.Thickness;
        bounds[2 * b + 1] = i * o.Spacing + 0.5 * o.Thickness;
        bounds[2 * c] = j * o.Spacing - 0.5 * o.Thickness;
        bounds[2 * c + 1] = j * o.Spacing + 0.5 * o.Thickness;
        vtkNew<vtkCubeSource> bar;
        bar->SetBounds(bounds);
        AddPiece(append, bar, scene, object);
      }
    }
  }
}

/// A mesh object's triangles, coloured per vertex as the tracer colours them.
void AddMesh(vtkAppendPolyData* append, const riemann::TriangleMesh& mesh,
  const riemann::Scene& scene, int object)
{
  const vtkIdType pointCount = static_cast<vtkIdType>(mesh.NumberOfPoints());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(pointCount);
  for (vtkIdType i = 0; i < pointCount; ++i)
  {
    points->SetPoint(i, &mesh.Points[3 * i]);
  }
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(static_cast<vtkIdType>(mesh.NumberOfTriangles()),
    3 * static_cast<vtkIdType>(mesh.NumberOfTriangles()));
  for (std::size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    const vtkIdType ids[3] = { mesh.Triangles[3 * t], mesh.Triangles[3 * t + 1],
      mesh.Triangles[3 * t + 2] };
    triangles->InsertNextCell(3, ids);
  }
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(pointCount);
  riemann::SceneHit hit;
  hit.Object = object;
  for (vtkIdType i = 0; i < pointCount; ++i)
  {
    riemann::Vec3 color;
    if (!mesh.Colors.empty())
    {
      color = riemann::Vec3(mesh.Colors[3 * i], mesh.Colors[3 * i + 1], mesh.Colors[3 * i + 2]);
    }
    else
    {
      hit.Position = riemann::Vec3(mesh.Points[3 * i], mesh.Points[3 * i + 1], mesh.Points[3 * i + 2]);
      color = riemann::SurfaceColor(scene, hit);
    }
    for (int c = 0; c < 3; ++c)
    {
      colors->SetTypedComponent(
        i, c, static_cast<unsigned char>(std::lround(255.0 * std::clamp(color[c], 0.0, 1.0))));
    }
  }
  vtkNew<vtkPolyData> piece;
  piece->SetPoints(points);
  piece->SetPolys(triangles);
  piece->GetPointData()->SetScalars(colors);
  AddObjectIndex(piece, object);
  append->AddInputData(piece);
}
}

int vtkRiemannSceneSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  const riemann::Scene scene = this->Scene ? this->Scene->GetScene() : riemann::DefaultScene();
  vtkNew<vtkAppendPolyData> append;
  for (size_t k = 0; k < scene.Objects.size(); ++k)
  {
    const riemann::SceneObject& o = scene.Objects[k];
    const int object = static_cast<int>(k);
    switch (o.Type)
    {
      case riemann::ObjectType::Grid:
        AddGridBars(append, o, scene, object);
        break;
      case riemann::ObjectType::Sphere:
      {
        vtkNew<vtkSphereSource> sphere;
        sphere->SetCenter(o.A.data());
        sphere->SetRadius(o.Radius);
        sphere->SetThetaResolution(48);
        sphere->SetPhiResolution(24);
        AddPiece(append, sphere, scene, object);
        break;
      }
      case riemann::ObjectType::Plane:
      {
        // A square patch around the point, subdivided so checkers show.
        riemann::Vec3 u = o.B.unitOrthogonal();
        riemann::Vec3 w = o.B.cross(u).normalized();
        const double h = 0.5 * this->PlaneSize;
        vtkNew<vtkPlaneSource> plane;
        riemann::Vec3 origin = o.A - h * u - h * w;
        riemann::Vec3 point1 = o.A + h * u - h * w;
        riemann::Vec3 point2 = o.A - h * u + h * w;
        plane->SetOrigin(origin.data());
        plane->SetPoint1(point1.data());
        plane->SetPoint2(point2.data());
        plane->SetResolution(64, 64);
        AddPiece(append, plane, scene, object);
        break;
      }
      case riemann::ObjectType::Box:
      {
        vtkNew<vtkCubeSource> box;
        box->SetBounds(o.A[0], o.B[0], o.A[1], o.B[1], o.A[2], o.B[2]);
        AddPiece(append, box, scene, object);
        break;
      }
      case riemann::ObjectType::Mesh:
        if (o.Mesh >= 0 && o.Mesh < static_cast<int>(scene.Meshes.size()) &&
          scene.Meshes[o.Mesh])
        {
          AddMesh(append, *scene.Meshes[o.Mesh], scene, object);
        }
        break;
    }
  }
  if (append->GetNumberOfInputConnections(0) > 0)
  {
    append->Update();
    output->ShallowCopy(append->GetOutput());
  }
  else
  {
    output->Initialize();
  }
  return 1;
}

void vtkRiemannSceneSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scene: " << this->Scene << "\n";
  os << indent << "PlaneSize: " << this->PlaneSize << "\n";
}
