/**
 * @file RiemannMeshTextures.h
 * @brief Private to Rendering/OpenGL: the meshes' hierarchy (RiemannMeshBVH.h)
 * as the GPU pass's five buffer textures (RiemannRayTraceMeshes.glsl reads
 * them), uploaded when the scene's meshes change and bound for each frame.
 */
#ifndef RiemannMeshTextures_h
#define RiemannMeshTextures_h

#include "RiemannMeshBVH.h"

#include "vtkSmartPointer.h"

#include <memory>
#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace riemann
{
struct Scene;
struct TriangleMesh;

class MeshTextures
{
public:
  /**
   * Make the textures hold the meshes of `scene`: nothing to do when they
   * are the meshes of the last call (the same objects and triangles);
   * otherwise build the hierarchy (Embree) and upload it. False with
   * `error` when the build fails or the context cannot hold the buffers.
   */
  bool Update(const Scene& scene, vtkOpenGLRenderWindow* window, std::string& error);

  /// Bind the textures to free units and point the samplers at them.
  void Activate(vtkShaderProgram* program);
  void Deactivate();

  void Release(vtkWindow* window);

  /// Triangles uploaded (0 before the first Update()).
  std::size_t GetNumberOfTriangles() const { return this->Triangles; }
  /// Hierarchy builds so far (a new mesh: one more; a moved camera: none).
  int GetNumberOfBuilds() const { return this->Builds; }

private:
  struct Buffer
  {
    const char* Uniform;
    vtkSmartPointer<vtkOpenGLBufferObject> Data;
    vtkSmartPointer<vtkTextureObject> Texture;
  };

  bool Upload(const MeshBVH& bvh, vtkOpenGLRenderWindow* window, std::string& error);

  std::vector<Buffer> Buffers;
  /// What was uploaded: each mesh object's index and triangles (held, so
  /// that a freed mesh's address cannot pass for the same mesh).
  std::vector<std::pair<std::size_t, std::shared_ptr<const TriangleMesh>>> Key;
  std::size_t Triangles = 0;
  int Builds = 0;
};
} // namespace riemann

#endif
