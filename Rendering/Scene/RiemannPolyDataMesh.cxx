#include "RiemannPolyDataMesh.h"

#include "InputFiles.h"
#include "RiemannPlyCheck.h"
#include "RiemannStlCheck.h"
#include "RiemannVtkMessages.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkPolyDataNormals.h"
#include "vtkSTLReader.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace riemann
{
namespace
{
/// Collects a reader's ErrorEvents (VTK readers report through them, not by return value).
struct ErrorText
{
  std::string Text;
  vtkNew<vtkCallbackCommand> Command;
  explicit ErrorText(vtkObject* object)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback(
      [](vtkObject* caller, unsigned long, void* self, void* message)
      {
        auto* errors = static_cast<ErrorText*>(self);
        if (errors->Text.empty() && message)
        {
          errors->Text =
            PlainVtkMessage(static_cast<const char*>(message), caller->GetClassName());
        }
      });
    object->AddObserver(vtkCommand::ErrorEvent, this->Command);
    object->AddObserver(vtkCommand::WarningEvent, this->Command);
  }
};

void Trim(std::string& text)
{
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
  {
    text.pop_back();
  }
}

/**
 * Why the cells of `data` cannot be used ("" when they can): a cell array
 * whose offsets do not rise within its connectivity, or a cell that refers
 * to a point the data does not have (VTK's readers keep what the file says:
 * an OBJ face "f 1 2 999999999", a VTP connectivity "-7").
 */
std::string CheckCells(vtkPolyData* data)
{
  const vtkIdType points = data->GetNumberOfPoints();
  struct Kind
  {
    const char* Name;
    vtkCellArray* Cells;
  } kinds[] = { { "vertex", data->GetVerts() }, { "line", data->GetLines() },
    { "polygon", data->GetPolys() }, { "strip", data->GetStrips() } };
  for (const Kind& kind : kinds)
  {
    if (!kind.Cells)
    {
      continue;
    }
    vtkDataArray* offsets = kind.Cells->GetOffsetsArray();
    vtkDataArray* connectivity = kind.Cells->GetConnectivityArray();
    const vtkIdType size = connectivity ? connectivity->GetNumberOfTuples() : 0;
    const vtkIdType count = offsets ? offsets->GetNumberOfTuples() : 0;
    double previous = 0.0;
    for (vtkIdType i = 0; i < count; ++i)
    {
      const double offset = offsets->GetComponent(i, 0);
      if (offset < previous || offset > static_cast<double>(size))
      {
        return std::string("the ") + kind.Name + " cells' offsets are broken (offset " +
          std::to_string(static_cast<long long>(offset)) + " at cell " + std::to_string(i) +
          ", connectivity of " + std::to_string(size) + " ids)";
      }
      previous = offset;
    }
    for (vtkIdType i = 0; i < size; ++i)
    {
      const double id = connectivity->GetComponent(i, 0);
      if (!(id >= 0.0) || id >= static_cast<double>(points))
      {
        return std::string("a ") + kind.Name + " cell refers to point " +
          std::to_string(static_cast<long long>(id)) + " (counting from 0), but the mesh has " +
          std::to_string(points) + " points";
      }
    }
  }
  return std::string();
}

vtkSmartPointer<vtkColorTransferFunction> ColorMap(const std::string& name, double lo, double hi)
{
  auto map = vtkSmartPointer<vtkColorTransferFunction>::New();
  const auto at = [lo, hi](double t) { return lo + t * (hi - lo); };
  if (name == "viridis")
  {
    // Samples of matplotlib's viridis, interpolated in RGB.
    const double points[5][4] = { { 0.0, 0.267, 0.005, 0.329 }, { 0.25, 0.229, 0.322, 0.546 },
      { 0.5, 0.128, 0.567, 0.551 }, { 0.75, 0.369, 0.789, 0.383 }, { 1.0, 0.993, 0.906, 0.144 } };
    for (const auto& p : points)
    {
      map->AddRGBPoint(at(p[0]), p[1], p[2], p[3]);
    }
  }
  else if (name == "grayscale")
  {
    map->AddRGBPoint(lo, 0, 0, 0);
    map->AddRGBPoint(hi, 1, 1, 1);
  }
  else if (name == "rainbow")
  {
    map->SetColorSpaceToHSV();
    map->HSVWrapOff();
    map->AddHSVPoint(lo, 0.667, 1, 1);
    map->AddHSVPoint(hi, 0.0, 1, 1);
  }
  else if (name == "cool-to-warm")
  {
    map->SetColorSpaceToDiverging();
    map->AddRGBPoint(lo, 0.230, 0.299, 0.754);
    map->AddRGBPoint(hi, 0.706, 0.016, 0.150);
  }
  else
  {
    throw SceneDefinitionError("unknown colour map \"" + name +
      "\"; expected \"cool-to-warm\", \"viridis\", \"grayscale\" or \"rainbow\"");
  }
  map->ClampingOn();
  return map;
}

std::string ArrayNames(vtkPointData* data)
{
  std::string names;
  for (int i = 0; i < data->GetNumberOfArrays(); ++i)
  {
    const char* name = data->GetArrayName(i);
    names += (names.empty() ? "" : ", ") + std::string(name ? name : "(unnamed)");
  }
  return names.empty() ? "none" : names;
}

// MeshFromPolyData's steps: TriangulatedSurface -> CopyGeometry ->
// ColorByArray or CopyRgbColors -> CheckMesh.

/// The surface as triangles (polygons and strips split; vertices and lines
/// dropped) with point normals: the data's own, else computed smooth across
/// faces and split at sharp edges (a cube stays a cube).
vtkSmartPointer<vtkPolyData> TriangulatedSurface(vtkPolyData* data)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(data);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  vtkSmartPointer<vtkPolyDataAlgorithm> last = triangles.Get();
  vtkNew<vtkPolyDataNormals> normals;
  if (!data->GetPointData()->GetNormals())
  {
    // Smooth shading across faces, split at sharp edges (a cube stays a cube).
    normals->SetInputConnection(triangles->GetOutputPort());
    normals->ComputePointNormalsOn();
    normals->ComputeCellNormalsOff();
    normals->SplittingOn();
    normals->SetFeatureAngle(45.0);
    normals->ConsistencyOn();
    normals->AutoOrientNormalsOff();
    last = normals.Get();
  }
  last->Update();
  return last->GetOutput();
}

