/**
 * @file RiemannPolyDataMesh.h
 * @brief Triangle meshes of the scene from VTK data: any vtkPolyData
 * (triangulated as needed) or a .vtp/.ply/.obj/.stl file read with VTK's
 * readers, converted to the VTK-free riemann::TriangleMesh that the CPU
 * tracer hands to Embree.
 *
 * Colours per vertex: a named point array mapped through a colour map
 * ("cool-to-warm", "viridis", "grayscale", "rainbow"; a vector array by
 * its magnitude), else the data's unsigned-char RGB(A) scalars, else none
 * (the object's material). Point normals: the data's, else computed
 * (vtkPolyDataNormals, sharp edges split) for smooth shading.
 *
 * Errors throw riemann::SceneDefinitionError with a message that names the
 * cause: file not found, unknown extension, a reader's error, no triangles,
 * non-finite coordinates, a colour array that is not there.
 */
#ifndef RiemannPolyDataMesh_h
#define RiemannPolyDataMesh_h

#include "RiemannRenderingSceneModule.h" // For export macro
#include "RiemannScene.h"

#include "vtkSmartPointer.h"

#include <memory>
#include <string>

class vtkPolyData;

namespace riemann
{
/// How a mesh's vertices are coloured.
struct MeshColoring
{
  /// Point array mapped through ColorMap; "" for the RGB scalars or the material.
  std::string Array;
  std::string ColorMap = "cool-to-warm";
  /// Colour-map range; the array's own range when HasRange is false.
  double Range[2] = { 0, 1 };
  bool HasRange = false;
};

/// Convert any vtkPolyData (polygons and strips are triangulated; vertices and lines ignored).
RIEMANNRENDERINGSCENE_EXPORT std::shared_ptr<TriangleMesh> MeshFromPolyData(
  vtkPolyData* data, const MeshColoring& coloring = MeshColoring());

/// Read a .vtp, .ply, .obj or .stl file with VTK's readers.
RIEMANNRENDERINGSCENE_EXPORT vtkSmartPointer<vtkPolyData> ReadMeshFile(
  const std::string& path);

/// Read and convert the file of every mesh object of `scene` that has one (SetMesh).
RIEMANNRENDERINGSCENE_EXPORT void LoadSceneMeshes(Scene& scene);
} // namespace riemann

#endif
