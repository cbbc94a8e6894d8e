#include "RiemannMeshTextures.h"

#include "RiemannScene.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <exception>

namespace riemann
{
namespace
{
/// The mesh objects of `scene` and their triangles.
std::vector<std::pair<std::size_t, std::shared_ptr<const TriangleMesh>>> MeshesOf(
  const Scene& scene)
{
  std::vector<std::pair<std::size_t, std::shared_ptr<const TriangleMesh>>> meshes;
  for (std::size_t i = 0; i < scene.Objects.size(); ++i)
  {
    const SceneObject& object = scene.Objects[i];
    if (object.Type == ObjectType::Mesh)
    {
      meshes.emplace_back(i,
        object.Mesh >= 0 && object.Mesh < static_cast<int>(scene.Meshes.size())
          ? scene.Meshes[object.Mesh]
          : nullptr);
    }
  }
  return meshes;
}
} // namespace

bool MeshTextures::Update(const Scene& scene, vtkOpenGLRenderWindow* window, std::string& error)
{
  auto meshes = MeshesOf(scene);
  if (meshes == this->Key && !this->Buffers.empty())
  {
    return true;
  }
  this->Release(window);
  MeshBVH bvh;
  try
  {
    bvh = BuildMeshBVH(scene);
  }
  catch (const std::exception& e)
  {
    error = e.what();
    return false;
  }
  ++this->Builds;
  if (!this->Upload(bvh, window, error))
  {
    this->Release(window);
    return false;
  }
  this->Key = std::move(meshes);
  this->Triangles = bvh.Triangles.size();
  return true;
}

bool MeshTextures::Upload(const MeshBVH& bvh, vtkOpenGLRenderWindow* window, std::string& error)
{
  // Every array as RGBA32F texels (integers as exact float values).
  struct Array
  {
    const char* Uniform;
    const void* Data;
    std::size_t Bytes;
  };
  const Array arrays[] = {
    { "rt_mesh_nodes", bvh.Nodes.data(), bvh.Nodes.size() * sizeof(MeshBVHNode) },
    { "rt_mesh_triangles", bvh.Triangles.data(), bvh.Triangles.size() * sizeof(MeshBVHTriangle) },
    { "rt_mesh_corners", bvh.Corners.data(), bvh.Corners.size() * sizeof(MeshBVHCorners) },
    { "rt_mesh_normals", bvh.VertexNormals.data(), bvh.VertexNormals.size() * sizeof(float) },
    { "rt_mesh_colors", bvh.VertexColors.data(), bvh.VertexColors.size() * sizeof(float) },
  };
  GLint limit = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &limit);
  constexpr std::size_t texel = 4 * sizeof(float);
  for (const Array& array : arrays)
  {
    const std::size_t texels = array.Bytes / texel;
    if (texels == 0 || texels > static_cast<std::size_t>(limit))
    {
      error = std::string("the meshes do not fit this GPU's buffer textures (") + array.Uniform +
        " needs " + std::to_string(texels) + " texels, the limit is " + std::to_string(limit) + ")";
      return false;
    }
    Buffer buffer{ array.Uniform, vtkSmartPointer<vtkOpenGLBufferObject>::New(),
      vtkSmartPointer<vtkTextureObject>::New() };
    buffer.Data->SetType(vtkOpenGLBufferObject::TextureBuffer);
    if (!buffer.Data->Upload(static_cast<const float*>(array.Data), array.Bytes / sizeof(float),
          vtkOpenGLBufferObject::TextureBuffer))
    {
      error = std::string("could not upload ") + array.Uniform + " (" +
        std::to_string(array.Bytes) + " bytes)";
      return false;
    }
    buffer.Texture->SetContext(window);
    if (!buffer.Texture->CreateTextureBuffer(
          static_cast<unsigned int>(texels), 4, VTK_FLOAT, buffer.Data))
    {
      error = std::string("could not create the buffer texture ") + array.Uniform;
      return false;
    }
    this->Buffers.push_back(buffer);
  }
  return true;
}

void MeshTextures::Activate(vtkShaderProgram* program)
{
  for (Buffer& buffer : this->Buffers)
  {
    buffer.Texture->Activate();
    program->SetUniformi(buffer.Uniform, buffer.Texture->GetTextureUnit());
  }
}

void MeshTextures::Deactivate()
{
  for (Buffer& buffer : this->Buffers)
  {
    buffer.Texture->Deactivate();
  }
}

void MeshTextures::Release(vtkWindow* window)
{
  for (Buffer& buffer : this->Buffers)
  {
    buffer.Texture->ReleaseGraphicsResources(window);
    buffer.Data->ReleaseGraphicsResources();
  }
  this->Buffers.clear();
  this->Key.clear();
  this->Triangles = 0;
}
} // namespace riemann
