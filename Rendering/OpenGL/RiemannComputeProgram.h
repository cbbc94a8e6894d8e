/**
 * @file RiemannComputeProgram.h
 * @brief Private to Rendering/OpenGL: a GLSL compute program (OpenGL 4.3)
 * that VTK's uniform setters can address, and its dispatch.
 *
 * VTK 9.1's shader cache builds vertex, fragment and geometry programs only.
 * vtkRiemannComputeProgram is a vtkShaderProgram whose program object is a
 * compute shader compiled and linked here, so the uniform, texture and
 * buffer setters written for the fragment path (SetUniformf,
 * MetricTextures::Activate, ...) serve the compute path unchanged.
 */
#ifndef RiemannComputeProgram_h
#define RiemannComputeProgram_h

#include "RiemannRenderingOpenGLModule.h" // For export macro (ScatteringStride, tested)
#include "vtkShaderProgram.h"

#include <string>

class vtkOpenGLRenderWindow;
class vtkWindow;

namespace riemann
{
/// True where the current context runs compute shaders with image stores (OpenGL 4.3, or its
/// ARB extensions).
bool ComputeShadersAvailable();

/**
 * The stride that scatters `count` tiles (RiemannRayTraceCS.glsl): the
 * largest prime up to 0.38 count that does not divide it and keeps
 * count * stride below 2^32 (1 for fewer than 3 tiles, or where none is
 * left), so that n -> n * stride mod count visits every tile once.
 */
RIEMANNRENDERINGOPENGL_EXPORT int ScatteringStride(unsigned int count);
} // namespace riemann

class vtkRiemannComputeProgram : public vtkShaderProgram
{
public:
  static vtkRiemannComputeProgram* New();
  vtkTypeMacro(vtkRiemannComputeProgram, vtkShaderProgram);

  /**
   * Compile and link `source` as a compute shader in the current context.
   * False with the GLSL compiler's or linker's log in `log`.
   */
  bool Build(const std::string& source, std::string& log);

  /// True after a successful Build() (and until ReleaseProgram()).
  bool IsReady() const { return this->Handle != 0 && this->Linked; }

  /**
   * Make this the current program. VTK's shader cache is told to forget the
   * program it bound, so that its next ReadyShaderProgram() binds again.
   */
  void Use(vtkOpenGLRenderWindow* window);

  /**
   * Run one invocation per pixel of a width x height image in workgroups of
   * groupX x groupY pixels, then make its image stores visible to texture
   * reads and framebuffer reads.
   */
  void Dispatch(int width, int height, int groupX, int groupY);

  /// Unbind the program (glUseProgram(0)).
  void Unuse();

  /// Delete the program (`window`'s context made current first).
  void ReleaseProgram(vtkWindow* window);

protected:
  vtkRiemannComputeProgram() = default;
  ~vtkRiemannComputeProgram() override;

private:
  vtkRiemannComputeProgram(const vtkRiemannComputeProgram&) = delete;
  void operator=(const vtkRiemannComputeProgram&) = delete;
};

#endif