/// The points, the triangles and the point normals (when there are), as floats.
void CopyGeometry(vtkPolyData* surface, TriangleMesh& mesh)
{
  const vtkIdType points = surface->GetNumberOfPoints();
  mesh.Points.resize(3 * static_cast<std::size_t>(points));
  for (vtkIdType i = 0; i < points; ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    for (int c = 0; c < 3; ++c)
    {
      mesh.Points[3 * i + c] = static_cast<float>(p[c]);
    }
  }
  vtkCellArray* polys = surface->GetPolys();
  mesh.Triangles.reserve(3 * static_cast<std::size_t>(polys->GetNumberOfCells()));
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    if (n == 3)
    {
      for (int k = 0; k < 3; ++k)
      {
        mesh.Triangles.push_back(static_cast<unsigned int>(ids[k]));
      }
    }
  }
  if (vtkDataArray* pointNormals = surface->GetPointData()->GetNormals())
  {
    mesh.Normals.resize(mesh.Points.size());
    for (vtkIdType i = 0; i < points; ++i)
    {
      double v[3];
      pointNormals->GetTuple(i, v);
      for (int c = 0; c < 3; ++c)
      {
        mesh.Normals[3 * i + c] = static_cast<float>(v[c]);
      }
    }
  }
}

/// Colours from the point array `coloring.Array` (its magnitude when it has
/// several components) through the colour map, over coloring.Range or the
/// array's own range. Throws when the surface has no such array.
void ColorByArray(vtkPointData* pointData, const MeshColoring& coloring, TriangleMesh& mesh)
{
  vtkDataArray* values = pointData->GetArray(coloring.Array.c_str());
  if (!values)
  {
    throw SceneDefinitionError("the mesh has no point array \"" + coloring.Array +
      "\" to colour by (its point arrays: " + ArrayNames(pointData) + ")");
  }
  const int components = values->GetNumberOfComponents();
  double range[2] = { coloring.Range[0], coloring.Range[1] };
  if (!coloring.HasRange)
  {
    values->GetRange(range, components == 1 ? 0 : -1);
  }
  if (!(range[1] > range[0]))
  {
    range[1] = range[0] + 1.0; // a constant array: one colour
  }
  auto map = ColorMap(coloring.ColorMap, range[0], range[1]);
  const vtkIdType points = static_cast<vtkIdType>(mesh.Points.size() / 3);
  mesh.Colors.resize(mesh.Points.size());
  for (vtkIdType i = 0; i < points; ++i)
  {
    double value = 0.0;
    if (components == 1)
    {
      value = values->GetComponent(i, 0);
    }
    else
    {
      for (int c = 0; c < components; ++c)
      {
        value += values->GetComponent(i, c) * values->GetComponent(i, c);
      }
      value = std::sqrt(value);
    }
    double rgb[3];
    map->GetColor(value, rgb);
    for (int c = 0; c < 3; ++c)
    {
      mesh.Colors[3 * i + c] = static_cast<float>(rgb[c]);
    }
  }
}

/// Colours from the surface's own RGB(A) unsigned-char scalars, when it has them.
void CopyRgbColors(vtkPointData* pointData, TriangleMesh& mesh)
{
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(pointData->GetScalars());
  if (!rgb || rgb->GetNumberOfComponents() < 3)
  {
    return;
  }
  const vtkIdType points = static_cast<vtkIdType>(mesh.Points.size() / 3);
  mesh.Colors.resize(mesh.Points.size());
  for (vtkIdType i = 0; i < points; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      mesh.Colors[3 * i + c] = rgb->GetTypedComponent(i, c) / 255.0f;
    }
  }
}
} // namespace

