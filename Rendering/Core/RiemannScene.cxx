#include "RiemannScene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace riemann
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
}

void SetDefaultMaterialBounds(Material& material, const Vec3& lo, const Vec3& hi)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    const bool flat = !(hi[axis] > lo[axis]);
    material.Bounds[2 * axis] = flat ? lo[axis] - 1 : lo[axis];
    material.Bounds[2 * axis + 1] = flat ? hi[axis] + 1 : hi[axis];
  }
}

Scene DefaultScene()
{
  Scene scene;
  SceneObject grid;
  grid.Type = ObjectType::Grid;
  grid.Spacing = 1.0;
  grid.Thickness = 0.06;
  for (int axis = 0; axis < 3; ++axis)
  {
    grid.Extent[2 * axis] = -4;
    grid.Extent[2 * axis + 1] = 4;
  }
  grid.Surface.Type = MaterialType::Position;
  std::copy(grid.Extent, grid.Extent + 6, grid.Surface.Bounds);
  scene.Objects.push_back(grid);

  scene.Camera.Position = Vec3(0, 0, 7.5);
  scene.Camera.LookAt = Vec3::Zero();
  scene.Camera.ViewUp = Vec3(0, 1, 0);
  scene.Camera.ViewAngle = 60.0;
  scene.Camera.Mode = Projection::Perspective;
  scene.HasCamera = true;

  scene.Rays.Integrator = IntegratorType::RungeKutta4;
  scene.Rays.Step = 0.02;
  scene.Rays.MaximumSteps = 800;
  scene.Rays.MaximumLength = 30.0;

  scene.Background = Vec3(0.05, 0.05, 0.08);
  scene.FogColor = Vec3::Zero();
  scene.FogDensity = 0.02;
  scene.ObserverLight = false;
  return scene;
}

//------------------------------------------------------------------------------
std::string CheckMesh(const TriangleMesh& mesh)
{
  const std::size_t points = mesh.NumberOfPoints();
  if (mesh.Points.size() % 3 != 0 || mesh.Triangles.size() % 3 != 0)
  {
    return "the point or triangle array is not a multiple of 3 long";
  }
  if (mesh.NumberOfTriangles() == 0)
  {
    return "the mesh has no triangles (empty, or only points and lines)";
  }
  if (!mesh.Normals.empty() && mesh.Normals.size() != mesh.Points.size())
  {
    return "the normal array does not match the points";
  }
  if (!mesh.Colors.empty() && mesh.Colors.size() != mesh.Points.size())
  {
    return "the colour array does not match the points";
  }
  for (std::size_t i = 0; i < mesh.Points.size(); ++i)
  {
    if (!std::isfinite(mesh.Points[i]))
    {
      return "point " + std::to_string(i / 3) + " has a coordinate that is not finite";
    }
  }
  for (std::size_t i = 0; i < mesh.Triangles.size(); ++i)
  {
    if (mesh.Triangles[i] >= points)
    {
      return "triangle " + std::to_string(i / 3) + " names point " +
        std::to_string(mesh.Triangles[i]) + " of " + std::to_string(points);
    }
  }
  return std::string();
}

namespace
{
void MeshBounds(const TriangleMesh& mesh, Vec3& lo, Vec3& hi)
{
  lo = Vec3::Constant(Infinity);
  hi = Vec3::Constant(-Infinity);
  for (std::size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      lo[axis] = std::min<double>(lo[axis], mesh.Points[3 * i + axis]);
      hi[axis] = std::max<double>(hi[axis], mesh.Points[3 * i + axis]);
    }
  }
}
}

const std::shared_ptr<const TriangleMesh>& ObjectMesh(const Scene& scene, std::size_t index)
{
  const SceneObject& object = scene.Objects.at(index);
  if (object.Mesh < 0 || object.Mesh >= static_cast<int>(scene.Meshes.size()) ||
    !scene.Meshes[object.Mesh])
  {
    throw SceneDefinitionError("scene.objects[" + std::to_string(index) +
      "]: the mesh has no triangles (" +
      (object.MeshFile.empty() ? std::string("no data given") : object.MeshFile + " not read") +
      ")");
  }
  return scene.Meshes[object.Mesh];
}

void SetMesh(Scene& scene, std::size_t object, std::shared_ptr<const TriangleMesh> mesh)
{
  if (object >= scene.Objects.size() || scene.Objects[object].Type != ObjectType::Mesh)
  {
    throw SceneDefinitionError("scene.objects[" + std::to_string(object) + "]: not a mesh object");
  }
  SceneObject& target = scene.Objects[object];
  const std::string where = "scene.objects[" + std::to_string(object) + "]" +
    (target.MeshFile.empty() ? std::string() : " (" + target.MeshFile + ")");
  if (!mesh)
  {
    throw SceneDefinitionError(where + ": no mesh");
  }
  const std::string problem = CheckMesh(*mesh);
  if (!problem.empty())
  {
    throw SceneDefinitionError(where + ": " + problem);
  }
  if (!target.HasMaterialBounds)
  {
    Vec3 lo;
    Vec3 hi;
    MeshBounds(*mesh, lo, hi);
    SetDefaultMaterialBounds(target.Surface, lo, hi);
  }
  if (target.Mesh >= 0 && target.Mesh < static_cast<int>(scene.Meshes.size()))
  {
    scene.Meshes[target.Mesh] = std::move(mesh);
  }
  else
  {
    target.Mesh = static_cast<int>(scene.Meshes.size());
    scene.Meshes.push_back(std::move(mesh));
  }
}

std::size_t AddMesh(
  Scene& scene, std::shared_ptr<const TriangleMesh> mesh, const Material& material, bool keepBounds)
{
  SceneObject object;
  object.Type = ObjectType::Mesh;
  object.Surface = material;
  object.HasMaterialBounds = keepBounds;
  scene.Objects.push_back(object);
  const std::size_t index = scene.Objects.size() - 1;
  try
  {
    SetMesh(scene, index, std::move(mesh));
  }
  catch (...)
  {
    scene.Objects.pop_back();
    throw;
  }
  return index;
}
} // namespace riemann
