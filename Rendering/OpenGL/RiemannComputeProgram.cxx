#include "RiemannComputeProgram.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtk_glew.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkRiemannComputeProgram);

namespace
{
/// The info log of a shader (`isProgram` false) or program object, trimmed.
std::string InfoLog(GLuint object, bool isProgram)
{
  const auto getParameter = isProgram ? glGetProgramiv : glGetShaderiv;
  const auto getLog = isProgram ? glGetProgramInfoLog : glGetShaderInfoLog;
  GLint length = 0;
  getParameter(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> text(static_cast<std::size_t>(length > 0 ? length : 0) + 1, '\0');
  if (length > 0)
  {
    getLog(object, length, nullptr, text.data());
  }
  std::string log(text.data());
  const std::size_t end = log.find_last_not_of(" \n\r\t");
  log.erase(end == std::string::npos ? 0 : end + 1);
  return log;
}
} // namespace

namespace riemann
{
bool ComputeShadersAvailable()
{
  return GLEW_VERSION_4_3 || (GLEW_ARB_compute_shader && GLEW_ARB_shader_image_load_store);
}


int ScatteringStride(unsigned int count)
{
  // A prime near 0.38 count (the golden section: consecutive workgroups land
  // far apart, and far from the ones before) that does not divide count, so
  // that n -> n * stride mod count is a permutation, and small enough that
  // n * stride stays below 2^32 (the shader's unsigned arithmetic).
  const auto isPrime = [](unsigned int n)
  {
    for (unsigned int d = 2; d * d <= n; ++d)
    {
      if (n % d == 0)
      {
        return false;
      }
    }
    return n >= 2;
  };
  if (count < 3)
  {
    return 1;
  }
  const unsigned int limit = 0xffffffffu / count;
  for (unsigned int stride = std::min(static_cast<unsigned int>(0.381966 * count), limit);
       stride >= 2; --stride)
  {
    if (isPrime(stride) && count % stride != 0)
    {
      return static_cast<int>(stride);
    }
  }
  return 1;
}
} // namespace riemann

vtkRiemannComputeProgram::~vtkRiemannComputeProgram()
{
  // ReleaseProgram() ran in the owner's ReleaseGraphicsResources; the base
  // class must not see a handle it did not make.
  this->Handle = 0;
  this->Linked = false;
}

bool vtkRiemannComputeProgram::Build(const std::string& source, std::string& log)
{
  log.clear();
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  if (shader == 0)
  {
    log = "glCreateShader(GL_COMPUTE_SHADER) failed: the context has no compute shaders";
    return false;
  }
  const GLchar* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint compiled = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
  if (compiled != GL_TRUE)
  {
    log = InfoLog(shader, false);
    glDeleteShader(shader);
    if (log.empty())
    {
      log = "(the GLSL compiler gave no log)";
    }
    return false;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  // The program keeps the compiled code; the shader object is not needed.
  glDetachShader(program, shader);
  glDeleteShader(shader);
  GLint linked = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  if (linked != GL_TRUE)
  {
    log = InfoLog(program, true);
    glDeleteProgram(program);
    if (log.empty())
    {
      log = "(the GLSL linker gave no log)";
    }
    return false;
  }
  // What vtkShaderProgram's uniform setters look at.
  this->Handle = static_cast<int>(program);
  this->Linked = true;
  this->Compiled = false; // no vertex or fragment shader objects of the base class to clean up
  return true;
}

void vtkRiemannComputeProgram::Use(vtkOpenGLRenderWindow* window)
{
  window->GetShaderCache()->ReleaseCurrentShader();
  glUseProgram(static_cast<GLuint>(this->Handle));
  this->Bound = true;
}

void vtkRiemannComputeProgram::Dispatch(int width, int height, int groupX, int groupY)
{
  if (width <= 0 || height <= 0)
  {
    return;
  }
  const GLuint tilesX = static_cast<GLuint>((width + groupX - 1) / groupX);
  const GLuint tilesY = static_cast<GLuint>((height + groupY - 1) / groupY);
  // The tiles in a scattered order (RiemannRayTraceCS.glsl: rt_tile_stride).
  const int grid[2] = { static_cast<int>(tilesX), static_cast<int>(tilesY) };
  this->SetUniform2i("rt_tile_grid", grid);
  this->SetUniformi("rt_tile_stride", riemann::ScatteringStride(tilesX * tilesY));
  glDispatchCompute(tilesX, tilesY, 1);
  // The images are read next as textures (composition) or through a
  // framebuffer (the hit capture).
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void vtkRiemannComputeProgram::Unuse()
{
  glUseProgram(0);
  this->Bound = false;
}

void vtkRiemannComputeProgram::ReleaseProgram(vtkWindow* window)
{
  if (this->Handle == 0)
  {
    return;
  }
  vtkOpenGLRenderWindow* context = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (context)
  {
    context->MakeCurrent();
  }
  glDeleteProgram(static_cast<GLuint>(this->Handle));
  this->Handle = 0;
  this->Linked = false;
  this->Bound = false;
}