std::shared_ptr<TriangleMesh> MeshFromPolyData(vtkPolyData* data, const MeshColoring& coloring)
{
  if (!data)
  {
    throw SceneDefinitionError("no mesh (null vtkPolyData)");
  }
  if (data->GetNumberOfPolys() + data->GetNumberOfStrips() == 0)
  {
    throw SceneDefinitionError("the mesh has no triangles (" +
      std::to_string(data->GetNumberOfPoints()) + " points, no polygons or strips)");
  }
  // VTK's filters trust the cells: an id past the points reads out of bounds.
  const std::string cells = CheckCells(data);
  if (!cells.empty())
  {
    throw SceneDefinitionError(cells);
  }
  const vtkSmartPointer<vtkPolyData> surface = TriangulatedSurface(data);
  auto mesh = std::make_shared<TriangleMesh>();
  CopyGeometry(surface, *mesh);
  if (!coloring.Array.empty())
  {
    ColorByArray(surface->GetPointData(), coloring, *mesh);
  }
  else
  {
    CopyRgbColors(surface->GetPointData(), *mesh);
  }
  const std::string problem = CheckMesh(*mesh);
  if (!problem.empty())
  {
    throw SceneDefinitionError(problem);
  }
  return mesh;
}

vtkSmartPointer<vtkPolyData> ReadMeshFile(const std::string& path)
{
  const std::string notAFile = InputFileProblem(path, "the mesh file");
  if (!notAFile.empty())
  {
    throw SceneDefinitionError(notAFile);
  }
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  // vtkXMLPolyDataReader is no vtkPolyDataAlgorithm: hold the readers as algorithms.
  vtkSmartPointer<vtkAlgorithm> reader;
  if (extension == ".vtp")
  {
    auto xml = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    xml->SetFileName(path.c_str());
    reader = xml;
  }
  else if (extension == ".ply")
  {
    // VTK's PLY reader trusts the header: checked against it first.
    const std::string problem = CheckPlyFile(path);
    if (!problem.empty())
    {
      throw SceneDefinitionError(path + ": cannot read the mesh: " + problem);
    }
    if (!vtkPLYReader::CanReadFile(path.c_str()))
    {
      throw SceneDefinitionError(path + ": not a PLY file VTK can read");
    }
    auto ply = vtkSmartPointer<vtkPLYReader>::New();
    ply->SetFileName(path.c_str());
    reader = ply;
  }
  else if (extension == ".obj")
  {
    auto obj = vtkSmartPointer<vtkOBJReader>::New();
    obj->SetFileName(path.c_str());
    reader = obj;
  }
  else if (extension == ".stl")
  {
    // VTK's STL reader reads a binary file cut short without a word: checked first.
    const std::string problem = CheckStlFile(path);
    if (!problem.empty())
    {
      throw SceneDefinitionError(path + ": cannot read the mesh: " + problem);
    }
    auto stl = vtkSmartPointer<vtkSTLReader>::New();
    stl->SetFileName(path.c_str());
    reader = stl;
  }
  else
  {
    throw SceneDefinitionError(path + ": unknown mesh format \"" + extension +
      "\"; expected .vtp, .ply, .obj or .stl");
  }
  ErrorText errors(reader);
  reader->Update();
  Trim(errors.Text);
  vtkPolyData* output = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!errors.Text.empty())
  {
    throw SceneDefinitionError(path + ": cannot read the mesh: " + errors.Text);
  }
  if (!output || output->GetNumberOfPoints() == 0)
  {
    throw SceneDefinitionError(path + ": cannot read the mesh: no points in the file");
  }
  vtkSmartPointer<vtkPolyData> result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(output);
  return result;
}

void LoadSceneMeshes(Scene& scene)
{
  for (std::size_t i = 0; i < scene.Objects.size(); ++i)
  {
    const SceneObject& object = scene.Objects[i];
    if (object.Type != ObjectType::Mesh || object.MeshFile.empty())
    {
      continue;
    }
    const std::string where =
      "scene.objects[" + std::to_string(i) + "].file (" + object.MeshFile + ")";
    MeshColoring coloring;
    coloring.Array = object.ColorArray;
    coloring.ColorMap = object.ColorMap;
    coloring.Range[0] = object.ColorRange[0];
    coloring.Range[1] = object.ColorRange[1];
    coloring.HasRange = object.HasColorRange;
    std::shared_ptr<TriangleMesh> mesh;
    try
    {
      mesh = MeshFromPolyData(ReadMeshFile(object.MeshFile), coloring);
    }
    catch (const SceneDefinitionError& e)
    {
      std::string message = e.what();
      // ReadMeshFile's messages start with the path already.
      if (message.rfind(object.MeshFile, 0) == 0)
      {
        message = message.substr(object.MeshFile.size() + 2);
      }
      throw SceneDefinitionError(where + ": " + message);
    }
    SetMesh(scene, i, std::move(mesh));
  }
}
} // namespace riemann
