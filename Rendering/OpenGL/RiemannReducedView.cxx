#include "RiemannReducedView.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

namespace
{
/// Magnifies the traced corner of the target over the viewport.
constexpr const char* MagnifyFragmentShader = R"(//VTK::System::Dec
in vec2 texCoord;
uniform sampler2D rt_traced_color;
uniform sampler2D rt_traced_depth;
// The viewport in texture coordinates: (viewport size / d) / texture size.
uniform vec2 rt_traced_extent;
//VTK::Output::Dec
void main()
{
  vec2 uv = texCoord * rt_traced_extent;
  gl_FragData[0] = texture(rt_traced_color, uv);
  gl_FragDepth = texture(rt_traced_depth, uv).r;
}
)";

/// Composes a progressively refined view: each pixel from the finest lattice traced there.
constexpr const char* LatticeFragmentShader = R"(//VTK::System::Dec
in vec2 texCoord;
uniform sampler2D rt_traced_color;
uniform sampler2D rt_traced_depth;
uniform ivec2 rt_origin;
uniform int rt_level;
uniform int rt_rows_done;
//VTK::Output::Dec
void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: keeps texCoord (and the quad's texCoordIn) in the program
  }
  ivec2 p = ivec2(gl_FragCoord.xy) - rt_origin;
  int d = rt_level;
  ivec2 q = (p / d) * d;
  if (q.y >= rt_rows_done)
  {
    d = 2 * d;
    q = (p / d) * d;
  }
  gl_FragData[0] = texelFetch(rt_traced_color, q, 0);
  gl_FragDepth = texelFetch(rt_traced_depth, q, 0).r;
}
)";

/// A 2D texture of `window` read with `filter`, clamped to its edges.
vtkSmartPointer<vtkTextureObject> NewTargetTexture(vtkOpenGLRenderWindow* window, int filter)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(filter);
  texture->SetMagnificationFilter(filter);
  return texture;
}

bool Fits(vtkTextureObject* texture, int width, int height)
{
  return texture && static_cast<int>(texture->GetWidth()) >= width &&
    static_cast<int>(texture->GetHeight()) >= height &&
    static_cast<int>(texture->GetWidth()) <= 2 * width + 2 &&
    static_cast<int>(texture->GetHeight()) <= 2 * height + 2;
}
} // namespace

namespace riemann
{
double AdjustedImageSampleDistance(
  double distance, double seconds, double budget, double minimum, double maximum)
{
  double adjusted = distance;
  if (std::isfinite(seconds) && seconds > 0.0 && std::isfinite(budget) && budget > 0.0)
  {
    adjusted = distance * std::sqrt(seconds / budget);
  }
  return std::min(std::max(adjusted, minimum), std::max(minimum, maximum));
}

int TracedPixels(int pixels, double distance)
{
  // One more than the viewport needs: the last pixel's bilinear footprint
  // reaches half a traced pixel beyond pixels / d.
  return distance <= 1.0 ? pixels : static_cast<int>(std::ceil(pixels / distance)) + 1;
}

ReducedView::ReducedView() = default;
ReducedView::~ReducedView() = default;

void ReducedView::ReadyColor(vtkOpenGLRenderWindow* window, int width, int height)
{
  if (!Fits(this->Color, width, height))
  {
    this->ReleaseTarget(window);
    // Colour interpolated, depth from the nearest traced ray (Magnify()).
    this->Color = NewTargetTexture(window, vtkTextureObject::Linear);
    this->Color->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
  }
}

bool ReducedView::Bind(vtkOpenGLRenderWindow* window, int width, int height, std::string& error)
{
  // Step 1: a target that holds the traced pixels (kept while sizes fit it).
  this->ReadyColor(window, width, height);
  if (!this->Depth)
  {
    this->Depth = NewTargetTexture(window, vtkTextureObject::Nearest);
    this->Depth->AllocateDepth(static_cast<unsigned int>(this->Color->GetWidth()),
      static_cast<unsigned int>(this->Color->GetHeight()), vtkTextureObject::Float32);
  }
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(window);
  }
  this->TracedDepth = this->Depth;

  // Step 2: bind it, the caller's bindings saved.
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  this->Framebuffer->Bind();
  this->Framebuffer->AddColorAttachment(0, this->Color);
  this->Framebuffer->AddDepthAttachment(this->Depth);
  this->Framebuffer->ActivateDrawBuffer(0);
  this->Framebuffer->ActivateReadBuffer(0);
  const char* status = nullptr;
  if (!vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_FRAMEBUFFER, status))
  {
    state->PopFramebufferBindings();
    error = std::string("the reduced-resolution framebuffer is incomplete (") +
      (status ? status : "unknown status") + ")";
    return false;
  }
  return true;
}

