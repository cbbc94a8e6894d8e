#include "RiemannSceneUniformBuffer.h"

#include "vtk_glew.h"

namespace riemann
{
namespace
{
/// The binding point of the scene's block. VTK 9.1's OpenGL classes bind no
/// uniform buffers, so any point is free; 1 leaves 0 to whatever comes next.
constexpr GLuint SceneBlockBinding = 1;
constexpr const char* SceneBlockName = "rt_scene_objects";
} // namespace

bool SceneUniformBuffer::Bind(
  const std::vector<float>& block, unsigned int programHandle, std::string& error)
{
  const GLuint index = glGetUniformBlockIndex(programHandle, SceneBlockName);
  if (index == GL_INVALID_INDEX)
  {
    error = std::string("the ray-tracing program has no uniform block ") + SceneBlockName;
    return false;
  }
  GLint size = 0;
  glGetActiveUniformBlockiv(programHandle, index, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
  const GLsizeiptr bytes = static_cast<GLsizeiptr>(block.size() * sizeof(float));
  if (size != bytes)
  {
    // The shader's declaration and SceneUniformBlock disagree: a bug, said plainly.
    error = std::string("the uniform block ") + SceneBlockName + " holds " +
      std::to_string(size) + " bytes in the program, " + std::to_string(bytes) + " packed";
    return false;
  }
  if (this->Buffer == 0)
  {
    glGenBuffers(1, &this->Buffer);
    this->Uploaded.clear();
  }
  if (this->Buffer == 0)
  {
    error = "could not create the scene's uniform buffer";
    return false;
  }
  glBindBuffer(GL_UNIFORM_BUFFER, this->Buffer);
  if (block != this->Uploaded)
  {
    glBufferData(GL_UNIFORM_BUFFER, bytes, block.data(), GL_STATIC_DRAW);
    this->Uploaded = block;
    ++this->Uploads;
  }
  glBindBuffer(GL_UNIFORM_BUFFER, 0);
  glUniformBlockBinding(programHandle, index, SceneBlockBinding);
  glBindBufferBase(GL_UNIFORM_BUFFER, SceneBlockBinding, this->Buffer);
  return true;
}

void SceneUniformBuffer::Release(bool contextIsCurrent)
{
  if (this->Buffer != 0 && contextIsCurrent)
  {
    glDeleteBuffers(1, &this->Buffer);
  }
  this->Buffer = 0;
  this->Uploaded.clear();
}
} // namespace riemann