bool ReducedView::BindImages(
  vtkOpenGLRenderWindow* window, int width, int height, std::string& error)
{
  // Step 1: colour and depth images that hold the traced pixels.
  this->ReadyColor(window, width, height);
  if (!this->DepthImage)
  {
    this->DepthImage = NewTargetTexture(window, vtkTextureObject::Nearest);
    this->DepthImage->Allocate2D(static_cast<unsigned int>(this->Color->GetWidth()),
      static_cast<unsigned int>(this->Color->GetHeight()), 1, VTK_FLOAT);
  }
  if (this->Color->GetHandle() == 0 || this->DepthImage->GetHandle() == 0)
  {
    error = "the compute path's colour and depth images could not be made";
    return false;
  }
  this->TracedDepth = this->DepthImage;

  // Step 2: bound for writing (units of RiemannRayTraceCS.glsl).
  glBindImageTexture(0, this->Color->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glBindImageTexture(1, this->DepthImage->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  return true;
}

void ReducedView::UnbindImages()
{
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glBindImageTexture(1, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
}

void ReducedView::Unbind(vtkOpenGLRenderWindow* window)
{
  window->GetState()->PopFramebufferBindings();
}

vtkShaderProgram* ReducedView::ReadyComposer(vtkOpenGLRenderWindow* window,
  std::unique_ptr<vtkOpenGLQuadHelper>& quad, const char* shader, std::string& error)
{
  if (!this->TracedDepth)
  {
    error = "nothing was traced to compose";
    return nullptr;
  }
  if (!quad)
  {
    quad.reset(new vtkOpenGLQuadHelper(window, nullptr, shader, ""));
  }
  vtkShaderProgram* program =
    quad->Program ? window->GetShaderCache()->ReadyShaderProgram(quad->Program) : nullptr;
  if (!program)
  {
    quad.reset();
    error = "the shader that composes the traced view could not be built";
    return nullptr;
  }
  this->Color->Activate();
  this->TracedDepth->Activate();
  program->SetUniformi("rt_traced_color", this->Color->GetTextureUnit());
  program->SetUniformi("rt_traced_depth", this->TracedDepth->GetTextureUnit());
  return program;
}

void ReducedView::Compose(
  vtkOpenGLRenderWindow* window, vtkOpenGLQuadHelper* quad, const int viewport[4])
{
  window->GetState()->vtkglViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  window->GetState()->vtkglScissor(viewport[0], viewport[1], viewport[2], viewport[3]);
  quad->Render();
  this->TracedDepth->Deactivate();
  this->Color->Deactivate();
}

bool ReducedView::Magnify(
  vtkOpenGLRenderWindow* window, const int viewport[4], const double traced[2], std::string& error)
{
  vtkShaderProgram* program =
    this->ReadyComposer(window, this->Quad, MagnifyFragmentShader, error);
  if (!program)
  {
    return false;
  }
  const float extent[2] = { static_cast<float>(traced[0] / this->Color->GetWidth()),
    static_cast<float>(traced[1] / this->Color->GetHeight()) };
  program->SetUniform2f("rt_traced_extent", extent);
  this->Compose(window, this->Quad.get(), viewport);
  return true;
}

bool ReducedView::ComposeLattice(vtkOpenGLRenderWindow* window, const int viewport[4],
  int level, int rowsDone, std::string& error)
{
  vtkShaderProgram* program =
    this->ReadyComposer(window, this->LatticeQuad, LatticeFragmentShader, error);
  if (!program)
  {
    return false;
  }
  const int origin[2] = { viewport[0], viewport[1] };
  program->SetUniform2i("rt_origin", origin);
  program->SetUniformi("rt_level", level);
  program->SetUniformi("rt_rows_done", rowsDone);
  this->Compose(window, this->LatticeQuad.get(), viewport);
  return true;
}

void ReducedView::Release(vtkWindow* window)
{
  this->Quad.reset(); // frees its VAO; the program stays in VTK's shader cache
  this->LatticeQuad.reset();
  this->ReleaseTarget(window);
}

void ReducedView::ReleaseTarget(vtkWindow* window)
{
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
    this->Framebuffer = nullptr;
  }
  this->TracedDepth = nullptr;
  for (vtkSmartPointer<vtkTextureObject>* texture :
    { &this->Color, &this->Depth, &this->DepthImage })
  {
    if (*texture)
    {
      (*texture)->ReleaseGraphicsResources(window);
      *texture = nullptr;
    }
  }
}
} // namespace riemann
